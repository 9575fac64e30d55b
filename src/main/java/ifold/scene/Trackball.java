package ifold.scene;

import org.joml.Quaterniond;
import org.joml.Vector3d;

/**
 * The virtual trackball that turns a camera by mouse drags (Shoemake's arcball with Bell's
 * hyperbolic sheet outside the ball, so a drag far from the centre still turns smoothly), zooms
 * by wheel steps and pans by right-drags. Screen coordinates are pixels, y down.
 */
public final class Trackball {
    private final Camera camera;
    private final Quaterniond startOrientation = new Quaterniond();
    private final Vector3d startPoint = new Vector3d();
    private final Vector3d homeTarget = new Vector3d();
    private final Quaterniond homeOrientation = new Quaterniond();
    private double homeDistance;
    private int lastX;
    private int lastY;

    public Trackball(Camera camera) {
        this.camera = camera;
        remember();
    }

    /** Remembers the camera as it is now as the view that {@link #reset()} returns to. */
    public void remember() {
        homeTarget.set(camera.target());
        homeOrientation.set(camera.orientation());
        homeDistance = camera.distance();
    }

    public void reset() {
        camera.setTarget(homeTarget);
        camera.setOrientation(homeOrientation);
        camera.setDistance(homeDistance);
    }

    /** A drag starts at pixel (x, y) of a view {@code width} by {@code height}. */
    public void begin(int x, int y, int width, int height) {
        startOrientation.set(camera.orientation());
        toSphere(x, y, width, height, startPoint);
        lastX = x;
        lastY = y;
    }

    /** The drag that began at {@link #begin} is now at (x, y): turn the camera. */
    public void rotateTo(int x, int y, int width, int height) {
        Vector3d point = toSphere(x, y, width, height, new Vector3d());
        Quaterniond drag = new Quaterniond().rotationTo(startPoint, point);
        camera.setOrientation(drag.mul(startOrientation, new Quaterniond()));
    }

    /** Moves the target with the cursor, from the last position to (x, y). */
    public void panTo(int x, int y, int width, int height) {
        double perPixel = 2 * camera.distance() * Math.tan(camera.fovY() / 2) / Math.max(1, height);
        Vector3d shift = new Vector3d(-(x - lastX) * perPixel, (y - lastY) * perPixel, 0);
        camera.orientation().transformInverse(shift);
        camera.setTarget(new Vector3d(camera.target()).add(shift));
        lastX = x;
        lastY = y;
    }

    /** Zooms in by {@code steps} wheel steps (out when negative), 10 % each. */
    public void zoom(double steps) {
        camera.setDistance(camera.distance() * Math.pow(1.1, -steps));
    }

    /** Turns the camera about the screen's vertical axis by {@code radians}. */
    public void turn(double radians) {
        Quaterniond spin = new Quaterniond().rotationY(radians);
        camera.setOrientation(spin.mul(camera.orientation(), new Quaterniond()));
    }

    /** Pixel (x, y) on the ball of radius 1 (fitting the smaller side), or on the hyperbola outside it. */
    static Vector3d toSphere(int x, int y, int width, int height, Vector3d dest) {
        double size = Math.max(1, Math.min(width, height));
        double nx = (2.0 * x - width) / size;
        double ny = (height - 2.0 * y) / size;
        double d2 = nx * nx + ny * ny;
        double z = d2 <= 0.5 ? Math.sqrt(1 - d2) : 0.5 / Math.sqrt(d2);
        return dest.set(nx, ny, z).normalize();
    }
}
