package ifold.scene;

import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3d;

/**
 * The root of a scenegraph with its camera, lights and background. Knows whether anything
 * changed since the last frame, and, once bound to a render thread, refuses changes made from
 * any other thread (they would race with the upload of buffers).
 */
public final class Scene {
    private final Root root = new Root();
    private final Camera camera = new Camera();
    private final List<Light> lights = new ArrayList<>();
    private int background = 0xFFFFFFFF;
    private List<Swatch> legend = List.of();
    private List<Label> labels = List.of();
    private volatile Thread renderThread;

    public Scene() {
        lights.add(new Light(new Vector3d(-0.4, 0.6, 1.0), 0.6));
        lights.add(new Light(new Vector3d(0.6, -0.3, 0.5), 0.3));
    }

    /** The root node: attach the scene's content here. */
    public Node root() {
        return root;
    }

    public Camera camera() {
        return camera;
    }

    public List<Light> lights() {
        return lights;
    }

    /** Light that reaches every surface, as a fraction of its colour. */
    public double ambient() {
        return 0.4;
    }

    public int background() {
        return background;
    }

    public void setBackground(int argb) {
        root.markChanged();
        background = argb;
    }

    /** A colour of the scene and what it stands for: a line of the legend of frames and movies. */
    public record Swatch(int color, String meaning) {
    }

    /** A name written at a point of the world in frames and movies: a corner's letter. */
    public record Label(String text, double x, double y, double z) {
    }

    /** What the scene's colours mean (the paper's top side, its underside, the model), shown in a corner of frames and movies. */
    public List<Swatch> legend() {
        return legend;
    }

    public void setLegend(List<Swatch> legend) {
        root.markChanged();
        this.legend = List.copyOf(legend);
    }

    /** The names written at points of the scene (a triangle's corners A, B, C), for frames and movies. */
    public List<Label> labels() {
        return labels;
    }

    public void setLabels(List<Label> labels) {
        root.markChanged();
        this.labels = List.copyOf(labels);
    }

    /** From now on only {@code thread} may change the scene; null lifts the rule. */
    public void bindToThread(Thread thread) {
        renderThread = thread;
    }

    /** Whether something changed since {@link #clearChanged()}. */
    public boolean isChanged() {
        return root.changed;
    }

    public void clearChanged() {
        root.changed = false;
    }

    /** The world-space bounds of everything visible. */
    public Bounds bounds() {
        Bounds bounds = new Bounds();
        root.addWorldBounds(bounds);
        return bounds;
    }

    /** Points the camera at everything visible, from the camera's current direction. */
    public void frameAll() {
        Vector3d center = bounds().center(new Vector3d());
        double[] radius = {0};
        root.visitGeometry(geometry -> radius[0] = Math.max(radius[0], geometry.worldDistanceFrom(center)));
        camera.frame(center, Math.max(radius[0], 1e-9));
    }

    private final class Root extends Node {
        private boolean changed = true;

        Root() {
            super("root");
        }

        @Override
        protected void markChanged() {
            Thread owner = renderThread;
            if (owner != null && owner != Thread.currentThread()) {
                throw new IllegalStateException("the scene was changed on thread " + Thread.currentThread().getName()
                        + ", off its render thread " + owner.getName());
            }
            changed = true;
        }
    }
}
