package ifold.scene;

import ifold.mesh.IndexedPolygons;
import ifold.wrap.Wrap;
import org.joml.Quaterniond;
import org.joml.Quaterniondc;
import org.joml.Vector3d;

/**
 * Where the camera of a wrap's playback looks: close on the triangle being wrapped and turned
 * to its side the paper is on (from below while a tuck is made), or, for a path of one or two
 * triangles, following the strip.
 */
final class PlaybackCamera {
    /** The whole model's view, in model radii: the model with a margin, the caption's band included. */
    static final double WIDE = 1.15;

    private final WrapPlayback playback;

    PlaybackCamera(WrapPlayback playback) {
        this.playback = playback;
    }

    /**
     * Frames triangle t while its folds are made: close, the triangle filling
     * {@link WrapView#CLOSE_FILL} of the frame's height (its folds are a few pixels wide when the
     * whole model is in view), easing out to the whole model at the start and end of its
     * time, so that each triangle is seen first where it lies on the model and the camera
     * turns from one to the next at a distance.
     */
    void frameTriangle(Camera camera, double position, int t) {
        double start = playback.slotStart[t];
        double end = playback.slotEnd[t];
        double ease = Math.min(0.25 * (end - start), 0.5 * playback.beatLength);
        double in = smooth(Math.max(0, Math.min(1, (position - start) / ease)));
        double out = smooth(Math.max(0, Math.min(1, (end - position) / ease)));
        double close = Math.min(in, out);
        Quaterniondc facing = closeOrientation(t);
        // Between two triangles the camera looks half way between their faces.
        int other = position - start < end - position ? t - 1 : t + 1;
        Quaterniond wide = new Quaterniond(facing);
        if (other >= 0 && other < playback.triangles && playback.endStep[other] > playback.firstStep[other]) {
            wide = new Quaterniond(facing).slerp(closeOrientation(other), 0.5);
        }
        Camera near = new Camera();
        near.setOrientation(facing);
        Vector3d centre = new Vector3d(playback.centres[3 * t], playback.centres[3 * t + 1], playback.centres[3 * t + 2]);
        near.setTarget(centre);
        near.setDistance(closeDistance(t, facing, near.fovY()));
        camera.frame(playback.modelCentre, WIDE * playback.modelRadius);
        double far = camera.distance();
        camera.setTarget(new Vector3d(playback.modelCentre).lerp(centre, close));
        // Zoomed at an even pace: the distance changes by equal ratios, not equal lengths.
        camera.setDistance(far * Math.pow(near.distance() / far, close));
        camera.setOrientation(wide.slerp(facing, close, new Quaterniond()));
        camera.setSceneRadius(3 * playback.modelRadius);
    }

    /** How triangle t is looked at close up: facing the viewer, tilted a little, as the whole model's view is. */
    Quaterniondc closeOrientation(int t) {
        Vector3d normal = new Vector3d(playback.normals[3 * t], playback.normals[3 * t + 1], playback.normals[3 * t + 2]).normalize();
        return new Quaterniond().rotateX(-0.25).mul(Camera.facing(normal));
    }

