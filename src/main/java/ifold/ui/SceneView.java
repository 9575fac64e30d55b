package ifold.ui;

import ifold.render.OffscreenRenderer;
import ifold.render.RenderUnavailableException;
import ifold.render.TextFit;
import ifold.scene.Scene;
import ifold.scene.Trackball;
import ifold.ui.model.Plan;
import java.awt.Color;
import java.awt.Dimension;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.event.MouseAdapter;
import java.awt.event.MouseEvent;
import java.awt.event.MouseWheelEvent;
import java.awt.image.BufferedImage;
import java.awt.image.DataBufferInt;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Consumer;
import javax.swing.JComponent;
import javax.swing.SwingUtilities;

/**
 * The 3D view: the plan's scene, rendered with OpenGL by {@link OffscreenRenderer} on a thread
 * of its own and painted by Swing, turned by the viewer's virtual trackball (drag to rotate,
 * wheel to zoom, right- or shift-drag to pan), with the viewer's status line along the bottom.
 *
 * <p>JOGL's {@code GLJPanel} renders the same way (into a framebuffer, read back into an
 * image) but on the event thread, where a wrap of many triangles on a software renderer
 * would hold up the whole window for every frame; here the event thread only paints the last
 * picture. The render thread is the only one that touches the scene: input is queued for it,
 * and the frames it is asked for while busy are drawn once.
 */
final class SceneView extends JComponent {
    private static final long serialVersionUID = 1L;

    static final List<String> HELP = List.of(
            "drag          rotate",
            "wheel         zoom",
            "right-drag    pan (or shift-drag)",
            "space         play / pause",
            "left/right    previous / next fold",
            "Home          back to the start",
            "R             reset the camera",
            "U             the underside",
            "H             this help");

    private final transient ExecutorService thread = Executors.newSingleThreadExecutor(runnable -> {
        Thread t = new Thread(runnable, "ifold render");
        t.setDaemon(true);
        return t;
    });
    /** Changes for the render thread to make before its next frame. */
    private final transient ConcurrentLinkedQueue<Runnable> input = new ConcurrentLinkedQueue<>();
    private final AtomicBoolean frameQueued = new AtomicBoolean();
    private final transient Consumer<String> failures;

    // Render thread only.
    private transient OffscreenRenderer renderer;
    /** The paper's colours, top and bottom (0xAARRGGBB), or 0 for the plan's own. */
    private int paperTop;
    private int paperBottom;
    /** Each paper geometry's own material, to go back to. */
    private final transient java.util.Map<ifold.scene.Geometry, ifold.scene.Material> ownMaterials = new java.util.IdentityHashMap<>();
    private transient Plan.Shown shown;
    private transient Trackball trackball;
    private double position;
    private int width;
    private int height;
    private boolean failed;

    // Read by the event thread.
    private volatile BufferedImage picture;
    private volatile String status = "";
    /** How long the last frame took to render, in milliseconds: the view's cost, shown when paused too (fps would say 0). */
    private volatile double frameMillis;
    private volatile boolean showHelp;
    private volatile boolean showStatus = true;
    private volatile String caption = "";
    private volatile long frames;

    /** @param failures told (on the event thread) why nothing can be drawn, once */
    SceneView(Consumer<String> failures) {
        this.failures = failures;
        // With the parameters (320) and the report (330) beside it, this fills a window of 1360:
        // the view takes what a bigger window adds, the report keeps room for its names.
        setPreferredSize(new Dimension(700, 560));
        setMinimumSize(new Dimension(200, 150));
        setFocusable(true);
        setOpaque(true);
        Mouse mouse = new Mouse();
        addMouseListener(mouse);
        addMouseMotionListener(mouse);
        addMouseWheelListener(mouse);
        addComponentListener(new java.awt.event.ComponentAdapter() {
            @Override
            public void componentResized(java.awt.event.ComponentEvent e) {
                requestFrame();
            }
        });
    }

    /** Shows a new plan's scene at {@code at}; the one before is let go. */
    void show(Plan.Shown next, double at, String newCaption) {
        caption = newCaption;
        input.add(() -> {
            shown = next;
            position = at;
            next.scene().bindToThread(Thread.currentThread());
            next.animation().apply(at);
            trackball = new Trackball(next.scene().camera());
            trackball.remember();
            ownMaterials.clear();
            paint();
            closeRenderer(); // the old scene's buffers go with the old context
        });
        requestFrame();
    }

