package ifold.mesh.io;

import static ifold.mesh.io.ByteTokenizer.EOF;
import static ifold.mesh.io.DecimalParser.NOT_AN_INTEGER;
import static ifold.mesh.io.ByteTokenizer.TOKEN;
import static ifold.mesh.io.DecimalParser.TOO_LARGE;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

/**
 * Reads an ASCII OFF file (Princeton Shape Benchmark / Geomview form) into a polygon soup.
 *
 * <p>Accepted: the headers {@code OFF}, {@code COFF}, {@code NOFF}, {@code CNOFF} and their
 * {@code ST} (texture coordinate) variants, alone on a line or followed by the counts; the
 * counts {@code vertices faces [edges]} (the edge count is ignored); {@code #} comments and
 * blank lines anywhere; CR, LF or CRLF line ends. A vertex record is one line: x, y, z and the
 * normal, colour or texture fields its header promises, which are skipped. A face record is a
 * vertex count n &ge; 3 and n 0-based vertex indices, which may run over several lines; the
 * values left on the line of its last index are its colour: none, one colour-map index
 * (ignored), or 3 or 4 components, integers 0..255 or, when any has a point or exponent,
 * fractions 0..1.
 *
 * <p>Header counts only say when to stop: memory grows with the data actually read.
 */
public final class OffReader {
    private final ByteTokenizer tokens;
    private PolygonSoup soup = new PolygonSoup();
    /** The indices of the face being read. */
    private int[] face = new int[16];
    /** The colour values after the indices of the face being read. */
    private final double[] color = new double[4];

    /** Header letters: how many values a vertex record carries, and its header for messages. */
    private String header;
    private int vertexValuesMin;
    private int vertexValuesMax;

    /** The counts of the header. */
    private int vertexCount;
    private int faceCount;

    /**
     * Where a piece of a file read in parallel puts its vertices (x, y, z interleaved, at their
     * index in the whole file); null when reading a file whole, into {@link #soup}.
     */
    private double[] coordinates;

    private OffReader(ByteTokenizer tokens) {
        this.tokens = tokens;
    }

