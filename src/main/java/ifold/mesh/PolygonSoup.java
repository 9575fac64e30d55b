package ifold.mesh;

import java.util.Arrays;

/**
 * Polygons as they come from a file: a list of vertex positions and a list of faces, each face
 * a list of vertex indices, with no connectivity. Readers fill a soup; {@link MeshBuilder}
 * turns it into a {@link HalfedgeMesh}. Every face remembers the source line it came from so
 * that a problem found later can still be reported by file and line.
 *
 * <p>Arrays grow by doubling. A reader may size them at the start ({@link #PolygonSoup(int, int,
 * int)}), from a header's counts as far as the file's size bears them out, never from the
 * counts alone.
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

    /** An empty soup. */
    public PolygonSoup() {
    }

    /**
     * An empty soup with room for {@code vertices} vertices and {@code faces} faces of
     * {@code corners} corners in all before its arrays grow: a big file read into it makes no
     * garbage of half-grown arrays.
     */
    public PolygonSoup(int vertices, int faces, int corners) {
        coordinates = new double[3 * Math.max(64, vertices)];
        faceStart = new int[Math.max(64, faces) + 1];
        faceVertices = new int[Math.max(3 * 64, corners)];
        faceLine = new int[faceStart.length - 1];
    }

    /**
     * A soup of {@code vertexCount} vertices, {@code coordinates} (x, y, z interleaved, taken
     * as it is, not copied), and the faces of {@code faceParts} one part after another, with
     * their source lines and colours; the parts' own vertices are ignored. For readers that
     * read a file in pieces.
     */
    public static PolygonSoup joined(double[] coordinates, int vertexCount, java.util.List<PolygonSoup> faceParts) {
        if (coordinates.length < 3 * vertexCount) {
            throw new IllegalArgumentException("fewer coordinates than 3 x " + vertexCount);
        }
        long faces = 0;
        long corners = 0;
        boolean colors = false;
        for (PolygonSoup part : faceParts) {
            faces += part.faceCount;
            corners += part.cornerCount();
            colors |= part.faceColor != null;
        }
        if (faces + 1 > Integer.MAX_VALUE - 8 || corners > Integer.MAX_VALUE - 8) {
            throw new IllegalArgumentException("more faces or corners than a soup can hold");
        }
        PolygonSoup soup = new PolygonSoup();
        soup.coordinates = coordinates;
        soup.vertexCount = vertexCount;
        soup.faceStart = new int[(int) faces + 1];
        soup.faceVertices = new int[(int) corners];
        soup.faceLine = new int[Math.max(1, (int) faces)];
        if (colors) {
            soup.faceColor = new int[soup.faceStart.length];
            Arrays.fill(soup.faceColor, DEFAULT_COLOR);
        }
        int f = 0;
        int c = 0;
        for (PolygonSoup part : faceParts) {
            int n = part.faceCount;
            int k = part.cornerCount();
            System.arraycopy(part.faceVertices, 0, soup.faceVertices, c, k);
            for (int g = 0; g < n; g++) {
                soup.faceStart[f + g + 1] = c + part.faceStart[g + 1];
            }
            System.arraycopy(part.faceLine, 0, soup.faceLine, f, n);
            if (part.faceColor != null) {
                System.arraycopy(part.faceColor, 0, soup.faceColor, f, n);
            }
            f += n;
            c += k;
        }
        soup.faceCount = f;
        return soup;
    }

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
        endFace(start + size, sourceLine);
        return faceCount++;
    }

    /** Adds the triangle a, b, c with no source line; makes no garbage (STL adds one a facet). */
    public int addTriangle(int a, int b, int c) {
        int start = faceStart[faceCount];
        if (start + 3 > faceVertices.length) {
            faceVertices = Arrays.copyOf(faceVertices, Math.max(2 * faceVertices.length, start + 3));
        }
        faceVertices[start] = a;
        faceVertices[start + 1] = b;
        faceVertices[start + 2] = c;
        endFace(start + 3, 0);
        return faceCount++;
    }

    /** Closes face {@link #faceCount} at corner {@code end}, growing the per-face arrays as needed. */
    private void endFace(int end, int sourceLine) {
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
        faceStart[faceCount + 1] = end;
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
