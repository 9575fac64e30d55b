package ifold.scene;

import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Tuck;
import ifold.wrap.Wrap;
import java.util.ArrayList;
import java.util.List;
import org.joml.Vector3d;

/**
 * The paper of the triangle being wrapped at a moment of a wrap's playback: its faces as laid
 * so far, the fold being made turning about its crease, and the tail.
 */
final class PlaybackMesh {
    private final WrapPlayback playback;

    PlaybackMesh(WrapPlayback playback) {
        this.playback = playback;
    }

    /**
     * The triangle being wrapped at step j: its faces as they stand then (the final state with
     * the tucks after step j undone), and the paper in motion: the tail swinging about its new
     * crease, or the flap of a tuck turning under.
     */
    SceneMesh currentMesh(Wrap.Strip strip, Wrap.Step step, int j, int firstFace, double fraction) {
        Sheet sheet = strip.sheet();
        int end = step.facesAfter();
        Pieces pieces = pieces(sheet, step, j, firstFace);
        int[][] loops = pieces.loops();
        Isometry2[] poses = pieces.poses();
        java.util.Set<Integer> turning = pieces.turning();
        Tuck shownTuck = pieces.tuck();
        int[] levels = playback.levels[step.strip()];
        double thickness = sheet.thickness();
        List<double[]> points = new ArrayList<>();
        List<int[]> triangles = new ArrayList<>();
        List<Integer> colors = new ArrayList<>();
        List<Integer> edges = new ArrayList<>();
        HostFrame frame = shownTuck != null ? playback.result.frames()[shownTuck.host()] : null;
        for (int f = firstFace; f < end; f++) {
            int[] loop = loops[f - firstFace];
            Isometry2 pose = poses[f - firstFace];
            double height = (levels[f] + 0.5) * thickness;
            HostFrame on = playback.result.frames()[sheet.host(f)];
            double[][] corners = new double[loop.length][];
            for (int c = 0; c < loop.length; c++) {
                double u = sheet.u(loop[c]);
                double v = sheet.v(loop[c]);
                double[] point = new double[3];
                on.toSpace(pose.x(u, v), pose.y(u, v), height, point, 0);
                if (turning.contains(f)) {
                    point = WrapView.turnAbout(point, frame, shownTuck.px(), shownTuck.py(), shownTuck.dx(), shownTuck.dy(), Math.PI * fraction);
                }
                corners[c] = point;
            }
            // Counter-clockwise on the sheet; a mirrored pose shows its underside, drawn as such.
            int base = points.size();
            WrapView.addPolygon(corners, PaperView.PAPER, points, triangles, colors);
            for (int c = 0; c < corners.length; c++) {
                edges.add(base + c);
                edges.add(base + (c + 1) % corners.length);
            }
        }
        if (step.tail() != null && step.kind() != Wrap.Kind.END) {
            addTail(sheet, step.strip(), step.tail(), fraction, points, triangles, colors);
        }
        double[] positions = new double[3 * points.size()];
        for (int p = 0; p < points.size(); p++) {
            System.arraycopy(points.get(p), 0, positions, 3 * p, 3);
        }
        int[] flat = new int[3 * triangles.size()];
        for (int t = 0; t < triangles.size(); t++) {
            System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
        }
        int[] edgeColors = new int[edges.size() / 2];
        java.util.Arrays.fill(edgeColors, WrapView.FACE_EDGE);
        return new SceneMesh(positions, flat, colors.stream().mapToInt(Integer::intValue).toArray(),
                edges.stream().mapToInt(Integer::intValue).toArray(), edgeColors);
    }

    /**
     * The faces of the triangle being wrapped at step j as they stand then, from {@code firstFace}:
     * their loops and poses (the final state with this triangle's tucks after step j undone; the
     * flap of a tuck being shown laid back over its line), and the faces of that flap.
     */
    private record Pieces(int[][] loops, Isometry2[] poses, java.util.Set<Integer> turning, Tuck tuck) {
    }

