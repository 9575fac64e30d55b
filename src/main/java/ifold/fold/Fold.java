package ifold.fold;

import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * One fold: a line on the current folded state, valley or mountain, an angle, and which side of
 * the line moves.
 *
 * @param kind valley (the moving side comes up, towards the paper's top normal) or mountain
 * @param angleDegrees how far the moving side turns, in (0, 180]
 * @param point a point of the fold line, in 3D
 * @param direction the line's direction, in 3D (only its part along the paper counts)
 * @param moving which side of the line moves, seen from the top with the line pointing ahead
 */
public record Fold(Kind kind, double angleDegrees, Vector3dc point, Vector3dc direction, Side moving) {
    public enum Kind { VALLEY, MOUNTAIN }

    public enum Side { LEFT, RIGHT }

    public Fold {
        point = new Vector3d(point);
        direction = new Vector3d(direction);
    }

    /** A fold along the line through two 3D points. */
    public static Fold through(Kind kind, double angleDegrees, Vector3dc from, Vector3dc to, Side moving) {
        return new Fold(kind, angleDegrees, from, new Vector3d(to).sub(from), moving);
    }
}
