package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.image.FrameWriter;
import ifold.image.Mp4Writer;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;
import javax.imageio.ImageReader;
import javax.imageio.stream.ImageInputStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.junit.jupiter.api.io.TempDir;

/** Movies and captions from the command line, checked by their pixels and frames. */
class MovieTest {
    @TempDir
    Path dir;

    /** The demos' background. */
    private static final int BACKGROUND = 0xD3DAE2;

    private static void assumeDisplay() {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
    }

    private static BufferedImage frame(Path folder, int index) throws Exception {
        return ImageIO.read(folder.resolve(FrameWriter.frameName(index)).toFile());
    }

    @Test
    void aGifOfTheDemoLoopsWithOneFrameAPeriod() throws Exception {
        assumeDisplay();
        Path gif = dir.resolve("zigzag.gif");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--movie", gif.toString(), "--size", "160x90", "--fps", "5", "--seconds", "3");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("wrote " + gif + ": 15 frames of 160x90 at 5 frames/s (3.0 s)"), run.out());
        try (ImageInputStream in = ImageIO.createImageInputStream(gif.toFile())) {
            ImageReader reader = ImageIO.getImageReadersByFormatName("gif").next();
            reader.setInput(in);
            assertEquals(15, reader.getNumImages(true));
        }
    }

    @Test
    void anMp4OfTheTurnDemoHasItsFrames() throws Exception {
        assumeDisplay();
        assumeTrue(Mp4Writer.available(), "no ffmpeg here (scripts/setup installs it)");
        Path mp4 = dir.resolve("turn.mp4");
        CliTest.Run run = CliTest.run("demo", "turn", "--angle", "60", "--movie", mp4.toString(), "--size", "160x90", "--fps", "10",
                "--seconds", "2");
        assertEquals(0, run.code(), run.err());
        assertTrue(Files.size(mp4) > 0);
        assertTrue(run.out().contains("20 frames of 160x90 at 10 frames/s"), run.out());
    }

    @Test
    void everyFrameKeepsItsBorderClearAndCarriesACaptionUnlessToldNot() throws Exception {
        assumeDisplay();
        Path with = dir.resolve("with");
        Path without = dir.resolve("without");
        int frames = 60;
        assertEquals(0, CliTest.run("demo", "zigzag", "--frames", with.toString(), "--size", "320x180", "--fps", "2").code());
        assertEquals(0, CliTest.run("demo", "zigzag", "--frames", without.toString(), "--size", "320x180", "--fps", "2",
                "--no-captions").code());
        int band = ifold.render.FrameExport.captionBand(320, 180);
        BufferedImage previous = null;
        for (int i = 0; i < frames; i++) {
            BufferedImage plain = frame(without, i);
            // The paper and the triangle stay inside the picture: its border is background.
            for (int x = 0; x < 320; x++) {
                assertEquals(BACKGROUND, plain.getRGB(x, 0) & 0xFFFFFF, "frame " + i + ": top border at x = " + x);
                assertEquals(BACKGROUND, plain.getRGB(x, 179) & 0xFFFFFF, "frame " + i + ": bottom border at x = " + x);
            }
            for (int y = 0; y < 180; y++) {
                assertEquals(BACKGROUND, plain.getRGB(0, y) & 0xFFFFFF, "frame " + i + ": left border at y = " + y);
                assertEquals(BACKGROUND, plain.getRGB(319, y) & 0xFFFFFF, "frame " + i + ": right border at y = " + y);
            }
            // The caption band differs from the background where there is a caption.
            BufferedImage captioned = frame(with, i);
            int differing = 0;
            for (int y = 180 - band; y < 180; y++) {
                for (int x = 0; x < 320; x++) {
                    differing += (captioned.getRGB(x, y) & 0xFFFFFF) != (plain.getRGB(x, y) & 0xFFFFFF) ? 1 : 0;
                }
            }
            assertTrue(differing > 320 * band / 2, "frame " + i + " has a caption: " + differing + " pixels differ");
            // Something moves in every frame.
            if (previous != null) {
                assertFalse(same(previous, plain), "frame " + i + " is the same as the one before");
            }
            previous = plain;
        }
    }

    private static boolean same(BufferedImage a, BufferedImage b) {
        for (int y = 0; y < a.getHeight(); y++) {
            for (int x = 0; x < a.getWidth(); x++) {
                if (a.getRGB(x, y) != b.getRGB(x, y)) {
                    return false;
                }
            }
        }
        return true;
    }

