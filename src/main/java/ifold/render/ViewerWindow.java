package ifold.render;

import com.jogamp.newt.event.KeyAdapter;
import com.jogamp.newt.event.KeyEvent;
import com.jogamp.newt.event.MouseAdapter;
import com.jogamp.newt.event.MouseEvent;
import com.jogamp.newt.event.WindowAdapter;
import com.jogamp.newt.event.WindowEvent;
import com.jogamp.newt.opengl.GLWindow;
import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLEventListener;
import com.jogamp.opengl.GLException;
import com.jogamp.opengl.util.Animator;
import ifold.image.PngEncoder;
import ifold.scene.CollisionView;
import ifold.scene.Player;
import ifold.scene.Scene;
import ifold.scene.Trackball;
import java.io.IOException;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDateTime;
import java.time.format.DateTimeFormatter;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.function.IntBinaryOperator;

/**
 * The viewer: a window showing a scene, turned by a virtual trackball (drag to rotate, wheel to
 * zoom, right-drag to pan), with keys to play the animation (space, arrows), reset the camera
 * (R), save a screenshot (S) and show help (H). Input arrives on NEWT's event thread and is
 * queued for the render thread, the only thread that touches the scene.
 */
public final class ViewerWindow {
    private static final List<String> HELP = List.of(
            "drag        rotate",
            "wheel       zoom",
            "right-drag  pan",
            "space       play / pause",
            "left/right  step back / forward",
            "Home        back to the start",
            "R           reset the camera",
            "S           save a screenshot (PNG)",
            "C           paper crossing paper, in red",
            "H           this help",
            "Q, Esc      quit");

    private final int samples;
    private final Scene scene;
    private final Player player;
    private final String caption;
    private final PrintWriter messages;
    private final Trackball trackball;
    private final ConcurrentLinkedQueue<IntBinaryOperator> input = new ConcurrentLinkedQueue<>();
    private volatile boolean showHelp;
    private volatile boolean screenshotWanted;

    /**
     * @param scene what to show; from now on only the render thread may change it
     * @param player the animation to play, or null
     * @param caption the start of the status line (the model and its size)
     * @param messages where to say that a screenshot was saved
     * @param samples samples per pixel for antialiasing (0 for none)
     */
    public ViewerWindow(Scene scene, Player player, String caption, PrintWriter messages, int samples) {
        this.samples = samples;
        this.scene = scene;
        this.player = player;
        this.caption = caption;
        this.messages = messages;
        this.trackball = new Trackball(scene.camera());
    }

