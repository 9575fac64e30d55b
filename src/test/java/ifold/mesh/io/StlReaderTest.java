package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** STL, binary and ASCII, against the OFF of the same model and against broken files. */
class StlReaderTest {
    @TempDir
    Path dir;

    /** The project's cube, its six squares cut into twelve triangles, as STL writes them: each corner again in each triangle. */
    private static List<float[][]> cubeTriangles() throws Exception {
        PolygonSoup cube = OffReader.read(Path.of("models", "cube.off"));
        List<float[][]> triangles = new ArrayList<>();
        for (int f = 0; f < cube.faceCount(); f++) {
            for (int k = 1; k + 1 < cube.faceSize(f); k++) {
                int[] corners = {cube.faceVertex(f, 0), cube.faceVertex(f, k), cube.faceVertex(f, k + 1)};
                float[][] t = new float[3][3];
                for (int c = 0; c < 3; c++) {
                    for (int axis = 0; axis < 3; axis++) {
                        t[c][axis] = (float) cube.coordinate(corners[c], axis);
                    }
                }
                triangles.add(t);
            }
        }
        return triangles;
    }

    /** A binary STL whose header begins with "solid", as many programs write it. */
    private static byte[] binary(List<float[][]> triangles) {
        ByteBuffer out = ByteBuffer.allocate(84 + 50 * triangles.size()).order(ByteOrder.LITTLE_ENDIAN);
        byte[] header = new byte[80];
        byte[] text = "solid written by a program that says solid in binary files".getBytes(StandardCharsets.US_ASCII);
        System.arraycopy(text, 0, header, 0, text.length);
        out.put(header).putInt(triangles.size());
        for (float[][] t : triangles) {
            out.putFloat(0).putFloat(0).putFloat(0);
            for (float[] corner : t) {
                out.putFloat(corner[0]).putFloat(corner[1]).putFloat(corner[2]);
            }
            out.putShort((short) 0);
        }
        return out.array();
    }

    private static String ascii(List<float[][]> triangles) {
        StringBuilder text = new StringBuilder("solid cube\n");
        for (float[][] t : triangles) {
            text.append("  facet normal 0 0 0\n    outer loop\n");
            for (float[] corner : t) {
                text.append(String.format(Locale.ROOT, "      vertex %s %s %s%n", corner[0], corner[1], corner[2]));
            }
            text.append("    endloop\n  endfacet\n");
        }
        return text.append("endsolid cube\n").toString();
    }

    private static Set<String> positions(PolygonSoup soup) {
        Set<String> positions = new HashSet<>();
        for (int v = 0; v < soup.vertexCount(); v++) {
            positions.add(soup.coordinate(v, 0) + " " + soup.coordinate(v, 1) + " " + soup.coordinate(v, 2));
        }
        return positions;
    }

    @Test
    void aBinaryFileThatSaysSolidIsReadAsBinaryAndItsCornersWelded() throws Exception {
        Path file = dir.resolve("cube.stl");
        Files.write(file, binary(cubeTriangles()));
        StlReader.Result read = StlReader.readWithCounts(file);
        assertTrue(read.binary());
        assertEquals(12, read.triangles());
        assertEquals(8, read.soup().vertexCount(), "the cube's eight corners, each once");
        assertEquals(36 - 8, read.welded());
        assertEquals(positions(OffReader.read(Path.of("models", "cube.off"))), positions(read.soup()));
        assertEquals(12, MeshReaders.read(file).faceCount(), "read by its name's extension too");
    }

    @Test
    void anAsciiFileGivesTheSameSoupAsTheBinaryOne() throws Exception {
        Path text = dir.resolve("cube-ascii.stl");
        Files.writeString(text, ascii(cubeTriangles()));
        Path bytes = dir.resolve("cube-binary.stl");
        Files.write(bytes, binary(cubeTriangles()));
        StlReader.Result a = StlReader.readWithCounts(text);
        PolygonSoup b = StlReader.read(bytes);
        assertTrue(!a.binary());
        assertEquals(b.vertexCount(), a.soup().vertexCount());
        assertEquals(b.faceCount(), a.soup().faceCount());
        for (int f = 0; f < b.faceCount(); f++) {
            for (int k = 0; k < 3; k++) {
                assertEquals(b.faceVertex(f, k), a.soup().faceVertex(f, k), "face " + f);
            }
        }
        assertEquals(positions(b), positions(a.soup()));
    }