    /**
     * Reads {@code file}. Every face records the line it starts on.
     *
     * @throws MeshFormatException naming the file and line for anything that is not a valid
     *         OFF file with at least one face, including a vertex index outside 0..V-1
     * @throws IOException when the file cannot be read
     */
    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        PolygonSoup parallel = ParallelOffReader.read(file);
        if (parallel != null) {
            return parallel;
        }
        try (ByteTokenizer tokens = ByteTokenizer.open(file, false)) {
            return new OffReader(tokens).read(Files.size(file));
        }
    }

    /** The shortest records: "0 0 0" and "3 0 1 2", each with its line break. */
    private static final int SHORTEST_VERTEX = 6;
    private static final int SHORTEST_TRIANGLE = 8;

    private PolygonSoup read(long fileSize) throws MeshFormatException, IOException {
        readPreamble();
        // Room for what the header says, as far as the file is big enough to hold it.
        int vertices = (int) Math.min(vertexCount, fileSize / SHORTEST_VERTEX);
        int faces = (int) Math.min(faceCount, fileSize / SHORTEST_TRIANGLE);
        soup = new PolygonSoup(vertices, faces, (int) Math.min(3L * faces, Integer.MAX_VALUE - 8));
        for (int v = 0; v < vertexCount; v++) {
            readVertex(v);
        }
        for (int f = 0; f < faceCount; f++) {
            readFace(f);
        }
        if (tokens.advanceAcrossLines() == TOKEN) {
            throw tokens.error(tokens.tokenLine(), "extra data '" + tokens.tokenText() + "' after the last of "
                    + faceCount + " faces: the header counts disagree with the data");
        }
        return soup;
    }

    /**
     * Reads the header and its counts. Returns true where the counts' line ends in a line
     * break (the records start on the next line), false where the file ends there.
     */
    private boolean readPreamble() throws MeshFormatException, IOException {
        if (tokens.advanceAcrossLines() == EOF) {
            throw tokens.error(0, "no data: only comments and blank lines");
        }
        readHeader();
        vertexCount = readCount("vertex", "vertices");
        faceCount = readCount("face", "faces");
        int countsLine = tokens.tokenLine();
        // advance() stops at a line end, so a token here is on the line of the face count.
        int t = tokens.advance();
        if (t == TOKEN) {
            if (tokens.tokenLong() == NOT_AN_INTEGER) {
                throw tokens.error(countsLine, "expected the edge count, found '" + tokens.tokenText() + "'");
            }
            t = tokens.advance();
            if (t == TOKEN) {
                throw tokens.error(countsLine, "unexpected '" + tokens.tokenText()
                        + "' after the header counts (vertices faces edges)");
            }
        }
        if (faceCount == 0) {
            throw tokens.error(countsLine, "no faces: the header declares 0 faces");
        }
        return t != EOF;
    }

    /** What the header says, for reading the records of a file in pieces. */
    record Preamble(String header, int vertexValuesMin, int vertexValuesMax, int vertexCount, int faceCount,
            long recordsOffset, int recordsLine) {
    }

    /**
     * Reads the header of {@code file}, or returns null where it holds nothing but a header
     * (the whole-file reader then says what is wrong).
     */
    static Preamble preamble(Path file) throws MeshFormatException, IOException {
        try (ByteTokenizer tokens = ByteTokenizer.open(file, false)) {
            OffReader reader = new OffReader(tokens);
            if (!reader.readPreamble()) {
                return null;
            }
            long offset = tokens.nextLineOffset();
            return new Preamble(reader.header, reader.vertexValuesMin, reader.vertexValuesMax, reader.vertexCount,
                    reader.faceCount, offset, tokens.line());
        }
    }

    /**
     * Reads records {@code first} to {@code end - 1} (vertices, then faces, counted together)
     * from {@code tokens}, a piece of a file that holds exactly them, each on a line of its
     * own: vertices into {@code coordinates}, faces into the soup returned.
     *
     * @throws MeshFormatException for anything the whole-file reader would not read the same
     *     way, a face over several lines included: the caller then reads the file whole
     */
    static PolygonSoup readRecords(ByteTokenizer tokens, Preamble preamble, double[] coordinates, int first, int end)
            throws MeshFormatException, IOException {
        OffReader reader = new OffReader(tokens);
        reader.header = preamble.header();
        reader.vertexValuesMin = preamble.vertexValuesMin();
        reader.vertexValuesMax = preamble.vertexValuesMax();
        reader.vertexCount = preamble.vertexCount();
        reader.faceCount = preamble.faceCount();
        reader.coordinates = coordinates;
        int vertices = preamble.vertexCount();
        for (int r = first; r < end; r++) {
            if (r < vertices) {
                reader.readVertex(r);
            } else {
                reader.readFace(r - vertices);
            }
        }
        if (tokens.advanceAcrossLines() != EOF) {
            throw tokens.error(tokens.tokenLine(), "more records in the piece than counted");
        }
        return reader.soup;
    }

    /** Reads [ST][C][N]OFF and sets what a vertex record holds. */
    private void readHeader() throws MeshFormatException {
        byte[] b = tokens.buffer();
        int start = tokens.tokenStart();
        int end = tokens.tokenEnd();
        int extraMin = 0;
        int extraMax = 0;
        int i = start;
        if (end - i >= 5 && b[i] == 'S' && b[i + 1] == 'T') {
            extraMin += 2; // texture coordinates s t
            extraMax += 2;
            i += 2;
        }
        if (end - i >= 4 && b[i] == 'C') {
            extraMin += 3; // r g b, or r g b a
            extraMax += 4;
            i++;
        }
        if (end - i >= 4 && b[i] == 'N') {
            extraMin += 3; // normal nx ny nz
            extraMax += 3;
            i++;
        }
        if (end - i == 4 && (b[i] == '4' || b[i] == 'n') && b[i + 1] == 'O' && b[i + 2] == 'F' && b[i + 3] == 'F') {
            throw tokens.error(tokens.tokenLine(), "header '" + tokens.tokenText()
                    + "' is not supported: only 3D OFF, COFF, NOFF and CNOFF (optionally ST...)");
        }
        if (end - i != 3 || b[i] != 'O' || b[i + 1] != 'F' || b[i + 2] != 'F') {
            if (!Double.isNaN(tokens.tokenDouble())) {
                throw tokens.error(tokens.tokenLine(), "missing OFF header: the file starts with '"
                        + tokens.tokenText() + "'");
            }
            throw tokens.error(tokens.tokenLine(), "expected an OFF header (OFF, COFF, NOFF or CNOFF), found '"
                    + tokens.tokenText() + "'");
        }
        header = tokens.tokenText();
        vertexValuesMin = 3 + extraMin;
        vertexValuesMax = 3 + extraMax;
    }

    private int readCount(String noun, String plural) throws MeshFormatException, IOException {
        if (tokens.advanceAcrossLines() == EOF) {
            throw tokens.error(tokens.lastTokenLine(), "truncated: the file ends before the " + noun + " count");
        }
        long count = tokens.tokenLong();
        if (tokens.tokenIs("BINARY")) {
            throw tokens.error(tokens.tokenLine(), "binary OFF is not supported, expected a text OFF file");
        }
        if (count == NOT_AN_INTEGER) {
            throw tokens.error(tokens.tokenLine(), "expected the " + noun + " count, found '" + tokens.tokenText() + "'");
        }
        if (count < 0) {
            throw tokens.error(tokens.tokenLine(), "negative " + noun + " count " + count);
        }
        if (count > Integer.MAX_VALUE) {
            throw tokens.error(tokens.tokenLine(), "the header claims " + (count == TOO_LARGE ? tokens.tokenText() : count)
                    + " " + plural + ", more than the " + Integer.MAX_VALUE + " a mesh can hold");
        }
        return (int) count;
    }

    private void readVertex(int v) throws MeshFormatException, IOException {
        if (tokens.advanceAcrossLines() == EOF) {
            throw truncated("the file ends after " + v + " of " + vertexCount + " vertices");
        }
        int line = tokens.tokenLine();
        double x = tokens.finiteDouble("coordinate");
        int t = tokens.advance();
        if (t != TOKEN) {
            throw badVertex(t, line, 1);
        }
        double y = tokens.finiteDouble("coordinate");
        t = tokens.advance();
        if (t != TOKEN) {
            throw badVertex(t, line, 2);
        }
        double z = tokens.finiteDouble("coordinate");
        int values = 3;
        // The values after x y z are normals, colours or texture coordinates, which a soup
        // does not keep; they must still be numbers, and as many as the header says.
        while (tokens.advance() == TOKEN) {
            if (Double.isNaN(tokens.tokenDouble())) {
                throw tokens.error(tokens.tokenLine(), "expected a number, found '" + tokens.tokenText() + "'");
            }
            values++;
        }
        if (values < vertexValuesMin || values > vertexValuesMax) {
            throw badVertex(TOKEN, line, values);
        }
        if (coordinates != null) {
            coordinates[3 * v] = x;
            coordinates[3 * v + 1] = y;
            coordinates[3 * v + 2] = z;
        } else {
            soup.addVertex(x, y, z);
        }
    }

    private MeshFormatException badVertex(int t, int line, int values) {
        if (t == EOF) {
            return truncated("the file ends inside vertex " + (soup.vertexCount() + 1));
        }
        String expected = vertexValuesMin == vertexValuesMax ? Integer.toString(vertexValuesMin)
                : vertexValuesMin + " or " + vertexValuesMax;
        return tokens.error(line, "vertex record has " + values + (values == 1 ? " value, " : " values, ")
                + header + " expects " + expected);
    }

    private void readFace(int f) throws MeshFormatException, IOException {
        if (tokens.advanceAcrossLines() == EOF) {
            throw truncated("the file ends after " + f + " of " + faceCount + " faces");
        }
        int line = tokens.tokenLine();
        long size = tokens.tokenLong();
        if (size == NOT_AN_INTEGER) {
            throw tokens.error(line, "expected the vertex count of a face, found '" + tokens.tokenText() + "'");
        }
        if (size < 3) {
            throw tokens.error(line, "face with " + size + (size == 1 ? " vertex" : " vertices") + ", need at least 3");
        }
        if (size > Integer.MAX_VALUE) {
            throw tokens.error(line, "face with " + tokens.tokenText() + " vertices, more than a mesh can hold");
        }
        int n = (int) size;
        for (int k = 0; k < n; k++) {
            if (tokens.advanceAcrossLines() == EOF) {
                throw truncated("the file ends after " + f + " of " + faceCount
                        + " faces, inside a face that declares " + n + " vertices and has " + k);
            }
            long index = tokens.tokenLong();
            if (index < 0 || index >= vertexCount) {
                throw badIndex(index, vertexCount);
            }
            // Grows with indices actually read, never with the declared size.
            if (k == face.length) {
                face = Arrays.copyOf(face, 2 * face.length);
            }
            face[k] = (int) index;
        }
        if (coordinates != null && tokens.tokenLine() != line) {
            // Read in pieces, a record is a line; a face over several is read whole instead.
            throw tokens.error(line, "a face over several lines");
        }
        int local = soup.addFace(face, n, line);
        readFaceColor(local, n);
    }

    private MeshFormatException badIndex(long index, int vertexCount) {
        if (index == NOT_AN_INTEGER) {
            return tokens.error(tokens.tokenLine(), "expected a vertex index, found '" + tokens.tokenText() + "'");
        }
        return tokens.error(tokens.tokenLine(), "vertex index " + (index == TOO_LARGE ? tokens.tokenText() : index)
                + " out of range: the file has " + (vertexCount == 0 ? "no vertices"
                        : vertexCount + " vertices (0 to " + (vertexCount - 1) + ")"));
    }

    /** Reads what follows a face's last index on its line: nothing, a colour-map index, or a colour. */
    private void readFaceColor(int f, int n) throws MeshFormatException, IOException {
        int count = 0;
        boolean fractions = false;
        int line = 0;
        while (tokens.advance() == TOKEN) {
            line = tokens.tokenLine();
            if (count == color.length) {
                throw badColorCount(line, n, "more than 4");
            }
            color[count++] = tokens.finiteDouble("colour component");
            fractions |= hasFraction();
        }
        if (count == 0 || count == 1) {
            // No colour, or an index into a colour map that OFF files do not carry. Set the
            // default explicitly: PolygonSoup fills slots it adds while growing with 0, not grey.
            if (soup.hasFaceColors()) {
                soup.setFaceColor(f, PolygonSoup.DEFAULT_COLOR);
            }
            return;
        }
        if (count == 2) {
            throw badColorCount(line, n, "2");
        }
        int r = channel(color[0], fractions, line);
        int g = channel(color[1], fractions, line);
        int b = channel(color[2], fractions, line);
        int a = count == 4 ? channel(color[3], fractions, line) : 255;
        soup.setFaceColor(f, a << 24 | r << 16 | g << 8 | b);
    }

    private MeshFormatException badColorCount(int line, int n, String count) {
        return tokens.error(line, "face has " + count + " values after its " + n
                + " vertex indices, expected none, a colour index, or 3 or 4 colour components");
    }

    /** Whether the current number token is written with a point or exponent, which makes a colour 0..1. */
    private boolean hasFraction() {
        byte[] b = tokens.buffer();
        for (int i = tokens.tokenStart(); i < tokens.tokenEnd(); i++) {
            if (b[i] == '.' || b[i] == 'e' || b[i] == 'E') {
                return true;
            }
        }
        return false;
    }

    private int channel(double value, boolean fractions, int line) throws MeshFormatException {
        if (fractions) {
            if (value < 0 || value > 1) {
                throw tokens.error(line, "colour component " + value + " outside 0 to 1");
            }
            return (int) Math.round(value * 255);
        }
        if (value < 0 || value > 255) {
            throw tokens.error(line, "colour component " + (long) value + " outside 0 to 255");
        }
        return (int) value;
    }

    private MeshFormatException truncated(String what) {
        return tokens.error(tokens.lastTokenLine(), "truncated: " + what);
    }
}
