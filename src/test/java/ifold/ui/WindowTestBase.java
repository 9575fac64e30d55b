package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.ui.model.Settings;
import java.awt.Component;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.KeyStroke;
import javax.swing.MenuElement;
import javax.swing.SwingUtilities;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.io.TempDir;

/**
 * What the window's tests share: the real window, opened on the X display (scripts/test runs
 * under Xvfb; skipped without one), closed after each test; its event thread, waits, menus,
 * dialogs and pixels; and the command line to compare with.
 */
abstract class WindowTestBase {
    @TempDir
    Path dir;

    MainWindow window;

    @BeforeAll
    static void needsDisplay() {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty() && App.canOpen(), "no X display (run the tests under xvfb-run)");
    }

    @AfterEach
    void close() throws Exception {
        if (window != null) {
            onEdt(() -> {
                window.dispose();
                return null;
            });
        }
    }

    Settings settings() {
        return new Settings(dir.resolve("settings.properties"));
    }

    static <T> T onEdt(Callable<T> action) throws Exception {
        AtomicReference<T> result = new AtomicReference<>();
        AtomicReference<Exception> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                result.set(action.call());
            } catch (Exception e) {
                failure.set(e);
            }
        });
        if (failure.get() != null) {
            throw failure.get();
        }
        return result.get();
    }

    /** Waits for the condition, checked on the event thread, for up to {@code seconds}. */
    static void waitFor(String what, double seconds, BooleanSupplier condition) throws Exception {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        while (System.nanoTime() < deadline) {
            if (onEdt(condition::getAsBoolean)) {
                return;
            }
            Thread.sleep(50);
        }
        throw new AssertionError("waited " + seconds + " s for " + what);
    }

    /** The window planned and drew its current job: the view's picture is of it. */
    BufferedImage settled() throws Exception {
        waitFor("the plan", 60, () -> !window.isWorking() && window.plan() != null);
        assertTrue(window.view.awaitFrame(30_000), "the view drew the plan");
        return window.view.picture();
    }

    /** Pixels of the strip's underside (0x8FAACB, lit): bluer than the model's grey-blue and the background. */
    static int undersidePixels(BufferedImage image) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                if ((rgb & 0xFF) > (rgb >> 16 & 0xFF) + 40) {
                    count++;
                }
            }
        }
        return count;
    }

    /** Pixels of the path's far end, as the darkness colours show it: dark, bluer than red or green. */
    static int pathEndPixels(BufferedImage image) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int rgb = image.getRGB(x, y);
                int red = rgb >> 16 & 0xFF;
                int green = rgb >> 8 & 0xFF;
                int blue = rgb & 0xFF;
                if (red + green + blue < 3 * 130 && blue > red + 20 && green < blue) { // not the tree edges' green
                    count++;
                }
            }
        }
        return count;
    }

    static int differing(BufferedImage a, BufferedImage b) {
        int count = 0;
        for (int y = 0; y < Math.min(a.getHeight(), b.getHeight()); y++) {
            for (int x = 0; x < Math.min(a.getWidth(), b.getWidth()); x++) {
                count += a.getRGB(x, y) == b.getRGB(x, y) ? 0 : 1;
            }
        }
        return count;
    }

    static int pixelsOf(BufferedImage image, int rgb, int tolerance) {
        int count = 0;
        for (int y = 0; y < image.getHeight(); y++) {
            for (int x = 0; x < image.getWidth(); x++) {
                int p = image.getRGB(x, y);
                if (Math.abs((p >> 16 & 0xFF) - (rgb >> 16 & 0xFF)) <= tolerance && Math.abs((p >> 8 & 0xFF) - (rgb >> 8 & 0xFF)) <= tolerance
                        && Math.abs((p & 0xFF) - (rgb & 0xFF)) <= tolerance) {
                    count++;
                }
            }
        }
        return count;
    }

    static JMenuItem menuItem(MainWindow window, String text) {
        for (MenuElement menu : window.getJMenuBar().getSubElements()) {
            JMenuItem found = find(menu, text);
            if (found != null) {
                return found;
            }
        }
        throw new AssertionError("no menu item " + text);
    }

    static JMenuItem find(MenuElement element, String text) {
        if (element instanceof JMenuItem item && item.getText().startsWith(text)) {
            return item;
        }
        MenuElement[] children = element instanceof JMenu menu ? menu.getPopupMenu().getSubElements() : element.getSubElements();
        for (MenuElement child : children) {
            JMenuItem found = find(child, text);
            if (found != null) {
                return found;
            }
        }
        return null;
    }

    /** A key pressed on a component with the focus, as the keyboard would: its WHEN_FOCUSED bindings answer. */
    static void press(JComponent component, int key) {
        KeyStroke stroke = KeyStroke.getKeyStroke(key, 0);
        Object name = component.getInputMap(JComponent.WHEN_FOCUSED).get(stroke);
        assertNotNull(name, "a binding for " + stroke);
        component.getActionMap().get(name).actionPerformed(new java.awt.event.ActionEvent(component, 0, String.valueOf(name)));
    }

    /**
     * How long the event thread took to take up one ping, less the time the collector stopped
     * every thread meanwhile, and less how long an idle thread pinged at the same moment took:
     * what the machine's load costs any thread. A full collection of a big wrap's heap holds the
     * event thread as much as the work's, and on a machine loaded by other work a ping took 284
     * to 361 ms though the work never held the thread; a thread the work holds keeps a ping
     * waiting for seconds while the idle thread answers at once.
     */
    static long pingNanos() throws Exception {
        long collecting = collectingMillis();
        long sent = System.nanoTime();
        java.util.concurrent.Future<Long> idle = IDLE.submit(System::nanoTime);
        long[] answered = new long[1];
        SwingUtilities.invokeAndWait(() -> answered[0] = System.nanoTime());
        long load = idle.get() - sent;
        long took = answered[0] - sent;
        return Math.max(0, took - load - (collectingMillis() - collecting) * 1_000_000L);
    }

    /** A thread that does nothing but answer {@link #pingNanos}'s pings. */
    private static final java.util.concurrent.ExecutorService IDLE = java.util.concurrent.Executors.newSingleThreadExecutor(task -> {
        Thread thread = new Thread(task, "idle ping");
        thread.setDaemon(true);
        return thread;
    });

    private static long collectingMillis() {
        long millis = 0;
        for (java.lang.management.GarbageCollectorMXBean collector : java.lang.management.ManagementFactory.getGarbageCollectorMXBeans()) {
            millis += Math.max(0, collector.getCollectionTime());
        }
        return millis;
    }

    /**
     * The event thread answered every ping in time while work that took far longer ran: a thread
     * held by the work would have kept a ping waiting for most of it. The bound is a quarter of
     * a second, well above what a busy machine's scheduling costs a ping ({@link #pingNanos}
     * leaves out the collections).
     */
    static void assertAnswered(long worstNanos, long tookNanos, int pings) {
        long bound = 250_000_000L;
        assertTrue(tookNanos > 2 * bound, "setup: the work took " + tookNanos / 1e6 + " ms, too short to tell a held thread");
        assertTrue(worstNanos < bound, "the event thread answered within 250 ms, at worst " + worstNanos / 1e6 + " ms over "
                + pings + " pings in " + tookNanos / 1e6 + " ms");
    }

    /** A menu item clicked as the mouse would, later on the event thread: an item that opens a modal dialog waits in it. */
    static void clickLater(MainWindow window, String item) {
        SwingUtilities.invokeLater(() -> menuItem(window, item).doClick());
    }

    /** The dialog now showing that holds a {@code type}, waited for. */
    static <T extends Component> T inDialog(Class<T> type) throws Exception {
        AtomicReference<T> found = new AtomicReference<>();
        waitFor("a dialog with a " + type.getSimpleName(), 30, () -> {
            for (java.awt.Window shown : java.awt.Window.getWindows()) {
                if (shown instanceof javax.swing.JDialog && shown.isShowing() && below(shown, type) != null) {
                    found.set(below(shown, type));
                    return true;
                }
            }
            return false;
        });
        return found.get();
    }

    /** Answers the file chooser now showing with {@code file}, as typing its name and pressing Save would. */
    static void saveAs(Path file) throws Exception {
        javax.swing.JFileChooser chooser = inDialog(javax.swing.JFileChooser.class);
        onEdt(() -> {
            chooser.setSelectedFile(file.toFile());
            chooser.approveSelection();
            return null;
        });
    }

    /** Presses OK in the option pane now showing whose form is {@code form}. */
    static void pressOk(Component form) throws Exception {
        onEdt(() -> {
            javax.swing.JOptionPane pane = (javax.swing.JOptionPane) SwingUtilities.getAncestorOfClass(javax.swing.JOptionPane.class, form);
            pane.setValue(javax.swing.JOptionPane.OK_OPTION);
            return null;
        });
    }

    /** What the command line printed and its exit code. */
    record CliRun(int code, String out, String err) {
    }

    static CliRun cliRun(String... args) {
        java.io.StringWriter out = new java.io.StringWriter();
        java.io.StringWriter err = new java.io.StringWriter();
        int code = ifold.cli.Main.commandLine(new java.io.PrintWriter(out), new java.io.PrintWriter(err)).execute(args);
        return new CliRun(code, out.toString(), err.toString());
    }

    static void cli(String... args) {
        java.io.StringWriter err = new java.io.StringWriter();
        int code = ifold.cli.Main.commandLine(new java.io.PrintWriter(new java.io.StringWriter()), new java.io.PrintWriter(err)).execute(args);
        assertEquals(0, code, err.toString());
    }

    /** Finds a component of a type below {@code root}: for the screenshots. */
    static <T extends Component> T below(Component root, Class<T> type) {
        if (type.isInstance(root)) {
            return type.cast(root);
        }
        if (root instanceof java.awt.Container container) {
            for (Component child : container.getComponents()) {
                T found = below(child, type);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }
}
