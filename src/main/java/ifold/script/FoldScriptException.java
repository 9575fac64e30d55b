package ifold.script;

/** A script that cannot be read or played: names the line of the script (0 when none) and what is wrong. */
public final class FoldScriptException extends Exception {
    private static final long serialVersionUID = 1L;

    private final int line;

    public FoldScriptException(int line, String message) {
        super((line > 0 ? "line " + line + ": " : "") + message);
        this.line = line;
    }

    public int line() {
        return line;
    }
}
