package ifold.ui.model;

/** A job that could not be done, with the {@link Problem} to show: at a field, or as one message. */
public final class JobFailure extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient Problem problem;

    public JobFailure(Problem problem) {
        super(problem.message());
        this.problem = problem;
    }

    public JobFailure(String message) {
        this(Problem.of(message));
    }

    public Problem problem() {
        return problem;
    }
}
