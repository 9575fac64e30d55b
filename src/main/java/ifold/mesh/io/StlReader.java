package ifold.mesh.io;

import ifold.mesh.PolygonSoup;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Reads STL, binary or ASCII, into a polygon soup. The two are told apart by content, not by
 * the 80-byte header: many binary files begin with "solid" too. A file whose size is exactly
 * 84 bytes and 50 a triangle for the count it declares is binary; any other that begins with
 * "solid" is ASCII. STL repeats every corner in each triangle: corners at exactly the same
 * position are welded into one vertex (as single-precision floats, as the file holds them), and
 * the soup goes to {@code MeshBuilder} as every reader's does, which reports the repairs.
 */
public final class StlReader {
    private static final int HEADER = 80;
    private static final int TRIANGLE = 50;

    private StlReader() {
    }

    /** What was read: the soup, and how many corners were welded into vertices they share. */
    public record Result(PolygonSoup soup, boolean binary, int triangles, long welded) {
    }

    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        return readWithCounts(file).soup();
    }

    public static Result readWithCounts(Path file) throws MeshFormatException, IOException {
        long size = Files.size(file);
        byte[] start = new byte[(int) Math.min(size, HEADER + 4)];
        try (InputStream in = Files.newInputStream(file)) {
            if (in.readNBytes(start, 0, start.length) != start.length) {
                throw new MeshFormatException(file, 0, "the file changed while it was read");
            }
        }
        if (start.length == HEADER + 4) {
            long count = ByteBuffer.wrap(start, HEADER, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xFFFFFFFFL;
            if (HEADER + 4 + TRIANGLE * count == size) {
                return binary(file, (int) count);
            }
        }
        String opening = new String(start, StandardCharsets.US_ASCII).stripLeading().toLowerCase(Locale.ROOT);
        if (opening.startsWith("solid") && isText(start)) {
            return ascii(file);
        }
        if (start.length < HEADER + 4) {
            throw new MeshFormatException(file, 0, "not an STL file: " + size + " bytes, shorter than a binary STL's 84-byte header"
                    + " and count, and not beginning with \"solid\"");
        }
        long count = ByteBuffer.wrap(start, HEADER, 4).order(ByteOrder.LITTLE_ENDIAN).getInt() & 0xFFFFFFFFL;
        throw new MeshFormatException(file, 0, String.format(Locale.ROOT, "binary STL cut short or padded: its %d triangles take"
                + " %d bytes, the file has %d", count, HEADER + 4 + TRIANGLE * count, size));
    }

    /**
     * Whether bytes can begin an ASCII STL: no control character but tab, line feed and carriage
     * return. A binary file's header may say "solid", but its triangle count (bytes 80 to 83)
     * holds zero bytes for any count under 2^24.
     */
    private static boolean isText(byte[] bytes) {
        for (byte b : bytes) {
            if ((b >= 0 && b < 0x20 && b != '\t' && b != '\n' && b != '\r') || b == 0x7F) {
                return false;
            }
        }
        return true;
    }

    private static Result binary(Path file, int count) throws MeshFormatException, IOException {
        Welder welder = new Welder();
        welder.expect(count);
        byte[] block = new byte[TRIANGLE * 4096];
        int[] corners = new int[3];
        try (InputStream in = Files.newInputStream(file)) {
            in.skipNBytes(HEADER + 4);
            int done = 0;
            while (done < count) {
                int n = Math.min(4096, count - done);
                if (in.readNBytes(block, 0, n * TRIANGLE) != n * TRIANGLE) {
                    throw new MeshFormatException(file, 0, "the file changed while it was read");
                }
                ByteBuffer buffer = ByteBuffer.wrap(block, 0, n * TRIANGLE).order(ByteOrder.LITTLE_ENDIAN);
                for (int t = 0; t < n; t++) {
                    int at = t * TRIANGLE + 12; // past the normal, which the corners' order gives again
                    for (int k = 0; k < 3; k++) {
                        float x = buffer.getFloat(at + 12 * k);
                        float y = buffer.getFloat(at + 12 * k + 4);
                        float z = buffer.getFloat(at + 12 * k + 8);
                        if (!Float.isFinite(x) || !Float.isFinite(y) || !Float.isFinite(z)) {
                            throw new MeshFormatException(file, 0, String.format(Locale.ROOT,
                                    "triangle %d (at byte %d): corner %d is not a finite number (%s %s %s)", done + t + 1,
                                    HEADER + 4 + (long) TRIANGLE * (done + t), k + 1, x, y, z));
                        }
                        corners[k] = welder.vertex(x, y, z);
                    }
                    welder.soup.addTriangle(corners[0], corners[1], corners[2]);
                }
                done += n;
            }
        }
        return new Result(welder.soup, true, count, welder.welded);
    }

    private static Result ascii(Path file) throws MeshFormatException, IOException {
        Welder welder = new Welder();
        int triangles = 0;
        try (BufferedReader reader = new BufferedReader(new InputStreamReader(Files.newInputStream(file), StandardCharsets.UTF_8))) {
            int lineNumber = 0;
            int[] corners = new int[3];
            int inFacet = -1; // corners read of the facet open, or -1 outside one
            int facetLine = 0;
            String line;
            while ((line = reader.readLine()) != null) {
                lineNumber++;
                String[] words = line.trim().split("\\s+");
                String keyword = words[0].toLowerCase(Locale.ROOT);
                switch (keyword) {
                    case "", "solid", "endsolid", "outer", "endloop" -> {
                    }
                    case "facet" -> {
                        if (inFacet >= 0) {
                            throw new MeshFormatException(file, lineNumber, "a facet begins inside the facet of line " + facetLine);
                        }
                        inFacet = 0;
                        facetLine = lineNumber;
                    }
                    case "vertex" -> {
                        if (inFacet < 0) {
                            throw new MeshFormatException(file, lineNumber, "a vertex outside any facet");
                        }
                        if (inFacet == 3) {
                            throw new MeshFormatException(file, lineNumber, "a fourth vertex in the facet of line " + facetLine
                                    + ": STL facets are triangles");
                        }
                        if (words.length != 4) {
                            throw new MeshFormatException(file, lineNumber, "expected 'vertex x y z', got '" + line.trim() + "'");
                        }
                        float[] xyz = new float[3];
                        for (int k = 0; k < 3; k++) {
                            try {
                                xyz[k] = Float.parseFloat(words[k + 1]);
                            } catch (NumberFormatException e) {
                                throw new MeshFormatException(file, lineNumber, "'" + words[k + 1] + "' is not a number");
                            }
                            if (!Float.isFinite(xyz[k]) || words[k + 1].endsWith("f") || words[k + 1].endsWith("d")
                                    || words[k + 1].endsWith("F") || words[k + 1].endsWith("D")) {
                                throw new MeshFormatException(file, lineNumber, "'" + words[k + 1] + "' is not a finite decimal number");
                            }
                        }
                        corners[inFacet++] = welder.vertex(xyz[0], xyz[1], xyz[2]);
                    }
                    case "endfacet" -> {
                        if (inFacet != 3) {
                            throw new MeshFormatException(file, lineNumber, "the facet of line " + facetLine + " has "
                                    + Math.max(inFacet, 0) + " vertices, not 3");
                        }
                        welder.soup.addFace(corners.clone(), 3, facetLine);
                        triangles++;
                        inFacet = -1;
                    }
                    default -> throw new MeshFormatException(file, lineNumber, "unknown keyword '" + words[0]
                            + "': ASCII STL has solid, facet, outer loop, vertex, endloop, endfacet and endsolid");
                }
            }
            if (inFacet >= 0) {
                throw new MeshFormatException(file, lineNumber, "the file ends inside the facet of line " + facetLine);
            }
        }
        return new Result(welder.soup, false, triangles, welder.welded);
    }

    /**
     * Corners by their exact position, each position one vertex: an open-addressing table of
     * the positions' float bits, in plain arrays (a map of boxed positions took twice as long as
     * reading the whole OFF of the same model).
     */
    private static final class Welder {
        PolygonSoup soup = new PolygonSoup();
        long welded;
        /** The vertices' positions as float bits, three a vertex. */
        private int[] bits = new int[3 * 1024];
        /** Slots of vertex + 1; 0 is empty. */
        private int[] slots = new int[2048];
        private int vertices;

        /** Sized for a closed mesh of {@code triangles}, about half as many vertices, at most half full. */
        void expect(int triangles) {
            int capacity = Integer.highestOneBit(Math.max(1024, Math.min(triangles, 1 << 29)) - 1) << 1;
            if (capacity > slots.length) {
                slots = new int[capacity];
                bits = new int[3 * (capacity / 2)];
            }
            soup = new PolygonSoup(capacity / 2, triangles, 3 * triangles);
        }

        int vertex(float x, float y, float z) {
            // -0 and 0 are one position.
            int bx = Float.floatToIntBits(x + 0f);
            int by = Float.floatToIntBits(y + 0f);
            int bz = Float.floatToIntBits(z + 0f);
            int mask = slots.length - 1;
            int slot = hash(bx, by, bz) & mask;
            while (slots[slot] != 0) {
                int v = slots[slot] - 1;
                if (bits[3 * v] == bx && bits[3 * v + 1] == by && bits[3 * v + 2] == bz) {
                    welded++;
                    return v;
                }
                slot = (slot + 1) & mask;
            }
            int v = soup.addVertex(x, y, z);
            if (3 * v + 3 > bits.length) {
                bits = java.util.Arrays.copyOf(bits, 2 * bits.length);
            }
            bits[3 * v] = bx;
            bits[3 * v + 1] = by;
            bits[3 * v + 2] = bz;
            slots[slot] = v + 1;
            if (++vertices > slots.length / 2) {
                grow();
            }
            return v;
        }

        private void grow() {
            int[] bigger = new int[2 * slots.length];
            int mask = bigger.length - 1;
            for (int v = 0; v < vertices; v++) {
                int slot = hash(bits[3 * v], bits[3 * v + 1], bits[3 * v + 2]) & mask;
                while (bigger[slot] != 0) {
                    slot = (slot + 1) & mask;
                }
                bigger[slot] = v + 1;
            }
            slots = bigger;
        }

        private static int hash(int x, int y, int z) {
            int h = x * 0x9E3779B1 + y * 0x85EBCA77 + z * 0xC2B2AE3D;
            return h ^ (h >>> 15);
        }
    }
}
