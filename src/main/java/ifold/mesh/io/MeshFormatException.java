package ifold.mesh.io;

import java.nio.file.Path;

/**
 * A model file that cannot be read: names the file and, where there is one, the line. The
 * message reads as one line for the user: {@code FILE:LINE: what is wrong}.
 */
public final class MeshFormatException extends Exception {
    private static final long serialVersionUID = 1L;

    private final transient Path file;
    private final int line;
    private final String problem;

    /**
     * @param file the file being read
     * @param line the 1-based line of the problem, or 0 when it concerns the whole file
     * @param problem what is wrong, without the file and line
     */
    public MeshFormatException(Path file, int line, String problem) {
        super((line > 0 ? file + ":" + line + ": " : file + ": ") + problem);
        this.file = file;
        this.line = line;
        this.problem = problem;
    }

    public Path file() {
        return file;
    }

    /** The 1-based line, or 0 when the problem concerns the whole file. */
    public int line() {
        return line;
    }

    public String problem() {
        return problem;
    }
}
