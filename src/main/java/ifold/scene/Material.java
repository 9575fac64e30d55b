package ifold.scene;

/**
 * How a geometry is drawn. Paper has two sides: {@code front} is the colour of the side the
 * faces' normals point to, {@code back} of the other; per-face colours, when used, replace the
 * front colour only, so the underside still reads as the back of the paper.
 *
 * @param front colour of the front side (0xAARRGGBB)
 * @param back colour of the back side
 * @param useFaceColors take the front colour of each triangle from the mesh
 * @param showEdges draw the mesh's edges over the faces
 */
public record Material(int front, int back, boolean useFaceColors, boolean showEdges) {
    /** White paper with a grey back and dark edges. */
    public static final Material PAPER = new Material(0xFFF4F1EA, 0xFF9FB7CF, false, true);
    /** The model's own face colours. */
    public static final Material FACE_COLORS = new Material(0xFFF4F1EA, 0xFF9FB7CF, true, true);
}
