package ifold.mesh;

/**
 * Input that the {@link MeshBuilder} refuses: a defect it cannot repair, or any defect in strict
 * mode. Names the kind and the first offending face or vertex of the input, and the source line
 * of that face when the input came from a file.
 */
public final class InvalidMeshException extends Exception {
    private static final long serialVersionUID = 1L;

    private final Defect defect;
    private final int sourceLine;

    public InvalidMeshException(Defect defect, int sourceLine, String message) {
        super(message);
        this.defect = defect;
        this.sourceLine = sourceLine;
    }

    public Defect defect() {
        return defect;
    }

    /** The 1-based line of the source file, or 0 when not known. */
    public int sourceLine() {
        return sourceLine;
    }
}
