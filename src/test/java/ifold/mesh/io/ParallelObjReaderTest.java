package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.testing.SharedMeshes;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;

/**
 * Reading an OBJ file in pieces gives what reading it whole gives, bit for bit, line numbers
 * included, negative indices and faces before their vertices too; and where it cannot (a line
 * continued by a backslash, bad data) it leaves the file to the whole-file reader, so that
 * errors are the same whatever the threads.
 */
class ParallelObjReaderTest extends ReadInPiecesTest {
    @Override
    PolygonSoup readFile(Path file) throws MeshFormatException, IOException {
        return ObjReader.read(file);
    }

    /** Whether {@code file} is read in pieces on 3 threads rather than left to the whole-file reader. */
    private static boolean readInPieces(Path file) throws IOException {
        System.setProperty("ifold.threads", "3");
        try {
            return ParallelObjReader.read(file) != null;
        } catch (MeshFormatException e) {
            return true; // refused in pieces, as the whole-file reader refuses it
        }
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.ISO_8859_1);
    }

    /**
     * A strip of quads over {@code rows} rows, each row's vertices followed by its faces, which
     * name them by negative indices in every reference form, with comments, skipped statements
     * and line ends of every kind; the last face names by positive indices vertices defined
     * after it.
     */
    private static String strip(int rows) {
        StringBuilder text = new StringBuilder("# a strip\r\nmtllib C:\\models\\strip.mtl\no strip\n");
        String[] breaks = {"\n", "\r\n", "\r", " # note\n", "\t\f\n", "\n\n"};
        String[] forms = {"%d", "%d/%d", "%d//%d", "%d/%d/%d"};
        int line = 0;
        for (int row = 0; row < rows; row++) {
            text.append(row % 3 == 0 ? "g row" + row + "\n" : "").append(row % 4 == 1 ? "usemtl m" + row % 2 + "\ns off\n" : "");
            for (int column = 0; column < 2; column++) {
                text.append("v ").append(column).append(' ').append(Math.sin(row * 0.37)).append(' ').append(row / 7.0)
                        .append(breaks[line++ % breaks.length]);
            }
            text.append("vt ").append(row).append(" 0.5\nvn 0 0 1\n");
            if (row > 0) {
                String form = forms[row % forms.length];
                text.append(row % 5 == 0 ? "fo" : "f");
                for (int back : new int[] {-4, -3, -1, -2}) {
                    text.append(' ').append(String.format(Locale.ROOT, form, back, -1, -1));
                }
                text.append(breaks[line++ % breaks.length]);
            }
        }
        return text.append("f 1 2 ").append(2 * rows + 1).append("\nv 9 9 9\n").toString();
    }

    @Test
    void aPlainFileIsReadInPiecesAsWhole() throws Exception {
        Path torus = dir.resolve("torus.obj");
        MeshWriters.write(Solids.torus(3, 1, 60, 40), torus);
        System.setProperty("ifold.threads", "3");
        assertNotNull(ParallelObjReader.read(torus), "setup: a plain file is read in pieces");
        assertSameAsWhole(torus);
    }

    @Test
    void lineEndsCommentsSkippedStatementsAndReferenceFormsAreCountedAsTheTokenizerCountsThem() throws Exception {
        Path strip = write("strip.obj", strip(40));
        assertTrue(readInPieces(strip), "setup: read in pieces");
        assertSameAsWhole(strip);
        Path marked = write("mark.obj", "\u00EF\u00BB\u00BF" + strip(40));
        assertTrue(readInPieces(marked), "setup: a UTF-8 byte order mark is read in pieces");
        assertSameAsWhole(marked);
    }

    @Test
    void negativeIndicesCountBackAcrossPieceBoundaries() throws Exception {
        // Each face names the vertices just before it, and many of its pieces start between
        // a face and the vertices it names.
        Path strip = write("long.obj", strip(400));
        PolygonSoup whole = (PolygonSoup) read(strip, 1);
        assertEquals(2 * 400 + 1, whole.vertexCount(), "setup");
        assertEquals(List.of(0, 1, 3, 2), List.of(whole.faceVertex(0, 0), whole.faceVertex(0, 1), whole.faceVertex(0, 2), whole.faceVertex(0, 3)), "setup");
        assertTrue(readInPieces(strip), "setup: read in pieces");
        assertSameAsWhole(strip);
    }

    @Test
    void facesMayNameVerticesDefinedAfterThemInLaterPieces() throws Exception {
        StringBuilder text = new StringBuilder();
        for (int f = 0; f < 200; f++) {
            text.append("f ").append(3 * f + 1).append(' ').append(3 * f + 2).append(' ').append(3 * f + 3).append('\n');
        }
        for (int v = 0; v < 600; v++) {
            text.append("v ").append(v).append(' ').append(v * 0.5).append(" 0\n");
        }
        Path later = write("later.obj", text.toString());
        assertTrue(readInPieces(later), "setup: read in pieces");
        assertSameAsWhole(later);
        Path beyond = write("beyond.obj", text.toString().replace("f 598 599 600", "f 598 599 601"));
        assertTrue(((String) read(beyond, 1)).endsWith("beyond.obj:200: vertex index 601 out of range: the file has 600 vertices (1 to 600)"), "setup");
        System.setProperty("ifold.threads", "3");
        assertThrows(MeshFormatException.class, () -> ParallelObjReader.read(beyond), "refused in pieces");
        assertSameAsWhole(beyond);
    }

    @Test
    void aContinuedLineIsReadWhole() throws Exception {
        String strip = strip(40);
        for (String continued : new String[] {"v 1 0 \\\n0\n", "v 1 0 \\\r\n 0\r\n", "v 1 0 \\\r0\r", "v 1 0\\ # why\n0\n",
                "f 1 2 \\\n3\n", "v 1 \\ \\\n0 0\n", "g a\\\nv 0 0 0\n"}) {
            Path file = write("continued.obj", strip.replace("o strip\n", "o strip\n" + continued));
            assertTrue(read(file, 1) instanceof PolygonSoup, "setup: " + continued);
            System.setProperty("ifold.threads", "3");
            assertNull(ParallelObjReader.read(file), continued);
            assertSameAsWhole(file);
        }
        // A backslash that continues nothing (a path, a comment) leaves the lines as they are.
        for (String kept : new String[] {"# C:\\models\\\n", "usemtl a\\b\n", "v 1\\ 0 0\n", "g a\\b # c\\\n"}) {
            Path file = write("kept.obj", strip.replace("o strip\n", "o strip\n" + kept));
            assertTrue(readInPieces(file), kept);
            assertSameAsWhole(file);
        }
        Path last = write("last.obj", strip + "v 1 0 0 \\");
        assertTrue(readInPieces(last), "a backslash at the end of the file continues nothing");
        assertSameAsWhole(last);
    }

    @Test
    void whatPiecesCannotReadIsReadWholeWithTheSameError() throws Exception {
        String strip = strip(40);
        String[] broken = {"v 1 one 0\n", "v 1 nan 0\n", "v 1 1.#INF 0\n", "v 1 1\n", "v\n", "f 1 2\n", "f 1 2 0\n",
            "f 1 2 x\n", "f 1 2 4/1/1/1\n", "f -1 -2 -999\n", "f 1 2 99999999999\n", "1 2 3\n", "v 1 \0 0\n",
            "# \0\n", "v 1 2 3\u0001\n", "f 1 2 3 #\0\n"};
        for (String bad : broken) {
            Path file = write("bad.obj", strip.replace("g row6\n", "g row6\n" + bad));
            assertTrue(read(file, 1) instanceof String, "setup: refused: " + bad);
            assertSameAsWhole(file);
        }
        assertSameAsWhole(write("empty.obj", ""));
        assertSameAsWhole(write("mark.obj", "\u00EF\u00BB\u00BF"));
        assertSameAsWhole(write("faceless.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"));
        assertSameAsWhole(write("utf16.obj", "\u00FF\u00FEv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
        assertSameAsWhole(write("bare.obj", strip + "f"));
        assertSameAsWhole(write("index.obj", strip + "f 1 2 9999\n"));
    }

    /** Mutations of a varied file (bytes changed, dropped, added): the result or the error never depends on the threads. */
    @Test
    void mutatedFilesReadTheSameWhateverTheThreads() throws Exception {
        byte[] original = strip(12).getBytes(StandardCharsets.ISO_8859_1);
        byte[] alphabet = "0123456789 .-+e#/\\\n\r\tvfox\0".getBytes(StandardCharsets.ISO_8859_1);
        Random random = new Random(17);
        int inPieces = 0;
        int mutants = 300;
        for (int n = 0; n < mutants; n++) {
            byte[] b = original.clone();
            int edits = 1 + random.nextInt(3);
            for (int e = 0; e < edits; e++) {
                int at = random.nextInt(b.length);
                byte with = alphabet[random.nextInt(alphabet.length)];
                switch (random.nextInt(3)) {
                    case 0 -> b[at] = with;
                    case 1 -> b = concat(b, 0, at, new byte[0], b, at + 1);
                    default -> b = concat(b, 0, at, new byte[] {with}, b, at);
                }
            }
            Path mutant = Files.write(dir.resolve("mutant" + n + ".obj"), b);
            if (readInPieces(mutant)) {
                inPieces++;
            }
            assertSameAsWhole(mutant);
        }
        assertTrue(inPieces > mutants / 4, "setup: many mutants read in pieces, not all left whole: " + inPieces);
    }

    private static byte[] concat(byte[] head, int headFrom, int headTo, byte[] middle, byte[] tail, int tailFrom) {
        byte[] joined = new byte[headTo - headFrom + middle.length + tail.length - tailFrom];
        System.arraycopy(head, headFrom, joined, 0, headTo - headFrom);
        System.arraycopy(middle, 0, joined, headTo - headFrom, middle.length);
        System.arraycopy(tail, tailFrom, joined, headTo - headFrom + middle.length, tail.length - tailFrom);
        return joined;
    }

    @Test
    void theSharedModelsReadTheSameInPieces() throws Exception {
        Path root = SharedMeshes.ROOT;
        Assumptions.assumeTrue(Files.isDirectory(root), "../shared/meshes is absent");
        List<Path> files = new ArrayList<>();
        try (Stream<Path> all = Files.walk(root)) {
            all.filter(p -> p.toString().toLowerCase(Locale.ROOT).endsWith(".obj")).filter(Files::isRegularFile).sorted()
                    .forEach(files::add);
        }
        assertTrue(files.size() > 5, "setup: models found");
        for (Path file : files) {
            assertSameAsWhole(file);
        }
    }
}
