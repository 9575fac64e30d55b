package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.image.FrameWriter;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The names Save dialogs suggest, and the window's movies paced as the command line's. */
class ExportsTest {
    @TempDir
    Path dir;

    @Test
    void saveDialogsSuggestTheModelsNameAndTheExtension() {
        assertEquals("zigzag.mp4", Exports.suggestedName(Job.ZigZag.DEMO, "mp4"));
        assertEquals("turn.obj", Exports.suggestedName(new Job.Turn("60", "", "", ""), "obj"));
        Path cube = Path.of("models", "cube.off");
        assertEquals("cube.fold", Exports.suggestedName(new Job.WrapModel(cube, "", "", "", false), "fold"));
        assertEquals("cube-export.off", Exports.suggestedName(new Job.WrapModel(cube, "", "", "", false), "off"),
                "saving as suggested does not write over the model");
        assertEquals("pleat20.json", Exports.suggestedName(new Job.Script(Path.of("models/scripts/pleat20.fold")), "json"));
        assertEquals("pleat20-export.fold", Exports.suggestedName(new Job.Script(Path.of("models/scripts/pleat20.fold")), "fold"));
    }

    @Test
    void aShortMovieOfAWrapKeepsEachCaptionLongEnoughToRead() throws Exception {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        Plan cube = Planning.plan(new Job.WrapModel(Path.of("models", "cube.off"), "", ""), Progress.NONE);
        Path folder = dir.resolve("frames");
        int fps = 2;
        Exports.frames(ifold.ui.OpenGlRenderer.INSTANCE, cube, folder, new Exports.FrameSettings(320, 180, fps, 30, true), Progress.NONE);
        // The caption's letters are white; nothing under the band's dark tint is: the white pixels
        // of the band are the caption. Each stays over at least 1.5 s: three frames, two where a
        // change falls between samples.
        int frames = 30 * fps;
        int band = ifold.render.FrameExport.captionBand(320, 180); // always under the tint, one line or two
        int run = 1;
        boolean[] previous = null;
        for (int i = 0; i < frames; i++) {
            BufferedImage image = ImageIO.read(folder.resolve(FrameWriter.frameName(i)).toFile());
            boolean[] text = new boolean[320 * band];
            for (int y = 180 - band; y < 180; y++) {
                for (int x = 0; x < 320; x++) {
                    text[(y - 180 + band) * 320 + x] = (image.getRGB(x, y) & 0xFFFFFF) == 0xFFFFFF;
                }
            }
            if (previous != null && !Arrays.equals(previous, text)) {
                assertTrue(run >= 2, "a caption for " + run + " frame(s) at " + fps + " frames/s, before frame " + i);
                run = 1;
            } else if (previous != null) {
                run++;
            }
            previous = text;
        }
    }

