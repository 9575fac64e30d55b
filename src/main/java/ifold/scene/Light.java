package ifold.scene;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/** A directional light, given in camera coordinates so that it moves with the viewer. */
public record Light(Vector3dc direction, double intensity) {
    public Light {
        direction = new Vector3d(direction).normalize();
    }
}