    @Test
    void theWrapAndThePathKeepTheirModelInsideThePicture() throws Exception {
        assumeDisplay();
        Path wrap = dir.resolve("wrap");
        Path path = dir.resolve("path");
        assertEquals(0, CliTest.run("wrap", "models/cube.off", "--frames", wrap.toString(), "--size", "320x180", "--fps", "1",
                "--seconds", "40", "--no-captions").code());
        assertEquals(0, CliTest.run("view", "models/torus.off", "--path", "--frames", path.toString(), "--size", "320x180", "--fps",
                "2", "--seconds", "10", "--no-captions").code());
        for (Path folder : new Path[] {wrap, path}) {
            try (var files = Files.list(folder)) {
                int count = (int) files.count();
                BufferedImage first = frame(folder, 0);
                int background = first.getRGB(0, 0) & 0xFFFFFF;
                for (int i = 0; i < count; i++) {
                    // While it folds, the wrap's camera comes close to the triangle being wrapped
                    // (WrapViewTest); the whole model is seen as it begins and in the final turn.
                    if (folder == wrap && i > 0 && i < 0.8 * count) {
                        continue;
                    }
                    BufferedImage image = frame(folder, i);
                    for (int x = 0; x < 320; x++) {
                        assertEquals(background, image.getRGB(x, 0) & 0xFFFFFF, folder.getFileName() + " frame " + i + ", top, x = " + x);
                        assertEquals(background, image.getRGB(x, 179) & 0xFFFFFF, folder.getFileName() + " frame " + i + ", bottom, x = " + x);
                    }
                    for (int y = 0; y < 180; y++) {
                        assertEquals(background, image.getRGB(0, y) & 0xFFFFFF, folder.getFileName() + " frame " + i + ", left, y = " + y);
                        assertEquals(background, image.getRGB(319, y) & 0xFFFFFF, folder.getFileName() + " frame " + i + ", right, y = " + y);
                    }
                }
            }
        }
    }

