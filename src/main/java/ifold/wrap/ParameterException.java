package ifold.wrap;

/**
 * A parameter of a wrap or a gadget outside what its geometry allows. It names the parameter
 * (as {@link Wrap.Options} and {@link TurnGadget.Options} spell their components), so that every
 * front end points at its own field or option with the same message: the command line says
 * {@code option --width: MESSAGE}, a window marks its width field.
 */
public final class ParameterException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final String parameter;

    public ParameterException(String parameter, String message) {
        super(message);
        this.parameter = parameter;
    }

    /** The parameter's name: {@code width}, {@code thickness}, {@code maxFaces}, {@code start}, {@code end}, {@code enterFrom}, {@code angle}, {@code overhang}. */
    public String parameter() {
        return parameter;
    }
}
