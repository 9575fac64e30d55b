package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@code ifold wrap} of models far from the origin, far too small or far too large: each wraps
 * as the same model at the origin does, or is refused in one line naming the model and why;
 * never an internal error, and never an exit 0 with stretched paper.
 */
class WrapCoordinatesTest {
    @TempDir
    Path dir;

    /** The unit cube of models/cube.off, its corners at {@code scale} times theirs, plus {@code offset} on every axis. */
    private Path cube(String name, double scale, double offset) throws Exception {
        StringBuilder off = new StringBuilder("OFF\n8 6 0\n");
        for (int v = 0; v < 8; v++) {
            off.append(String.format(Locale.ROOT, "%s %s %s%n", (v & 1) * scale + offset, (v >> 1 & 1) * scale + offset,
                    (v >> 2 & 1) * scale + offset));
        }
        off.append("4 0 2 3 1\n4 4 5 7 6\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
        Path file = dir.resolve(name);
        Files.writeString(file, off);
        return file;
    }

    /** What the summary line says after the model's name: the same for the same wrap wherever the model lies. */
    private static String afterName(String out, Path model) {
        String line = out.lines().filter(l -> l.startsWith(model + ": ")).findFirst().orElseThrow(() -> new AssertionError(out));
        return line.substring(model.toString().length());
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e9, 1e15})
    void aCubeFarFromTheOriginWrapsAsAtTheOrigin(double offset) throws Exception {
        Path atOrigin = cube("origin.off", 1, 0);
        CliTest.Run origin = CliTest.run("wrap", atOrigin.toString(), "--no-view");
        assertEquals(0, origin.code(), origin.err());
        Path far = cube("far.off", 1, offset);
        // Check the setup: the cube is where it was asked to be, to the last bit.
        assertTrue(Files.readString(far).contains("\n" + (offset + 1) + " " + offset + " " + offset + "\n"), Files.readString(far));
        Path report = dir.resolve("far.json");
        Path obj = dir.resolve("far.obj");
        CliTest.Run run = CliTest.run("wrap", far.toString(), "--no-view", "--report", report.toString(), "--export-obj", obj.toString());
        assertEquals(0, run.code(), run.err());
        assertEquals(afterName(origin.out(), atOrigin).lines().findFirst(), afterName(run.out(), far).lines().findFirst(),
                "the same wrap, fold for fold");
        // The OBJ says where its coordinates are about, not only the line on stderr (it said nothing).
        String header = Files.readAllLines(obj).get(0);
        assertTrue(header.contains("(coordinates about (" + offset + ", " + offset + ", " + offset + "), near its centre"), header);
        assertTrue(CliTest.number(Files.readString(report), "isometryError") <= 1e-9, Files.readString(report));
        assertTrue(run.err().contains("wrapped about (" + offset + ", " + offset + ", " + offset + ")"), run.err());
    }

    @Test
    void aCubeNearTheOriginIsNotMoved() throws Exception {
        // models/cube.off spans 0..1: its exports keep the model's own coordinates, and nothing is said.
        CliTest.Run run = CliTest.run("wrap", "models/cube.off", "--no-view", "--report", dir.resolve("r.json").toString());
        assertEquals(0, run.code(), run.err());
        assertEquals("", run.err());
        assertFalse(Files.readString(dir.resolve("r.json")).contains("movedBy"));
    }

    @Test
    void stretchedPaperIsRefusedNotReported() throws Exception {
        // Two unit cubes 1e7 apart: no move helps (the model is 1e7 across), and the far cube's
        // folds round by 1e-9 of its size. Before, this exited 0 with "isometry error 3.9e-08".
        StringBuilder off = new StringBuilder("OFF\n16 12 0\n");
        for (double x0 : new double[] {0, 1e7}) {
            for (int v = 0; v < 8; v++) {
                off.append(String.format(Locale.ROOT, "%s %d %d%n", x0 + (v & 1), v >> 1 & 1, v >> 2 & 1));
            }
        }
        for (int base : new int[] {0, 8}) {
            for (int[] face : new int[][] {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}}) {
                off.append(String.format(Locale.ROOT, "4 %d %d %d %d%n", base + face[0], base + face[1], base + face[2], base + face[3]));
            }
        }
        Path model = dir.resolve("two.off");
        Files.writeString(model, off);
        Path obj = dir.resolve("two.obj");
        CliTest.Run run = CliTest.run("wrap", model.toString(), "--no-view", "--export-obj", obj.toString());
        CliTest.assertOneLineError(run, model + ": cannot wrap: the paper came out stretched (isometry error ");
        assertFalse(Files.exists(obj), "nothing written");
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e-100, 1e155})
    void aCubeTooSmallOrTooLargeIsRefusedInOneLine(double scale) throws Exception {
        Path model = cube("scaled.off", scale, 0);
        CliTest.assertOneLineError(CliTest.run("wrap", model.toString(), "--no-view"), model + ": cannot wrap: the model is ",
                " across", "scale it");
    }

    @ParameterizedTest
    @ValueSource(doubles = {1e-300, 1e300})
    void aTriangleTooSmallOrTooLargeIsRefusedInOneLine(double side) throws Exception {
        Path model = dir.resolve("triangle.off");
        Files.writeString(model, String.format(Locale.ROOT, "OFF\n3 1 0\n0 0 0\n%s 0 0\n%s %s 0\n3 0 1 2%n", side, side / 2,
                side * Math.sqrt(3) / 2));
        CliTest.assertOneLineError(CliTest.run("wrap", model.toString(), "--no-view"), model + ": cannot wrap: the model is ",
                " across", "scale it");
    }
}
