package ifold.geom;

/**
 * A value given to the core that its geometry does not allow: a wrap's width or thickness, a
 * turn gadget's angle, a built-in model's counts, a demo's triangle. It names the parameter (as
 * the options records spell their components: {@code width}, {@code angle}, {@code around}), so
 * that every front end points at its own field or option with the same message: the command
 * line says {@code option --width: MESSAGE}, the window marks its width field. It lives with the
 * geometry so that every layer that checks a value (the wrap, the jobs) throws the same one.
 */
public final class ParameterException extends IllegalArgumentException {
    private static final long serialVersionUID = 1L;

    private final String parameter;

    public ParameterException(String parameter, String message) {
        super(message);
        this.parameter = parameter;
    }

    /**
     * A number as a user would have typed it: a whole one without Java's ".0" ({@code --width -1}
     * was echoed "got -1.0"), any other as Java writes it.
     */
    public static String shown(double value) {
        if (value == Math.rint(value) && Math.abs(value) < 1e15) {
            return Long.toString((long) value);
        }
        return Double.toString(value);
    }

    /** The parameter's name: {@code width}, {@code thickness}, {@code maxFaces}, {@code start}, {@code end}, {@code enterFrom}, {@code angle}, {@code overhang}. */
    public String parameter() {
        return parameter;
    }
}
