package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.image.Mp4Writer;
import ifold.job.Scenes;
import ifold.scene.PathView;
import ifold.ui.model.Exports;
import ifold.ui.model.Job;
import ifold.ui.model.Settings;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.stream.Stream;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The real window with models and files: a model opened, wrapped, viewed, described, refined,
 * made new; scripts and FOLD files opened; movies, OBJ, FOLD and reports exported as the command
 * line writes them; settings kept between runs; the event thread never held. Skipped without a
 * display.
 */
@Timeout(180)
class MainWindowFilesTest extends WindowTestBase {
    @Test
    void aModelOpensThroughTheMenuAndIsWrapped() throws Exception {
        Settings settings = settings();
        // The coarse torus of 6 x 6 (`ifold generate torus --around 6 --across 6`): its flat rings
        // cut into hosts, where the walls of folds along the cuts stand on each other in one plane
        // (3,520 pairs), and bends by its inner equator cross (126). The L of three cubes showed
        // its pairs here until its top was cut into two rectangles, whose walls the view sees edge
        // on; the plus of five cubes until folds nested along its cuts stood back from them (1,636
        // pairs, 381 left, none in view); figure3's the view sees edge on.
        Path torus = dir.resolve("torus6.off");
        ifold.job.GenerateJob.run(new ifold.job.GenerateJob.Request(ifold.job.BuiltInModels.Shape.torus, 6, 6, 3, torus, false),
                ifold.job.JobWatcher.NONE);
        settings.addRecent(torus);
        settings.addRecent(Path.of("models", "cube.off"));
        window = App.open(null, settings);
        settled();
        onEdt(() -> {
            menuItem(window, "1  cube.off").doClick();
            return null;
        });
        waitFor("the cube wrapped", 60, () -> window.plan() != null && window.plan().job() instanceof Job.WrapModel && !window.isWorking());
        BufferedImage picture = settled();
        assertEquals("12", onEdt(() -> window.report.value("inputTriangles")));
        assertEquals("wrap", onEdt(() -> window.parameters.card()));
        assertTrue(onEdt(() -> window.getTitle()).contains("cube.off"));
        assertTrue(pixelsOf(picture, 0xD3DAE2, 3) > 1000, "the wrap on the demos' grey-blue background, where white paper stands out");
        onEdt(() -> {
            window.timeline.seek(0);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage plain = window.view.picture();
        onEdt(() -> {
            menuItem(window, "Path of triangles").doClick();
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage path = window.view.picture();
        // The cube's wrap runs along its own 12 triangles (the seam's choice: 9 layers, not 13),
        // so its path has no tree edges: the curve through its triangles, in red.
        assertTrue(pixelsOf(path, PathView.PATH_CURVE & 0xFFFFFF, 60) > 50 && pixelsOf(plain, PathView.PATH_CURVE & 0xFFFFFF, 60) < 10,
                "the path's curve in red, where the plain model has none");
        // View > Collisions: the faces of paper that cross, in red, seen through the paper. The
        // cube's paper crosses nothing; the torus's walls along its cuts overlap.
        onEdt(() -> {
            menuItem(window, "2  torus6.off").doClick();
            return null;
        });
        waitFor("the torus wrapped", 60, () -> window.plan() != null && !window.isWorking()
                && window.getTitle().contains("torus6.off"));
        settled();
        onEdt(() -> {
            window.timeline.seek(Double.MAX_VALUE); // the whole wrap, its cuts covered
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        onEdt(() -> {
            menuItem(window, "Collisions").doClick();
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        int red = pixelsOf(window.view.picture(), 0xE0262B, 40);
        onEdt(() -> {
            menuItem(window, "Collisions").doClick();
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        int without = pixelsOf(window.view.picture(), 0xE0262B, 40);
        assertTrue(red > without + 5, "red where paper collides (along the cuts): " + red + " pixels, " + without + " without");
        onEdt(() -> {
            // Under the default (0.0623, a third of the widest 0.1869): a wider strip is refused.
            window.parameters.wrapWidth.setText("0.05");
            return null;
        });
        waitFor("the narrower wrap", 60, () -> "0.05".equals(window.report.value("width")));
        // Another model starts from its own width, not the one typed for the cube.
        onEdt(() -> {
            window.open(Path.of("models", "tetrahedron.off"));
            return null;
        });
        waitFor("the tetrahedron wrapped", 60, () -> window.plan() != null && window.plan().job() instanceof Job.WrapModel w
                && w.model().endsWith("tetrahedron.off") && !window.isWorking());
        assertEquals("", onEdt(() -> window.parameters.wrapWidth.getText()));
        assertTrue(!"0.05".equals(onEdt(() -> window.report.value("width"))), "the tetrahedron's own width");
    }

    /**
     * A FOLD file that fails to open changes nothing but the error shown: before, the panel named
     * the new file with its error while the view, the report and the folds showed the last job,
     * and the file went into the recent files. One that opens then plays and is recent.
     */
    @Test
    void aFoldFileThatFailsToOpenChangesNothingButTheErrorShown() throws Exception {
        Settings settings = settings();
        window = App.open(null, settings);
        settled();
        Object before = onEdt(() -> window.plan());
        String card = onEdt(() -> window.parameters.card());
        String title = onEdt(() -> window.getTitle());
        Path bad = dir.resolve("bad.fold");
        Files.writeString(bad, "{\"file_spec\": 1.1, \"vertices_coords\": [[0, 0], [1, 0], [1, 1]], \"edges_vertices\": [[0]],"
                + " \"faces_vertices\": [[0, 1, 2]]}");
        List<String> said = new CopyOnWriteArrayList<>();
        onEdt(() -> {
            window.messages = said::add;
            window.open(bad);
            return null;
        });
        waitFor("the open refused", 60, () -> !window.isWorking() && said.stream().anyMatch(m -> m.startsWith("cannot open bad.fold: ")));
        assertTrue(before == onEdt(() -> window.plan()), "the plan shown is the one before");
        assertEquals(card, onEdt(() -> window.parameters.card()));
        assertEquals(title, onEdt(() -> window.getTitle()));
        assertFalse(settings.recent().contains(bad), "a file that failed is not recent: " + settings.recent());
        Path good = dir.resolve("good.fold");
        Files.writeString(good, "paper square 10\nfold valley 180 points 5 0 0 5 1 0 right\n");
        onEdt(() -> {
            window.open(good);
            return null;
        });
        waitFor("the script played", 60, () -> !window.isWorking() && window.plan() != null && window.plan().job() instanceof Job.Script);
        assertEquals("script", onEdt(() -> window.parameters.card()));
        assertTrue(settings.recent().contains(good), "recent once it plays: " + settings.recent());
    }

    /**
     * A model file that cannot be read is refused at its field and is not left among the recent
     * files (it went to the top of Open recent); one that can is recent.
     */
    @Test
    void aModelThatCannotBeReadIsNotLeftRecent() throws Exception {
        Settings settings = settings();
        window = App.open(null, settings);
        settled();
        Path garbage = dir.resolve("garbage.off");
        Files.writeString(garbage, "OFF\n3 1 0\n0 0 0\nzz 1 0\n0 1 0\n3 0 1 2\n");
        onEdt(() -> {
            window.open(garbage);
            return null;
        });
        waitFor("the model refused", 60, () -> !window.isWorking() && window.parameters.isMarked("model"));
        assertTrue(onEdt(() -> window.parameters.note("model")).contains("garbage.off:4"), "refused at its field, naming the line");
        assertFalse(settings.recent().contains(garbage.toAbsolutePath().normalize()), "not recent: " + settings.recent());
        onEdt(() -> {
            window.open(Path.of("models", "cube.off"));
            return null;
        });
        waitFor("the cube wrapped", 60, () -> !window.isWorking() && window.plan() != null && window.plan().job() instanceof Job.WrapModel);
        assertTrue(settings.recent().contains(Path.of("models", "cube.off").toAbsolutePath().normalize()), settings.recent().toString());
    }

    /** The progress bar is as high as its text ("1234 / 6398"): it was a few pixels high, the text cut in half. */
    @Test
    void theProgressBarHoldsItsText() throws Exception {
        window = App.open(null, settings());
        settled();
        int text = onEdt(() -> window.progress.getFontMetrics(window.progress.getFont()).getAscent()
                + window.progress.getFontMetrics(window.progress.getFont()).getDescent());
        int bar = onEdt(() -> window.progress.getPreferredSize().height);
        assertTrue(bar >= text, "the bar is " + bar + " px high for text " + text + " px high");
    }

    /**
     * A model whose wrap is refused is drawn anyway, with the refusal at its field: before, the
     * view stayed on what it showed before (or grey), and the model was never drawn.
     */
    @Test
    void aModelWhoseWrapIsRefusedIsDrawnAnyway() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.parameters.show(new Job.WrapModel(Path.of("models", "cube.off"), "0.8", "")); // wider than either path's widest
            return null;
        });
        waitFor("the cube drawn", 60, () -> !window.isWorking() && window.plan() != null && window.plan().job() instanceof Job.View v
                && v.model().endsWith("cube.off"));
        assertTrue(window.view.awaitFrame(30_000), "the view drew the cube");
        assertEquals("wrap", onEdt(() -> window.parameters.card()), "the wrap's card stays, for another width");
        assertTrue(onEdt(() -> window.parameters.isMarked("width")), "the refused width is marked");
        assertTrue(onEdt(() -> window.message.getText()).contains("too wide"), onEdt(() -> window.message.getText()));
        assertTrue(onEdt(() -> window.getTitle()).contains("cube.off (not wrapped)"), onEdt(() -> window.getTitle()));
        assertEquals("6", onEdt(() -> window.report.value("faces")), "the model's report, as the view gives it: its six squares");
    }

    @Test
    void aMovieIsExportedAndACancelledOneLeavesNothing() throws Exception {
        window = App.open(null, settings());
        settled();
        List<String> said = new CopyOnWriteArrayList<>();
        onEdt(() -> {
            window.messages = said::add;
            return null;
        });
        Path gif = dir.resolve("zigzag.gif");
        onEdt(() -> {
            window.exports.movie(gif, new Exports.FrameSettings(160, 90, 10, 1, true));
            return null;
        });
        waitFor("the GIF", 60, () -> !window.isWorking());
        assertTrue(window.awaitExport(10_000));
        assertTrue(Files.isRegularFile(gif), "written: " + said);
        byte[] head = Files.readAllBytes(gif);
        assertEquals("GIF89a", new String(head, 0, 6, java.nio.charset.StandardCharsets.US_ASCII));
        assertTrue(said.stream().anyMatch(s -> s.startsWith("wrote " + gif)), said.toString());

        if (Mp4Writer.available()) {
            Path mp4 = dir.resolve("zigzag.mp4");
            onEdt(() -> {
                window.exports.movie(mp4, new Exports.FrameSettings(320, 180, 10, 1, true));
                return null;
            });
            waitFor("the MP4", 60, () -> !window.isWorking());
            assertTrue(Files.size(mp4) > 1000, "an MP4 with frames in it");
        }

        Path cancelled = dir.resolve("cancelled.gif");
        onEdt(() -> {
            window.exports.movie(cancelled, new Exports.FrameSettings(640, 360, 30, 60, true));
            return null;
        });
        waitFor("the export under way", 60, () -> window.progress.isVisible() && !window.progress.isIndeterminate());
        onEdt(() -> {
            window.cancel.doClick();
            return null;
        });
        assertTrue(window.awaitExport(60_000), "the export stopped");
        assertFalse(onEdt(() -> window.isWorking()));
        try (Stream<Path> files = Files.list(dir)) {
            List<String> names = files.map(p -> p.getFileName().toString()).filter(n -> n.contains("cancelled")).toList();
            assertEquals(List.of(), names, "a cancelled export leaves no file, whole or temporary");
        }
        assertTrue(said.stream().anyMatch(s -> s.contains("cancelled")), said.toString());
    }

    @Test
    void objFoldAndReportAreWrittenAsTheCommandLineWritesThem() throws Exception {
        window = App.open(null, settings());
        settled();
        Path obj = dir.resolve("zigzag.obj");
        Path fold = dir.resolve("zigzag.fold");
        Path json = dir.resolve("zigzag.json");
        for (Runnable export : List.<Runnable>of(() -> window.exports.obj(obj), () -> window.exports.fold(fold), () -> window.exports.report(json))) {
            onEdt(() -> {
                export.run();
                return null;
            });
            waitFor("the export", 60, () -> !window.isWorking());
        }
        Path cliObj = dir.resolve("cli.obj");
        Path cliFold = dir.resolve("cli.fold");
        Path cliJson = dir.resolve("cli.json");
        cli("demo", "zigzag", "--no-view", "--export-obj", cliObj.toString(), "--report", cliJson.toString());
        cli("demo", "zigzag", "--no-view", "--export-fold", cliFold.toString());
        assertEquals(Files.readString(cliObj), Files.readString(obj), "the OBJ is the command line's");
        assertEquals(Files.readString(cliFold), Files.readString(fold), "the FOLD file is the command line's");
        assertEquals(Files.readString(cliJson), Files.readString(json), "the report is the command line's");
        Path figure = dir.resolve("figure11.png");
        onEdt(() -> {
            window.exports.figure(figure);
            return null;
        });
        waitFor("the figure", 60, () -> !window.isWorking());
        BufferedImage panel = javax.imageio.ImageIO.read(figure.toFile());
        assertEquals(2 * 800 + 2, panel.getWidth(), "two stages a row, as --figure draws them");
        assertEquals(2 * 500 + 2, panel.getHeight());
        // The crease pattern and the step diagrams, printed as the command line prints them.
        Path svg = dir.resolve("zigzag.svg");
        Path steps = dir.resolve("steps.pdf");
        List<String> said = new java.util.concurrent.CopyOnWriteArrayList<>();
        window.messages = said::add;
        onEdt(() -> {
            window.exports.creasePattern(svg, new ifold.print.CreasePatternPages.Options(20, ifold.print.Page.A4));
            return null;
        });
        waitFor("the crease pattern", 60, () -> !window.isWorking());
        onEdt(() -> {
            window.exports.diagrams(steps);
            return null;
        });
        waitFor("the step diagrams", 60, () -> !window.isWorking());
        assertTrue(Files.readString(svg).contains("piece 1 of 4; glue piece 2 on its tab at mark A"), "the strip's four pieces");
        assertTrue(said.stream().anyMatch(m -> m.contains("wrote " + svg + ": 1 page, 4 pieces")), said.toString());
        assertTrue(said.stream().anyMatch(m -> m.contains("wrote " + steps + ": 4 pages, 12 steps")), said.toString());

        // The same through the menu and its dialog, as a user prints: 3 cm wide on an A4 on its side.
        Path landscape = dir.resolve("landscape.pdf");
        clickLater(window, "Export crease pattern (PDF, SVG)...");
        javax.swing.JTextField width = inDialog(javax.swing.JTextField.class);
        javax.swing.JComboBox<?> page = inDialog(javax.swing.JComboBox.class);
        assertEquals("auto", onEdt(width::getText), "the width the printer chooses, unless told");
        onEdt(() -> {
            width.setText("3cm");
            page.setSelectedItem("a4-landscape");
            return null;
        });
        pressOk(width);
        saveAs(landscape);
        waitFor("the crease pattern from the dialog", 60, () -> said.stream().anyMatch(m -> m.contains("wrote " + landscape)));
        // 48.4 by 1.6 at 18.75 mm a unit is 907.5 mm: four pieces of 265 mm, three rows of 3 cm to a page.
        assertTrue(said.stream().anyMatch(m -> m.contains("wrote " + landscape + ": 2 pages, 4 pieces")), said.toString());
        try (org.apache.pdfbox.pdmodel.PDDocument pdf = org.apache.pdfbox.Loader.loadPDF(landscape.toFile())) {
            assertEquals(297, pdf.getPage(0).getMediaBox().getWidth() * 25.4 / 72, 0.01, "A4 on its side");
            String text = new org.apache.pdfbox.text.PDFTextStripper().getText(pdf);
            assertTrue(text.contains("the strip 3 cm wide"), text);
        }
        // And the step diagrams through theirs: where to write them, nothing else asked.
        Path menuSteps = dir.resolve("menu-steps.pdf");
        clickLater(window, "Export step diagrams (PDF)...");
        saveAs(menuSteps);
        waitFor("the step diagrams from the menu", 60, () -> said.stream().anyMatch(m -> m.contains("wrote " + menuSteps)));
        assertTrue(said.stream().anyMatch(m -> m.contains("wrote " + menuSteps + ": 4 pages, 12 steps")), said.toString());
    }

    /**
     * Fold, Check the wrap checks the wrap shown as {@code ifold check} does and shows its lines;
     * the zig-zag demo, which wraps no model, has nothing to check and says so.
     */
    @Test
    void theWrapShownIsCheckedThroughTheMenu() throws Exception {
        Settings settings = settings();
        settings.addRecent(Path.of("models", "tetrahedron.off"));
        window = App.open(null, settings);
        settled();
        List<String> said = new java.util.concurrent.CopyOnWriteArrayList<>();
        window.messages = said::add;
        onEdt(() -> {
            menuItem(window, "Check the wrap").doClick();
            return null;
        });
        assertTrue(said.stream().anyMatch(m -> m.contains("only a wrap of a model is checked")), said.toString());
        onEdt(() -> {
            menuItem(window, "1  tetrahedron.off").doClick();
            return null;
        });
        waitFor("the tetrahedron wrapped", 60, () -> window.plan() != null && window.plan().job() instanceof Job.WrapModel && !window.isWorking());
        clickLater(window, "Check the wrap");
        javax.swing.JTextArea lines = inDialog(javax.swing.JTextArea.class);
        String text = onEdt(lines::getText);
        assertTrue(text.startsWith("tetrahedron.off: 1 strip, "), text);
        assertTrue(text.contains("\ntruths: every one holds (tiled, isometric, not torn, covered, on surface)\n"), text);
        assertTrue(text.contains("\ncollisions: 0 crossing pairs"), text);
        assertTrue(text.contains("\nlayer order: valid"), text);
        assertTrue(said.stream().anyMatch(m -> m.startsWith("every check holds; truths: every one holds")), said.toString());
        pressOk(lines);
    }

    /** The pings below would see a held event thread: one held for 0.6 s keeps a ping waiting that long, whatever the load. */
    @Test
    void aPingWaitsWhileTheEventThreadIsHeld() throws Exception {
        SwingUtilities.invokeLater(() -> {
            try {
                Thread.sleep(600);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        long waited = pingNanos();
        assertTrue(waited > 400_000_000L, "a ping waited " + waited / 1e6 + " ms while the event thread was held for 600");
    }

    @Test
    void theEventThreadIsNeverHeldWhileAModelIsWrapped() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.open(Path.of("models", "torus.off"));
            return null;
        });
        long start = System.nanoTime();
        long worst = 0;
        int pings = 0;
        while ((pings < 3 || onEdt(() -> window.isWorking())) && pings < 3000) {
            worst = Math.max(worst, pingNanos());
            pings++;
            Thread.sleep(10);
        }
        long took = System.nanoTime() - start;
        assertTrue(onEdt(() -> window.plan().job() instanceof Job.WrapModel), "the torus was wrapped");
        assertAnswered(worst, took, pings);
    }

    @Test
    void theEventThreadIsNeverHeldWhileAnExportRuns() throws Exception {
        window = App.open(null, settings());
        settled();
        Path gif = dir.resolve("busy.gif");
        onEdt(() -> {
            window.exports.movie(gif, new Exports.FrameSettings(960, 540, 20, 8, true));
            return null;
        });
        long start = System.nanoTime();
        long worst = 0;
        int pings = 0;
        while (onEdt(() -> window.isWorking()) && pings < 2000) {
            worst = Math.max(worst, pingNanos());
            pings++;
            Thread.sleep(10);
        }
        assertAnswered(worst, System.nanoTime() - start, pings);
        assertTrue(Files.isRegularFile(gif));
    }

    @Test
    void settingsAreRememberedBetweenRuns() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.parameters.zigzagWidth.setText("1.2");
            window.setSize(1000, 700);
            return null;
        });
        waitFor("the new plan", 60, () -> "1.2".equals(window.report.value("stripWidth")));
        onEdt(() -> {
            window.dispose();
            return null;
        });
        window = App.open(null, settings());
        assertEquals("1.2", onEdt(() -> window.parameters.zigzagWidth.getText()));
        assertEquals(1000, (int) onEdt(() -> window.getWidth()));
        settled();
        assertEquals("1.2", onEdt(() -> window.report.value("stripWidth")));
    }

    @Test
    void aModelIsViewedThroughTheMenuItsPathScrubbedAndExported() throws Exception {
        window = App.open(null, settings());
        settled();
        clickLater(window, "View a model");
        saveAs(Path.of("models", "icosahedron.off").toAbsolutePath()); // no model open yet: the chooser asks for one
        waitFor("the icosahedron viewed", 60, () -> window.plan() != null && window.plan().job() instanceof Job.View && !window.isWorking());
        assertEquals("view", onEdt(() -> window.parameters.card()));
        onEdt(() -> {
            window.parameters.viewShow.setSelectedItem("Model");
            return null;
        });
        waitFor("the model itself", 60, () -> window.plan().job() instanceof Job.View v && v.show() == Scenes.Show.MODEL && !window.isWorking());
        assertEquals("20", onEdt(() -> window.report.value("faces")));
        assertFalse(onEdt(() -> window.parameters.viewColours.isEnabled()), "colours are the path's only");
        onEdt(() -> {
            window.parameters.viewShow.setSelectedItem("Hamiltonian path");
            return null;
        });
        waitFor("the path", 60, () -> window.plan().job() instanceof Job.View v && v.show() == Scenes.Show.PATH && !window.isWorking());
        settled();
        assertEquals("98", onEdt(() -> window.report.value("outputTriangles")), "5 * 20 - 2 triangles, as ifold refine makes them");
        assertTrue(onEdt(() -> window.getTitle()).contains("icosahedron.off: 20 -> 98 triangles"), window.getTitle());
        assertEquals(10, (int) onEdt(() -> window.timeline.folds.getModel().getSize()), "the reveal in tenths");
        assertEquals("1. triangles 1-10 of 98  [path]", onEdt(() -> window.timeline.folds.getModel().getElementAt(0)));
        assertTrue(onEdt(() -> window.timeline.where.getText()).matches("step \\d+ of 10"), "a view has steps, not folds: "
                + onEdt(() -> window.timeline.where.getText()));

        onEdt(() -> {
            window.timeline.slider.setValue(TimelinePanel.TICKS / 10);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage early = window.view.picture();
        assertEquals("path: triangle 9 of 98", onEdt(() -> window.view.status()),
                "a tenth of the way: 9.8 triangles, 9 whole ones shown");
        onEdt(() -> {
            window.timeline.slider.setValue(TimelinePanel.TICKS);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage whole = window.view.picture();
        assertEquals(9, (int) onEdt(() -> window.timeline.timeline().currentFold()), "the last tenth at the end");
        assertTrue(differing(early, whole) > early.getWidth() * early.getHeight() / 50, "the path grew: "
                + differing(early, whole) + " pixels changed");
        assertTrue(pixelsOf(whole, PathView.TREE_EDGE, 50) > 50, "the tree edges in green");
        // Along the path the triangles darken to a deep blue-grey; those not yet shown are light grey.
        int darkEarly = pathEndPixels(early);
        int darkWhole = pathEndPixels(whole);
        assertTrue(darkEarly < 100 && darkWhole > 2000, "the path's dark end shown at the end only: " + darkEarly + " pixels early, "
                + darkWhole + " at the end");

        Path gif = dir.resolve("path.gif");
        onEdt(() -> {
            window.exports.movie(gif, new Exports.FrameSettings(160, 90, 10, 1, true));
            return null;
        });
        waitFor("the GIF", 60, () -> !window.isWorking());
        assertTrue(window.awaitExport(10_000));
        byte[] head = Files.readAllBytes(gif);
        assertEquals("GIF89a", new String(head, 0, 6, java.nio.charset.StandardCharsets.US_ASCII));
        assertTrue(onEdt(() -> window.message.getText()).startsWith("wrote " + gif + ": 10 frames"), window.message.getText());
        Path frames = dir.resolve("frames");
        onEdt(() -> {
            window.exports.frames(frames, new Exports.FrameSettings(320, 180, 4, 1, false));
            return null;
        });
        waitFor("the frames", 60, () -> !window.isWorking());
        assertTrue(window.awaitExport(10_000));
        BufferedImage first = javax.imageio.ImageIO.read(frames.resolve("frame_00000.png").toFile());
        BufferedImage last = javax.imageio.ImageIO.read(frames.resolve("frame_00003.png").toFile());
        assertTrue(pathEndPixels(last) > 10 * Math.max(1, pathEndPixels(first)), "the exported frames reveal the path too: "
                + pathEndPixels(first) + " dark pixels in the first, " + pathEndPixels(last) + " in the last");
    }

    @Test
    void modelInformationShowsWhatInfoPrintsForTheOpenModel() throws Exception {
        window = App.open(null, settings());
        settled();
        assertFalse(onEdt(() -> menuItem(window, "Model information").isEnabled()), "no model open yet: the item is off");
        assertFalse(onEdt(() -> menuItem(window, "Export refinement").isEnabled()));
        onEdt(() -> {
            window.open(Path.of("models", "cube.off"));
            return null;
        });
        settled();
        assertTrue(onEdt(() -> menuItem(window, "Model information").isEnabled()));
        clickLater(window, "Model information");
        waitFor("the model's information", 60, () -> window.informationDialog != null && window.informationDialog.isShowing());
        assertEquals("Model information: cube.off", onEdt(() -> window.informationDialog.getTitle()));
        CliRun info = cliRun("info", Path.of("models", "cube.off").toString());
        assertEquals(0, info.code(), info.err());
        for (String line : info.out().lines().toList()) {
            String key = line.substring(0, line.indexOf(": "));
            String value = line.substring(line.indexOf(": ") + 2);
            if (key.equals("faceSizes")) {
                assertEquals("6", onEdt(() -> window.information.value("faceSizes.4")), "the cube's six quads: " + value);
            } else if (!key.equals("repairs")) {
                assertEquals(value, onEdt(() -> window.information.value(key)), key + ", as ifold info prints it");
            }
        }
        assertEquals(null, onEdt(() -> window.information.value("repairs")), "none to make");
        // Esc closes it, as it closes the window's other dialogs.
        onEdt(() -> {
            javax.swing.JRootPane root = window.informationDialog.getRootPane();
            root.dispatchEvent(new java.awt.event.KeyEvent(root, java.awt.event.KeyEvent.KEY_PRESSED, System.currentTimeMillis(), 0,
                    java.awt.event.KeyEvent.VK_ESCAPE, java.awt.event.KeyEvent.CHAR_UNDEFINED));
            return null;
        });
        waitFor("Esc to close the model's information", 10, () -> !window.informationDialog.isShowing());
    }

    @Test
    void theRefinementIsExportedThroughTheMenuAsRefineWritesIt() throws Exception {
        window = App.open(Path.of("models", "icosahedron.off"), settings());
        settled();
        Path file = dir.resolve("refined.obj");
        clickLater(window, "Export refinement");
        javax.swing.JFileChooser chooser = inDialog(javax.swing.JFileChooser.class);
        assertEquals("icosahedron-export.off", onEdt(() -> chooser.getSelectedFile().getName()),
                "the model's name suggested, not its own file's");
        saveAs(file);
        waitFor("the refinement written", 60, () -> Files.isRegularFile(file) && !window.isWorking());
        Path cli = dir.resolve("cli.obj");
        CliRun refine = cliRun("refine", Path.of("models", "icosahedron.off").toString(), "-o", cli.toString());
        assertEquals(0, refine.code(), refine.err());
        assertEquals(Files.readString(cli), Files.readString(file), "the refinement is ifold refine's, byte for byte");
        assertTrue(onEdt(() -> window.message.getText()).startsWith("wrote " + file + ": 20 triangles"), window.message.getText());
    }

    @Test
    void aNewModelIsMadeThroughTheMenuRefusedAtItsFieldAndWrapped() throws Exception {
        window = App.open(null, settings());
        settled();
        clickLater(window, "New model");
        NewModelForm form = inDialog(NewModelForm.class);
        onEdt(() -> {
            form.shape.setSelectedItem(ifold.job.BuiltInModels.Shape.icosphere);
            form.subdivisions.setText("9");
            return null;
        });
        pressOk(form);
        CliRun tooFine = cliRun("generate", "icosphere", "--subdivisions", "9", "-o", dir.resolve("fine.off").toString());
        waitFor("the subdivisions refused", 30, () -> form.isShowing() && !form.note("subdivisions").startsWith("icosphere:"));
        assertEquals(tooFine.err().lines().findFirst().orElseThrow(), "ifold: option --subdivisions: " + onEdt(() -> form.note("subdivisions")),
                "the command line's message, at the field");
        onEdt(() -> {
            form.subdivisions.setText("1");
            return null;
        });
        pressOk(form);
        Path file = dir.resolve("sphere.off");
        saveAs(file);
        waitFor("the sphere wrapped", 60, () -> window.plan() != null && window.plan().job() instanceof Job.WrapModel w
                && w.model().equals(file) && !window.isWorking());
        assertEquals("80", onEdt(() -> window.report.value("inputTriangles")), "one subdivision: 80 triangles");
        Path cli = dir.resolve("cli.off");
        assertEquals(0, cliRun("generate", "icosphere", "--subdivisions", "1", "-o", cli.toString()).code());
        assertEquals(Files.readString(cli), Files.readString(file), "the model is ifold generate's, byte for byte");
    }

    @Test
    void strictModeRefusesADefectiveModelAtItsFieldAndIsRemembered() throws Exception {
        ifold.mesh.PolygonSoup soup = ifold.mesh.Solids.tetrahedron();
        soup.addTriangle(0, 1, 2); // a duplicate face
        Path model = dir.resolve("dup.off");
        ifold.mesh.io.MeshWriters.write(soup, model);
        window = App.open(model, settings());
        settled();
        assertEquals("4", onEdt(() -> window.report.value("inputTriangles")), "repaired: the duplicate dropped");
        onEdt(() -> {
            window.parameters.wrapStrict.doClick();
            return null;
        });
        waitFor("the model refused", 30, () -> window.parameters.isMarked("model"));
        String note = onEdt(() -> window.parameters.note("model"));
        assertTrue(note.contains("dup.off:11:") && note.contains("duplicates an earlier face") && note.endsWith("(clear Strict to repair it)"),
                note);
        onEdt(() -> {
            window.dispose();
            return null;
        });
        assertEquals("true", settings().get("wrap.strict", null), "remembered");
        window = App.open(null, settings());
        assertTrue(onEdt(() -> window.parameters.wrapStrict.isSelected()), "and set again");
    }

    @Test
    void theViewsStrictModeRefusesADefectiveModelAtItsFieldAndItsChoicesAreRemembered() throws Exception {
        ifold.mesh.PolygonSoup soup = ifold.mesh.Solids.tetrahedron();
        soup.addTriangle(0, 1, 2); // a duplicate face
        Path model = dir.resolve("dup.off");
        ifold.mesh.io.MeshWriters.write(soup, model);
        window = App.open(model, settings());
        settled();
        onEdt(() -> {
            menuItem(window, "View a model").doClick();
            return null;
        });
        waitFor("the open model viewed", 60, () -> window.plan() != null && window.plan().job() instanceof Job.View && !window.isWorking());
        assertEquals(model, ((Job.View) onEdt(() -> window.plan().job())).model(), "the wrap's model, without asking");
        assertEquals("4", onEdt(() -> window.report.value("inputTriangles")), "repaired: the duplicate dropped");
        onEdt(() -> {
            window.parameters.viewColours.setSelectedItem("rainbow");
            window.parameters.viewStrict.doClick();
            return null;
        });
        waitFor("the model refused", 30, () -> window.parameters.isMarked("model"));
        String note = onEdt(() -> window.parameters.note("model"));
        assertTrue(note.contains("dup.off:11:") && note.endsWith("(clear Strict to repair it)") && !note.contains("Exception"), note);
        onEdt(() -> {
            window.dispose();
            return null;
        });
        assertEquals("RAINBOW", settings().get("view.colors", null));
        assertEquals("true", settings().get("view.strict", null));
        window = App.open(null, settings());
        assertEquals("rainbow", onEdt(() -> window.parameters.viewColours.getSelectedItem()), "set again");
        assertTrue(onEdt(() -> window.parameters.viewStrict.isSelected()));
        assertFalse(onEdt(() -> window.parameters.wrapStrict.isSelected()), "the wrap's own box untouched");
    }
}
