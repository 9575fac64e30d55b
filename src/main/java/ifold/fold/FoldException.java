package ifold.fold;

/** A fold that cannot be made: the line misses the paper, nothing would move, a bad angle. */
public final class FoldException extends Exception {
    private static final long serialVersionUID = 1L;

    public FoldException(String message) {
        super(message);
    }
}