    /**
     * The distance at which triangle t, seen turned by {@code facing}, is {@link WrapView#CLOSE_FILL}
     * of the frame's height, and at most seven tenths of a 16:9 frame's width.
     */
    private double closeDistance(int t, Quaterniondc facing, double fovY) {
        IndexedPolygons mesh = playback.result.mesh();
        int face = triangleFace(t);
        double top = Double.NEGATIVE_INFINITY;
        double bottom = Double.POSITIVE_INFINITY;
        double left = Double.POSITIVE_INFINITY;
        double right = Double.NEGATIVE_INFINITY;
        for (int c = 0; c < 3; c++) {
            int v = mesh.faceVertex(face, c);
            Vector3d p = new Vector3d(mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2))
                    .sub(playback.centres[3 * t], playback.centres[3 * t + 1], playback.centres[3 * t + 2]);
            facing.transform(p);
            top = Math.max(top, p.y);
            bottom = Math.min(bottom, p.y);
            left = Math.min(left, p.x);
            right = Math.max(right, p.x);
        }
        double tan = Math.tan(fovY / 2);
        double distance = Math.max((top - bottom) / (2 * WrapView.CLOSE_FILL * tan), (right - left) / (2 * 0.7 * tan * 16 / 9.0));
        if (playback.result.method() == Wrap.Method.HINGE) {
            // A pass's half square fills the frame with one face: the square and those round it
            // show where the strip comes from and goes.
            distance *= HINGE_CONTEXT;
        }
        return Math.max(distance, 1e-9 * playback.modelRadius);
    }

    /** How much farther the camera stands from a hinge strip's pass than from a zig-zag's triangle. */
    static final double HINGE_CONTEXT = 3;

    /** The refined mesh's face of path triangle t (strips one after another). */
    private int triangleFace(int t) {
        int g = t;
        for (Wrap.Strip strip : playback.result.strips()) {
            if (g < strip.triangles()) {
                return strip.firstTriangle() + g;
            }
            g -= strip.triangles();
        }
        throw new IllegalArgumentException("no path triangle " + t);
    }

    /**
     * How far the camera has turned to look from below at a position along the folds (0 to
     * 1): on a lone triangle, its tucks fold the excess under it, out of sight from above,
     * so the camera turns under for them, easing in half a fold before and out half a fold
     * after (the last stays under until the final turn).
     * A polyhedron hides its tucks in the solid; the camera stays outside.
     */
    double underAt(double along) {
        if (playback.triangles != 1) {
            return 0;
        }
        double under = 0;
        int n = playback.steps.size();
        for (int j = 0; j < n; j++) {
            if (playback.steps.get(j).kind() != Wrap.Kind.TUCK) {
                continue;
            }
            double rise = (along - (j - 0.5)) / 0.5;
            // After the last tuck the camera stays under to the end of its caption: the final
            // turn glides up from there.
            double fall = j == n - 1 ? 1 : ((j + 1.5) - along) / 0.5;
            under = Math.max(under, smooth(Math.max(0, Math.min(1, Math.min(rise, fall)))));
        }
        return under;
    }

    static double smooth(double t) {
        return t * t * (3 - 2 * t);
    }

    void follow(Camera camera, double at, double under) {
        Vector3d centre = new Vector3d();
        Vector3d normal = new Vector3d();
        double weights = 0;
        int middle = (int) Math.floor(at);
        for (int t = Math.max(0, middle - playback.window); t <= Math.min(playback.triangles - 1, middle + playback.window + 1); t++) {
            double weight = playback.window + 1 - Math.abs(t + 0.5 - at);
            if (weight <= 0) {
                continue;
            }
            centre.fma(weight, new Vector3d(playback.centres[3 * t], playback.centres[3 * t + 1], playback.centres[3 * t + 2]));
            normal.fma(weight, new Vector3d(playback.normals[3 * t], playback.normals[3 * t + 1], playback.normals[3 * t + 2]));
            weights += weight;
        }
        int here = Math.min(playback.triangles - 1, Math.max(0, middle));
        if (weights == 0) {
            centre.set(playback.centres[3 * here], playback.centres[3 * here + 1], playback.centres[3 * here + 2]);
        } else {
            centre.div(weights);
        }
        if (normal.length() < 1e-9) {
            normal.set(playback.normals[3 * here], playback.normals[3 * here + 1], playback.normals[3 * here + 2]);
        }
        normal.normalize();
        // Aim between the model's centre and the triangle, close enough to see the fold and
        // far enough to see where on the model it is; the triangle faces the viewer.
        // The whole model stays in the picture, with a margin (the caption's band included):
        // the aim leans 0.3 of the way towards the triangle, and the view holds 0.3 more than
        // the model, so the model's sphere never leaves it; the triangle faces the viewer.
        // A lone triangle or two are the model.
        Vector3d target = new Vector3d(playback.modelCentre).lerp(centre, playback.triangles <= 2 ? 0.6 : 0.3);
        camera.frame(target, (playback.triangles <= 2 ? 1.15 : 1.38) * playback.modelRadius);
        camera.setSceneRadius(3 * playback.modelRadius);
        camera.setOrientation(new Quaterniond().rotateX(-0.25 - under * (Math.PI - 0.9)).mul(Camera.facing(normal)));
    }
}