    /**
     * Files another program wrote (trimesh 5.2.0, from the project's own models: binary with a
     * header of zero bytes, ASCII with its own spacing): the same mesh as the OFF, built the
     * same way, its corners at the OFF's positions in single precision.
     */
    @ParameterizedTest
    @CsvSource({"torus.stl, torus.off", "figure3.stl, figure3.off", "tetrahedron-ascii.stl, tetrahedron.off"})
    void filesWrittenByTrimeshReadAsTheirOff(String stl, String off) throws Exception {
        PolygonSoup fromStl = StlReader.read(Path.of("src", "test", "resources", "stl", stl));
        PolygonSoup fromOff = OffReader.read(Path.of("models", off));
        HalfedgeMesh a = MeshBuilder.build(fromStl, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        HalfedgeMesh b = MeshBuilder.build(fromOff, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        assertEquals(b.vertexCount(), a.vertexCount());
        assertEquals(b.faceCount(), a.faceCount());
        Set<String> offPositions = new HashSet<>();
        for (int v = 0; v < fromOff.vertexCount(); v++) {
            offPositions.add((float) fromOff.coordinate(v, 0) + " " + (float) fromOff.coordinate(v, 1) + " " + (float) fromOff.coordinate(v, 2));
        }
        Set<String> stlPositions = new HashSet<>();
        for (int v = 0; v < fromStl.vertexCount(); v++) {
            stlPositions.add((float) fromStl.coordinate(v, 0) + " " + (float) fromStl.coordinate(v, 1) + " " + (float) fromStl.coordinate(v, 2));
        }
        assertEquals(offPositions, stlPositions);
    }

    @Test
    void minusZeroAndZeroAreOneVertex() throws Exception {
        Path file = dir.resolve("zeros.stl");
        Files.writeString(file, "solid z\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
                + "facet normal 0 0 1\nouter loop\nvertex -0 -0 0\nvertex 0 1 0\nvertex 1 0 0\nendloop\nendfacet\nendsolid z\n");
        assertEquals(3, StlReader.read(file).vertexCount());
    }

    @Test
    void brokenFilesAreRefusedInOneLineNamingWhere() throws Exception {
        byte[] whole = binary(cubeTriangles());
        Path cut = dir.resolve("cut.stl");
        Files.write(cut, java.util.Arrays.copyOf(whole, 500));
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> StlReader.read(cut));
        assertTrue(e.getMessage().contains("binary STL cut short or padded: its 12 triangles take 684 bytes, the file has 500"),
                e.getMessage());

        ByteBuffer nan = ByteBuffer.wrap(whole.clone()).order(ByteOrder.LITTLE_ENDIAN);
        nan.putFloat(84 + 50 + 12 + 4, Float.NaN); // triangle 2, corner 1, y
        Path notANumber = dir.resolve("nan.stl");
        Files.write(notANumber, nan.array());
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(notANumber));
        assertTrue(e.getMessage().contains("triangle 2 (at byte 134): corner 1 is not a finite number"), e.getMessage());

        Path two = dir.resolve("two.stl");
        Files.writeString(two, "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\nendfacet\n");
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(two));
        assertEquals(7, e.line());
        assertTrue(e.getMessage().contains("the facet of line 2 has 2 vertices, not 3"), e.getMessage());

        Path word = dir.resolve("word.stl");
        Files.writeString(word, "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 zero\n");
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(word));
        assertEquals(4, e.line());

        Path open = dir.resolve("open.stl");
        Files.writeString(open, "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n");
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(open));
        assertTrue(e.getMessage().contains("the file ends inside the facet of line 2"), e.getMessage());

        Path neither = dir.resolve("neither.stl");
        Files.writeString(neither, "hello");
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(neither));
        assertTrue(e.getMessage().contains("not an STL file"), e.getMessage());

        // A count that claims 2^31 triangles in a small file is refused by the size, before any is read.
        ByteArrayOutputStream claim = new ByteArrayOutputStream();
        claim.write(new byte[80]);
        claim.write(new byte[] {0, 0, 0, (byte) 0x80});
        claim.write(new byte[50]);
        Path huge = dir.resolve("huge.stl");
        Files.write(huge, claim.toByteArray());
        e = assertThrows(MeshFormatException.class, () -> StlReader.read(huge));
        assertTrue(e.getMessage().contains("its 2147483648 triangles take"), e.getMessage());
    }
}
