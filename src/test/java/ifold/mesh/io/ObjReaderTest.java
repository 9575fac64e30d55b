package ifold.mesh.io;

import static ifold.mesh.io.Fixtures.assertFace;
import static ifold.mesh.io.Fixtures.assertVertex;
import static ifold.mesh.io.Fixtures.fails;
import static ifold.mesh.io.Fixtures.read;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import ifold.mesh.PolygonSoup;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ObjReaderTest {
    @TempDir
    Path dir;

    private static final String SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";

    @Test
    void readsVerticesAndFaces() throws Exception {
        PolygonSoup soup = read(dir, "s.obj", "v 1.5 -2.25e-3 3\nv -0 0.1 1E+2\nv 4 5 6\nv 7 8 9\nf 1 2 3 4\nf 4 3 2\n");
        assertEquals(4, soup.vertexCount());
        assertEquals(2, soup.faceCount());
        assertVertex(soup, 0, 1.5, -2.25e-3, 3);
        assertVertex(soup, 1, -0.0, 0.1, 100);
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(soup.coordinate(1, 0)));
        assertFace(soup, 0, 0, 1, 2, 3);
        assertFace(soup, 1, 3, 2, 1);
        assertEquals(5, soup.faceLine(0));
        assertEquals(6, soup.faceLine(1));
        assertFalse(soup.hasFaceColors());
    }

    @Test
    void readsEverySlashForm() throws Exception {
        PolygonSoup soup = read(dir, "s.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvn 0 0 1\n"
                + "f 1/1 2/2 3/3\nf 1//1 3//1 4//1\nf 1/1/1 2/2/1 3/3/1\nf 4/1/1 3//1 2/3 1\nf 1// 2// 3//\n"
                + "f 4/-1/-1 3/-2 1\n");
        assertEquals(6, soup.faceCount());
        assertFace(soup, 0, 0, 1, 2);
        assertFace(soup, 1, 0, 2, 3);
        assertFace(soup, 2, 0, 1, 2);
        assertFace(soup, 3, 3, 2, 1, 0);
        assertFace(soup, 4, 0, 1, 2);
        assertFace(soup, 5, 3, 2, 0);
    }

    @Test
    void resolvesNegativeIndicesAgainstTheVerticesSoFar() throws Exception {
        PolygonSoup soup = read(dir, "n.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nf -3 -2 -1\nv 0 1 0\nf -4 -2 -1\nf 1 -3 4\n");
        assertFace(soup, 0, 0, 1, 2);
        assertFace(soup, 1, 0, 2, 3);
        assertFace(soup, 2, 0, 1, 3);
    }

    @Test
    void ignoresEverythingButVerticesAndFaces() throws Exception {
        String text = "# header\nmtllib a.mtl b.mtl\no object one\ng group\ns 1\ns off\nusemtl red\n"
                + "v 0 0 0 1\nv 1 0 0 1.0 0.5 0.5 0.5\nv 1 1 0 0.2 0.3 0.4\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\n"
                + "vp 0.1 0.2\nl 1 2 3\np 1 2\ncstype bezier\nUSEMTL x\nf 1 2 3 # a triangle\n\n   \nf 1 3 4\n";
        PolygonSoup soup = read(dir, "i.obj", text);
        assertEquals(4, soup.vertexCount());
        assertEquals(2, soup.faceCount());
        assertVertex(soup, 1, 1, 0, 0);
        assertVertex(soup, 2, 1, 1, 0);
        assertEquals(19, soup.faceLine(0));
        assertEquals(22, soup.faceLine(1));
    }

    @Test
    void readsCrlfAndLineContinuations() throws Exception {
        PolygonSoup soup = read(dir, "c.obj", "v 0 0 0\r\nv 1 0 \\\r\n 0\r\nv 1 1 0\r\nv 0 1 0\r\nf 1 2 \\\r\n3 \\\n4\r\nf 1 3 4\r\n");
        assertEquals(4, soup.vertexCount());
        assertVertex(soup, 1, 1, 0, 0);
        assertFace(soup, 0, 0, 1, 2, 3);
        assertEquals(6, soup.faceLine(0));
        assertEquals(9, soup.faceLine(1));
    }

    @Test
    void readsPolygonsOfAnySize() throws Exception {
        StringBuilder text = new StringBuilder();
        StringBuilder face = new StringBuilder("f");
        for (int v = 1; v <= 40; v++) {
            text.append("v ").append(Math.cos(v)).append(' ').append(Math.sin(v)).append(" 0\n");
            face.append(' ').append(v);
        }
        PolygonSoup soup = read(dir, "p.obj", text.append(face).append('\n').toString());
        assertEquals(40, soup.faceSize(0));
        assertEquals(39, soup.faceVertex(0, 39));
        assertVertex(soup, 39, Math.cos(40), Math.sin(40), 0);
    }

    @Test
    void acceptsFacesBeforeTheirVertices() throws Exception {
        PolygonSoup soup = read(dir, "f.obj", "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
        assertFace(soup, 0, 0, 1, 2);
    }

    // ---- errors ----

    @Test
    void refusesAnEmptyFile() throws Exception {
        fails(dir, "e.obj", "", 0, "empty file");
    }

    @Test
    void refusesAFileWithoutFaces() throws Exception {
        fails(dir, "e.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n", 0, "no faces: 2 vertices and no 'f' statement");
        fails(dir, "e.obj", "# only a comment\n", 0, "no faces: 0 vertices");
    }

    @Test
    void refusesIndexZero() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 0"), 6, "face index 0: OBJ vertex indices start at 1");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 0/1/1"), 6, "face index 0");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 -0"), 6, "face index 0");
    }

    @Test
    void refusesAnIndexOutOfRange() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 5"), 6,
                "vertex index 5 out of range: the file has 4 vertices (1 to 4)");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 99999999999"), 6,
                "vertex reference '99999999999' is too large");
    }

    @Test
    void refusesARelativeIndexBeforeTheFirstVertex() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f -1 -3 -5"), 6,
                "relative vertex index -5 points before the first vertex: only 4 vertices so far");
        fails(dir, "e.obj", "v 0 0 0\nf -1 -2 -3\nv 1 1 1\nv 2 2 2\n", 2, "relative vertex index -2 points before");
    }

    @ParameterizedTest
    @ValueSource(strings = {"nan", "-nan", "inf", "-inf", "1.#IND", "-1.#IND", "1.#INF", "-1.#INF", "1e999"})
    void refusesNonFiniteCoordinates(String value) throws Exception {
        fails(dir, "e.obj", SQUARE.replace("v 1 1 0", "v 1 " + value + " 0"), 3,
                "coordinate '" + value + "' is not a finite number");
    }

    @Test
    void refusesAVertexWithTooFewCoordinates() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("v 1 1 0", "v 1 1"), 3, "vertex with 2 coordinates, need 3 (x y z)");
        fails(dir, "e.obj", SQUARE.replace("v 1 1 0", "v 1 # 1 0"), 3, "vertex with 1 coordinate, need 3");
        fails(dir, "e.obj", SQUARE.replace("v 1 1 0", "v"), 3, "vertex with 0 coordinates, need 3");
    }

    @Test
    void refusesAFaceWithFewerThanThreeVertices() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1// 2//"), 6, "face with 2 vertices, need at least 3");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1"), 6, "face with 1 vertex, need at least 3");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f"), 6, "face with 0 vertices, need at least 3");
    }

    @Test
    void refusesNonNumericTokens() throws Exception {
        fails(dir, "e.obj", SQUARE.replace("v 1 1 0", "v 1 one 0"), 3, "expected a coordinate, found 'one'");
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 x"), 6,
                "expected a vertex reference (v, v/vt, v//vn or v/vt/vn), found 'x'");
        for (String bad : new String[] {"4/1/1/1", "4a", "/4", "4/x", "4//1.5", "1.5", "4/-"}) {
            fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 " + bad), 6, "found '" + bad + "'");
        }
        fails(dir, "e.obj", SQUARE.replace("f 1 3 4", "f 1 3 4\n1 2 3"), 7,
                "expected a statement such as 'v' or 'f', found '1'");
    }

    @Test
    void refusesBinaryAndUtf16Content() throws Exception {
        fails(dir, "e.obj", "\u00FF\u00FEv\u0000 \u00001\u0000", 1, "binary or UTF-16 content, expected a text OFF/OBJ file");
        fails(dir, "e.obj", "\u0000v\u0000 \u00001", 1, "binary or UTF-16 content");
        fails(dir, "e.obj", SQUARE.replace("f 1 2 3", "f 1 2 3\u0000\u0000"), 5, "binary or UTF-16 content");
        fails(dir, "e.obj", SQUARE.replace("f 1 2 3", "# \u0000\u0000"), 5, "binary or UTF-16 content");
    }
}
