package ifold.print;

import ifold.scene.Camera;
import ifold.scene.Geometry;
import ifold.scene.Scene;
import ifold.scene.SceneMesh;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.joml.Vector4d;

/**
 * A scene drawn as vectors into a panel of a page, as its camera sees it: the triangles of its
 * visible geometries (as far as each is revealed) projected, the farthest first (the painter's
 * order), each filled with its colour, lighter where it faces the camera. The same scene the
 * movies render, drawn for paper.
 */
final class SceneDrawing {
    private SceneDrawing() {
    }

    /** A projected triangle: its corners on the panel, whether it lies under the rest (the model under its paper), its depth. */
    private record Flat(double[] xy, boolean under, double depth, int color) {
    }

    /** Draws {@code scene} into the panel (x, y) to (x + width, y + height), in millimetres. */
    static void draw(Scene scene, Canvas canvas, double x, double y, double width, double height) throws IOException {
        Camera camera = scene.camera();
        Matrix4d view = camera.viewMatrix(new Matrix4d());
        Matrix4d projection = camera.projectionMatrix(width / height, new Matrix4d());
        Matrix4d viewProjection = new Matrix4d(projection).mul(view);
        List<Flat> flats = new ArrayList<>();
        scene.root().visitGeometry(geometry -> collect(geometry, view, viewProjection, x, y, width, height, flats));
        // What lies under the rest first (the model under its paper, which rests on it), then the
        // farthest first: a big triangle of the model would otherwise cover the paper on it.
        flats.sort((a, b) -> a.under() != b.under() ? (a.under() ? -1 : 1) : Double.compare(b.depth(), a.depth()));
        canvas.beginClip(x, y, width, height);
        for (Flat flat : flats) {
            canvas.fill(flat.xy(), flat.color());
        }
        // The scene's labels (the triangle's corners A, B, C, which the captions name) over it all.
        for (Scene.Label label : scene.labels()) {
            double[] at = project(scene, x, y, width, height, new double[] {label.x(), label.y(), label.z()});
            if (at != null && at[0] >= x && at[0] <= x + width && at[1] >= y && at[1] <= y + height) {
                canvas.text(at[0] + 0.8, at[1] - 0.8, 3.2, label.text(), true);
            }
        }
        canvas.endClip();
    }

