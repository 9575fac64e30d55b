package ifold.render;

/** OpenGL 3.3 cannot be had here: no display, no Xvfb, or a driver too old. The message says what to do. */
public final class RenderUnavailableException extends Exception {
    private static final long serialVersionUID = 1L;

    public RenderUnavailableException(String message, Throwable cause) {
        super(message, cause);
    }
}