    /**
     * Opens the window and returns when it is closed, or after {@code closeAfterSeconds} if
     * that is positive (for measurements and tests).
     *
     * @return the frames per second drawn while the window was open
     */
    public double show(String title, int width, int height, double closeAfterSeconds) throws RenderUnavailableException {
        GLCapabilities caps = GlContexts.capabilities();
        caps.setSampleBuffers(samples > 1);
        caps.setNumSamples(Math.max(1, samples));
        GLWindow window;
        try {
            window = GLWindow.create(caps);
        } catch (GLException | IllegalStateException e) {
            throw new RenderUnavailableException("cannot open a window: " + GlContexts.firstLine(e), e);
        }
        window.setTitle(title);
        window.setSize(width, height);
        CountDownLatch closed = new CountDownLatch(1);
        window.addWindowListener(new WindowAdapter() {
            @Override
            public void windowDestroyed(WindowEvent e) {
                closed.countDown();
            }
        });
        window.addGLEventListener(new Listener());
        window.addMouseListener(new Mouse());
        window.addKeyListener(new Keys(window));
        Animator animator = new Animator(window);
        window.setVisible(true);
        animator.start();
        long opened = System.nanoTime();
        try {
            if (closeAfterSeconds > 0) {
                closed.await((long) (closeAfterSeconds * 1e9), java.util.concurrent.TimeUnit.NANOSECONDS);
            } else {
                closed.await();
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        } finally {
            animator.stop();
            if (window.isRealized()) {
                window.destroy();
            }
        }
        return framesDrawn / Math.max(1e-9, (System.nanoTime() - opened) * 1e-9);
    }

    private volatile long framesDrawn;

    private final class Listener implements GLEventListener {
        private final SceneRenderer renderer = new SceneRenderer();
        private TextOverlay overlay;
        private long lastFrame;
        private long fpsWindowStart;
        private int fpsFrames;
        private double fps;

        @Override
        public void init(GLAutoDrawable drawable) {
            GL3 gl = drawable.getGL().getGL3();
            renderer.init(gl);
            overlay = new TextOverlay(gl);
            trackball.remember();
            lastFrame = System.nanoTime();
            fpsWindowStart = lastFrame;
        }

        @Override
        public void display(GLAutoDrawable drawable) {
            GL3 gl = drawable.getGL().getGL3();
            // JOGL calls display from the animator and, on exposure, from NEWT's event thread,
            // one at a time under the context lock: whichever runs it owns the scene meanwhile.
            scene.bindToThread(Thread.currentThread());
            int width = drawable.getSurfaceWidth();
            int height = drawable.getSurfaceHeight();
            for (IntBinaryOperator event; (event = input.poll()) != null; ) {
                event.applyAsInt(width, height);
            }
            long now = System.nanoTime();
            if (player != null) {
                player.advance((now - lastFrame) * 1e-9);
            }
            lastFrame = now;
            if (screenshotWanted) {
                screenshotWanted = false;
                saveScreenshot(gl, width, height);
            }
            renderer.render(gl, scene, width, height);
            fpsFrames++;
            framesDrawn++;
            if (now - fpsWindowStart >= 1_000_000_000L) {
                fps = fpsFrames / ((now - fpsWindowStart) * 1e-9);
                fpsFrames = 0;
                fpsWindowStart = now;
            }
            String status = String.format(Locale.ROOT, "%s | %.1f fps%s | H: help", caption, fps,
                    player == null ? "" : " | " + player.describe());
            overlay.draw(gl, List.of(status), false, width, height);
            if (showHelp) {
                overlay.draw(gl, HELP, true, width, height);
            }
            scene.clearChanged();
        }

        private void saveScreenshot(GL3 gl, int width, int height) {
            Framebuffer framebuffer = new Framebuffer(gl, width, height, samples);
            try {
                framebuffer.bind(gl);
                renderer.render(gl, scene, width, height);
                byte[] rgb = framebuffer.read(gl);
                String name = "ifold_" + LocalDateTime.now().format(DateTimeFormatter.ofPattern("yyyyMMdd_HHmmss")) + ".png";
                Path file = Path.of(name).toAbsolutePath();
                try (OutputStream out = Files.newOutputStream(file)) {
                    PngEncoder.encode(width, height, rgb, out);
                }
                messages.println("ifold: saved screenshot " + file);
            } catch (IOException e) {
                messages.println("ifold: cannot save the screenshot: " + e.getMessage());
            } finally {
                framebuffer.delete(gl);
                messages.flush();
            }
        }

        @Override
        public void reshape(GLAutoDrawable drawable, int x, int y, int width, int height) {
            // The viewport is set on every frame from the surface size.
        }

        @Override
        public void dispose(GLAutoDrawable drawable) {
            GL3 gl = drawable.getGL().getGL3();
            renderer.dispose(gl);
            overlay.delete(gl);
        }
    }

    private final class Mouse extends MouseAdapter {
        private boolean panning;

        @Override
        public void mousePressed(MouseEvent e) {
            int x = e.getX();
            int y = e.getY();
            panning = e.getButton() == MouseEvent.BUTTON3 || e.isShiftDown();
            input.add((w, h) -> {
                trackball.begin(x, y, w, h);
                return 0;
            });
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            int x = e.getX();
            int y = e.getY();
            boolean pan = panning;
            input.add((w, h) -> {
                if (pan) {
                    trackball.panTo(x, y, w, h);
                } else {
                    trackball.rotateTo(x, y, w, h);
                }
                return 0;
            });
        }

        @Override
        public void mouseWheelMoved(MouseEvent e) {
            float[] rotation = e.getRotation();
            double steps = rotation[1] != 0 ? rotation[1] : rotation[0];
            input.add((w, h) -> {
                trackball.zoom(steps);
                return 0;
            });
        }
    }

    private final class Keys extends KeyAdapter {
        private final GLWindow window;

        Keys(GLWindow window) {
            this.window = window;
        }

        @Override
        public void keyPressed(KeyEvent e) {
            if (e.isAutoRepeat() && e.getKeyCode() != KeyEvent.VK_LEFT && e.getKeyCode() != KeyEvent.VK_RIGHT) {
                return;
            }
            switch (e.getKeyCode()) {
                case KeyEvent.VK_SPACE -> queue(() -> {
                    if (player != null) {
                        player.togglePlaying();
                    }
                });
                case KeyEvent.VK_LEFT -> queue(() -> {
                    if (player != null) {
                        player.step(-1);
                    }
                });
                case KeyEvent.VK_RIGHT -> queue(() -> {
                    if (player != null) {
                        player.step(1);
                    }
                });
                case KeyEvent.VK_HOME -> queue(() -> {
                    if (player != null) {
                        player.restart();
                    }
                });
                case KeyEvent.VK_R -> queue(trackball::reset);
                case KeyEvent.VK_S -> screenshotWanted = true;
                case KeyEvent.VK_H -> showHelp = !showHelp;
                case KeyEvent.VK_C -> queue(() -> CollisionView.toggle(scene.root()));
                case KeyEvent.VK_Q, KeyEvent.VK_ESCAPE -> new Thread(window::destroy, "close").start();
                default -> {
                }
            }
        }

        private void queue(Runnable action) {
            input.add((w, h) -> {
                action.run();
                return 0;
            });
        }
    }

}
