package ifold.scene;

import org.joml.Quaterniond;
import org.joml.Quaterniondc;

/** Turns the camera once around the model, about the screen's vertical axis: for movies of a still model. */
public final class Turntable implements Animation {
    private static final int STEPS = 360;
    private final Camera camera;
    private final Quaterniond start;

    public Turntable(Camera camera) {
        this.camera = camera;
        this.start = new Quaterniond(camera.orientation());
    }

    @Override
    public int stepCount() {
        return STEPS;
    }

    @Override
    public void apply(double position) {
        Quaterniondc spin = new Quaterniond().rotationY(Math.toRadians(position * 360.0 / STEPS));
        camera.setOrientation(start.mul(spin, new Quaterniond()));
    }

    @Override
    public String describe(double position) {
        return String.format(java.util.Locale.ROOT, "turntable %.0f degrees", position * 360.0 / STEPS);
    }
}
