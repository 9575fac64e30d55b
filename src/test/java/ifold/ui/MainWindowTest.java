package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.ui.model.Job;
import ifold.ui.model.Planning;
import ifold.ui.model.Progress;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * The real window, opened on the X display (scripts/test runs under Xvfb) and driven through
 * its menus, keys and controls on the event thread: the demos, their fields, the viewer's keys,
 * the timeline, the paper's colours; outcomes checked by pixels. Skipped without a display.
 */
@Timeout(180)
class MainWindowTest extends WindowTestBase {
    @Test
    void opensOnTheZigZagDemoAndDrawsItWithItsReport() throws Exception {
        window = App.open(null, settings());
        BufferedImage picture = settled();
        assertNotNull(picture);
        assertTrue(onEdt(() -> window.getTitle()).contains("zig-zag"), "the title says what is shown");
        assertTrue(pixelsOf(picture, 0xD3DAE2, 3) > picture.getWidth() * picture.getHeight() / 10, "the demo's background");
        assertEquals("5", onEdt(() -> window.report.value("passes")), "the report panel holds the --report figures");
        assertTrue(onEdt(() -> window.timeline.where.getText()).matches("fold \\d+ of 12"), onEdt(() -> window.timeline.where.getText()));
        assertEquals("1", onEdt(() -> window.report.value("coverage")));
        assertEquals(Planning.plan(Job.ZigZag.DEMO, Progress.NONE).folds().size(), (int) onEdt(() -> window.timeline.folds.getModel().getSize()));
        // Every menu the issue asks for, each item with its shortcut.
        for (String item : List.of("Open model", "Open fold script", "Export frames", "Export movie", "Export OBJ", "Export FOLD",
                "Export report", "Export figure", "Quit", "Model", "Path of triangles", "Collisions", "Paper colours", "Captions", "Reset camera", "Underside", "Zig-zag a triangle", "Turn gadget",
                "Wrap the model", "Play a script", "Check the wrap", "Keys", "New model", "Model information", "Export refinement")) {
            assertNotNull(onEdt(() -> menuItem(window, item).getAccelerator()), item + " has a shortcut");
        }
        // Shortcuts of punctuation keys read as the key: "Ctrl+[", not "Ctrl+Open Bracket".
        assertTrue(onEdt(() -> menuItem(window, "Previous fold").getUI()) instanceof ShortcutMenuItemUI);
    }

    /** Alt+F opens the File menu as soon as the window is up, without a click in it first (Xvfb has no window manager to focus it). */
    @Test
    void altFOpensTheFileMenuWithoutAClickFirst() throws Exception {
        window = App.open(null, settings());
        settled();
        java.awt.Robot robot = new java.awt.Robot();
        robot.setAutoDelay(30);
        // The pointer away from the window: without a window manager X gives keys to the window
        // under the pointer, unless one has taken the focus.
        java.awt.Dimension screen = java.awt.Toolkit.getDefaultToolkit().getScreenSize();
        robot.mouseMove(screen.width - 1, screen.height - 1);
        robot.keyPress(java.awt.event.KeyEvent.VK_ALT);
        robot.keyPress(java.awt.event.KeyEvent.VK_F);
        robot.keyRelease(java.awt.event.KeyEvent.VK_F);
        robot.keyRelease(java.awt.event.KeyEvent.VK_ALT);
        waitFor("the File menu open", 10, () -> window.getJMenuBar().getMenu(0).isPopupMenuVisible());
        robot.keyPress(java.awt.event.KeyEvent.VK_ESCAPE);
        robot.keyRelease(java.awt.event.KeyEvent.VK_ESCAPE);
    }

