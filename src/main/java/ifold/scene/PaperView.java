package ifold.scene;

import ifold.geom.Vectors;
import ifold.script.ScriptFolding;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.wrap.PaperInSpace;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/** Paper on screen: its faces (caps in grey), outlined, with the creases in red; and a fold script played as an animation. */
public final class PaperView {
    public static final int PAPER = 0xFFF4F1EA;
    public static final int CAP = 0xFF9A9A9A;
    public static final int CREASE = 0xFFB03030;

    private PaperView() {
    }

    /** How the paper is drawn: face colours (paper or cap) on the front, a blue-grey back. */
    public static final Material MATERIAL = new Material(PAPER, 0xFF8FAACB, true, true);

    /** Folded paper as it is written: its faces, the caps between layers in grey, face edges outlined and creases in red. */
    public static SceneMesh mesh(PaperInSpace geometry, Sheet sheet) {
        Mesh mesh = new Mesh();
        double[] xyz = geometry.xyz();
        int[] index = new int[geometry.vertexCount()];
        for (int v = 0; v < geometry.vertexCount(); v++) {
            index[v] = mesh.point(new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]});
        }
        for (int f = 0; f < geometry.sheetFaceCount(); f++) {
            int[] loop = sheet.loop(f);
            for (int piece = geometry.pieceStart()[f]; piece < geometry.pieceStart()[f + 1]; piece++) {
                int[] face = geometry.paperFaces().get(piece);
                int[] corners = new int[face.length];
                for (int i = 0; i < face.length; i++) {
                    corners[i] = index[face[i]];
                }
                mesh.face(corners, PAPER);
                if (face.length == loop.length) {
                    mesh.outline(corners, loop, sheet); // a face placed whole: its sides, creases in red
                }
            }
        }
        for (int[] cap : geometry.caps()) {
            int[] corners = new int[cap.length];
            for (int i = 0; i < cap.length; i++) {
                corners[i] = index[cap[i]];
            }
            mesh.face(corners, CAP);
        }
        return mesh.build();
    }

    /**
     * Plays a fold script one fold a step: the paper that turns swings about the fold's axis
     * from where it lay to where the fold lays it; at the end, the folded paper as written, caps
     * and all. The paper between folds is stepped back and forth by each fold's record of the
     * faces it changed, not kept whole per fold.
     */
    public static Animation folding(Geometry geometry, ScriptFolding.Result result, PaperInSpace folded) {
        return new Playback(geometry, result, folded, null);
    }

    /**
     * As {@link #folding(Geometry, ScriptFolding.Result, PaperInSpace)}, the camera framing the
     * paper as it stands in every frame (its direction kept): it follows the paper as it folds
     * up, and moves smoothly, since the paper does.
     */
    public static Animation folding(Geometry geometry, ScriptFolding.Result result, PaperInSpace folded, Camera camera) {
        return new Playback(geometry, result, folded, camera);
    }

    /**
     * Plays a crease pattern folded all at once, as Origami Simulator folds: every crease turning
     * together from flat to its fold angle, each face carried by the hinges from the first, its
     * layer rising with it; at the end, the folded paper as written. The camera frames the paper
     * as it stands.
     */
    public static Animation formFolding(Geometry geometry, Motion motion, PaperInSpace folded, Camera camera) {
        return new FormPlayback(geometry, motion, folded, camera);
    }

    /**
     * A sheet folded all at once, as the scene plays it: the sheet folded, the planes its hosts
     * are, each face's motion part way, and what to call it.
     *
     * @param motionAt for t from 0 (flat) to 1 (folded without thickness), each face's motion:
     *     12 numbers, R (3 × 3, rows first) then t, taking paper (u, v, 0) into space
     * @param creases how many creases turn
     * @param how how its folded state was found, in words
     */
    public record Motion(Sheet sheet, HostFrame[] frames, java.util.function.DoubleFunction<double[][]> motionAt, int creases, String how) {
    }

    private static final class FormPlayback implements Animation {
        private final Geometry geometry;
        private final Motion motion;
        private final SceneMesh end;
        private final int[] levels;
        private final Camera camera;
        private double shown = Double.NaN;
        private double sceneRadius;

        FormPlayback(Geometry geometry, Motion motion, PaperInSpace folded, Camera camera) {
            this.geometry = geometry;
            this.motion = motion;
            this.end = mesh(folded, motion.sheet());
            this.levels = motion.sheet().levels();
            this.camera = camera;
        }

        @Override
        public int stepCount() {
            return 1;
        }

        @Override
        public void apply(double position) {
            if (position == shown) {
                return;
            }
            shown = position;
            if (position >= 1) {
                sceneRadius = frameCamera(camera, end, sceneRadius);
                geometry.setMesh(end);
                return;
            }
            double t = Math.max(0, position);
            Sheet sheet = motion.sheet();
            double[][] placed = motion.motionAt().apply(t);
            Mesh mesh = new Mesh();
            for (int f = 0; f < sheet.faceCount(); f++) {
                double[] m = placed[f];
                double[] normal = motion.frames()[sheet.host(f)].normal();
                // The layer rises with the fold: by its level's height once folded.
                double lift = t * (levels[f] + 0.5) * sheet.thickness();
                int[] loop = sheet.loop(f);
                int[] corners = new int[loop.length];
                for (int c = 0; c < loop.length; c++) {
                    double u = sheet.u(loop[c]);
                    double v = sheet.v(loop[c]);
                    corners[c] = mesh.point(new double[] {m[0] * u + m[1] * v + m[9] + lift * normal[0],
                        m[3] * u + m[4] * v + m[10] + lift * normal[1], m[6] * u + m[7] * v + m[11] + lift * normal[2]});
                }
                mesh.face(corners, PAPER);
                mesh.outline(corners, loop, sheet);
            }
            SceneMesh built = mesh.build();
            sceneRadius = frameCamera(camera, built, sceneRadius);
            geometry.setMesh(built);
        }

        @Override
        public String describe(double position) {
            if (position >= 1) {
                return "folded: " + motion.sheet().faceCount() + " faces, " + motion.how();
            }
            return String.format(java.util.Locale.ROOT, "all %d creases folding at once (%.0f %%)", motion.creases(), 100 * Math.max(0, position));
        }
    }

    /**
     * Frames {@code camera} (where there is one) on the paper as it stands, its direction kept,
     * the clipping planes set for the largest the paper has been so far ({@code sceneRadius},
     * returned grown), so that they do not hop.
     */
    static double frameCamera(Camera camera, SceneMesh mesh, double sceneRadius) {
        if (camera == null || mesh.vertexCount() == 0) {
            return sceneRadius;
        }
        double[] p = mesh.positions();
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int i = 0; i < p.length; i += 3) {
            for (int axis = 0; axis < 3; axis++) {
                min[axis] = Math.min(min[axis], p[i + axis]);
                max[axis] = Math.max(max[axis], p[i + axis]);
            }
        }
        org.joml.Vector3d centre = new org.joml.Vector3d((min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2);
        double radius = Math.max(1e-9, Math.hypot(max[0] - min[0], Math.hypot(max[1] - min[1], max[2] - min[2])) / 2);
        camera.frame(centre, radius);
        double grown = Math.max(sceneRadius, 4 * radius);
        camera.setSceneRadius(grown);
        return grown;
    }

    private static final class Playback implements Animation {
        private final Geometry geometry;
        private final ScriptFolding.Result result;
        private final SceneMesh end;
        private final Sheet sheet;
        private final int[][] loops;
        private final Isometry2[] poses;
        private final int[] hosts;
        private final int[] levels;
        private int count;
        /** The folds made in the arrays above. */
        private int at;
        private double shown = Double.NaN;
        private final Camera camera;
        private double sceneRadius;

        Playback(Geometry geometry, ScriptFolding.Result result, PaperInSpace folded, Camera camera) {
            this.geometry = geometry;
            this.camera = camera;
            this.result = result;
            this.sheet = result.sheet();
            this.end = mesh(folded, sheet);
            int n = sheet.faceCount();
            loops = new int[n][];
            poses = new Isometry2[n];
            hosts = new int[n];
            levels = sheet.levels();
            for (int f = 0; f < n; f++) {
                loops[f] = sheet.loop(f);
                poses[f] = sheet.pose(f);
                hosts[f] = sheet.host(f);
            }
            count = n;
            at = result.steps().size();
        }

        @Override
        public int stepCount() {
            return result.steps().size();
        }

        private void seek(int k) {
            while (at > k) {
                ScriptFolding.Step step = result.steps().get(--at);
                for (int i = 0; i < step.faces().length; i++) {
                    int f = step.faces()[i];
                    if (step.loopsBefore()[i] != null) {
                        loops[f] = step.loopsBefore()[i];
                        poses[f] = step.posesBefore()[i];
                        hosts[f] = step.hostsBefore()[i];
                        levels[f] = step.levelsBefore()[i];
                    }
                }
                count = step.facesBefore();
            }
            while (at < k) {
                ScriptFolding.Step step = result.steps().get(at++);
                for (int i = 0; i < step.faces().length; i++) {
                    int f = step.faces()[i];
                    loops[f] = step.loopsAfter()[i];
                    poses[f] = step.posesAfter()[i];
                    hosts[f] = step.hostsAfter()[i];
                    levels[f] = step.levelsAfter()[i];
                }
                count = step.facesAfter();
            }
        }

        @Override
        public void apply(double position) {
            if (position == shown) {
                return;
            }
            shown = position;
            List<ScriptFolding.Step> steps = result.steps();
            if (steps.isEmpty() || position >= steps.size()) {
                show(end);
                return;
            }
            int k = Math.max(0, (int) Math.floor(position));
            double fraction = Math.max(0, Math.min(1, position - k));
            ScriptFolding.Step step = steps.get(k);
            seek(k + 1);
            // The faces that turn, as they lay before the fold (cut as it cuts them), swung part of the way.
            Map<Integer, Integer> turning = new HashMap<>();
            for (int f : step.moved()) {
                turning.put(f, -1);
            }
            for (int i = 0; i < step.faces().length; i++) {
                if (turning.containsKey(step.faces()[i])) {
                    turning.put(step.faces()[i], i);
                }
            }
            Mesh mesh = new Mesh();
            HostFrame[] frames = result.frames();
            double[] point = new double[3];
            for (int f = 0; f < count; f++) {
                int i = turning.getOrDefault(f, -1);
                Isometry2 pose = i >= 0 ? step.posesBefore()[i] : poses[f];
                HostFrame frame = frames[i >= 0 ? step.hostsBefore()[i] : hosts[f]];
                double height = ((i >= 0 ? step.levelsBefore()[i] : levels[f]) + 0.5) * sheet.thickness();
                int[] loop = loops[f];
                int[] corners = new int[loop.length];
                for (int c = 0; c < loop.length; c++) {
                    double u = sheet.u(loop[c]);
                    double v = sheet.v(loop[c]);
                    frame.toSpace(pose.x(u, v), pose.y(u, v), height, point, 0);
                    double[] p = point.clone();
                    if (i >= 0) {
                        p = turned(p, step.axisPoint(), step.axisDirection(), step.angle() * fraction);
                    }
                    corners[c] = mesh.point(p);
                }
                mesh.face(corners, PAPER);
                mesh.outline(corners, loop, sheet);
            }
            show(mesh.build());
        }

        private void show(SceneMesh mesh) {
            geometry.setMesh(mesh);
            sceneRadius = frameCamera(camera, mesh, sceneRadius);
        }

        /**
         * Fold k's line: its axis in space, as long as the sheet's diagonal each way from the
         * point the script gave (the panel shows the part over the paper); a valley or mountain as
         * the script says.
         */
        @Override
        public FoldLine foldLine(int k) {
            if (k < 0 || k >= result.steps().size()) {
                return null;
            }
            ScriptFolding.Step step = result.steps().get(k);
            double[] p = step.axisPoint();
            double[] d = step.axisDirection();
            // The crease is where the faces the fold changed meet its axis: their corners on it,
            // which the turn leaves where they were.
            double reach = Math.hypot(sheet.length(), sheet.width());
            // Thick paper's faces lie their levels above their planes, and the axis at the paper it
            // turns: a corner within a thickness or two of the axis lies on the crease.
            double near = 1e-6 * reach + 2 * sheet.thickness();
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            double[] q = new double[3];
            for (int i = 0; i < step.faces().length; i++) {
                Isometry2 pose = step.posesAfter()[i];
                HostFrame frame = result.frames()[step.hostsAfter()[i]];
                for (int v : step.loopsAfter()[i]) {
                    frame.toSpace(pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)),
                            (step.levelsAfter()[i] + 0.5) * sheet.thickness(), q, 0);
                    double wx = q[0] - p[0];
                    double wy = q[1] - p[1];
                    double wz = q[2] - p[2];
                    double t = wx * d[0] + wy * d[1] + wz * d[2];
                    if (wx * wx + wy * wy + wz * wz - t * t <= near * near) {
                        low = Math.min(low, t);
                        high = Math.max(high, t);
                    }
                }
            }
            if (!(high > low)) {
                low = -reach;
                high = reach;
            }
            return new FoldLine(new double[] {p[0] + low * d[0], p[1] + low * d[1], p[2] + low * d[2]},
                    new double[] {p[0] + high * d[0], p[1] + high * d[1], p[2] + high * d[2]},
                    step.fold().kind() == ifold.script.FoldScript.Kind.VALLEY, null);
        }

        /** The centre of the paper fold k turns, as it lay before the fold, swung about the fold's axis. */
        @Override
        public double[][] foldPath(int k) {
            if (k < 0 || k >= result.steps().size()) {
                return null;
            }
            ScriptFolding.Step step = result.steps().get(k);
            java.util.Set<Integer> moved = new java.util.HashSet<>();
            for (int f : step.moved()) {
                moved.add(f);
            }
            double[] centre = new double[3];
            double[] q = new double[3];
            int corners = 0;
            for (int i = 0; i < step.faces().length; i++) {
                if (!moved.contains(step.faces()[i])) {
                    continue;
                }
                Isometry2 pose = step.posesBefore()[i];
                HostFrame frame = result.frames()[step.hostsBefore()[i]];
                for (int v : step.loopsAfter()[i]) {
                    frame.toSpace(pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)),
                            (step.levelsBefore()[i] + 0.5) * sheet.thickness(), q, 0);
                    for (int axis = 0; axis < 3; axis++) {
                        centre[axis] += q[axis];
                    }
                    corners++;
                }
            }
            if (corners == 0) {
                return null;
            }
            for (int axis = 0; axis < 3; axis++) {
                centre[axis] /= corners;
            }
            double[][] path = new double[PATH_POINTS][];
            for (int p = 0; p < PATH_POINTS; p++) {
                path[p] = turned(centre, step.axisPoint(), step.axisDirection(), step.angle() * p / (PATH_POINTS - 1));
            }
            return path;
        }

        @Override
        public String describe(double position) {
            List<ScriptFolding.Step> steps = result.steps();
            if (steps.isEmpty()) {
                return "no folds";
            }
            int k = Math.min(steps.size() - 1, Math.max(0, (int) Math.floor(position)));
            double fraction = position >= steps.size() ? 1 : Math.max(0, Math.min(1, position - k));
            var fold = steps.get(k).fold();
            return String.format(java.util.Locale.ROOT, "fold %d of %d (%.0f %%): %s %.4g°%s", k + 1, steps.size(), 100 * fraction,
                    fold.kind().name().toLowerCase(java.util.Locale.ROOT), fold.degrees(), fold.line() > 0 ? ", line " + fold.line() : "");
        }
    }

    /** Point p turned by {@code angle} about the line through {@code origin} along the unit {@code axis}. */
    private static double[] turned(double[] p, double[] origin, double[] axis, double angle) {
        double[] v = Vectors.turn(new double[] {p[0] - origin[0], p[1] - origin[1], p[2] - origin[2]}, axis, angle);
        return new double[] {origin[0] + v[0], origin[1] + v[1], origin[2] + v[2]};
    }

    /** A mesh being put together: points, fans of convex faces, outlines (creases in red). */
    private static final class Mesh {
        private final List<double[]> points = new ArrayList<>();
        private final List<int[]> triangles = new ArrayList<>();
        private final List<Integer> colors = new ArrayList<>();
        private final List<Integer> edges = new ArrayList<>();
        private final List<Integer> edgeColors = new ArrayList<>();

        int point(double[] p) {
            points.add(p);
            return points.size() - 1;
        }

        void face(int[] corners, int color) {
            for (int i = 1; i + 1 < corners.length; i++) { // faces are convex: a fan will do
                triangles.add(new int[] {corners[0], corners[i], corners[i + 1]});
                colors.add(color);
            }
        }

        void outline(int[] corners, int[] loop, Sheet sheet) {
            for (int i = 0; i < corners.length; i++) {
                int j = (i + 1) % corners.length;
                edges.add(corners[i]);
                edges.add(corners[j]);
                edgeColors.add(sheet.crease(loop[i], loop[j]) != null ? CREASE : SceneMesh.EDGE_COLOR);
            }
        }

        SceneMesh build() {
            double[] positions = new double[3 * points.size()];
            for (int p = 0; p < points.size(); p++) {
                System.arraycopy(points.get(p), 0, positions, 3 * p, 3);
            }
            int[] flat = new int[3 * triangles.size()];
            for (int t = 0; t < triangles.size(); t++) {
                System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
            }
            return new SceneMesh(positions, flat, colors.stream().mapToInt(Integer::intValue).toArray(),
                    edges.stream().mapToInt(Integer::intValue).toArray(), edgeColors.stream().mapToInt(Integer::intValue).toArray());
        }
    }
}
