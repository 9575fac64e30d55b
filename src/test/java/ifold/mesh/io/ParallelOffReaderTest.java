package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
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
import java.util.Random;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Reading an OFF file in pieces gives what reading it whole gives, bit for bit, line numbers
 * and colours included; and where it cannot (a face over several lines, bad data) it leaves the
 * file to the whole-file reader, so that errors are the same whatever the threads.
 */
class ParallelOffReaderTest extends ReadInPiecesTest {
    @Override
    PolygonSoup readFile(Path file) throws MeshFormatException, IOException {
        return OffReader.read(file);
    }

    private Path write(String name, String text) throws IOException {
        return Files.writeString(dir.resolve(name), text, StandardCharsets.ISO_8859_1);
    }

    @Test
    void aPlainFileIsReadInPiecesAsWhole() throws Exception {
        Path torus = dir.resolve("torus.off");
        MeshWriters.write(Solids.torus(3, 1, 60, 40), torus);
        System.setProperty("ifold.threads", "3");
        assertNotNull(ParallelOffReader.read(torus), "setup: a plain file is read in pieces");
        assertSameAsWhole(torus);
    }

    @Test
    void commentsBlankLinesColoursAndLineEndsAreCountedAsTheTokenizerCountsThem() throws Exception {
        StringBuilder text = new StringBuilder("# a cube\nOFF\r\n8 6 12 # counts\r\n\r\n");
        double[][] corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
        String[] breaks = {"\n", "\r\n", "\r", "\n\n", " # note\n", "\t\f\n"};
        for (int v = 0; v < 8; v++) {
            text.append(corners[v][0]).append(' ').append(corners[v][1]).append(' ').append(corners[v][2]).append(breaks[v % breaks.length]);
        }
        text.append("#\n4 0 3 2 1 255 0 0\n4 4 5 6 7\r\n4 0 1 5 4 0.5 0.5 0.5 1\r4 1 2 6 5 7\n4 2 3 7 6\n\n  \n4 3 0 4 7");
        Path cube = write("cube.off", text.toString());
        System.setProperty("ifold.threads", "3");
        assertNotNull(ParallelOffReader.read(cube), "setup: read in pieces");
        assertSameAsWhole(cube);
    }

    @Test
    void whatPiecesCannotReadIsReadWholeWithTheSameResultOrError() throws Exception {
        System.setProperty("ifold.threads", "3");
        Path overTwoLines = write("split.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1\n2\n3 0 2 3\n");
        assertNull(ParallelOffReader.read(overTwoLines), "a face over two lines is read whole");
        assertSameAsWhole(overTwoLines);
        assertSameAsWhole(write("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"));
        assertSameAsWhole(write("extra.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n"));
        assertSameAsWhole(write("short.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
        assertSameAsWhole(write("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"));
        assertSameAsWhole(write("msvc.off", "OFF\n3 1 0\n0 0 0\n1 1.#INF 0\n0 1 0\n3 0 1 2\n"));
        assertSameAsWhole(write("binary.off", "OFF\n3 1 0\n0 0 0\n1 \0 0\n0 1 0\n3 0 1 2\n"));
        assertSameAsWhole(write("header.off", "OFF\n3 1 0"));
    }

    /** Mutations of a plain file (bytes changed, dropped, doubled): the result or the error never depends on the threads. */
    @Test
    void mutatedFilesReadTheSameWhateverTheThreads() throws Exception {
        Path torus = dir.resolve("torus.off");
        MeshWriters.write(Solids.torus(3, 1, 12, 8), torus);
        byte[] original = Files.readAllBytes(torus);
        byte[] alphabet = "0123456789 .-+e#\n\r\tx".getBytes(StandardCharsets.ISO_8859_1);
        Random random = new Random(13);
        for (int n = 0; n < 150; n++) {
            byte[] b = original.clone();
            int edits = 1 + random.nextInt(3);
            for (int e = 0; e < edits; e++) {
                b[20 + random.nextInt(b.length - 20)] = alphabet[random.nextInt(alphabet.length)];
            }
            assertSameAsWhole(Files.write(dir.resolve("mutant" + n + ".off"), b));
        }
    }

    @Test
    void theSharedModelsReadTheSameInPieces() throws Exception {
        Path root = SharedMeshes.ROOT;
        org.junit.jupiter.api.Assumptions.assumeTrue(Files.isDirectory(root), "../shared/meshes is absent");
        List<Path> files = new ArrayList<>();
        try (Stream<Path> all = Files.walk(root)) {
            all.filter(p -> p.toString().toLowerCase(java.util.Locale.ROOT).endsWith(".off"))
                    .filter(p -> {
                        try {
                            return Files.size(p) < 20_000_000;
                        } catch (IOException e) {
                            return false;
                        }
                    })
                    .forEach(files::add);
        }
        assertTrue(files.size() > 5, "setup: models found");
        for (Path file : files) {
            assertSameAsWhole(file);
        }
    }
}