    /** Shows the animation at {@code at}. */
    void setPosition(double at) {
        input.add(() -> position = at);
        requestFrame();
    }

    void resetCamera() {
        queue(tb -> tb.reset());
    }

    /** Turns the camera half way round: the side the paper was tucked under. */
    void underside() {
        queue(tb -> tb.turn(Math.PI));
    }

    void setShowHelp(boolean show) {
        showHelp = show;
        repaint();
    }

    boolean isShowingHelp() {
        return showHelp;
    }

    void setShowStatus(boolean show) {
        showStatus = show;
        repaint();
    }

    /**
     * Colours the paper: {@code top} the side its faces face (caps and per-face colours give
     * way to it), {@code bottom} the other; 0 for either keeps the plan's own.
     */
    void setPaperColours(int top, int bottom) {
        input.add(() -> {
            paperTop = top;
            paperBottom = bottom;
            paint();
        });
        requestFrame();
    }

    /** On the render thread: the paper's materials as the colours chosen say. */
    private void paint() {
        if (shown == null) {
            return;
        }
        shown.scene().root().visitGeometry(g -> {
            if (!g.name().equals("paper") && !g.name().equals("folding")) {
                return;
            }
            ifold.scene.Material own = ownMaterials.computeIfAbsent(g, ignored -> g.material());
            g.setMaterial(new ifold.scene.Material(paperTop == 0 ? own.front() : paperTop, paperBottom == 0 ? own.back() : paperBottom,
                    paperTop == 0 && own.useFaceColors(), own.showEdges()));
        });
    }

    /** Shows or hides the geometry named {@code name} (the model under the paper). */
    void setVisible(String name, boolean visible) {
        input.add(() -> {
            if (shown != null) {
                setVisible(shown.scene().root(), name, visible);
            }
        });
        requestFrame();
    }

    /** Walks the children themselves: visiting geometry passes the hidden by, and they are the ones to show again. */
    private static void setVisible(ifold.scene.Node node, String name, boolean visible) {
        for (ifold.scene.Spatial child : node.children()) {
            if (child instanceof ifold.scene.Node inner) {
                setVisible(inner, name, visible);
            } else if (child.name().equals(name)) {
                child.setVisible(visible);
            }
        }
    }

    /** The last picture drawn, or null before the first: for tests and screenshots. */
    BufferedImage picture() {
        return picture;
    }

    /** Frames drawn so far. */
    long frames() {
        return frames;
    }

    /** The status line: what the animation shows. */
    String status() {
        return status;
    }

    /** Waits until every change asked for so far is drawn. */
    boolean awaitFrame(long millis) throws InterruptedException {
        long deadline = System.nanoTime() + millis * 1_000_000L;
        while (System.nanoTime() < deadline) {
            java.util.concurrent.CountDownLatch drawn = new java.util.concurrent.CountDownLatch(1);
            thread.execute(drawn::countDown);
            if (drawn.await(Math.max(1, (deadline - System.nanoTime()) / 1_000_000L), TimeUnit.MILLISECONDS)
                    && input.isEmpty() && !frameQueued.get()) {
                return true;
            }
        }
        return false;
    }

    /** Stops the render thread, letting its OpenGL context go. */
    void dispose() {
        thread.execute(this::closeRenderer);
        thread.shutdown();
    }

    private void queue(Consumer<Trackball> action) {
        input.add(() -> {
            if (trackball != null) {
                action.accept(trackball);
            }
        });
        requestFrame();
    }

    private void requestFrame() {
        if (frameQueued.compareAndSet(false, true) && !thread.isShutdown()) {
            thread.execute(this::frame);
        }
    }

    /** On the render thread: makes the changes queued, then draws the scene at the component's size. */
    private void frame() {
        frameQueued.set(false);
        for (Runnable change; (change = input.poll()) != null; ) {
            change.run();
        }
        int w = Math.max(16, getWidth());
        int h = Math.max(16, getHeight());
        if (shown == null || failed || getWidth() <= 0) {
            return;
        }
        try {
            if (renderer == null || w != width || h != height) {
                closeRenderer();
                renderer = new OffscreenRenderer(w, h, 0);
                width = w;
                height = h;
            }
        } catch (RenderUnavailableException e) {
            failed = true;
            SwingUtilities.invokeLater(() -> failures.accept(e.getMessage()));
            return;
        }
        long started = System.nanoTime();
        Scene scene = shown.scene();
        shown.animation().apply(position);
        byte[] rgb = renderer.render(scene);
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        int[] pixels = ((DataBufferInt) image.getRaster().getDataBuffer()).getData();
        for (int p = 0, b = 0; p < pixels.length; p++, b += 3) {
            pixels[p] = (rgb[b] & 0xFF) << 16 | (rgb[b + 1] & 0xFF) << 8 | (rgb[b + 2] & 0xFF);
        }
        scene.clearChanged();
        status = shown.animation().describe(position);
        frameMillis = (System.nanoTime() - started) * 1e-6;
        picture = image;
        frames++;
        repaint();
    }

