package ifold.mesh.io;

import static ifold.mesh.io.ByteTokenizer.EOF;
import static ifold.mesh.io.ByteTokenizer.EOL;
import static ifold.mesh.io.ByteTokenizer.TOKEN;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Reads the polygons of a Wavefront OBJ file into a polygon soup.
 *
 * <p>Kept: {@code v x y z} (a w or vertex colour after z is ignored) and {@code f} with vertex
 * references {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}, 1-based or negative
 * (counting back from the last vertex so far). Every other statement that starts with a letter
 * ({@code o g s usemtl mtllib vt vn vp l p} and the free-form ones) is skipped. A backslash at
 * the end of a line continues the statement on the next one.
 *
 * <p>Positive indices are checked once the whole file is read, so a face may name a vertex
 * defined after it, as some exporters write them; negative ones are resolved on the spot.
 *
 * <p>A big file is read in pieces on every core ({@link ParallelObjReader}), by this same
 * parser, to the same soup and the same errors.
 */
public final class ObjReader {
    private final ByteTokenizer tokens;
    /** The faces read, and when reading a file whole its vertices too. */
    private final PolygonSoup soup;
    /** The 0-based vertex indices of the face being read. */
    private int[] face = new int[16];

    /**
     * Where a piece of a file read in parallel puts its vertices (x, y, z interleaved, at their
     * index in the whole file); null when reading a file whole, into {@link #soup}.
     */
    private final double[] coordinates;
    /** The vertices defined so far in the whole file: the next vertex's index, and what a negative index counts back from. */
    private int vertexCount;
    /** The index just past the last vertex this reader may define: its piece's share of {@link #coordinates}. */
    private final int vertexEnd;

    private ObjReader(ByteTokenizer tokens, PolygonSoup soup, double[] coordinates, int firstVertex, int vertexEnd) {
        this.tokens = tokens;
        this.soup = soup;
        this.coordinates = coordinates;
        this.vertexCount = firstVertex;
        this.vertexEnd = vertexEnd;
    }