    private Pieces pieces(Sheet sheet, Wrap.Step step, int j, int firstFace) {
        int end = step.facesAfter();
        int count = end - firstFace;
        int[][] loops = new int[count][];
        Isometry2[] poses = new Isometry2[count];
        for (int f = firstFace; f < end; f++) {
            loops[f - firstFace] = sheet.loop(f);
            poses[f - firstFace] = sheet.pose(f);
        }
        // Undo the tucks of this triangle after the one shown.
        int lastStep = j;
        while (lastStep + 1 < playback.steps.size() && playback.triangleOf[lastStep + 1] == playback.triangleOf[j]) {
            lastStep++;
        }
        for (int q = lastStep; q > j; q--) {
            Tuck tuck = playback.steps.get(q).tuck();
            if (tuck == null) {
                continue;
            }
            for (int c = 0; c < tuck.changed().length; c++) {
                int f = tuck.changed()[c];
                if (f >= firstFace && f < end) {
                    loops[f - firstFace] = tuck.loopsBefore()[c];
                    poses[f - firstFace] = tuck.posesBefore()[c];
                }
            }
        }
        // A tuck being shown: its faces are cut already, and the flap turns from where it lay
        // (its reflection back over the tuck line) to under the paper.
        java.util.Set<Integer> turning = new java.util.HashSet<>();
        Tuck shownTuck = step.kind() == Wrap.Kind.TUCK ? step.tuck() : null;
        if (shownTuck != null) {
            Isometry2 back = Isometry2.reflection(shownTuck.px(), shownTuck.py(), shownTuck.dx(), shownTuck.dy());
            for (int f : shownTuck.moved()) {
                if (f >= firstFace && f < end) {
                    turning.add(f);
                    poses[f - firstFace] = back.after(poses[f - firstFace]);
                }
            }
        }
        return new Pieces(loops, poses, turning, shownTuck);
    }

