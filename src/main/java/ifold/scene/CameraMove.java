package ifold.scene;

import org.joml.Quaterniond;
import org.joml.Quaterniondc;

/** Turns the camera, over one step, from one orientation to another: to show a model's other side. */
public final class CameraMove implements Animation {
    private final Camera camera;
    private final Quaterniond from;
    private final Quaterniond to;
    private final String description;
    /** The position last shown: the camera is only turned when it changes, so it stays the user's to turn before and after. */
    private double shown = Double.NaN;

    public CameraMove(Camera camera, Quaterniondc from, Quaterniondc to, String description) {
        this.camera = camera;
        this.from = new Quaterniond(from);
        this.to = new Quaterniond(to);
        this.description = description;
    }

    @Override
    public int stepCount() {
        return 1;
    }

    @Override
    public void apply(double position) {
        double t = Math.max(0, Math.min(1, position));
        if (t == shown) {
            return;
        }
        shown = t;
        double eased = t * t * (3 - 2 * t); // start and stop gently
        camera.setOrientation(from.slerp(to, eased, new Quaterniond()));
    }

    @Override
    public String describe(double position) {
        return description;
    }
}