    /**
     * Fold, Check the wrap checks the wrap shown as {@code ifold check} does, from its OBJ and
     * FOLD files written into a folder of their own, which it takes back; a plan that wraps no
     * model has nothing to check.
     */
    @Test
    void aWrapIsCheckedFromItsFilesAndTheFilesTakenBack() throws Exception {
        Path temporary = Path.of(System.getProperty("java.io.tmpdir"));
        java.util.function.Supplier<java.util.Set<Path>> checkFolders = () -> {
            try (var files = java.nio.file.Files.list(temporary)) {
                return files.filter(f -> f.getFileName().toString().startsWith("ifold-check")).collect(java.util.stream.Collectors.toSet());
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
        };
        java.util.Set<Path> before = checkFolders.get();
        Plan tetrahedron = Planning.plan(new Job.WrapModel(Path.of("models", "tetrahedron.off"), "", ""), Progress.NONE);
        Exports.Checked checked = Exports.check(tetrahedron, Progress.NONE);
        assertTrue(checked.holds(), String.join("\n", checked.lines()));
        assertEquals(4, checked.lines().size(), "what was checked, the truths, the collisions, the layer order: " + checked.lines());
        assertTrue(checked.lines().get(0).startsWith("tetrahedron.off: 1 strip, "), checked.lines().get(0));
        assertEquals("truths: every one holds (tiled, isometric, not torn, covered, on surface)", checked.lines().get(1));
        assertTrue(checked.lines().get(2).startsWith("collisions: 0 crossing pairs"), checked.lines().get(2));
        assertTrue(checked.lines().get(3).startsWith("layer order: valid"), checked.lines().get(3));
        assertEquals(before, checkFolders.get(), "the check's files are taken back");

        Plan zigzag = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        JobFailure none = org.junit.jupiter.api.Assertions.assertThrows(JobFailure.class, () -> Exports.check(zigzag, Progress.NONE));
        assertTrue(none.getMessage().contains("only a wrap of a model is checked"), none.getMessage());
    }

    /**
     * A grid polyhedron whose zig-zag paper crosses itself (a random polycube of 30 cubes): the
     * check says so and, as the command line does, that the hinge strip wraps it in two layers.
     */
    @Test
    void aCollidingPolycubesCheckPointsToTheHingeStrip() throws Exception {
        Path polycube = dir.resolve("pc30.off");
        ifold.job.GenerateJob.run(new ifold.job.GenerateJob.Request(ifold.job.BuiltInModels.Shape.polycube, 24, 12, 3,
                new ifold.job.BuiltInModels.Grid(new int[] {2, 1, 1}, 30, 5), polycube, false), ifold.job.JobWatcher.NONE);
        Plan wrapped = Planning.plan(new Job.WrapModel(polycube, "", ""), Progress.NONE);
        Exports.Checked checked = Exports.check(wrapped, Progress.NONE);
        assertFalse(checked.holds(), "setup: its paper collides: " + checked.lines());
        List<String> lines = checked.lines();
        assertTrue(lines.get(lines.size() - 2).startsWith("failed: collisions"), lines.toString());
        assertTrue(lines.get(lines.size() - 1).endsWith("its paper crosses itself; it is a grid polyhedron, which the hinge strip"
                + " wraps in two layers (Method: Hinge strip)"), lines.toString());
    }

    /**
     * The window's model draws nothing itself: where nothing can draw, an export fails in the
     * renderer's one line and takes back the folder it made, with no display needed to test it.
     */
    @Test
    void anExportWhereNothingCanDrawFailsInOneLineAndLeavesNothing() throws Exception {
        Plan zigzag = Planning.plan(Job.ZigZag.DEMO, Progress.NONE);
        Renderer none = new Renderer() {
            @Override
            public Rendered frames(ifold.scene.Scene scene, ifold.scene.Animation animation, ifold.image.FrameSink sink, int width,
                    int height, int frames, boolean captions, ifold.image.FrameSink.Progress progress) throws Unavailable {
                throw new Unavailable("no X display: run under xvfb-run", null);
            }

            @Override
            public void panel(ifold.scene.Scene scene, ifold.scene.Animation animation, double[] positions, java.util.List<String> labels,
                    int columns, int width, int height, int samples, Path file) throws Unavailable {
                throw new Unavailable("no X display: run under xvfb-run", null);
            }
        };
        Path folder = dir.resolve("frames");
        JobFailure frames = org.junit.jupiter.api.Assertions.assertThrows(JobFailure.class,
                () -> Exports.frames(none, zigzag, folder, new Exports.FrameSettings(320, 180, 2, 1, true), Progress.NONE));
        assertEquals("no X display: run under xvfb-run", frames.getMessage());
        assertTrue(!java.nio.file.Files.exists(folder), "the folder it made is taken back");
        Path figure = dir.resolve("figure.png");
        JobFailure panel = org.junit.jupiter.api.Assertions.assertThrows(JobFailure.class,
                () -> Exports.figure(none, zigzag, figure, Progress.NONE));
        assertEquals("no X display: run under xvfb-run", panel.getMessage());
        assertTrue(!java.nio.file.Files.exists(figure));
    }
}
