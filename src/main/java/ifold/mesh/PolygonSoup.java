package ifold.mesh;

import java.util.Arrays;

/**
 * Polygons as they come from a file: a list of vertex positions and a list of faces, each face
 * a list of vertex indices, with no connectivity. Readers fill a soup; {@link MeshBuilder}
 * turns it into a {@link HalfedgeMesh}. Every face remembers the source line it came from so
 * that a problem found later can still be reported by file and line.
 *
 * <p>Arrays grow by doubling, so a soup never trusts a header's count to size itself.
 */
public final class PolygonSoup implements IndexedPolygons {
    /** x, y, z of each vertex, interleaved. */
    private double[] coordinates = new double[3 * 64];
    private int vertexCount;

    /** faceStart[f] .. faceStart[f + 1] index {@link #faceVertices}; faceStart has faceCount + 1 entries. */
    private int[] faceStart = new int[65];
    /** The vertex indices of all faces, one face after another. */
    private int[] faceVertices = new int[3 * 64];
    /** The source line of each face, or 0 when it did not come from a file. */
    private int[] faceLine = new int[64];
    /** Packed 0xAARRGGBB colour of each face; null until the first colour is set. */
    private int[] faceColor;
    private int faceCount;

    /** The coordinates array itself (x, y, z interleaved; only the first 3·vertexCount entries count). */
    double[] coordinateArray() {
        return coordinates;
    }

    public int addVertex(double x, double y, double z) {
        if (3 * vertexCount + 3 > coordinates.length) {
            coordinates = Arrays.copyOf(coordinates, 2 * coordinates.length);
        }
        coordinates[3 * vertexCount] = x;
        coordinates[3 * vertexCount + 1] = y;
        coordinates[3 * vertexCount + 2] = z;
        return vertexCount++;
    }

    /**
     * Adds a face through {@code size} vertex indices taken from {@code vertices}. Indices are
     * stored as given; {@link MeshBuilder} checks them against the vertex count.
     *
     * @return the new face's index
     */
    public int addFace(int[] vertices, int size, int sourceLine) {
        int start = faceStart[faceCount];
        if (start + size > faceVertices.length) {
            faceVertices = Arrays.copyOf(faceVertices, Math.max(2 * faceVertices.length, start + size));
        }
        System.arraycopy(vertices, 0, faceVertices, start, size);
        if (faceCount + 2 > faceStart.length) {
            faceStart = Arrays.copyOf(faceStart, 2 * faceStart.length);
            faceLine = Arrays.copyOf(faceLine, faceStart.length);
            if (faceColor != null) {
                int old = faceColor.length;
                faceColor = Arrays.copyOf(faceColor, faceStart.length);
                Arrays.fill(faceColor, old, faceColor.length, DEFAULT_COLOR);
            }
        }
        faceLine[faceCount] = sourceLine;
        faceStart[faceCount + 1] = start + size;
        return faceCount++;
    }

    public int addTriangle(int a, int b, int c) {
        return addFace(new int[] {a, b, c}, 3, 0);
    }

    /** Sets the colour of face {@code f} (packed 0xAARRGGBB); faces never coloured are grey. */
    public void setFaceColor(int f, int argb) {
        if (faceColor == null) {
            faceColor = new int[faceStart.length];
            Arrays.fill(faceColor, DEFAULT_COLOR);
        }
        faceColor[f] = argb;
    }

    /** The colour given to faces of a coloured soup that carry none of their own. */
    public static final int DEFAULT_COLOR = 0xFFB4B4B4;

    @Override
    public int vertexCount() {
        return vertexCount;
    }

    @Override
    public double coordinate(int v, int axis) {
        return coordinates[3 * v + axis];
    }

    @Override
    public int faceCount() {
        return faceCount;
    }

    @Override
    public int faceSize(int f) {
        return faceStart[f + 1] - faceStart[f];
    }

    @Override
    public int faceVertex(int f, int k) {
        return faceVertices[faceStart[f] + k];
    }

    /** The line of the source file that face {@code f} came from, or 0 if none. */
    public int faceLine(int f) {
        return faceLine[f];
    }

    @Override
    public boolean hasFaceColors() {
        return faceColor != null;
    }

    @Override
    public int faceColor(int f) {
        return faceColor == null ? DEFAULT_COLOR : faceColor[f];
    }

    /** Total number of face-vertex references (the sum of all face sizes). */
    public int cornerCount() {
        return faceStart[faceCount];
    }
}
