package ifold.mesh;

/**
 * A read-only view of vertices and polygonal faces by index: what the writers need, and what
 * a polygon soup, a halfedge mesh and a refinement result all offer.
 *
 * <p>Vertex indices run from 0 to {@link #vertexCount()} - 1; faces list their vertices
 * counter-clockwise seen from outside. Colours are packed as {@code 0xAARRGGBB}.
 */
public interface IndexedPolygons {
    int vertexCount();

    /** Coordinate {@code axis} (0 = x, 1 = y, 2 = z) of vertex {@code v}. */
    double coordinate(int v, int axis);

    int faceCount();

    int faceSize(int f);

    /** The {@code k}-th vertex of face {@code f}, {@code 0 <= k < faceSize(f)}. */
    int faceVertex(int f, int k);

    boolean hasFaceColors();

    /** The colour of face {@code f}; meaningful only when {@link #hasFaceColors()}. */
    int faceColor(int f);
}
