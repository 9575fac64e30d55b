package ifold.cli;

import ifold.geom.ParameterException;

/**
 * A failure the user can act on: printed as one line, {@code ifold: MESSAGE}. An error in what
 * the user typed (an option's value, a path that cannot be an output) exits
 * {@link #USAGE_EXIT_CODE}, as picocli's own errors do; an error in the data (a bad file, a model
 * that cannot be wrapped, a disk that fails) exits {@link #EXIT_CODE}.
 */
final class UserError extends RuntimeException {
    private static final long serialVersionUID = 1L;

    /** Exit code for bad data. */
    static final int EXIT_CODE = 1;

    /** Exit code for bad usage: what the user typed; picocli's too. */
    static final int USAGE_EXIT_CODE = 2;

    private final int exitCode;

    UserError(String message) {
        this(message, EXIT_CODE);
    }

    private UserError(String message, int exitCode) {
        super(message);
        this.exitCode = exitCode;
    }

    /** An error in what the user typed: exit 2. */
    static UserError usage(String message) {
        return new UserError(message, USAGE_EXIT_CODE);
    }

    /**
     * A parameter the core refused, as an error in the option that gave it: the core's name
     * {@code enterFrom} is the option {@code --enter-from}.
     */
    static UserError usage(ParameterException e) {
        String option = "--" + e.parameter().replaceAll("([A-Z])", "-$1").toLowerCase(java.util.Locale.ROOT);
        return usage("option " + option + ": " + e.getMessage());
    }

    int exitCode() {
        return exitCode;
    }
}