    private static void collect(Geometry geometry, Matrix4d view, Matrix4d viewProjection, double x, double y, double width,
            double height, List<Flat> flats) {
        if (!isShown(geometry) || geometry.isSeenThrough()) {
            return;
        }
        SceneMesh mesh = geometry.mesh();
        Matrix4d world = new Matrix4d(geometry.worldTransform());
        Matrix4d clip = new Matrix4d(viewProjection).mul(world);
        Matrix4d eye = new Matrix4d(view).mul(world);
        double[] positions = mesh.positions();
        int[] triangles = mesh.triangles();
        int[] colors = mesh.triangleColors();
        int count = Math.min(mesh.triangleCount(), geometry.revealed());
        Vector4d p = new Vector4d();
        Vector3d[] e = {new Vector3d(), new Vector3d(), new Vector3d()};
        for (int t = 0; t < count; t++) {
            double[] xy = new double[6];
            boolean behind = false;
            for (int k = 0; k < 3; k++) {
                int v = triangles[3 * t + k];
                p.set(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1);
                eye.transformPosition(e[k].set(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]));
                clip.transform(p);
                if (!(p.w > 0)) {
                    behind = true;
                    break;
                }
                xy[2 * k] = x + (p.x / p.w + 1) / 2 * width;
                xy[2 * k + 1] = y + (1 - p.y / p.w) / 2 * height;
            }
            if (behind || outside(xy, x, y, width, height)) {
                continue;
            }
            // Lit from the camera: full where a face looks at it, darker as it turns away.
            Vector3d normal = new Vector3d(e[1]).sub(e[0]).cross(new Vector3d(e[2]).sub(e[0]));
            Vector3d centre = new Vector3d(e[0]).add(e[1]).add(e[2]).div(3);
            double facing = normal.length() > 0 && centre.length() > 0 ? Math.abs(normal.dot(centre)) / (normal.length() * centre.length()) : 1;
            // The material's front where the triangle faces the camera, its back where it turns away,
            // as the renderer colours the paper's top side and underside; or the triangle's own colour.
            boolean front = normal.dot(centre) < 0;
            int color = geometry.material().useFaceColors() && colors != null && t < colors.length ? colors[t]
                    : front ? geometry.material().front() : geometry.material().back();
            flats.add(new Flat(xy, geometry.isUnder(), -centre.z, shade(color, 0.6 + 0.4 * facing)));
        }
    }

    /**
     * Whether the triangle lies wholly beyond one side of the panel, or is too small to see (a
     * hundredth of a square millimetre): a wrap's panel frames one triangle of thousands.
     */
    private static boolean outside(double[] xy, double x, double y, double width, double height) {
        double minX = Math.min(xy[0], Math.min(xy[2], xy[4]));
        double maxX = Math.max(xy[0], Math.max(xy[2], xy[4]));
        double minY = Math.min(xy[1], Math.min(xy[3], xy[5]));
        double maxY = Math.max(xy[1], Math.max(xy[3], xy[5]));
        double area = Math.abs((xy[2] - xy[0]) * (xy[5] - xy[1]) - (xy[4] - xy[0]) * (xy[3] - xy[1])) / 2;
        return maxX < x || minX > x + width || maxY < y || minY > y + height || area < 0.01;
    }

    /**
     * Draws the segment from {@code from} to {@code to} (x, y, z) in {@code ink} over the panel, as
     * the scene's camera sees it: a fold's crease over the paper it creases.
     */
    static void line(Scene scene, Canvas canvas, double x, double y, double width, double height, double[] from, double[] to, Ink ink)
            throws IOException {
        double[] a = project(scene, x, y, width, height, from);
        double[] b = project(scene, x, y, width, height, to);
        if (a == null || b == null) {
            return;
        }
        canvas.beginClip(x, y, width, height);
        canvas.line(a[0], a[1], b[0], b[1], ink);
        canvas.endClip();
    }

    /**
     * Where the scene's camera sees {@code point} (x, y, z) in the panel (x, y) to (x + width,
     * y + height), in millimetres on the page; null where it lies behind the camera.
     */
    static double[] project(Scene scene, double x, double y, double width, double height, double[] point) {
        Camera camera = scene.camera();
        Matrix4d viewProjection = camera.projectionMatrix(width / height, new Matrix4d()).mul(camera.viewMatrix(new Matrix4d()));
        Vector4d p = viewProjection.transform(new Vector4d(point[0], point[1], point[2], 1));
        if (!(p.w > 0)) {
            return null;
        }
        return new double[] {x + (p.x / p.w + 1) / 2 * width, y + (1 - p.y / p.w) / 2 * height};
    }

    /** The direction the scene's camera looks in, in space (a unit vector). */
    static Vector3d viewDirection(Scene scene) {
        Matrix4d view = scene.camera().viewMatrix(new Matrix4d());
        // The view matrix's third row is the camera's backward axis in world coordinates.
        return new Vector3d(-view.m02(), -view.m12(), -view.m22()).normalize();
    }

    /** Whether the geometry and every node above it are visible. */
    private static boolean isShown(Geometry geometry) {
        for (ifold.scene.Spatial s = geometry; s != null; s = s.parent()) {
            if (!s.isVisible()) {
                return false;
            }
        }
        return true;
    }

    private static int shade(int argb, double light) {
        int r = (int) Math.round(((argb >> 16) & 255) * light);
        int g = (int) Math.round(((argb >> 8) & 255) * light);
        int b = (int) Math.round((argb & 255) * light);
        return 0xFF000000 | (Math.min(255, r) << 16) | (Math.min(255, g) << 8) | Math.min(255, b);
    }
}