    private void closeRenderer() {
        if (renderer != null) {
            renderer.close();
            renderer = null;
        }
    }

    @Override
    protected void paintComponent(Graphics g) {
        Graphics2D g2 = (Graphics2D) g.create();
        try {
            BufferedImage image = picture;
            g2.setColor(new Color(0xD3DAE2));
            g2.fillRect(0, 0, getWidth(), getHeight());
            if (image != null) {
                // While the window is resized the last picture stands, at its own size, until the next is drawn.
                g2.drawImage(image, 0, 0, null);
            }
            g2.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g2.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
            FontMetrics metrics = g2.getFontMetrics();
            if (showStatus) {
                // The key to the help stays in sight at the right. Where the line does not fit,
                // the step shown (the status) has a line of its own above the rest: cut short with
                // them, a step read "tuck 2: excess folded under along edge CA (seen fro…".
                String help = "H: help";
                String timing = String.format(Locale.ROOT, "%.0f ms a frame", frameMillis);
                int room = getWidth() - 12 - metrics.stringWidth(" | " + help) - 6;
                String line = caption + " | " + timing + " | " + status;
                List<String> lines = metrics.stringWidth(line) <= room || status.isBlank() ? List.of(TextFit.cutShort(line, metrics, room))
                        : List.of(TextFit.cutShort(status, metrics, getWidth() - 12), TextFit.cutShort(caption + " | " + timing, metrics, room));
                int band = lines.size() * metrics.getHeight() + 6;
                g2.setColor(new Color(0, 0, 0, 150));
                g2.fillRect(0, getHeight() - band, getWidth(), band);
                g2.setColor(Color.WHITE);
                for (int i = 0; i < lines.size(); i++) {
                    int baseline = getHeight() - 6 - metrics.getDescent() - (lines.size() - 1 - i) * metrics.getHeight();
                    g2.drawString(lines.get(i) + (i == lines.size() - 1 ? " | " : ""), 6, baseline);
                }
                g2.drawString(help, getWidth() - 6 - metrics.stringWidth(help), getHeight() - 6 - metrics.getDescent());
            }
            if (showHelp) {
                int lineHeight = metrics.getHeight();
                int boxWidth = 0;
                for (String line : HELP) {
                    boxWidth = Math.max(boxWidth, metrics.stringWidth(line));
                }
                g2.setColor(new Color(0, 0, 0, 170));
                g2.fillRoundRect(12, 12, boxWidth + 24, lineHeight * HELP.size() + 16, 10, 10);
                g2.setColor(Color.WHITE);
                for (int i = 0; i < HELP.size(); i++) {
                    g2.drawString(HELP.get(i), 24, 20 + metrics.getAscent() + i * lineHeight);
                }
            }
        } finally {
            g2.dispose();
        }
    }

    private final class Mouse extends MouseAdapter {
        private boolean panning;

        @Override
        public void mousePressed(MouseEvent e) {
            requestFocusInWindow();
            int x = e.getX();
            int y = e.getY();
            int w = getWidth();
            int h = getHeight();
            panning = SwingUtilities.isRightMouseButton(e) || e.isShiftDown();
            queue(tb -> tb.begin(x, y, w, h));
        }

        @Override
        public void mouseDragged(MouseEvent e) {
            int x = e.getX();
            int y = e.getY();
            int w = getWidth();
            int h = getHeight();
            boolean pan = panning;
            queue(tb -> {
                if (pan) {
                    tb.panTo(x, y, w, h);
                } else {
                    tb.rotateTo(x, y, w, h);
                }
            });
        }

        @Override
        public void mouseWheelMoved(MouseWheelEvent e) {
            double steps = e.getPreciseWheelRotation();
            queue(tb -> tb.zoom(-steps)); // AWT counts a turn away from the user as negative
        }
    }
}
