package ifold.scene;

import ifold.refine.RefinedMesh;
import ifold.wrap.Wrap;
import ifold.wrap.WrapGeometry;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.joml.AxisAngle4d;
import org.joml.Quaterniond;
import org.joml.Quaterniondc;
import org.joml.Vector3d;

/**
 * A wrap on screen: the model, solid in a quiet colour, and the strips laid over it face by
 * face in the order they were folded, the camera following the triangle being wrapped; at the
 * end the camera turns once around the wrapped model. The strips are one mesh whose triangles
 * come in the order their faces were made, so that showing the wrap up to a moment is showing
 * a prefix of it: nothing is rebuilt per frame.
 */
public final class WrapView {
    public static final int MODEL = 0xFF7D8A99;
    private static final int REVEAL_STEPS = 4 * 360;
    private static final int TURN_STEPS = 360;

    private WrapView() {
    }

    /** How the paper is drawn: its top side cream, caps grey, its underside blue-grey; no outlines (the faces are many and small). */
    public static final Material PAPER = new Material(PaperView.PAPER, 0xFF8FAACB, true, false);

    /** The wrap's strips and, for each strip and path triangle, how many of the mesh's triangles exist once it is wrapped. */
    public record Strips(SceneMesh mesh, int[][] trianglesAfter, int[][] trianglesBeforeTucks) {
    }

    public static Strips strips(Wrap.Result result, List<WrapGeometry> geometries) {
        int total = 0;
        for (WrapGeometry g : geometries) {
            total += g.vertexCount();
        }
        double[] positions = new double[3 * total];
        List<int[]> triangles = new ArrayList<>();
        List<Integer> colors = new ArrayList<>();
        int[][] after = new int[geometries.size()][];
        int[][] beforeTucks = new int[geometries.size()][];
        int base = 0;
        for (int k = 0; k < geometries.size(); k++) {
            WrapGeometry g = geometries.get(k);
            Wrap.Strip strip = result.strips().get(k);
            System.arraycopy(g.xyz(), 0, positions, 3 * base, 3 * g.vertexCount());
            // Caps come right after the later of the faces they join.
            List<List<Integer>> capsAfter = new ArrayList<>();
            for (int f = 0; f < g.paperFaces().size(); f++) {
                capsAfter.add(new ArrayList<>());
            }
            for (int c = 0; c < g.caps().size(); c++) {
                capsAfter.get(g.capAfter()[c]).add(c);
            }
            int[] trianglesAtFace = new int[g.paperFaces().size() + 1];
            for (int f = 0; f < g.paperFaces().size(); f++) {
                trianglesAtFace[f] = triangles.size();
                fan(g.paperFaces().get(f), base, PaperView.PAPER, triangles, colors);
                for (int c : capsAfter.get(f)) {
                    fan(g.caps().get(c), base, PaperView.CAP, triangles, colors);
                }
            }
            trianglesAtFace[g.paperFaces().size()] = triangles.size();
            after[k] = new int[strip.triangles()];
            beforeTucks[k] = new int[strip.triangles()];
            for (int i = 0; i < strip.triangles(); i++) {
                after[k][i] = trianglesAtFace[strip.facesAfter()[i]];
                beforeTucks[k][i] = trianglesAtFace[strip.facesBeforeTucks()[i]];
            }
            base += g.vertexCount();
        }
        int[] flat = new int[3 * triangles.size()];
        for (int t = 0; t < triangles.size(); t++) {
            System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
        }
        int[] colorArray = colors.stream().mapToInt(Integer::intValue).toArray();
        return new Strips(new SceneMesh(positions, flat, colorArray, new int[0], new int[0]), after, beforeTucks);
    }

    private static void fan(int[] face, int base, int color, List<int[]> triangles, List<Integer> colors) {
        for (int i = 1; i + 1 < face.length; i++) { // faces are convex
            triangles.add(new int[] {base + face[0], base + face[i], base + face[i + 1]});
            colors.add(color);
        }
    }

