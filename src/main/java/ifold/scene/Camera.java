package ifold.scene;

import org.joml.AxisAngle4d;
import org.joml.Matrix4d;
import org.joml.Quaterniond;
import org.joml.Quaterniondc;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * A perspective camera that orbits a target: it looks at {@code target} from {@code distance}
 * away, turned by {@code orientation} (which rotates the world into the camera's frame, where
 * the camera looks down -z with +y up).
 */
public final class Camera {
    private final Vector3d target = new Vector3d();
    private final Quaterniond orientation = new Quaterniond();
    private double distance = 5;
    private double sceneRadius = 1;
    private double fovY = Math.toRadians(35);

    public Vector3dc target() {
        return target;
    }

    public void setTarget(Vector3dc target) {
        this.target.set(target);
    }

    public Quaterniondc orientation() {
        return orientation;
    }

    public void setOrientation(Quaterniondc orientation) {
        this.orientation.set(orientation).normalize();
    }

    public double distance() {
        return distance;
    }

    public void setDistance(double distance) {
        if (!(distance > 0) || !Double.isFinite(distance)) {
            throw new IllegalArgumentException("camera distance must be positive, got " + distance);
        }
        this.distance = distance;
    }

    /** The vertical field of view, in radians. */
    public double fovY() {
        return fovY;
    }

    /** Aims at a sphere: its centre becomes the target, and the distance fits it in view. */
    public void frame(Vector3dc center, double radius) {
        target.set(center);
        sceneRadius = radius;
        distance = 1.08 * radius / Math.sin(fovY / 2);
    }

    /**
     * Widens (or narrows) the clipping planes to hold a sphere of {@code radius} about the target,
     * without moving the camera: for paper that swings far beyond what the camera is framed on.
     */
    public void setSceneRadius(double radius) {
        if (!(radius > 0) || !Double.isFinite(radius)) {
            throw new IllegalArgumentException("scene radius must be positive, got " + radius);
        }
        sceneRadius = radius;
    }

    /** The radius of what is being looked at, which sets the clipping planes. */
    public double sceneRadius() {
        return sceneRadius;
    }

    /** World to camera: move the target to the origin, turn, then step back by the distance. */
    public Matrix4d viewMatrix(Matrix4d dest) {
        return dest.translation(0, 0, -distance).rotate(orientation).translate(-target.x, -target.y, -target.z);
    }

    public Matrix4d projectionMatrix(double aspect, Matrix4d dest) {
        double near = Math.max(distance - 2 * sceneRadius, distance * 1e-3);
        double far = distance + 2 * sceneRadius;
        return dest.setPerspective(fovY, aspect, near, far);
    }

    /** The camera's position in the world. */
    public Vector3d eye(Vector3d dest) {
        // The camera sits at (0, 0, distance) in its frame; bring that back to the world.
        return orientation.transformInverse(dest.set(0, 0, distance)).add(target);
    }

    /** The orientation that turns {@code normal} to face the viewer (+z in the camera's frame), by the shortest turn. */
    public static Quaterniondc facing(Vector3dc normal) {
        double cos = normal.z();
        if (cos > 1 - 1e-12) {
            return new Quaterniond();
        }
        if (cos < -1 + 1e-12) {
            // Turned about the vertical, not the horizontal: what is up in the plane stays up.
            return new Quaterniond(new AxisAngle4d(Math.PI, 0, 1, 0));
        }
        Vector3d axis = new Vector3d(normal).cross(0, 0, 1).normalize();
        return new Quaterniond(new AxisAngle4d(Math.acos(cos), axis));
    }
}
