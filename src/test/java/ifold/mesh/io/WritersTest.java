package ifold.mesh.io;

import static ifold.mesh.io.Fixtures.assertFace;
import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.IndexedPolygons;
import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.List;
import java.util.Random;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class WritersTest {
    @TempDir
    Path dir;

    /** Doubles that a careless writer or reader gets wrong. */
    private static final double[] TRICKY = {
        0.0, -0.0, 1.0, -1.0, 0.1, 0.2, 0.3, 1.0 / 3, -2.0 / 3, Math.PI, 1e-300, -4.9e-324, Double.MIN_NORMAL,
        Double.MAX_VALUE, -Double.MAX_VALUE, 9007199254740992.0, 9007199254740993.0 * 2, 123456789012345678.0,
        1e22, 1e23, 2.5e-8, 5.6843418860808015E-14, 93.87400100000001, 1e7, 1e-3, 12345.0, -65536.0,
    };

    /** A mesh of triangles, quads and pentagons over tricky and random coordinates. */
    private static PolygonSoup mesh(int vertexCount, boolean colors, long seed) {
        Random random = new Random(seed);
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < vertexCount; v++) {
            double[] c = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                int i = 3 * v + axis;
                c[axis] = i < TRICKY.length ? TRICKY[i]
                        : switch (random.nextInt(4)) {
                            case 0 -> Double.longBitsToDouble(random.nextLong() & 0x7FEF_FFFF_FFFF_FFFFL) * (random.nextBoolean() ? 1 : -1);
                            case 1 -> random.nextInt(2000) - 1000;
                            case 2 -> Math.round(random.nextGaussian() * 1e6) / 1e6;
                            default -> random.nextDouble() * 200 - 100;
                        };
            }
            soup.addVertex(c[0], c[1], c[2]);
        }
        int[] face = new int[5];
        for (int f = 0; f < 2 * vertexCount; f++) {
            int size = 3 + f % 3;
            for (int k = 0; k < size; k++) {
                face[k] = random.nextInt(vertexCount);
            }
            soup.addFace(face, size, 0);
            if (colors) {
                // Every face, as uncoloured faces past the first growth of a soup read as 0.
                soup.setFaceColor(f, 0xFF000000 | random.nextInt(1 << 24));
            }
        }
        return soup;
    }

    private static void assertSameMesh(IndexedPolygons expected, PolygonSoup actual, boolean colors) {
        assertEquals(expected.vertexCount(), actual.vertexCount());
        assertEquals(expected.faceCount(), actual.faceCount());
        for (int v = 0; v < expected.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                long want = Double.doubleToRawLongBits(expected.coordinate(v, axis));
                long got = Double.doubleToRawLongBits(actual.coordinate(v, axis));
                if (want != got) {
                    assertEquals(expected.coordinate(v, axis), actual.coordinate(v, axis), "vertex " + v + " axis " + axis);
                    assertEquals(want, got, "bits of vertex " + v + " axis " + axis);
                }
            }
        }
        for (int f = 0; f < expected.faceCount(); f++) {
            int[] vertices = new int[expected.faceSize(f)];
            for (int k = 0; k < vertices.length; k++) {
                vertices[k] = expected.faceVertex(f, k);
            }
            assertFace(actual, f, vertices);
        }
        assertEquals(colors, actual.hasFaceColors());
        if (colors) {
            for (int f = 0; f < expected.faceCount(); f++) {
                assertEquals(expected.faceColor(f), actual.faceColor(f), "colour of face " + f);
            }
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"m.off", "m.obj", "M.OFF", "M.Obj", "m.ply", "M.PLY", "ascii.ply"})
    void roundTripsExactly(String name) throws Exception {
        // OFF and PLY keep face colours; OBJ has no place for them.
        boolean keepsColors = !name.toLowerCase().endsWith(".obj");
        for (boolean colors : new boolean[] {false, true}) {
            PolygonSoup mesh = mesh(300, colors, 11);
            Path file = dir.resolve(name);
            MeshWriters.write(mesh, file, name.startsWith("ascii"));
            assertSameMesh(mesh, MeshReaders.read(file), colors && keepsColors);
        }
    }

    /**
     * STL holds each triangle's corners in single precision, with its unit normal: the cube's
     * corners come back welded into its 8 vertices, each face's corners in their order, and the
     * normals point out by the right-hand rule; its quads are fanned into 12 triangles.
     */
    @ParameterizedTest
    @ValueSource(booleans = {false, true})
    void writesStlThatReadsBackWelded(boolean ascii) throws Exception {
        PolygonSoup cube = OffReader.read(Path.of("models", "cube.off"));
        Path file = dir.resolve("cube.stl");
        MeshWriters.write(cube, file, ascii);
        StlReader.Result read = StlReader.readWithCounts(file);
        assertEquals(!ascii, read.binary());
        PolygonSoup soup = read.soup();
        assertEquals(8, soup.vertexCount());
        assertEquals(36 - 8, read.welded());
        int t = 0;
        for (int f = 0; f < cube.faceCount(); f++) {
            for (int k = 1; k + 1 < cube.faceSize(f); k++, t++) {
                int[] corners = {cube.faceVertex(f, 0), cube.faceVertex(f, k), cube.faceVertex(f, k + 1)};
                for (int c = 0; c < 3; c++) {
                    for (int axis = 0; axis < 3; axis++) {
                        assertEquals(cube.coordinate(corners[c], axis), soup.coordinate(soup.faceVertex(t, c), axis), 0);
                    }
                }
            }
        }
        assertEquals(12, soup.faceCount());
        if (!ascii) {
            byte[] raw = Files.readAllBytes(file);
            java.nio.ByteBuffer bytes = java.nio.ByteBuffer.wrap(raw).order(java.nio.ByteOrder.LITTLE_ENDIAN);
            assertFalse(new String(raw, 0, 5, java.nio.charset.StandardCharsets.US_ASCII).equals("solid"),
                    "a binary header that no reader takes for text");
            for (int i = 0; i < 12; i++) {
                int at = 84 + 50 * i;
                double[] p = new double[9];
                for (int k = 0; k < 9; k++) {
                    p[k] = bytes.getFloat(at + 12 + 4 * k);
                }
                // The normal points from the cube's centre out through the triangle.
                double cx = (p[0] + p[3] + p[6]) / 3 - 0.5;
                double cy = (p[1] + p[4] + p[7]) / 3 - 0.5;
                double cz = (p[2] + p[5] + p[8]) / 3 - 0.5;
                double nx = bytes.getFloat(at);
                double ny = bytes.getFloat(at + 4);
                double nz = bytes.getFloat(at + 8);
                assertEquals(1, Math.sqrt(nx * nx + ny * ny + nz * nz), 1e-6);
                assertTrue(nx * cx + ny * cy + nz * cz > 0.1, "outward normal of triangle " + i);
            }
        }
    }

    @Test
    void roundTripsAMeshLargerThanTheWriteBuffer() throws Exception {
        PolygonSoup mesh = mesh(60_000, true, 5);
        for (String name : new String[] {"big.off", "big.obj"}) {
            Path file = dir.resolve(name);
            MeshWriters.write(mesh, file);
            assertTrue(Files.size(file) > 2 << 20, "the test must overflow the 1 MiB buffer");
            assertSameMesh(mesh, MeshReaders.read(file), name.endsWith(".off"));
        }
    }

    private static PolygonSoup coloredSquare() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, -0.0);
        soup.addVertex(1, 1.5, 0);
        soup.addVertex(0, 1, 1e-7);
        soup.addTriangle(0, 1, 2);
        soup.addFace(new int[] {2, 3, 0, 1}, 3, 0);
        soup.setFaceColor(1, 0xFF0A14FF);
        return soup;
    }

    @Test
    void writesPlainOffWithFaceColours() throws Exception {
        Path file = dir.resolve("s.off");
        OffWriter.write(coloredSquare(), file);
        assertEquals("OFF\n4 2 0\n0 0 0\n1 0 -0\n1 1.5 0\n0 1 1.0E-7\n3 0 1 2 180 180 180\n3 2 3 0 10 20 255\n",
                Files.readString(file));
    }

    @Test
    void writesObjWithOneBasedIndices() throws Exception {
        Path file = dir.resolve("s.obj");
        ObjWriter.write(coloredSquare(), file);
        assertEquals("# iFold: 4 vertices, 2 faces\n# face colours not written: OBJ has no standard per-face colour\n"
                + "v 0 0 0\nv 1 0 -0\nv 1 1.5 0\nv 0 1 1.0E-7\nf 1 2 3\nf 3 4 1\n", Files.readString(file));
    }

    @Test
    void writesIntegersLikeLongToString() throws Exception {
        long[] values = {0, 1, -1, 9, 10, -10, 99, 100, 12345, Integer.MAX_VALUE, Integer.MIN_VALUE,
            Long.MAX_VALUE, Long.MIN_VALUE, 1_000_000_000_000L, -999_999_999_999_999_999L};
        Path file = dir.resolve("ints.txt");
        AsciiOutput.writeAtomically(file, out -> {
            for (long value : values) {
                out.writeLong(value);
                out.writeByte(' ');
            }
        });
        StringBuilder expected = new StringBuilder();
        for (long value : values) {
            expected.append(value).append(' ');
        }
        assertEquals(expected.toString(), Files.readString(file));
    }

    @Test
    void writesDoublesThatParseBackToTheSameBits() throws Exception {
        Random random = new Random(9);
        double[] values = new double[100_000];
        for (int i = 0; i < values.length; i++) {
            double d = i < TRICKY.length ? TRICKY[i] : Double.longBitsToDouble(random.nextLong());
            values[i] = Double.isFinite(d) ? d : random.nextDouble();
        }
        Path file = dir.resolve("doubles.txt");
        AsciiOutput.writeAtomically(file, out -> {
            for (double value : values) {
                out.writeDouble(value);
                out.writeByte('\n');
            }
        });
        List<String> lines = Files.readAllLines(file);
        for (int i = 0; i < values.length; i++) {
            byte[] text = lines.get(i).getBytes(StandardCharsets.US_ASCII);
            assertEquals(Double.doubleToRawLongBits(values[i]),
                    Double.doubleToRawLongBits(DecimalParser.parseDouble(text, 0, text.length)), lines.get(i));
        }
    }

    @Test
    void replacesAnExistingFile() throws Exception {
        Path file = Files.writeString(dir.resolve("s.off"), "old content that is longer than the new one ".repeat(20));
        MeshWriters.write(coloredSquare(), file);
        assertSameMesh(coloredSquare(), MeshReaders.read(file), true);
        assertEquals(List.of(file), files());
    }

    @Test
    void givesTheFileOrdinaryPermissions() throws Exception {
        Assumptions.assumeTrue(Files.getFileAttributeView(dir, PosixFileAttributeView.class) != null);
        Path plain = Files.createFile(dir.resolve("plain.txt"));
        Path file = dir.resolve("s.off");
        MeshWriters.write(coloredSquare(), file);
        // A temporary file from Files.createTempFile is rw------- and the rename would keep that.
        assertEquals(PosixFilePermissions.toString(Files.getPosixFilePermissions(plain)),
                PosixFilePermissions.toString(Files.getPosixFilePermissions(file)));
    }

    /** The files in the temporary directory: a failed write must leave no temporary file behind. */
    private List<Path> files() throws IOException {
        try (Stream<Path> files = Files.list(dir)) {
            return files.sorted().collect(Collectors.toList());
        }
    }

    @Test
    void failsCleanlyInAMissingDirectory() {
        Path file = dir.resolve("missing").resolve("s.off");
        assertThrows(IOException.class, () -> MeshWriters.write(coloredSquare(), file));
        assertFalse(Files.exists(file.getParent()));
    }

    @Test
    void failsCleanlyWhereTheDirectoryIsAFile() throws Exception {
        Path notADirectory = Files.writeString(dir.resolve("file"), "x");
        assertThrows(IOException.class, () -> MeshWriters.write(coloredSquare(), notADirectory.resolve("s.obj")));
        assertEquals("x", Files.readString(notADirectory));
        assertEquals(List.of(notADirectory), files());
    }

    @Test
    void failsCleanlyInAReadOnlyDirectory() throws Exception {
        Path readOnly = Files.createDirectory(dir.resolve("ro"));
        Assumptions.assumeTrue(Files.getFileAttributeView(readOnly, PosixFileAttributeView.class) != null);
        Files.setPosixFilePermissions(readOnly, PosixFilePermissions.fromString("r-xr-xr-x"));
        try {
            // Root writes anyway; then there is nothing to test.
            Assumptions.assumeFalse(Files.isWritable(readOnly), "running as a user who can write anywhere");
            Path file = readOnly.resolve("s.off");
            assertThrows(IOException.class, () -> MeshWriters.write(coloredSquare(), file));
            try (Stream<Path> left = Files.list(readOnly)) {
                assertEquals(0, left.count());
            }
        } finally {
            Files.setPosixFilePermissions(readOnly, PosixFilePermissions.fromString("rwxr-xr-x"));
        }
    }

    /** A mesh that breaks down after {@code failAt} vertices, as a writer's source might mid-way. */
    private static IndexedPolygons failingAt(PolygonSoup mesh, int failAt) {
        return new IndexedPolygons() {
            @Override
            public int vertexCount() {
                return mesh.vertexCount();
            }

            @Override
            public double coordinate(int v, int axis) {
                if (v == failAt) {
                    throw new IllegalStateException("source failed at vertex " + v);
                }
                return mesh.coordinate(v, axis);
            }

            @Override
            public int faceCount() {
                return mesh.faceCount();
            }

            @Override
            public int faceSize(int f) {
                return mesh.faceSize(f);
            }

            @Override
            public int faceVertex(int f, int k) {
                return mesh.faceVertex(f, k);
            }

            @Override
            public boolean hasFaceColors() {
                return mesh.hasFaceColors();
            }

            @Override
            public int faceColor(int f) {
                return mesh.faceColor(f);
            }
        };
    }

    @ParameterizedTest
    @ValueSource(strings = {"s.off", "s.obj", "s.ply"})
    void aFailureMidWriteLeavesTheOldFile(String name) throws Exception {
        Path file = Files.writeString(dir.resolve(name), "previous");
        PolygonSoup mesh = mesh(60_000, false, 3);
        // Past the first megabyte, so that part of the file has already gone to disk.
        IllegalStateException e = assertThrows(IllegalStateException.class,
                () -> MeshWriters.write(failingAt(mesh, 50_000), file));
        assertEquals("source failed at vertex 50000", e.getMessage());
        assertEquals("previous", Files.readString(file));
        assertEquals(List.of(file), files());
    }

    @Test
    void anInterruptedWriteLeavesNoPartialFile() throws Exception {
        Path file = dir.resolve("s.off");
        Thread.currentThread().interrupt();
        try {
            // A FileChannel closes itself when its thread is interrupted: the write cannot finish.
            assertThrows(IOException.class, () -> MeshWriters.write(mesh(60_000, true, 1), file));
        } finally {
            Thread.interrupted();
        }
        assertEquals(List.of(), files());
    }

    @Test
    void refusesAMeshNoReaderWouldAccept() throws Exception {
        PolygonSoup nan = coloredSquare();
        nan.addVertex(0, Double.NaN, 0);
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MeshWriters.write(nan, dir.resolve("nan.off")));
        assertEquals("vertex 4 has a non-finite coordinate NaN", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> MeshWriters.write(nan, dir.resolve("nan.ply")));
        assertEquals("vertex 4 has a non-finite coordinate NaN", e.getMessage());
        nan.addTriangle(0, 1, 4);
        e = assertThrows(IllegalArgumentException.class, () -> MeshWriters.write(nan, dir.resolve("nan.stl")));
        assertEquals("vertex 4 has a non-finite coordinate NaN", e.getMessage());

        PolygonSoup edge = coloredSquare();
        edge.addFace(new int[] {0, 1}, 2, 0);
        e = assertThrows(IllegalArgumentException.class, () -> MeshWriters.write(edge, dir.resolve("edge.obj")));
        assertEquals("face 2 has 2 vertices, need at least 3", e.getMessage());

        PolygonSoup outside = coloredSquare();
        outside.addTriangle(0, 1, 4);
        e = assertThrows(IllegalArgumentException.class, () -> MeshWriters.write(outside, dir.resolve("out.off")));
        assertEquals("face 2 has vertex index 4, outside 0 to 3", e.getMessage());
        assertEquals(List.of(), files());
    }

    @Test
    void dispatchesOnTheExtension() throws Exception {
        MeshWriters.write(coloredSquare(), dir.resolve("a.OFF"));
        assertTrue(Files.readString(dir.resolve("a.OFF")).startsWith("OFF\n"));
        MeshWriters.write(coloredSquare(), dir.resolve("a.oBj"));
        assertTrue(Files.readString(dir.resolve("a.oBj")).startsWith("# iFold"));

        MeshWriters.write(coloredSquare(), dir.resolve("a.Ply"));
        assertTrue(Files.readString(dir.resolve("a.Ply"), java.nio.charset.StandardCharsets.ISO_8859_1)
                .startsWith("ply\nformat binary_little_endian 1.0\n"));
        MeshWriters.write(coloredSquare(), dir.resolve("a.STL"), true);
        assertTrue(Files.readString(dir.resolve("a.STL")).startsWith("solid ifold\n"));

        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> MeshWriters.write(coloredSquare(), dir.resolve("a.3mf")));
        assertTrue(e.getMessage().contains("expected a name ending in .off, .obj, .ply or .stl"), e.getMessage());
        assertFalse(Files.exists(dir.resolve("a.3mf")));

        Path gltf = Files.writeString(dir.resolve("a.gltf"), "{}\n");
        MeshFormatException m = assertThrows(MeshFormatException.class, () -> MeshReaders.read(gltf));
        assertEquals(gltf + ": unsupported file type: expected a name ending in .off, .obj, .ply or .stl", m.getMessage());
        assertEquals(0, m.line());
        Path noExtension = Files.writeString(dir.resolve("off"), "OFF\n");
        assertThrows(MeshFormatException.class, () -> MeshReaders.read(noExtension));
    }

    @Test
    void readsAndWritesByExtensionWithoutChangingFaceOrder() throws Exception {
        PolygonSoup mesh = new PolygonSoup();
        for (int v = 0; v < 6; v++) {
            mesh.addVertex(v, v * v, -v);
        }
        int[][] faces = {{5, 4, 3}, {0, 1, 2}, {2, 3, 4, 5}, {1, 0, 5}};
        for (int[] face : faces) {
            mesh.addFace(face, face.length, 0);
        }
        for (String name : new String[] {"o.off", "o.obj"}) {
            MeshWriters.write(mesh, dir.resolve(name));
            PolygonSoup back = MeshReaders.read(dir.resolve(name));
            for (int f = 0; f < faces.length; f++) {
                int[] actual = new int[back.faceSize(f)];
                for (int k = 0; k < actual.length; k++) {
                    actual[k] = back.faceVertex(f, k);
                }
                assertArrayEquals(faces[f], actual, name + " face " + f);
            }
        }
    }

    /** Big models are formatted in blocks on every core: the file must not depend on how many. */
    @ParameterizedTest
    @ValueSource(strings = {"torus.off", "torus.obj"})
    void aBigModelIsWrittenTheSameWhateverTheThreads(String name) throws Exception {
        PolygonSoup torus = ifold.mesh.Solids.torus(3, 1, 300, 120); // 36,000 vertices, 72,000 faces: several blocks
        torus.setFaceColor(7, 0xFF102030);
        assertTrue(torus.vertexCount() > 2 * AsciiOutput.BLOCK_LINES, "setup: more than one block of lines");
        String old = System.getProperty("ifold.threads");
        try {
            System.setProperty("ifold.threads", "1");
            Path one = dir.resolve("one-" + name);
            MeshWriters.write(torus, one);
            System.setProperty("ifold.threads", "3");
            Path three = dir.resolve("three-" + name);
            MeshWriters.write(torus, three);
            assertArrayEquals(Files.readAllBytes(one), Files.readAllBytes(three));
            PolygonSoup back = MeshReaders.read(three);
            assertEquals(torus.faceCount(), back.faceCount());
            assertEquals(torus.coordinate(35_999, 2), back.coordinate(35_999, 2), 0, "bit for bit");
            // A failure in a late block comes out as the sequential write's, and leaves no file.
            PolygonSoup broken = ifold.mesh.Solids.torus(3, 1, 300, 120);
            broken.addFace(new int[] {0, 1, 99_999}, 3, 0);
            Path none = dir.resolve("broken-" + name);
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> MeshWriters.write(broken, none));
            assertTrue(e.getMessage().contains("face 72000 has vertex index 99999"), e.getMessage());
            assertFalse(Files.exists(none));
        } finally {
            if (old == null) {
                System.clearProperty("ifold.threads");
            } else {
                System.setProperty("ifold.threads", old);
            }
        }
    }
}
