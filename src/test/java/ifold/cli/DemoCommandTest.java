package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code ifold demo zigzag} and {@code ifold demo turn}: reports, exports and their errors. */
class DemoCommandTest {
    @TempDir
    Path dir;

    @Test
    void theDefaultDemoReportsAWrappedTriangle() throws Exception {
        Path obj = dir.resolve("zigzag.obj");
        Path report = dir.resolve("zigzag.json");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--no-view", "--export-obj", obj.toString(), "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        String json = Files.readString(report);
        assertEquals(1.0, CliTest.number(json, "coverage"), 0);
        assertEquals(5, CliTest.number(json, "passes"), 0, "⌈8 / 1.6⌉");
        assertEquals(1.6, CliTest.number(json, "stripWidth"), 1e-12, "a fifth of the altitude from C");
        assertTrue(CliTest.number(json, "paperOutsideArea") < 1e-9, json);
        // One vocabulary with the wrap's report: its strips' L/w is lengthOverWidth.
        assertEquals(CliTest.number(json, "stripLength") / 1.6, CliTest.number(json, "lengthOverWidth"), 1e-9);
        assertFalse(json.contains("aspectRatio"), json);
        assertEquals(40 / (CliTest.number(json, "stripLength") * 1.6), CliTest.number(json, "paperEfficiency"), 1e-5);
        assertTrue(run.out().contains("coverage 1.000"), run.out());
        ObjReadBack back = ObjReadBack.read(obj);
        assertTrue(back.paperFaces() > 0 && back.capFaces() > 0, "paper and caps written");
        assertTrue(back.worstIsometry() <= 1e-9, "the OBJ is isometric as written: " + back.worstIsometry());
    }

    @Test
    void thinAndObtuseTrianglesAreWrapped() throws Exception {
        for (String triangle : new String[] {"0,0,12,0,5,1.5", "0,0,10,0,14,3", "0,0,1,0,0.5,9"}) {
            Path report = dir.resolve("r.json");
            CliTest.Run run = CliTest.run("demo", "zigzag", "--triangle", triangle, "--no-view", "--report", report.toString());
            assertEquals(0, run.code(), triangle + ": " + run.err());
            assertEquals(1.0, CliTest.number(Files.readString(report), "coverage"), 0, triangle);
        }
    }

    @Test
    void aFlatTriangleOfCornersUnderAQuarterDegreeIsWrapped() throws Exception {
        // Base corners of 0.23 degrees: the tucks bounce its paper more than 1,000 times, where
        // the demo used to give up.
        Path report = dir.resolve("flat.json");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--triangle", "0,0,10,0,5,0.02", "--width", "0.001", "--no-view",
                "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        String json = Files.readString(report);
        assertEquals(1.0, CliTest.number(json, "coverage"), 0);
        assertTrue(CliTest.number(json, "tucks") > 1000, json);
    }

