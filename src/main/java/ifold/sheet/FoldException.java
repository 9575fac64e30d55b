package ifold.sheet;

/** A fold that cannot be made on the sheet as it lies: the message says why, in the user's terms. */
public final class FoldException extends Exception {
    private static final long serialVersionUID = 1L;

    public FoldException(String message) {
        super(message);
    }
}
