package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

/** Inline model files for the reader tests, and the checks they share. */
final class Fixtures {
    private Fixtures() {
    }

    /** Writes {@code text} as bytes (one byte per char, so tests can put any byte in). */
    static Path file(Path dir, String name, String text) throws IOException {
        return Files.write(dir.resolve(name), text.getBytes(StandardCharsets.ISO_8859_1));
    }

    static PolygonSoup read(Path dir, String name, String text) throws IOException, MeshFormatException {
        return MeshReaders.read(file(dir, name, text));
    }

    /**
     * Reads {@code text} as the file {@code name}, expects it refused at {@code line} with a
     * message containing {@code phrase}, and returns the exception for further checks.
     */
    static MeshFormatException fails(Path dir, String name, String text, int line, String phrase) throws IOException {
        Path file = file(dir, name, text);
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> MeshReaders.read(file));
        assertEquals(line, e.line(), () -> "line of: " + e.getMessage());
        assertTrue(e.problem().contains(phrase), () -> "expected '" + phrase + "' in: " + e.getMessage());
        assertEquals(file, e.file());
        String prefix = line > 0 ? file + ":" + line + ": " : file + ": ";
        assertEquals(prefix + e.problem(), e.getMessage());
        return e;
    }

    static void assertVertex(PolygonSoup soup, int v, double x, double y, double z) {
        assertEquals(x, soup.coordinate(v, 0), 0.0, "x of vertex " + v);
        assertEquals(y, soup.coordinate(v, 1), 0.0, "y of vertex " + v);
        assertEquals(z, soup.coordinate(v, 2), 0.0, "z of vertex " + v);
    }

    static void assertFace(PolygonSoup soup, int f, int... vertices) {
        int[] actual = new int[soup.faceSize(f)];
        for (int k = 0; k < actual.length; k++) {
            actual[k] = soup.faceVertex(f, k);
        }
        org.junit.jupiter.api.Assertions.assertArrayEquals(vertices, actual, "vertices of face " + f);
    }
}
