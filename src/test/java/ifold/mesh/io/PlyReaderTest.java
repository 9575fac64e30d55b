package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** PLY, ASCII and binary of both byte orders, against the OFF of the same model and against broken files. */
class PlyReaderTest {
    @TempDir
    Path dir;

    private static void assertSameSoup(PolygonSoup expected, PolygonSoup actual) {
        assertEquals(expected.vertexCount(), actual.vertexCount(), "vertices");
        assertEquals(expected.faceCount(), actual.faceCount(), "faces");
        for (int v = 0; v < expected.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                assertEquals(expected.coordinate(v, axis), actual.coordinate(v, axis), 0, "vertex " + v);
            }
        }
        for (int f = 0; f < expected.faceCount(); f++) {
            assertEquals(expected.faceSize(f), actual.faceSize(f), "face " + f);
            for (int k = 0; k < expected.faceSize(f); k++) {
                assertEquals(expected.faceVertex(f, k), actual.faceVertex(f, k), "face " + f);
            }
        }
        assertEquals(expected.hasFaceColors(), actual.hasFaceColors(), "colours");
        for (int f = 0; expected.hasFaceColors() && f < expected.faceCount(); f++) {
            assertEquals(expected.faceColor(f) & 0xFFFFFF, actual.faceColor(f) & 0xFFFFFF, "colour of face " + f);
        }
    }

    /** The project's models, OFF → PLY (binary and ASCII) → read back: the same vertices bit for bit, faces, and colours. */
    @ParameterizedTest
    @CsvSource({"cube.off,false", "cube.off,true", "torus.off,false", "figure3.off,true", "icosahedron.off,false"})
    void theProjectsModelsComeBackAsTheyWere(String model, boolean ascii) throws Exception {
        PolygonSoup off = OffReader.read(Path.of("models", model));
        Path ply = dir.resolve("m.ply");
        MeshWriters.write(off, ply, ascii);
        PlyReader.Result read = PlyReader.readWithCounts(ply);
        assertEquals(ascii ? PlyReader.Format.ASCII : PlyReader.Format.BINARY_LITTLE_ENDIAN, read.format());
        assertSameSoup(off, read.soup());
        // And again through OFF: the file is the same text.
        Path back = dir.resolve("back.off");
        MeshWriters.write(read.soup(), back);
        Path first = dir.resolve("first.off");
        MeshWriters.write(off, first);
        assertEquals(Files.readString(first), Files.readString(back));
    }

    /** Files other programs wrote (src/test/resources/ply/README.md) read as the OFF they were made from. */
    @ParameterizedTest
    @CsvSource({"tetrahedron-ascii.ply,tetrahedron.off,ASCII", "torus.ply,torus.off,BINARY_LITTLE_ENDIAN",
        "tetrahedron-big-endian.ply,tetrahedron.off,BINARY_BIG_ENDIAN"})
    void readsFilesOtherProgramsWrote(String ply, String off, PlyReader.Format format) throws Exception {
        PolygonSoup expected = OffReader.read(Path.of("models", off));
        PlyReader.Result read = PlyReader.readWithCounts(Path.of("src", "test", "resources", "ply", ply));
        assertEquals(format, read.format());
        PolygonSoup soup = read.soup();
        assertEquals(expected.vertexCount(), soup.vertexCount());
        assertEquals(expected.faceCount(), soup.faceCount());
        for (int v = 0; v < expected.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                // trimesh writes single precision.
                assertEquals(expected.coordinate(v, axis), soup.coordinate(v, axis), 1e-6 * (1 + Math.abs(expected.coordinate(v, axis))));
            }
        }
        for (int f = 0; f < expected.faceCount(); f++) {
            for (int k = 0; k < 3; k++) {
                assertEquals(expected.faceVertex(f, k), soup.faceVertex(f, k), "face " + f);
            }
        }
        assertEquals(format == PlyReader.Format.BINARY_BIG_ENDIAN, soup.hasFaceColors());
        if (soup.hasFaceColors()) {
            assertEquals(0xFFC86432, soup.faceColor(2));
        }
    }

    /**
     * A big-endian file with properties of other types and an element of its own, as scanners
     * write them: float coordinates with normals, a confidence, int counts of uint indices, and
     * a material element to read past.
     */
    @Test
    void readsBigEndianWithOtherPropertiesAndElements() throws Exception {
        String header = "ply\r\nformat binary_big_endian 1.0\r\ncomment made by hand\r\nobj_info scanner\r\n"
                + "element vertex 4\r\nproperty float x\r\nproperty float nx\r\nproperty float y\r\nproperty float z\r\nproperty uchar confidence\r\n"
                + "element material 1\r\nproperty list uchar float ambient\r\nproperty int id\r\n"
                + "element face 2\r\nproperty uchar flags\r\nproperty list int uint vertex_index\r\n"
                + "property uchar red\r\nproperty uchar green\r\nproperty uchar blue\r\nend_header\r\n";
        ByteBuffer body = ByteBuffer.allocate(4096).order(ByteOrder.BIG_ENDIAN);
        float[][] xyz = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.5f}};
        for (float[] p : xyz) {
            body.putFloat(p[0]).putFloat(9).putFloat(p[1]).putFloat(p[2]).put((byte) 7);
        }
        body.put((byte) 3).putFloat(1).putFloat(2).putFloat(3).putInt(42);
        body.put((byte) 0).putInt(3).putInt(0).putInt(1).putInt(2).put((byte) 255).put((byte) 0).put((byte) 10);
        body.put((byte) 0).putInt(3).putInt(0).putInt(2).putInt(3).put((byte) 1).put((byte) 2).put((byte) 3);
        Path file = write("scan.ply", header, body);
        PlyReader.Result read = PlyReader.readWithCounts(file);
        assertEquals(PlyReader.Format.BINARY_BIG_ENDIAN, read.format());
        PolygonSoup soup = read.soup();
        assertEquals(4, soup.vertexCount());
        assertEquals(0.5, soup.coordinate(3, 2), 0);
        assertEquals(1, soup.coordinate(2, 1), 0);
        assertEquals(2, soup.faceCount());
        assertEquals(3, soup.faceVertex(1, 2));
        assertTrue(soup.hasFaceColors());
        assertEquals(0xFFFF000A, soup.faceColor(0));
        assertEquals(0xFF010203, soup.faceColor(1));
    }

    /** Faces before vertices are legal: their indices are checked once the vertices are read. */
    @Test
    void readsFacesBeforeVertices() throws Exception {
        Path file = dir.resolve("late.ply");
        Files.writeString(file, "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                + "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n3 0 1 2\n0 0 0\n1 0 0\n0 1 0\n");
        assertEquals(3, PlyReader.read(file).faceSize(0));
        Files.writeString(file, "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n"
                + "element vertex 3\nproperty double x\nproperty double y\nproperty double z\nend_header\n3 0 1 3\n0 0 0\n1 0 0\n0 1 0\n");
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> PlyReader.read(file));
        assertEquals(file + ":10: face 1: vertex index 3 is not among the 3 vertices", e.getMessage());
    }

    private Path write(String name, String header, ByteBuffer body) throws Exception {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        bytes.write(header.getBytes(StandardCharsets.US_ASCII));
        bytes.write(body.array(), 0, body.position());
        Path file = dir.resolve(name);
        Files.write(file, bytes.toByteArray());
        return file;
    }

    private static final String TRIANGLE_HEADER = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
            + "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";

    private static ByteBuffer triangleBody(int count, float z) {
        ByteBuffer body = ByteBuffer.allocate(4096).order(ByteOrder.LITTLE_ENDIAN);
        body.putFloat(0).putFloat(0).putFloat(z).putFloat(1).putFloat(0).putFloat(0).putFloat(0).putFloat(1).putFloat(0);
        body.put((byte) count).putInt(0).putInt(1).putInt(2);
        return body;
    }

    private String refusal(String name, String header, ByteBuffer body) throws Exception {
        Path file = write(name, header, body);
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> PlyReader.read(file));
        assertTrue(e.getMessage().startsWith(file.toString() + ":"), e.getMessage());
        assertTrue(!e.getMessage().contains("\n"), "one line");
        return e.getMessage().substring(file.toString().length() + 1).trim();
    }

    @Test
    void hostileFilesEndInOneLineNamingTheByteOrTheLine() throws Exception {
        // A good one first, so that each refusal below is the change it makes.
        assertEquals(1, PlyReader.read(write("good.ply", TRIANGLE_HEADER, triangleBody(3, 0))).faceCount());
        // The header is 169 bytes: 10 bytes of vertices are fewer than 3 take.
        ByteBuffer cut = triangleBody(3, 0);
        cut.position(10);
        assertEquals("3: element 'vertex' claims 3, which take at least 36 bytes; the file has 10 after its header",
                refusal("cut.ply", TRIANGLE_HEADER, cut));
        // A face's colour cut off: its blue, at byte 280 (the header is 229 bytes), is not there.
        String coloured = TRIANGLE_HEADER.replace("end_header", "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header");
        ByteBuffer noBlue = triangleBody(3, 0);
        noBlue.put((byte) 1).put((byte) 2);
        assertEquals("the file ends at byte 280, where a value of 1 byte goes: it is cut short", refusal("blue.ply", coloured, noBlue));
        // Cut in the face's indices: the count says more than the bytes left (the face begins at byte 205).
        ByteBuffer shortList = triangleBody(3, 0);
        shortList.position(shortList.position() - 6);
        assertEquals("face 1: a list of 3 vertices, more than the rest of the file holds (at byte 205)",
                refusal("short-list.ply", TRIANGLE_HEADER, shortList));
        // 2^31 - 1 vertices claimed in a file of a few hundred bytes: refused before anything is kept.
        assertEquals("3: element 'vertex' claims 2147483647, which take at least 25769803764 bytes; the file has 49 after its header",
                refusal("huge.ply", TRIANGLE_HEADER.replace("vertex 3", "vertex 2147483647"), triangleBody(3, 0)));
        assertEquals("3: element 'vertex' has a count of '2147483648', not one of 0 to 2147483647",
                refusal("huger.ply", TRIANGLE_HEADER.replace("vertex 3", "vertex 2147483648"), triangleBody(3, 0)));
        // A list count of 255 on a triangle mesh reads indices that are not there.
        assertTrue(refusal("list.ply", TRIANGLE_HEADER, triangleBody(255, 0)).startsWith("face 1: a list of 255 vertices, more than the rest"));
        ByteBuffer one = ByteBuffer.allocate(64).order(ByteOrder.LITTLE_ENDIAN);
        one.putFloat(0).putFloat(0).putFloat(0).put((byte) 3).putInt(0).putInt(1).putInt(2);
        assertEquals("face 1: vertex index 1 is not among the 1 vertices (at byte 186)",
                refusal("index.ply", TRIANGLE_HEADER.replace("vertex 3", "vertex 1"), one));
        assertEquals("vertex 1: z is not a finite number (NaN) (at byte 177)", refusal("nan.ply", TRIANGLE_HEADER, triangleBody(3, Float.NaN)));
        assertEquals("no 'end_header' in the first 65536 bytes",
                refusal("endless.ply", "ply\nformat ascii 1.0\n" + "comment x\n".repeat(7000), ByteBuffer.allocate(0)));
        assertEquals("5: the file ends before 'end_header'", refusal("short.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n",
                ByteBuffer.allocate(0)));
        assertEquals("1: not a PLY file: it does not begin with the line 'ply'", refusal("off.ply", "OFF\n3 1 0\n", ByteBuffer.allocate(0)));
        assertEquals("no 'face' element in the header: a cloud of points, not a surface",
                refusal("cloud.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n",
                        ByteBuffer.wrap("0 0 0\n".getBytes(StandardCharsets.US_ASCII)).position(6)));
        ByteBuffer extra = triangleBody(3, 0);
        extra.put((byte) 9);
        assertEquals("1 byte after the last element, from byte 218: the header's counts do not match the body",
                refusal("extra.ply", TRIANGLE_HEADER, extra));
        assertEquals("2: unknown format 'binary_middle_endian 1.0': PLY 1.0 is ascii, binary_little_endian or binary_big_endian",
                refusal("middle.ply", TRIANGLE_HEADER.replace("little", "middle"), triangleBody(3, 0)));
    }

    @Test
    void asciiFilesNameTheLine() throws Exception {
        String header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                + "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
        Path file = dir.resolve("a.ply");
        Files.writeString(file, header + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n");
        assertEquals(file + ":11: number 'nan' is not a finite number",
                assertThrows(MeshFormatException.class, () -> PlyReader.read(file)).getMessage());
        Files.writeString(file, header + "0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n");
        assertEquals(file + ":13: expected an integer, found '1.5'",
                assertThrows(MeshFormatException.class, () -> PlyReader.read(file)).getMessage());
        Files.writeString(file, header + "0 0 0\n1 0 0\n0 1 0\n3 0 1\n");
        assertEquals(file + ":13: the file ends where an integer goes: the header's counts are more than the body holds",
                assertThrows(MeshFormatException.class, () -> PlyReader.read(file)).getMessage());
        // A count of 2^31 - 1 in a text file: read as far as the file goes, no bigger.
        Files.writeString(file, header.replace("uchar int", "int int") + "0 0 0\n1 0 0\n0 1 0\n2147483647 0 1 2\n");
        assertEquals(file + ":13: the file ends where an integer goes: the header's counts are more than the body holds",
                assertThrows(MeshFormatException.class, () -> PlyReader.read(file)).getMessage());
    }
}
