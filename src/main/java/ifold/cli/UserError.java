package ifold.cli;

/**
 * A failure the user can act on (a bad file, a bad option, an unwritable folder): printed as
 * one line, {@code ifold: MESSAGE}, with exit code {@link #EXIT_CODE}.
 */
final class UserError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** Exit code for bad input; picocli uses 2 for bad usage. */
    static final int EXIT_CODE = 1;

    UserError(String message) {
        super(message);
    }
}