    /**
     * Reads {@code file}. Every face records the line of its {@code f}.
     *
     * @throws MeshFormatException naming the file and line for anything that is not an OBJ file
     *         with at least one face, including an index 0 or one past the vertices
     * @throws IOException when the file cannot be read
     */
    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        PolygonSoup parallel = ParallelObjReader.read(file);
        if (parallel != null) {
            return parallel;
        }
        try (ByteTokenizer tokens = ByteTokenizer.open(file, true)) {
            PolygonSoup soup = new PolygonSoup();
            new ObjReader(tokens, soup, null, 0, Integer.MAX_VALUE).readStatements();
            if (soup.faceCount() == 0) {
                throw tokens.error(0, "no faces: " + soup.vertexCount() + " vertices and no 'f' statement");
            }
            checkIndices(soup, file);
            return soup;
        }
    }

    /**
     * Reads the statements of {@code tokens}, a piece of a file that starts at a line break and
     * holds, by a count of its lines, the vertices {@code firstVertex} to {@code vertexEnd - 1}
     * (put into {@code coordinates}) and {@code faces} faces of {@code corners} corners in all
     * (put into the soup returned, sized for them). Positive indices are left unchecked: only
     * the whole file's vertex count can tell.
     *
     * @throws MeshFormatException for anything the whole-file reader would not read the same
     *     way, counts that disagree included: the caller then reads the file whole
     */
    static PolygonSoup readStatements(ByteTokenizer tokens, double[] coordinates, int firstVertex, int vertexEnd,
            int faces, int corners) throws MeshFormatException, IOException {
        PolygonSoup soup = new PolygonSoup(0, faces, corners);
        ObjReader reader = new ObjReader(tokens, soup, coordinates, firstVertex, vertexEnd);
        reader.readStatements();
        if (reader.vertexCount != vertexEnd || soup.faceCount() != faces || soup.cornerCount() != corners) {
            throw tokens.error(0, "the piece holds other statements than counted");
        }
        return soup;
    }

    /** Reads statements up to the end of the file or piece. */
    private void readStatements() throws MeshFormatException, IOException {
        for (;;) {
            int t = tokens.advance();
            if (t == EOF) {
                break;
            }
            if (t == EOL) {
                continue;
            }
            byte[] b = tokens.buffer();
            int start = tokens.tokenStart();
            int length = tokens.tokenEnd() - start;
            byte first = b[start];
            if (length == 1 && first == 'v') {
                readVertex();
            } else if (length == 1 && first == 'f' || tokens.tokenIs("fo")) { // "fo" is an old spelling of f
                readFace();
            } else if ((first >= 'a' && first <= 'z') || (first >= 'A' && first <= 'Z')) {
                tokens.skipLine();
            } else {
                throw tokens.error(tokens.tokenLine(), "expected a statement such as 'v' or 'f', found '"
                        + tokens.tokenText() + "'");
            }
        }
    }

    private void readVertex() throws MeshFormatException, IOException {
        int line = tokens.tokenLine();
        if (tokens.advance() != TOKEN) {
            throw tooFewCoordinates(line, 0);
        }
        double x = tokens.finiteDouble("coordinate");
        if (tokens.advance() != TOKEN) {
            throw tooFewCoordinates(line, 1);
        }
        double y = tokens.finiteDouble("coordinate");
        if (tokens.advance() != TOKEN) {
            throw tooFewCoordinates(line, 2);
        }
        double z = tokens.finiteDouble("coordinate");
        if (coordinates == null) {
            soup.addVertex(x, y, z);
        } else if (vertexCount < vertexEnd) {
            coordinates[3 * vertexCount] = x;
            coordinates[3 * vertexCount + 1] = y;
            coordinates[3 * vertexCount + 2] = z;
        } else {
            // Past its share, a piece would write over the next piece's vertices.
            throw tokens.error(line, "more vertices in the piece than counted");
        }
        vertexCount++;
        tokens.skipLine(); // w, or a vertex colour: neither is kept
    }

    private MeshFormatException tooFewCoordinates(int line, int count) {
        return tokens.error(line, "vertex with " + count + (count == 1 ? " coordinate" : " coordinates")
                + ", need 3 (x y z)");
    }

    private void readFace() throws MeshFormatException, IOException {
        int line = tokens.tokenLine();
        int n = 0;
        while (tokens.advance() == TOKEN) {
            if (n == face.length) {
                face = Arrays.copyOf(face, 2 * face.length);
            }
            face[n++] = vertexReference();
        }
        if (n < 3) {
            throw tokens.error(line, "face with " + n + (n == 1 ? " vertex" : " vertices") + ", need at least 3");
        }
        soup.addFace(face, n, line);
    }

    /**
     * Parses the current token as {@code v}, {@code v/vt}, {@code v//vn} or {@code v/vt/vn}.
     *
     * @return the 0-based vertex index; for a positive reference it may still be out of range
     */
    private int vertexReference() throws MeshFormatException {
        byte[] b = tokens.buffer();
        int i = tokens.tokenStart();
        int end = tokens.tokenEnd();
        boolean negative = b[i] == '-';
        if (negative || b[i] == '+') {
            i++;
        }
        int digitsStart = i;
        long index = 0;
        for (; i < end && b[i] >= '0' && b[i] <= '9'; i++) {
            // Saturates instead of overflowing: anything this large is out of range anyway.
            if (index <= Integer.MAX_VALUE) {
                index = 10 * index + (b[i] - '0');
            }
        }
        if (i == digitsStart) {
            throw badReference();
        }
        // The texture and normal references are not kept, but they must be well formed.
        for (int slashes = 0; i < end && slashes < 2; slashes++) {
            if (b[i] != '/') {
                throw badReference();
            }
            i++;
            boolean signed = i < end && b[i] == '-';
            if (signed) {
                i++;
            }
            int fieldStart = i;
            while (i < end && b[i] >= '0' && b[i] <= '9') {
                i++;
            }
            if (signed && i == fieldStart) {
                throw badReference(); // an empty field is allowed ("1//2"), a lone minus is not
            }
        }
        if (i != end) {
            throw badReference();
        }
        if (index == 0) {
            throw tokens.error(tokens.tokenLine(), "face index 0: OBJ vertex indices start at 1 ('"
                    + tokens.tokenText() + "')");
        }
        if (index > Integer.MAX_VALUE) {
            throw tokens.error(tokens.tokenLine(), "vertex reference '" + tokens.tokenText() + "' is too large");
        }
        if (negative) {
            int v = vertexCount - (int) index;
            if (v < 0) {
                throw tokens.error(tokens.tokenLine(), "relative vertex index -" + index
                        + " points before the first vertex: only " + vertexCount + " vertices so far");
            }
            return v;
        }
        return (int) (index - 1);
    }

    private MeshFormatException badReference() {
        return tokens.error(tokens.tokenLine(), "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found '"
                + tokens.tokenText() + "'");
    }

    /**
     * Checks the positive references of {@code soup}, read from {@code file} whole or in
     * pieces, which may name vertices defined after their face.
     */
    static void checkIndices(PolygonSoup soup, Path file) throws MeshFormatException {
        int vertexCount = soup.vertexCount();
        for (int f = 0; f < soup.faceCount(); f++) {
            int size = soup.faceSize(f);
            for (int k = 0; k < size; k++) {
                int v = soup.faceVertex(f, k);
                if (v >= vertexCount) {
                    throw new MeshFormatException(file, soup.faceLine(f), "vertex index " + (v + 1L) + " out of range: the file has "
                            + vertexCount + " vertices (1 to " + vertexCount + ")");
                }
            }
        }
    }
}