    /** The window manager and the task bar know the window as iFold, not as the main class (ifold-cli-Main). */
    @Test
    void theWindowsClassIsIFold() throws Exception {
        assumeTrue(Files.isExecutable(Path.of("/usr/bin/xprop")), "xprop (x11-utils) reads the window's class");
        window = App.open(null, settings());
        settled();
        String title = onEdt(() -> window.getTitle());
        Process xprop = new ProcessBuilder("/usr/bin/xprop", "-name", title, "WM_CLASS").redirectErrorStream(true).start();
        String said = new String(xprop.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
        assertEquals(0, xprop.waitFor(), said);
        assertTrue(said.contains("\"" + App.WINDOW_CLASS + "\""), said);
        assertFalse(said.contains("ifold-cli-Main") || said.contains("ifold-ui"), said);
    }

    @Test
    void aBadWidthIsMarkedWithTheCoresMessageAndAGoodOneReplans() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.parameters.zigzagWidth.setText("9");
            return null;
        });
        String expected = Planning.check(new Job.ZigZag("0,0,10,0,3.5,8", 2, 0, -1, "9", "")).get(0).message();
        waitFor("the width marked", 10, () -> window.parameters.isMarked("width"));
        assertEquals(expected, onEdt(() -> window.parameters.note("width")), "the core's message, at the field");
        assertEquals("1.6", onEdt(() -> window.report.value("stripWidth")), "nothing ran: the last plan stays");
        onEdt(() -> {
            window.parameters.zigzagWidth.setText("0.8");
            return null;
        });
        waitFor("the new plan", 60, () -> "0.8".equals(window.report.value("stripWidth")));
        assertFalse(onEdt(() -> window.parameters.isMarked("width")));
        assertEquals("10", onEdt(() -> window.report.value("passes")), "half the width, twice the passes");
    }

    @Test
    void draggingACornerOfTheSketchMovesItAndReplans() throws Exception {
        window = App.open(null, settings());
        settled();
        TriangleSketch sketch = window.parameters.sketch;
        java.awt.Point c = onEdt(() -> sketch.corner(2));
        assertNotNull(c, "setup: the demo's triangle is drawn");
        onEdt(() -> {
            long now = System.currentTimeMillis();
            sketch.dispatchEvent(new java.awt.event.MouseEvent(sketch, java.awt.event.MouseEvent.MOUSE_PRESSED, now, 0, c.x, c.y, 1, false,
                    java.awt.event.MouseEvent.BUTTON1));
            sketch.dispatchEvent(new java.awt.event.MouseEvent(sketch, java.awt.event.MouseEvent.MOUSE_DRAGGED, now + 10,
                    java.awt.event.InputEvent.BUTTON1_DOWN_MASK, c.x, c.y - 20, 0, false, 0));
            sketch.dispatchEvent(new java.awt.event.MouseEvent(sketch, java.awt.event.MouseEvent.MOUSE_RELEASED, now + 20, 0, c.x, c.y - 20,
                    1, false, java.awt.event.MouseEvent.BUTTON1));
            return null;
        });
        String corners = onEdt(() -> window.parameters.triangle.getText());
        assertTrue(corners.startsWith("0,0,10,0,3.5,"), "A and B stay, C moves: " + corners);
        double y = Double.parseDouble(corners.substring(corners.lastIndexOf(',') + 1));
        assertTrue(y > 8.5, "C dragged up: " + corners);
        waitFor("the taller triangle planned", 60, () -> corners.equals(window.report.value("triangle")));
    }

    @Test
    void theViewersKeysDriveTheTimeline() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.timeline.restart();
            return null;
        });
        for (int key : new int[] {java.awt.event.KeyEvent.VK_RIGHT, java.awt.event.KeyEvent.VK_RIGHT}) {
            onEdt(() -> {
                press(window.view, key);
                return null;
            });
        }
        assertEquals(window.plan().folds().get(2).position(), onEdt(() -> window.timeline.timeline().position()), 1e-12,
                "two folds forward: the third begins");
        onEdt(() -> {
            press(window.view, java.awt.event.KeyEvent.VK_LEFT);
            press(window.view, java.awt.event.KeyEvent.VK_SPACE);
            return null;
        });
        assertTrue(onEdt(() -> window.timeline.timeline().isPlaying()), "space plays");
        assertEquals("Pause", onEdt(() -> window.timeline.play.getText()));
        onEdt(() -> {
            press(window.view, java.awt.event.KeyEvent.VK_H);
            return null;
        });
        assertTrue(onEdt(() -> window.view.isShowingHelp()), "H shows the keys");
    }

    @Test
    void theTurnFromTheFoldMenuMarksABadAngle() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            menuItem(window, "Turn gadget").doClick();
            return null;
        });
        waitFor("the turn planned", 60, () -> window.plan() != null && window.plan().job() instanceof Job.Turn && !window.isWorking());
        assertEquals("60", onEdt(() -> window.report.value("angle")));
        onEdt(() -> {
            window.parameters.angle.setText("200");
            return null;
        });
        waitFor("the angle marked", 10, () -> window.parameters.isMarked("angle"));
        assertEquals(Planning.check(new Job.Turn("200", "0", "1", "")).get(0).message(), onEdt(() -> window.parameters.note("angle")));
        onEdt(() -> {
            window.parameters.angle.setText("90");
            return null;
        });
        waitFor("the right angle", 60, () -> "90".equals(window.report.value("angle")));
    }

    @Test
    void runReturnsOnceTheWindowIsClosed() throws Exception {
        Thread run = new Thread(() -> {
            try {
                App.run(null, settings());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "app run");
        run.start();
        waitFor("the window", 30, () -> java.util.Arrays.stream(java.awt.Frame.getFrames())
                .anyMatch(f -> f instanceof MainWindow && f.isDisplayable()));
        onEdt(() -> {
            for (java.awt.Frame frame : java.awt.Frame.getFrames()) {
                if (frame instanceof MainWindow && frame.isDisplayable()) {
                    frame.dispose(); // as File, Quit does
                }
            }
            return null;
        });
        run.join(30_000);
        assertFalse(run.isAlive(), "App.run returned: the launcher then exits");
        assertTrue(Files.isRegularFile(dir.resolve("settings.properties")), "and the settings were saved");
    }

    @Test
    void thePapersColoursAreChosenAndKept() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.timeline.folds.setSelectedIndex(window.timeline.folds.getModel().getSize() - 1); // the tucks: seen from below
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        assertTrue(undersidePixels(window.view.picture()) > 20_000, "setup: the blue-grey underside shows");
        onEdt(() -> {
            window.menuBar.setPaperColours(0xFFFFFF00, 0xFFFF0000);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage red = window.view.picture();
        assertTrue(undersidePixels(red) < 100, "no blue-grey left");
        int reddish = 0;
        for (int y = 0; y < red.getHeight(); y++) {
            for (int x = 0; x < red.getWidth(); x++) {
                int p = red.getRGB(x, y);
                reddish += (p >> 16 & 0xFF) > 120 && (p >> 8 & 0xFF) < 40 && (p & 0xFF) < 40 ? 1 : 0;
            }
        }
        assertTrue(reddish > 20_000, "the underside is red: " + reddish + " pixels");
        onEdt(() -> {
            window.dispose();
            return null;
        });
        window = App.open(null, settings());
        assertEquals(0xFFFF0000, settings().getInt("paper.bottom", 0), "remembered");
    }

    @Test
    void theSliderScrubsThroughTheFoldsAndTheListJumps() throws Exception {
        window = App.open(null, settings());
        settled();
        onEdt(() -> {
            window.timeline.slider.setValue(0);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage start = window.view.picture();
        int last = onEdt(() -> window.timeline.folds.getModel().getSize()) - 1;
        onEdt(() -> {
            window.timeline.folds.setSelectedIndex(last);
            return null;
        });
        assertTrue(window.view.awaitFrame(30_000));
        BufferedImage folded = window.view.picture();
        assertEquals(last, (int) onEdt(() -> window.timeline.timeline().currentFold()), "the fold chosen is the one shown");
        assertTrue(onEdt(() -> window.view.status()).startsWith("tuck"), "the status line names the last fold: " + window.view.status());
        // The tucks are shown from below, where the strip's underside (blue) covers the triangle.
        int before = undersidePixels(start);
        int after = undersidePixels(folded);
        assertTrue(before < 100 && after > 20_000, "the strip laid over the triangle: " + before + " underside pixels at the start, "
                + after + " folded");
        assertTrue(differing(start, folded) > start.getWidth() * start.getHeight() / 10, "the view changed");
        onEdt(() -> {
            window.timeline.slider.setValue(TimelinePanel.TICKS / 4);
            return null;
        });
        double quarter = onEdt(() -> window.timeline.timeline().position() / window.timeline.timeline().end());
        assertEquals(0.25, quarter, 1e-4, "dragging the slider moves the timeline at once");
        assertFalse(onEdt(() -> window.timeline.timeline().isPlaying()), "and pauses it");
    }
}
