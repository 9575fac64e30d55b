package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the tests of reading a format in pieces share: every file, however small, is read in
 * pieces (the threads given with {@code ifold.threads}), and compared with the same file read
 * whole: the same soup to the bit, or the same error.
 */
abstract class ReadInPiecesTest {
    @TempDir
    Path dir;

    private String threads;
    private String bytes;

    /** Reads {@code file} as the format's reader does, in pieces where the properties say so. */
    abstract PolygonSoup readFile(Path file) throws MeshFormatException, IOException;

    @BeforeEach
    void readEveryFileInPieces() {
        threads = System.getProperty("ifold.threads");
        bytes = System.getProperty("ifold.parallelReadBytes");
        System.setProperty("ifold.parallelReadBytes", "0");
    }

    @AfterEach
    void restoreProperties() {
        restore("ifold.threads", threads);
        restore("ifold.parallelReadBytes", bytes);
    }

    private static void restore(String key, String value) {
        if (value == null) {
            System.clearProperty(key);
        } else {
            System.setProperty(key, value);
        }
    }

    /** What reading gives: the soup, or the error's message. */
    Object read(Path file, int threadCount) {
        System.setProperty("ifold.threads", Integer.toString(threadCount));
        try {
            return readFile(file);
        } catch (MeshFormatException | IOException e) {
            return e.getMessage();
        }
    }

    void assertSameAsWhole(Path file) {
        Object whole = read(file, 1);
        for (int threadCount : new int[] {2, 3, 5}) {
            Object pieces = read(file, threadCount);
            if (whole instanceof String message) {
                assertEquals(message, pieces, file + " with " + threadCount + " threads");
            } else {
                assertTrue(pieces instanceof PolygonSoup, () -> file + " with " + threadCount + " threads: " + pieces);
                assertSameSoup((PolygonSoup) whole, (PolygonSoup) pieces, file + " with " + threadCount + " threads");
            }
        }
    }

    static void assertSameSoup(PolygonSoup expected, PolygonSoup actual, String what) {
        assertEquals(expected.vertexCount(), actual.vertexCount(), what);
        for (int v = 0; v < expected.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                if (Double.doubleToRawLongBits(expected.coordinate(v, axis)) != Double.doubleToRawLongBits(actual.coordinate(v, axis))) {
                    assertEquals(expected.coordinate(v, axis), actual.coordinate(v, axis), what + ": vertex " + v);
                }
            }
        }
        assertEquals(expected.faceCount(), actual.faceCount(), what);
        assertEquals(expected.hasFaceColors(), actual.hasFaceColors(), what);
        for (int f = 0; f < expected.faceCount(); f++) {
            assertEquals(expected.faceSize(f), actual.faceSize(f), what + ": face " + f);
            for (int k = 0; k < expected.faceSize(f); k++) {
                assertEquals(expected.faceVertex(f, k), actual.faceVertex(f, k), what + ": face " + f);
            }
            assertEquals(expected.faceLine(f), actual.faceLine(f), what + ": line of face " + f);
            assertEquals(expected.faceColor(f), actual.faceColor(f), what + ": colour of face " + f);
        }
    }
}
