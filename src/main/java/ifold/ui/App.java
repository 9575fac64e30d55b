package ifold.ui;

import com.formdev.flatlaf.FlatLightLaf;
import ifold.ui.model.Settings;
import java.awt.GraphicsEnvironment;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import javax.swing.UIManager;
import javax.swing.UnsupportedLookAndFeelException;

/** Starts the desktop window: {@code ifold} with no arguments, or {@code ifold app [FILE]}. */
public final class App {
    private App() {
    }

    /** Whether a window can open here: a display, and a JVM that is not headless. */
    public static boolean canOpen() {
        return !GraphicsEnvironment.isHeadless();
    }

    /**
     * Opens the window on {@code file} (a model, a fold script or a FOLD file), or on the
     * zig-zag demo as it was left if null, and waits until it is closed.
     *
     * @param settings where the window keeps what it remembers
     */
    public static void run(Path file, Settings settings) throws InterruptedException {
        CountDownLatch closed = new CountDownLatch(1);
        MainWindow window = open(file, settings);
        // A bug on the event thread: one line in the window's status bar and on stderr, never a stack trace.
        Thread.setDefaultUncaughtExceptionHandler((thread, e) -> {
            String message = "internal error: " + e + " (please report it)";
            System.err.println("ifold: " + message);
            SwingUtilities.invokeLater(() -> window.say(message));
        });
        window.addWindowListener(new java.awt.event.WindowAdapter() {
            @Override
            public void windowClosed(java.awt.event.WindowEvent e) {
                closed.countDown();
            }
        });
        closed.await();
    }

    /** Opens the window (on the event thread) and returns it, shown. */
    static MainWindow open(Path file, Settings settings) throws InterruptedException {
        AtomicReference<MainWindow> window = new AtomicReference<>();
        try {
            SwingUtilities.invokeAndWait(() -> {
                lookAndFeel();
                windowClass();
                MainWindow frame = new MainWindow(settings);
                frame.remembered.restoreOtherParameters();
                frame.setVisible(true);
                if (file != null) {
                    frame.open(file);
                } else {
                    frame.parameters.show(frame.remembered.rememberedZigZag());
                }
                window.set(frame);
            });
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("the window could not open: " + e.getCause(), e.getCause());
        }
        return window.get();
    }

    /** FlatLaf's light look; the system's if it cannot be had. */
    private static void lookAndFeel() {
        if (UIManager.getLookAndFeel() instanceof FlatLightLaf) {
            return;
        }
        if (FlatLightLaf.setup()) {
            UIManager.put("MenuItemUI", ShortcutMenuItemUI.class.getName());
        } else {
            try {
                UIManager.setLookAndFeel(UIManager.getSystemLookAndFeelClassName());
            } catch (ReflectiveOperationException | UnsupportedLookAndFeelException e) {
                // The default look it is: every component still works.
            }
        }
    }

    /** The class the window manager and the task bar know the window by (X11's WM_CLASS). */
    static final String WINDOW_CLASS = "iFold";

    /**
     * Names the window's class iFold: X11's toolkit takes it from the main class's name
     * ("ifold-cli-Main") unless told otherwise, in a field it reads as each window opens. The
     * field is the JDK's own, opened to iFold by the launcher
     * ({@code --add-opens java.desktop/sun.awt.X11}); elsewhere (another toolkit, a JVM started
     * without the flag) the name stays as it was and nothing else changes.
     */
    private static void windowClass() {
        java.awt.Toolkit toolkit = java.awt.Toolkit.getDefaultToolkit();
        if (!toolkit.getClass().getName().equals("sun.awt.X11.XToolkit")) {
            return;
        }
        try {
            java.lang.reflect.Field name = toolkit.getClass().getDeclaredField("awtAppClassName");
            name.setAccessible(true);
            name.set(toolkit, WINDOW_CLASS);
        } catch (ReflectiveOperationException | RuntimeException e) {
            // Not opened to iFold: the window keeps the toolkit's name for its class.
        }
    }

    /** iFold's version, from the jar's manifest; "development" when run from classes. */
    static String version() {
        String version = App.class.getPackage().getImplementationVersion();
        return version == null ? "(development build)" : version;
    }
}
