package ifold.mesh.io;

import static ifold.mesh.io.Fixtures.assertFace;
import static ifold.mesh.io.Fixtures.assertVertex;
import static ifold.mesh.io.Fixtures.fails;
import static ifold.mesh.io.Fixtures.read;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class OffReaderTest {
    @TempDir
    Path dir;

    private static final String TETRAHEDRON = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

    private static void assertTetrahedron(PolygonSoup soup) {
        assertEquals(4, soup.vertexCount());
        assertEquals(4, soup.faceCount());
        assertVertex(soup, 1, 1, 0, 0);
        assertVertex(soup, 3, 0, 0, 1);
        assertFace(soup, 0, 0, 2, 1);
        assertFace(soup, 3, 1, 2, 3);
        assertFalse(soup.hasFaceColors());
    }

    @Test
    void readsATetrahedron() throws Exception {
        PolygonSoup soup = read(dir, "t.off", TETRAHEDRON);
        assertTetrahedron(soup);
        assertEquals(7, soup.faceLine(0));
        assertEquals(10, soup.faceLine(3));
    }

    @Test
    void readsExactCoordinates() throws Exception {
        PolygonSoup soup = read(dir, "t.off", "OFF\n3 1 0\n-1.5 2.25e-3 1E+2\n0.1 -0 123456789.123456789\n"
                + "4.9e-324 1.7976931348623157e308 -.5\n3 0 1 2\n");
        assertVertex(soup, 0, -1.5, 2.25e-3, 100);
        assertVertex(soup, 1, 0.1, -0.0, 123456789.123456789);
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(soup.coordinate(1, 1)));
        assertVertex(soup, 2, Double.MIN_VALUE, Double.MAX_VALUE, -0.5);
    }

    @Test
    void readsAHeaderFusedWithTheCounts() throws Exception {
        assertTetrahedron(read(dir, "t.off", TETRAHEDRON.replace("OFF\n4 4 6", "OFF 4 4 6")));
    }

    @Test
    void readsCountsWithoutTheEdgeCount() throws Exception {
        assertTetrahedron(read(dir, "t.off", TETRAHEDRON.replace("4 4 6", "4 4")));
    }

    @Test
    void readsCommentsBlankLinesAndCrlf() throws Exception {
        String text = "# made by hand\n\nOFF # header\r\n# counts next\r\n\r\n  4 4 0#edges\r\n0 0 0 # origin\r\n"
                + "1 0 0\r\n\r\n# more\r\n0 1 0\r\n0 0 1#fused\r\n3 0 2 1\r\n  # between faces\r\n3 0 1 3\r\n"
                + "3 0 3 2\r\n3 1 2 3 # last\r\n\r\n# trailing\r\n\r\n";
        PolygonSoup soup = read(dir, "t.off", text);
        assertTetrahedron(soup);
        assertEquals(13, soup.faceLine(0));
        assertEquals(17, soup.faceLine(3));
    }

    @Test
    void readsOldMacLineEnds() throws Exception {
        PolygonSoup soup = read(dir, "t.off", TETRAHEDRON.replace('\n', '\r'));
        assertTetrahedron(soup);
        assertEquals(10, soup.faceLine(3));
    }

    @Test
    void readsFaceRecordsSplitOverLines() throws Exception {
        PolygonSoup soup = read(dir, "t.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n"
                + "4\n0 1\n 2\n\n3 # a quad over 4 lines\n3 1 # triangle\n4 2\n");
        assertEquals(2, soup.faceCount());
        assertFace(soup, 0, 0, 1, 2, 3);
        assertFace(soup, 1, 1, 4, 2);
        assertEquals(8, soup.faceLine(0));
        assertEquals(13, soup.faceLine(1));
    }

    @Test
    void readsPolygonsOfAnySize() throws Exception {
        StringBuilder text = new StringBuilder("OFF\n12 3 0\n");
        for (int v = 0; v < 12; v++) {
            text.append(Math.cos(v)).append(' ').append(Math.sin(v)).append(" 0\n");
        }
        text.append("12 0 1 2 3 4 5 6 7 8 9 10 11\n5 0 1 2 3 4\n3 5 6 7\n");
        PolygonSoup soup = read(dir, "p.off", text.toString());
        assertEquals(12, soup.faceSize(0));
        assertEquals(5, soup.faceSize(1));
        assertEquals(3, soup.faceSize(2));
        assertFace(soup, 0, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11);
        assertVertex(soup, 7, Math.cos(7), Math.sin(7), 0);
        assertEquals(20, soup.cornerCount());
    }

    @Test
    void readsIntegerFaceColors() throws Exception {
        PolygonSoup soup = read(dir, "c.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                + "3 0 2 1 255 0 0\n3 0 1 3 0 255 0 128\n3 0 3 2\n3 1 2 3 18 52 86\n");
        assertTrue(soup.hasFaceColors());
        assertEquals(0xFFFF0000, soup.faceColor(0));
        assertEquals(0x8000FF00, soup.faceColor(1));
        assertEquals(PolygonSoup.DEFAULT_COLOR, soup.faceColor(2));
        assertEquals(0xFF123456, soup.faceColor(3));
    }

    @Test
    void readsFractionalFaceColors() throws Exception {
        // One value with a point or exponent makes the whole colour fractional: "1 0 0.5" is 0..1.
        PolygonSoup soup = read(dir, "c.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                + "3 0 2 1 1 0 0.5\n3 0 1 3 0.2 1e0 0.0 0.5\n3 0 3 2 1.0 1.0 1.0 # white\n");
        assertEquals(0xFFFF0080, soup.faceColor(0));
        assertEquals(0x8033FF00, soup.faceColor(1));
        assertEquals(0xFFFFFFFF, soup.faceColor(2));
    }

    @Test
    void colourIsReadFromTheLineOfTheLastIndexOnly() throws Exception {
        PolygonSoup soup = read(dir, "c.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
                + "3 0 2\n1 10 20 30\n3\n0 1 3\n");
        assertEquals(0xFF0A141E, soup.faceColor(0));
        assertEquals(PolygonSoup.DEFAULT_COLOR, soup.faceColor(1));
    }

    @Test
    void facesWithoutAColourAreGreyInAColouredFile() throws Exception {
        StringBuilder text = new StringBuilder("OFF\n3 200 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 1 2 3\n");
        for (int f = 1; f < 200; f++) {
            text.append(f == 150 ? "3 0 1 2 4 5 6\n" : "3 0 1 2\n");
        }
        PolygonSoup soup = read(dir, "c.off", text.toString());
        for (int f = 0; f < 200; f++) {
            int expected = f == 0 ? 0xFF010203 : f == 150 ? 0xFF040506 : PolygonSoup.DEFAULT_COLOR;
            assertEquals(expected, soup.faceColor(f), "face " + f);
        }
    }

    @Test
    void ignoresAColourMapIndex() throws Exception {
        PolygonSoup soup = read(dir, "c.off", TETRAHEDRON.replace("3 0 2 1\n", "3 0 2 1 7\n"));
        assertTetrahedron(soup);
    }

    @Test
    void skipsVertexColoursOfCoff() throws Exception {
        PolygonSoup soup = read(dir, "c.off", "COFF\n4 1 0\n0 0 0 1 0 0\n1 0 0 0 1 0 1\n0 1 0 0.5 0.5 0.5 0.5\n"
                + "0 0 1 255 255 255\n3 0 1 2\n");
        assertEquals(4, soup.vertexCount());
        assertVertex(soup, 1, 1, 0, 0);
        assertVertex(soup, 3, 0, 0, 1);
        assertFalse(soup.hasFaceColors());
    }

    @Test
    void skipsNormalsOfNoffAndBothOfCnoff() throws Exception {
        PolygonSoup noff = read(dir, "n.off", "NOFF\n3 1\n1 2 3 0 0 1\n4 5 6 0 0 1\n7 8 9 0 0 1\n3 0 1 2\n");
        assertVertex(noff, 2, 7, 8, 9);
        PolygonSoup cnoff = read(dir, "cn.off", "CNOFF 3 1 0\n1 2 3 0 0 1 1 0 0\n4 5 6 0 0 1 0 1 0 1\n"
                + "7 8 9 0 0 1 0 0 1\n3 0 1 2 0 0 255\n");
        assertVertex(cnoff, 1, 4, 5, 6);
        assertEquals(0xFF0000FF, cnoff.faceColor(0));
        PolygonSoup st = read(dir, "st.off", "STOFF\n3 1\n1 2 3 0.5 0.5\n4 5 6 0 1\n7 8 9 1 1\n3 0 1 2\n");
        assertVertex(st, 0, 1, 2, 3);
    }

    @Test
    void skipsAUtf8ByteOrderMark() throws Exception {
        assertTetrahedron(read(dir, "t.off", "\u00EF\u00BB\u00BF" + TETRAHEDRON));
    }

    @Test
    void readsUppercaseExtension() throws Exception {
        assertTetrahedron(read(dir, "T.OFF", TETRAHEDRON));
    }

    // ---- errors ----

    @Test
    void refusesAnEmptyFile() throws Exception {
        fails(dir, "e.off", "", 0, "empty file");
    }

    @Test
    void refusesAFileOfOnlyComments() throws Exception {
        fails(dir, "e.off", "# nothing\n\n   \n# here\n", 0, "no data: only comments and blank lines");
    }

    @Test
    void refusesAFileWithoutFaces() throws Exception {
        fails(dir, "e.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", 2, "no faces: the header declares 0 faces");
    }

    @Test
    void refusesAnIndexOutOfRange() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("3 1 2 3\n", "3 1 2\n 4\n"), 11,
                "vertex index 4 out of range: the file has 4 vertices (0 to 3)");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 -1 3\n"), 8, "vertex index -1 out of range");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 99999999999999999999 3\n"), 8,
                "vertex index 99999999999999999999 out of range");
        fails(dir, "e.off", "OFF 0 1 0\n3 0 1 2\n", 2, "vertex index 0 out of range: the file has no vertices");
    }

    @ParameterizedTest
    @ValueSource(strings = {"nan", "-nan", "NaN", "inf", "-inf", "Infinity", "1.#IND", "-1.#IND", "1.#INF", "1.#QNAN",
        "nan(ind)"})
    void refusesNonFiniteCoordinates(String value) throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 " + value + " 0\n"), 4,
                "coordinate '" + value + "' is not a finite number");
    }

    @Test
    void refusesACoordinateTooLargeForADouble() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 0 1e309\n"), 4,
                "coordinate '1e309' is not a finite number (too large for a double)");
    }

    @Test
    void refusesNonNumericTokens() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 zero 0\n"), 4, "expected a coordinate, found 'zero'");
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 0,5 0\n"), 4, "expected a coordinate, found '0,5'");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1.0 3\n"), 8, "expected a vertex index, found '1.0'");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "three 0 1 3\n"), 8,
                "expected the vertex count of a face, found 'three'");
        fails(dir, "e.off", TETRAHEDRON.replace("4 4 6", "4 four 6"), 2, "expected the face count, found 'four'");
        fails(dir, "e.off", TETRAHEDRON.replace("4 4 6", "4 4 six"), 2, "expected the edge count, found 'six'");
        fails(dir, "e.off", TETRAHEDRON.replace("4 4 6", "4 4 6 8"), 2, "unexpected '8' after the header counts");
        fails(dir, "e.off", TETRAHEDRON.replace("3 1 2 3\n", "3 1 2 3 red\n"), 10,
                "expected a colour component, found 'red'");
    }

    @Test
    void refusesAVertexWithTooFewOrTooManyValues() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 0\n"), 4, "vertex record has 2 values, OFF expects 3");
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1\n"), 4, "vertex record has 1 value, OFF expects 3");
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 0 0 1\n"), 4, "vertex record has 4 values, OFF expects 3");
        fails(dir, "e.off", TETRAHEDRON.replace("OFF", "COFF"), 3, "vertex record has 3 values, COFF expects 6 or 7");
        fails(dir, "e.off", TETRAHEDRON.replace("OFF", "NOFF").replace("1 0 0\n", "1 0 0 0 0 1 1\n"), 3,
                "vertex record has 3 values, NOFF expects 6");
        fails(dir, "e.off", TETRAHEDRON.replace("1 0 0\n", "1 0 0 x\n"), 4, "expected a number, found 'x'");
    }

    @Test
    void refusesAFaceWithFewerThanThreeVertices() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "2 0 1\n"), 8, "face with 2 vertices, need at least 3");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "0\n"), 8, "face with 0 vertices, need at least 3");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "-3 0 1 3\n"), 8, "face with -3 vertices");
    }

    @Test
    void refusesBadFaceColours() throws Exception {
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1 3 300 0 0\n"), 8,
                "colour component 300 outside 0 to 255");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1 3 1.5 0 0\n"), 8, "colour component 1.5 outside 0 to 1");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1 3 255 0\n"), 8,
                "face has 2 values after its 3 vertex indices");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1 3 1 2 3 4 5\n"), 8,
                "face has more than 4 values after its 3 vertex indices");
        fails(dir, "e.off", TETRAHEDRON.replace("3 0 1 3\n", "3 0 1 3 255 nan 0\n"), 8,
                "colour component 'nan' is not a finite number");
    }

    @Test
    void refusesATruncatedFile() throws Exception {
        fails(dir, "e.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n\n# gone\n", 4, "truncated: the file ends after 2 of 4 vertices");
        fails(dir, "e.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1", 5, "truncated: the file ends inside vertex 3");
        fails(dir, "e.off", TETRAHEDRON.replace("3 1 2 3\n", ""), 9, "truncated: the file ends after 3 of 4 faces");
        fails(dir, "e.off", TETRAHEDRON.replace("3 1 2 3\n", "3 1\n"), 10,
                "truncated: the file ends after 3 of 4 faces, inside a face that declares 3 vertices and has 1");
        fails(dir, "e.off", "OFF\n", 1, "truncated: the file ends before the vertex count");
        fails(dir, "e.off", "OFF 4\n", 1, "truncated: the file ends before the face count");
    }

    @Test
    void refusesDataAfterTheLastFace() throws Exception {
        fails(dir, "e.off", TETRAHEDRON + "\n# fine\n3 0 1 2\n", 13,
                "extra data '3' after the last of 4 faces: the header counts disagree with the data");
        // Too few vertices in the header: a coordinate line is read as a face.
        fails(dir, "e.off", TETRAHEDRON.replace("4 4 6", "3 4 6"), 6, "face with 0 vertices, need at least 3");
        // Too many: a face line is read as a vertex, and OFF vertices carry 3 values.
        fails(dir, "e.off", TETRAHEDRON.replace("4 4 6", "5 4 6"), 7, "vertex record has 4 values, OFF expects 3");
    }

    @Test
    void neverAllocatesFromHeaderCounts() throws Exception {
        assertTimeoutPreemptively(() -> {
            fails(dir, "e.off", "OFF\n2000000000 2000000000 0\n0 0 0\n", 3,
                    "truncated: the file ends after 1 of 2000000000 vertices");
            fails(dir, "e.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n", 6,
                    "inside a face that declares 2000000000 vertices and has 3");
        });
    }

    private static void assertTimeoutPreemptively(org.junit.jupiter.api.function.Executable body) {
        org.junit.jupiter.api.Assertions.assertTimeoutPreemptively(Duration.ofSeconds(10), body);
    }

    @Test
    void refusesCountsTooLargeOrNegative() throws Exception {
        fails(dir, "e.off", "OFF\n353535235358 6 0\n0 0 0\n", 2,
                "the header claims 353535235358 vertices, more than the 2147483647 a mesh can hold");
        fails(dir, "e.off", "OFF\n4 99999999999999999999999 0\n", 2,
                "the header claims 99999999999999999999999 faces");
        fails(dir, "e.off", "OFF\n-4 4 0\n", 2, "negative vertex count -4");
    }

    @Test
    void refusesWhatIsNotAnOffHeader() throws Exception {
        fails(dir, "e.off", "ply\nformat ascii 1.0\n", 1, "expected an OFF header (OFF, COFF, NOFF or CNOFF), found 'ply'");
        fails(dir, "e.off", "4 4 0\n0 0 0\n", 1, "missing OFF header: the file starts with '4'");
        fails(dir, "e.off", "\n# c\n4OFF\n3 1 0\n", 3, "header '4OFF' is not supported");
        fails(dir, "e.off", "OFF BINARY\n", 1, "binary OFF is not supported");
        fails(dir, "e.off", "OFFF\n", 1, "expected an OFF header");
    }

    @Test
    void refusesBinaryAndUtf16Content() throws Exception {
        fails(dir, "e.off", "\u00FF\u00FEO\u0000F\u0000F\u0000", 1, "binary or UTF-16 content, expected a text OFF/OBJ file");
        fails(dir, "e.off", "O\u0000F\u0000F\u0000\n\u0000", 1, "binary or UTF-16 content");
        fails(dir, "e.off", TETRAHEDRON.replace("0 0 1\n", "0 \u0000\u0003\u00F0 1\n"), 6, "binary or UTF-16 content");
    }
}