    /**
     * The animation: the strips laid triangle by triangle along their paths (four fifths of its
     * length), the camera following; then a turn around the wrapped model.
     */
    public static Animation animation(Scene scene, Geometry paper, Strips strips, Wrap.Result result) {
        RefinedMesh mesh = result.mesh();
        int total = 0;
        for (Wrap.Strip strip : result.strips()) {
            total += strip.triangles();
        }
        int triangles = total;
        double[] centres = new double[3 * triangles];
        double[] normals = new double[3 * triangles];
        int[] stripOf = new int[triangles];
        int[] indexOf = new int[triangles];
        int g = 0;
        for (int k = 0; k < result.strips().size(); k++) {
            Wrap.Strip strip = result.strips().get(k);
            for (int i = 0; i < strip.triangles(); i++, g++) {
                int t = strip.firstTriangle() + i;
                double[] n = result.frames()[t].normal();
                for (int axis = 0; axis < 3; axis++) {
                    double sum = 0;
                    for (int c = 0; c < 3; c++) {
                        sum += mesh.coordinate(mesh.faceVertex(t, c), axis);
                    }
                    centres[3 * g + axis] = sum / 3;
                    normals[3 * g + axis] = n[axis];
                }
                stripOf[g] = k;
                indexOf[g] = i;
            }
        }
        Bounds bounds = scene.bounds();
        Vector3d modelCentre = bounds.center(new Vector3d());
        double modelRadius = bounds.radius();
        // The camera follows a moving average of the triangles, so that it glides rather than jumps.
        int window = Math.max(1, triangles / 40);
        Quaterniondc finalView = new Quaterniond().rotateX(-0.5).rotateY(0.6);
        return new Animation() {
            @Override
            public int stepCount() {
                return REVEAL_STEPS + TURN_STEPS;
            }

            @Override
            public void apply(double position) {
                Camera camera = scene.camera();
                if (position >= REVEAL_STEPS) {
                    paper.setRevealed(Geometry.ALL);
                    camera.frame(modelCentre, modelRadius);
                    double angle = Math.toRadians((position - REVEAL_STEPS) * 360.0 / TURN_STEPS);
                    camera.setOrientation(new Quaterniond(finalView).mul(new Quaterniond().rotationY(angle)));
                    return;
                }
                double along = position / REVEAL_STEPS * triangles;
                int at = Math.min(triangles - 1, (int) Math.floor(along));
                double fraction = along - at;
                int k = stripOf[at];
                int i = indexOf[at];
                int from = i == 0 ? (k == 0 ? 0 : strips.trianglesAfter()[k - 1][strips.trianglesAfter()[k - 1].length - 1])
                        : strips.trianglesAfter()[k][i - 1];
                int to = strips.trianglesAfter()[k][i];
                paper.setRevealed(from + (int) Math.round(fraction * (to - from)));
                Vector3d centre = new Vector3d();
                Vector3d normal = new Vector3d();
                double weights = 0;
                for (int j = Math.max(0, at - window); j <= Math.min(triangles - 1, at + window); j++) {
                    double weight = window + 1 - Math.abs(j - along);
                    if (weight <= 0) {
                        continue;
                    }
                    centre.fma(weight, new Vector3d(centres[3 * j], centres[3 * j + 1], centres[3 * j + 2]));
                    normal.fma(weight, new Vector3d(normals[3 * j], normals[3 * j + 1], normals[3 * j + 2]));
                    weights += weight;
                }
                centre.div(weights);
                if (normal.length() < 1e-9) {
                    normal.set(normals[3 * at], normals[3 * at + 1], normals[3 * at + 2]);
                }
                normal.normalize();
                camera.frame(centre, 0.55 * modelRadius);
                camera.setSceneRadius(3 * modelRadius);
                camera.setOrientation(new Quaterniond().rotateX(-0.35).mul(frontToViewer(normal)));
            }

            @Override
            public String describe(double position) {
                if (position >= REVEAL_STEPS) {
                    return "wrapped: " + result.strips().size() + " strip(s) over " + triangles + " triangles";
                }
                double along = position / REVEAL_STEPS * triangles;
                int at = Math.min(triangles - 1, (int) Math.floor(along));
                int k = stripOf[at];
                int i = indexOf[at];
                int from = i == 0 ? (k == 0 ? 0 : strips.trianglesAfter()[k - 1][strips.trianglesAfter()[k - 1].length - 1])
                        : strips.trianglesAfter()[k][i - 1];
                int revealed = from + (int) Math.round((along - at) * (strips.trianglesAfter()[k][i] - from));
                String what = revealed <= strips.trianglesBeforeTucks()[k][i] ? "zig-zag passes, turn gadget, fold over the edge"
                        : "tucks: the excess folded under";
                return String.format(Locale.ROOT, "%striangle %d of %d: %s", result.strips().size() > 1 ? "strip " + (k + 1) + ", " : "",
                        i + 1, result.strips().get(k).triangles(), what);
            }
        };
    }

    /** The turn that brings {@code normal} to face the viewer (+z in the camera's frame). */
    static Quaterniondc frontToViewer(Vector3d normal) {
        double cos = normal.z;
        if (cos > 1 - 1e-12) {
            return new Quaterniond();
        }
        if (cos < -1 + 1e-12) {
            return new Quaterniond(new AxisAngle4d(Math.PI, 1, 0, 0));
        }
        Vector3d axis = new Vector3d(normal).cross(0, 0, 1).normalize();
        return new Quaterniond(new AxisAngle4d(Math.acos(cos), axis));
    }
}