    @Test
    void badMovieOptionsGetOneLineAndWriteNothing() throws Exception {
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--movie", dir.resolve("z.avi").toString()), "--movie", ".mp4 or .gif");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--movie", dir.resolve("z.gif").toString(), "--fps", "60"), "--fps", "GIF");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--movie", dir.resolve("no/z.gif").toString()), "--movie", "does not exist");
        if (Mp4Writer.available()) {
            CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--movie", dir.resolve("z.mp4").toString(), "--size", "641x360"),
                    "--size", "even");
        }
        try (var files = Files.list(dir)) {
            assertEquals(0, files.count(), "nothing written");
        }
    }

    @Test
    void aGifIsSizedForTheWebUnlessToldOtherwise() throws Exception {
        assumeDisplay();
        Path gif = dir.resolve("web.gif");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--movie", gif.toString(), "--seconds", "1");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("wrote " + gif + ": 12 frames of 640x360 at 12 frames/s"), run.out());
        // Either given, it is kept; the other keeps the GIF's default.
        Path sized = dir.resolve("sized.gif");
        run = CliTest.run("demo", "zigzag", "--movie", sized.toString(), "--seconds", "1", "--size", "320x180");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("12 frames of 320x180 at 12 frames/s"), run.out());
        Path fast = dir.resolve("fast.gif");
        run = CliTest.run("demo", "zigzag", "--movie", fast.toString(), "--seconds", "1", "--fps", "20");
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("20 frames of 640x360 at 20 frames/s"), run.out());
    }

    /** Without a display the demo, and view (which wrote 300 PNGs into view-frames/), write one movie and say where. */
    @ParameterizedTest
    @ValueSource(strings = {"demo zigzag", "view"})
    void withoutADisplayACommandWritesOneMovieAndSaysWhere(String command) throws Exception {
        assumeTrue(Mp4Writer.available(), "no ffmpeg here (scripts/setup installs it)");
        assumeTrue(new ProcessBuilder("sh", "-c", "command -v Xvfb").start().waitFor() == 0, "no Xvfb here");
        Path launcher = Path.of("build", "install", "ifold", "bin", "ifold").toAbsolutePath();
        assumeTrue(Files.isExecutable(launcher), "not installed (gradle installDist)");
        Path log = dir.resolve("log");
        java.util.List<String> args = new java.util.ArrayList<>(java.util.List.of(launcher.toString()));
        args.addAll(java.util.List.of(command.split(" ")));
        String name = command.equals("view") ? "view" : "zigzag";
        if (name.equals("view")) {
            args.add(Path.of("models", "cube.off").toAbsolutePath().toString());
        }
        args.addAll(java.util.List.of("--seconds", "1", "--size", "160x90"));
        Process process = withoutDisplay(args, log, 120);
        String output = Files.readString(log);
        assertEquals(0, process.exitValue(), output);
        Path movie = dir.resolve(name + ".mp4");
        assertTrue(Files.size(movie) > 0, output);
        assertFalse(Files.exists(dir.resolve(name + "-frames")), "no folder of PNGs");
        assertTrue(output.contains("no display: rendering the animation into " + movie.toRealPath()), output);
        assertTrue(output.contains("--frames DIR for PNG frames"), "and how to get frames instead: " + output);
        assertTrue(output.contains("wrote " + name + ".mp4: 30 frames of 160x90"), output);
    }

    /** A model or script that is not there is said first, and alone: no movie is announced for it. */
    @ParameterizedTest
    @ValueSource(strings = {"wrap", "fold"})
    void withoutADisplayAMissingInputIsOneLineAndNoMovie(String command) throws Exception {
        Path launcher = Path.of("build", "install", "ifold", "bin", "ifold").toAbsolutePath();
        assumeTrue(Files.isExecutable(launcher), "not installed (gradle installDist)");
        Path log = dir.resolve("log");
        Process process = withoutDisplay(java.util.List.of(launcher.toString(), command, "missing.off"), log, 60);
        String output = Files.readString(log);
        assertEquals(1, process.exitValue(), output);
        assertEquals("ifold: missing.off: no such file", output.strip(), "one line, and no movie announced");
        assertFalse(Files.exists(dir.resolve(command + ".mp4")) || Files.exists(dir.resolve(command + ".gif")), "no movie");
    }

    /** Runs {@code args} in the test's folder with no display, its output and errors into {@code log}; ended within {@code seconds}. */
    private Process withoutDisplay(java.util.List<String> args, Path log, int seconds) throws Exception {
        ProcessBuilder builder = new ProcessBuilder(args).directory(dir.toFile()).redirectErrorStream(true).redirectOutput(log.toFile());
        builder.environment().remove("DISPLAY");
        builder.environment().remove("IFOLD_IN_XVFB");
        Process process = builder.start();
        assertTrue(process.waitFor(seconds, java.util.concurrent.TimeUnit.SECONDS), "it ends");
        return process;
    }

    @Test
    void framesCarryALegendOfTheColoursAndTheCornersNamesUnlessToldNot() throws Exception {
        assumeDisplay();
        Path with = dir.resolve("legend");
        Path without = dir.resolve("plain");
        assertEquals(0, CliTest.run("demo", "zigzag", "--frames", with.toString(), "--size", "640x360", "--fps", "1", "--seconds", "3").code());
        assertEquals(0, CliTest.run("demo", "zigzag", "--frames", without.toString(), "--size", "640x360", "--fps", "1", "--seconds", "3",
                "--no-captions").code());
        int band = ifold.render.FrameExport.captionBand(640, 360);
        BufferedImage captioned = frame(with, 0);
        BufferedImage plain = frame(without, 0);
        // The legend, top right: each colour's swatch as it is drawn, on nothing but background without it.
        java.util.Set<Integer> legend = new java.util.HashSet<>();
        for (int y = 0; y < 90; y++) {
            for (int x = 400; x < 640; x++) {
                legend.add(captioned.getRGB(x, y) & 0xFFFFFF);
                assertEquals(BACKGROUND, plain.getRGB(x, y) & 0xFFFFFF, "nothing in the corner without captions, at " + x + ", " + y);
            }
        }
        for (int color : new int[] {ifold.scene.PaperView.PAPER, ifold.scene.WrapView.PAPER.back(), ifold.scene.WrapView.MODEL}) {
            assertTrue(legend.contains(color & 0xFFFFFF), String.format("the swatch %06x in the legend", color & 0xFFFFFF));
        }
        // The corners' letters: pixels written over the picture outside the caption's band and the legend's corner.
        int written = 0;
        for (int y = 0; y < 360 - band; y++) {
            for (int x = 0; x < 640; x++) {
                if (!(x >= 400 && y < 90) && captioned.getRGB(x, y) != plain.getRGB(x, y)) {
                    written++;
                }
            }
        }
        assertTrue(written > 3 * 100, "three letters A, B, C: " + written + " pixels");
    }

    @Test
    void theCubesWrapAsAGifFitsAWebPage() throws Exception {
        assumeDisplay();
        Path gif = dir.resolve("cube.gif");
        CliTest.Run run = CliTest.run("wrap", "models/cube.off", "--movie", gif.toString());
        assertEquals(0, run.code(), run.err());
        assertTrue(run.out().contains("1440 frames of 640x360 at 12 frames/s (120.0 s)"), run.out());
        assertTrue(Files.size(gif) <= 8_000_000, "at most 8 MB: " + Files.size(gif) + " bytes (30.4 MB at 1280x720 and 30 frames/s)");
    }
}