    @Test
    void badOptionsGetOneLineAndWriteNothing() throws Exception {
        Path report = dir.resolve("r.json");
        String out = report.toString();
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "1,2,3", "--no-view", "--report", out), "--triangle", "six numbers");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "0,0,1,1,x,2", "--no-view", "--report", out), "--triangle", "'x'");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "0,0,1,1,2,2", "--no-view", "--report", out), "--triangle", "no area");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--start", "D", "--no-view", "--report", out), "--start", "A, B or C");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--start", "B", "--end", "b", "--no-view", "--report", out), "--end");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--width", "-1", "--no-view", "--report", out), "--width");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--width", "9", "--no-view", "--report", out), "--width", "altitude");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "1e9,0,1000000001,0,1e9,1", "--no-view", "--report", out),
                "--triangle", "too small");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--width", "1", "--thickness", "0.5", "--no-view", "--report", out), "--thickness");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--export-obj", dir.resolve("x.stl").toString()), "--export-obj");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--report", dir.resolve("no/r.json").toString()), "--report", "does not exist");
        CliTest.assertOneLineError(CliTest.run("demo", "turn", "--angle", "180", "--no-view"), "--angle");
        CliTest.assertOneLineError(CliTest.run("demo", "turn", "--angle", "0.001", "--no-view"), "--angle", "0.01 to 179.9");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "0,0,1e308,0,3e307,8e307", "--no-view"), "--triangle",
                "1e+60");
        // Before, a triangle 1e100 across passed this check and the default width overflowed: "option --width: ... got Infinity".
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "0,0,1e100,0,3e99,8e99", "--no-view"), "--triangle",
                "from 1e-60 to 1e+60");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "0,0,1e-100,0,3e-101,8e-101", "--no-view"), "--triangle",
                "from 1e-60 to 1e+60");
        CliTest.assertOneLineError(CliTest.run("demo", "turn", "--angle", "90", "--overhang", "-1", "--no-view"), "--overhang");
        // A side too long was "not WIDTHxHEIGHT".
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--frames", dir.resolve("big").toString(), "--size", "100000x100000"),
                "--size", "each side must be between 16 and 8192 pixels, got 100000x100000");
        assertFalse(Files.exists(report), "nothing written by a refused run");
        assertEquals(2, CliTest.run("demo").code(), "a demo must be named");
    }

    @Test
    void aTriangleInSpaceIsWrappedOnItsFront() throws Exception {
        Path report = dir.resolve("space.json");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--triangle", "1,2,3,6,1,5,2,7,4", "--no-view", "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        assertEquals(1.0, CliTest.number(Files.readString(report), "coverage"), 0);
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--triangle", "1,2,3,6,1,5,2,7", "--no-view"), "--triangle", "nine");
    }

    @Test
    void theCreasePatternIsWrittenAsFold() throws Exception {
        Path fold = dir.resolve("zigzag.fold");
        Path report = dir.resolve("fold.json");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--no-view", "--export-fold", fold.toString(), "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        String json = Files.readString(report);
        assertEquals(13, CliTest.number(json, "mountains"), 0, json);
        assertEquals(16, CliTest.number(json, "valleys"), 0, json);
        assertTrue(Files.readString(fold).contains("\"creasePattern\""));
        Path wrapFold = dir.resolve("cube.fold");
        assertEquals(0, CliTest.run("wrap", "models/cube.off", "--no-view", "--export-fold", wrapFold.toString()).code());
        assertTrue(Files.size(wrapFold) > 0);
        Path scriptFold = dir.resolve("pleat.fold");
        assertEquals(0, CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--export-fold", scriptFold.toString()).code());
        assertTrue(Files.size(scriptFold) > 0);
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--export-fold", dir.resolve("x.json").toString()),
                "--export-fold", ".fold");
    }

    @Test
    void everyStartCornerWorksWithTheDefaultEnd() throws Exception {
        for (String start : new String[] {"A", "B", "C"}) {
            CliTest.Run run = CliTest.run("demo", "zigzag", "--start", start, "--no-view");
            assertEquals(0, run.code(), start + ": " + run.err());
        }
    }

    @Test
    void theTurnGadgetTakesTheWholeRangeItsGeometryAllows() throws Exception {
        for (String angle : new String[] {"0.05", "179.5"}) {
            Path report = dir.resolve("turn" + angle + ".json");
            CliTest.Run run = CliTest.run("demo", "turn", "--angle", angle, "--no-view", "--report", report.toString());
            assertEquals(0, run.code(), run.err());
            assertEquals(Double.parseDouble(angle), CliTest.number(Files.readString(report), "measuredAngle"), 1e-9);
        }
    }

    @Test
    void theTurnDemoMeasuresItsTurn() throws Exception {
        Path report = dir.resolve("turn.json");
        CliTest.Run run = CliTest.run("demo", "turn", "--angle", "70", "--overhang", "0.5", "--no-view", "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        String json = Files.readString(report);
        assertEquals(70, CliTest.number(json, "measuredAngle"), 1e-9);
        assertTrue(json.contains("\"topSideUp\": true"), json);
        assertTrue(run.out().contains("top side up"), run.out());
    }

    @Test
    void theFigureShowsItsFourStagesLabelled() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        Path figure = dir.resolve("figure.png");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--no-view", "--figure", figure.toString());
        assertEquals(0, run.code(), run.err());
        java.awt.image.BufferedImage panel = javax.imageio.ImageIO.read(figure.toFile());
        assertEquals(1602, panel.getWidth(), "two tiles of 800 and a line between");
        assertEquals(1002, panel.getHeight());
        for (int tile = 0; tile < 4; tile++) {
            int left = (tile % 2) * 802;
            int top = (tile / 2) * 502;
            int dark = 0;
            int pale = 0;
            for (int y = top + 12; y < top + 50; y++) {
                for (int x = left + 12; x < left + 200; x++) {
                    int rgb = panel.getRGB(x, y) & 0xFFFFFF;
                    dark += ((rgb >> 16) & 0xFF) < 0x60 && ((rgb >> 8) & 0xFF) < 0x60 && (rgb & 0xFF) < 0x60 ? 1 : 0;
                    pale += ((rgb >> 16) & 0xFF) > 0xEC && ((rgb >> 8) & 0xFF) > 0xEC && (rgb & 0xFF) > 0xEC ? 1 : 0;
                }
            }
            assertTrue(dark > 200 && pale > 1000, "stage " + (char) ('a' + tile) + " has its label in its corner: " + dark
                    + " dark and " + pale + " pale pixels");
        }
    }

    @Test
    void framesAreRenderedWithoutAWindow() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        Path frames = dir.resolve("frames");
        Files.createDirectory(frames);
        Files.writeString(frames.resolve("frame_00030.png"), "stale"); // left by a longer export
        Files.writeString(frames.resolve("notes.txt"), "mine");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--frames", frames.toString(), "--size", "64x36", "--fps", "1");
        assertEquals(0, run.code(), run.err());
        try (var files = Files.list(frames)) {
            assertEquals(31, files.count(), "two seconds a step, 13 steps (12 folds and the end) and four for the turn, one frame "
                    + "a second; the frame past them gone, the user's own file kept");
        }
        assertTrue(Files.exists(frames.resolve("notes.txt")));
    }

    /** One frame is "1 frame" (was "wrote 1 frames"). */
    @Test
    void oneFrameIsSaidSo() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        Path frames = dir.resolve("one");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--frames", frames.toString(), "--size", "64x36", "--seconds", "0.01");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("wrote 1 frame of 64x36 to "), run.out());
    }
}