    /**
     * The way the centre of step j's moving paper travels, {@link Animation#PATH_POINTS} points
     * from before the fold to after: the tail swinging about its new crease, or a tuck's flap
     * turning under; null for a step that moves neither.
     */
    double[][] flapPath(Wrap.Strip strip, Wrap.Step step, int j, int firstFace) {
        Sheet sheet = strip.sheet();
        double[][] path = new double[Animation.PATH_POINTS][];
        if (step.tail() != null && step.kind() != Wrap.Kind.END) {
            Swing swing = swing(sheet, step.strip(), step.tail());
            // The tail piece's far end, two widths beyond the crease: the flap's tip, where a
            // diagram's arrow starts.
            double[] centre = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                centre[axis] = (swing.from()[1][axis] + swing.from()[2][axis]) / 2;
            }
            for (int p = 0; p < path.length; p++) {
                path[p] = WrapView.rotate(centre, swing.origin(), swing.axis(), swing.angle() * p / (path.length - 1));
            }
            return path;
        }
        Pieces pieces = pieces(sheet, step, j, firstFace);
        if (pieces.tuck() == null || pieces.turning().isEmpty()) {
            return null;
        }
        int[] levels = playback.levels[step.strip()];
        double[] centre = new double[3];
        int corners = 0;
        for (int f : pieces.turning()) {
            Isometry2 pose = pieces.poses()[f - firstFace];
            HostFrame on = playback.result.frames()[sheet.host(f)];
            double[] point = new double[3];
            for (int v : pieces.loops()[f - firstFace]) {
                on.toSpace(pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)), (levels[f] + 0.5) * sheet.thickness(), point, 0);
                for (int axis = 0; axis < 3; axis++) {
                    centre[axis] += point[axis];
                }
                corners++;
            }
        }
        for (int axis = 0; axis < 3; axis++) {
            centre[axis] /= corners;
        }
        Tuck tuck = pieces.tuck();
        HostFrame frame = playback.result.frames()[tuck.host()];
        for (int p = 0; p < path.length; p++) {
            path[p] = WrapView.turnAbout(centre, frame, tuck.px(), tuck.py(), tuck.dx(), tuck.dy(), Math.PI * p / (path.length - 1));
        }
        return path;
    }

    /** A tail's swing: its piece's corners before, and the turn about its crease that lays it where the fold does. */
    private record Swing(double[][] from, Vector3d origin, Vector3d axis, double angle) {
    }

    /**
     * The tail beyond its new crease, two widths of it, swinging from where it would run on
     * unfolded to where the fold lays it: a turn about the crease line in space.
     */
    private void addTail(Sheet sheet, int strip, Wrap.TailMove move, double fraction, List<double[]> points, List<int[]> triangles,
            List<Integer> colors) {
        Swing swing = swing(sheet, strip, move);
        double[][] corners = new double[4][];
        for (int c = 0; c < 4; c++) {
            corners[c] = WrapView.rotate(swing.from()[c], swing.origin(), swing.axis(), swing.angle() * fraction);
        }
        WrapView.addPolygon(corners, PaperView.CAP, points, triangles, colors);
    }

    private Swing swing(Sheet sheet, int strip, Wrap.TailMove move) {
        double w = sheet.width();
        double[][] paper = {{move.u0(), 0}, {move.u0() + 2 * w, 0}, {move.u1() + 2 * w, w}, {move.u1(), w}};
        HostFrame before = playback.result.frames()[move.hostBefore()];
        HostFrame after = playback.result.frames()[move.hostAfter()];
        double height = (topLevel(sheet, playback.levels[strip], move.hostBefore()) + 1.5) * sheet.thickness();
        double[][] from = new double[4][3];
        double[][] to = new double[4][3];
        for (int c = 0; c < 4; c++) {
            before.toSpace(move.before().x(paper[c][0], paper[c][1]), move.before().y(paper[c][0], paper[c][1]), height, from[c], 0);
            after.toSpace(move.after().x(paper[c][0], paper[c][1]), move.after().y(paper[c][0], paper[c][1]), height, to[c], 0);
        }
        // The axis: the crease, where both placements agree; the angle: between the tail piece's
        // direction across the axis before and after.
        Vector3d a = new Vector3d(from[0][0], from[0][1], from[0][2]);
        Vector3d axis = new Vector3d(from[3][0], from[3][1], from[3][2]).sub(a).normalize();
        Vector3d out0 = new Vector3d(from[1][0], from[1][1], from[1][2]).sub(a);
        out0.fma(-out0.dot(axis), axis).normalize();
        Vector3d out1 = new Vector3d(to[1][0], to[1][1], to[1][2]).sub(new Vector3d(to[0][0], to[0][1], to[0][2]));
        out1.fma(-out1.dot(axis), axis).normalize();
        double angle = Math.atan2(new Vector3d(out0).cross(out1).dot(axis), out0.dot(out1));
        if (Math.abs(Math.abs(angle) - Math.PI) < 1e-6) {
            // A flat fold: swing over (towards the triangle's outside) or under, as the fold says.
            Vector3d up = new Vector3d(before.normal()[0], before.normal()[1], before.normal()[2]);
            double sign = new Vector3d(axis).cross(out0).dot(up) > 0 ? 1 : -1;
            angle = move.over() ? sign * Math.PI : -sign * Math.PI;
        } else if (move.hostAfter() != move.hostBefore() && after.height(from[1]) < 0) {
            // Over a concave edge, the tail running on would lie inside the solid, and swinging from
            // there would sweep through it: it comes from laid back over the paper instead (a half
            // turn about the crease), and swings up through the air onto the face across.
            for (int c = 0; c < 4; c++) {
                from[c] = WrapView.rotate(from[c], a, axis, Math.PI);
            }
            angle -= Math.signum(angle) * Math.PI;
        }
        return new Swing(from, a, axis, angle);
    }

    /** The area of triangle t of the mesh. */
    static double area(IndexedPolygons mesh, int t) {
        double[] e1 = new double[3];
        double[] e2 = new double[3];
        for (int axis = 0; axis < 3; axis++) {
            double o = mesh.coordinate(mesh.faceVertex(t, 0), axis);
            e1[axis] = mesh.coordinate(mesh.faceVertex(t, 1), axis) - o;
            e2[axis] = mesh.coordinate(mesh.faceVertex(t, 2), axis) - o;
        }
        double x = e1[1] * e2[2] - e1[2] * e2[1];
        double y = e1[2] * e2[0] - e1[0] * e2[2];
        double z = e1[0] * e2[1] - e1[1] * e2[0];
        return Math.sqrt(x * x + y * y + z * z) / 2;
    }

    private int topLevel(Sheet sheet, int[] levels, int host) {
        int top = -1;
        for (int f : sheet.facesOn(host)) {
            top = Math.max(top, levels[f]);
        }
        return top;
    }
}
