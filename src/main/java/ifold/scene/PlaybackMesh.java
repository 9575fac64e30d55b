package ifold.scene;

import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import ifold.sheet.Tuck;
import ifold.wrap.PaperInSpace;
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
        PaperInSpace placed = playback.strips.geometries().get(step.strip());
        for (int f = firstFace; f < end; f++) {
            int[] loop = loops[f - firstFace];
            Isometry2 pose = poses[f - firstFace];
            double height = (levels[f] + 0.5) * thickness;
            HostFrame on = playback.result.frames()[sheet.host(f)];
            List<double[][]> shapes = new ArrayList<>(1);
            if (!turning.contains(f) && f < placed.sheetFaceCount() && pose == sheet.pose(f)
                    && java.util.Arrays.equals(loop, sheet.loop(f))) {
                // As it finally lies (no tuck after this step cuts or moves it): where thick layers
                // stand back from a concave edge it does too, in the pieces the paper laid round it is drawn in.
                for (int piece = placed.pieceStart()[f]; piece < placed.pieceStart()[f + 1]; piece++) {
                    int[] corner = placed.paperFaces().get(piece);
                    double[][] corners = new double[corner.length][];
                    for (int c = 0; c < corner.length; c++) {
                        corners[c] = java.util.Arrays.copyOfRange(placed.xyz(), 3 * corner[c], 3 * corner[c] + 3);
                    }
                    shapes.add(corners);
                }
            } else {
                double[][] corners = new double[loop.length][];
                for (int c = 0; c < loop.length; c++) {
                    double u = sheet.u(loop[c]);
                    double v = sheet.v(loop[c]);
                    double[] point = new double[3];
                    on.toSpace(pose.x(u, v), pose.y(u, v), height, point, 0);
                    if (turning.contains(f)) {
                        point = WrapView.turnAbout(point, frame, shownTuck.px(), shownTuck.py(), shownTuck.dx(), shownTuck.dy(),
                                Math.PI * fraction);
                    }
                    corners[c] = point;
                }
                shapes.add(corners);
            }
            for (double[][] corners : shapes) {
                // Counter-clockwise on the sheet; a mirrored pose shows its underside, drawn as such.
                int base = points.size();
                WrapView.addPolygon(corners, PaperView.PAPER, points, triangles, colors);
                for (int c = 0; c < corners.length; c++) {
                    edges.add(base + c);
                    edges.add(base + (c + 1) % corners.length);
                }
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
            // diagram's arrow starts; the middle of a piece cut to the host it lands on.
            double[] centre = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                if (swing.piece() == swing.from()) {
                    centre[axis] = (swing.from()[1][axis] + swing.from()[2][axis]) / 2;
                } else {
                    for (double[] corner : swing.piece()) {
                        centre[axis] += corner[axis] / swing.piece().length;
                    }
                }
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

    /**
     * A tail's swing: its piece's corners before (two widths beyond the crease), the turn about
     * its crease that lays it where the fold does, and the corners of the piece drawn (the same
     * corners, or of the part of it that lands on the host it folds onto).
     */
    private record Swing(double[][] from, Vector3d origin, Vector3d axis, double angle, double[][] piece) {
    }

    /**
     * The tail beyond its new crease swinging from where it would run on unfolded to where the
     * fold lays it: a turn about the crease line in space. The piece is two widths of it; a hinge
     * strip's is cut to the square it folds onto, so it turns within the cube of air over that
     * square (or the one beyond the edge it folds over) and never into the solid or a wall
     * beside it.
     */
    private void addTail(Sheet sheet, int strip, Wrap.TailMove move, double fraction, List<double[]> points, List<int[]> triangles,
            List<Integer> colors) {
        Swing swing = swing(sheet, strip, move);
        double[][] corners = new double[swing.piece().length][];
        for (int c = 0; c < corners.length; c++) {
            corners[c] = WrapView.rotate(swing.piece()[c], swing.origin(), swing.axis(), swing.angle() * fraction);
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
        // A hinge strip's piece is cut to its square (a zig-zag's host, a flat piece of the
        // surface, is mostly wider than two widths of strip: its piece swings whole).
        boolean squares = playback.result.method() == Wrap.Method.HINGE;
        double[][] landing = squares ? landing(paper, move, after, height, sheet.tolerance()) : null;
        double[][] piece = from;
        if (landing != null) {
            piece = new double[landing.length][3];
            for (int c = 0; c < landing.length; c++) {
                before.toSpace(move.before().x(landing[c][0], landing[c][1]), move.before().y(landing[c][0], landing[c][1]), height, piece[c], 0);
            }
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
            if (piece != from) {
                for (int c = 0; c < piece.length; c++) {
                    piece[c] = WrapView.rotate(piece[c], a, axis, Math.PI);
                }
            }
            angle -= Math.signum(angle) * Math.PI;
        }
        if (squares && move.hostAfter() != move.hostBefore()) {
            // Over an edge of the surface the piece turns about the line where its layer's plane
            // before meets its plane after, not about the crease on the surface: so it ends on top
            // of the paper on the face across rather than under it.
            Vector3d[] turn = meeting(from, to);
            if (turn != null) {
                Vector3d out2 = new Vector3d(from[1][0], from[1][1], from[1][2]).sub(turn[0]);
                out2.fma(-out2.dot(turn[1]), turn[1]);
                Vector3d in2 = new Vector3d(to[1][0], to[1][1], to[1][2]).sub(turn[0]);
                in2.fma(-in2.dot(turn[1]), turn[1]);
                if (out2.lengthSquared() > 0 && in2.lengthSquared() > 0) {
                    double about = Math.atan2(new Vector3d(out2).cross(in2).dot(turn[1]), out2.dot(in2));
                    if (Math.abs(about - angle) < Math.PI / 2) {
                        return new Swing(from, turn[0], turn[1], about, landing == null ? from : piece);
                    }
                }
            }
        }
        return new Swing(from, a, axis, angle, landing == null ? from : piece);
    }

    /**
     * The line where the plane of quadrilateral {@code a} meets that of {@code b}: a point on it
     * and its unit direction; null where the planes are parallel.
     */
    private static Vector3d[] meeting(double[][] a, double[][] b) {
        Vector3d n1 = normal(a);
        Vector3d n2 = normal(b);
        Vector3d d = new Vector3d(n1).cross(n2);
        if (d.length() < 1e-6) {
            return null;
        }
        d.normalize();
        double c1 = n1.dot(a[0][0], a[0][1], a[0][2]);
        double c2 = n2.dot(b[0][0], b[0][1], b[0][2]);
        // The point of the line nearest the origin: (c1 (n2 × d) + c2 (d × n1)) / ((n1 × n2) · d).
        double det = new Vector3d(n1).cross(n2).dot(d);
        Vector3d point = new Vector3d(n2).cross(d).mul(c1).add(new Vector3d(d).cross(n1).mul(c2)).div(det);
        return new Vector3d[] {point, d};
    }

    /** The unit normal of quadrilateral q (corners 0, 1 and 3 span it). */
    private static Vector3d normal(double[][] q) {
        Vector3d u = new Vector3d(q[1][0] - q[0][0], q[1][1] - q[0][1], q[1][2] - q[0][2]);
        Vector3d v = new Vector3d(q[3][0] - q[0][0], q[3][1] - q[0][1], q[3][2] - q[0][2]);
        return u.cross(v).normalize();
    }

    /**
     * The part of the tail piece {@code paper} (sheet corners) that the fold lays on its host's
     * polygon, {@code height} above it, as sheet points: in from a concave edge by its mitre, as
     * the layers there stand (the wall's layers across), and from every other edge by the
     * tolerance; null where it all lands there, or none of it does.
     */
    private static double[][] landing(double[][] paper, Wrap.TailMove move, HostFrame after, double height, double tolerance) {
        double[] xy = new double[2 * paper.length];
        for (int c = 0; c < paper.length; c++) {
            xy[2 * c] = move.after().x(paper[c][0], paper[c][1]);
            xy[2 * c + 1] = move.after().y(paper[c][0], paper[c][1]);
        }
        if (Polygons2.twiceArea(xy, paper.length) < 0) {
            // Laid mirrored: the same corners run clockwise in the host's frame.
            for (int c = 0; c < paper.length / 2; c++) {
                int d = paper.length - 1 - c;
                double x = xy[2 * c];
                double y = xy[2 * c + 1];
                xy[2 * c] = xy[2 * d];
                xy[2 * c + 1] = xy[2 * d + 1];
                xy[2 * d] = x;
                xy[2 * d + 1] = y;
            }
        }
        double[] corners = after.corners();
        int n = corners.length / 2;
        double[] cut = xy;
        boolean cutAny = false;
        for (int k = 0; k < n && cut != null; k++) {
            double[] edge = after.edge(k);
            // Outward normal of a counter-clockwise polygon's edge: (dy, -dx).
            double nx = edge[3] / edge[4];
            double ny = -edge[2] / edge[4];
            double in = tolerance;
            for (int i = 0; after.mitre() != null && after.mitre()[k] != null && i + 2 < after.mitre()[k].length; i += 3) {
                in = Math.max(in, height * after.mitre()[k][i + 2]);
            }
            double c = nx * edge[0] + ny * edge[1] - in;
            int count = cut.length / 2;
            double[] next = Polygons2.clip(cut, count, nx, ny, c, tolerance);
            cutAny |= next == null || next.length != cut.length || !java.util.Arrays.equals(next, cut);
            cut = next;
        }
        if (cut == null || !cutAny) {
            return null;
        }
        Isometry2 back = move.after().inverse();
        double[][] landing = new double[cut.length / 2][];
        for (int c = 0; c < landing.length; c++) {
            landing[c] = new double[] {back.x(cut[2 * c], cut[2 * c + 1]), back.y(cut[2 * c], cut[2 * c + 1])};
        }
        return landing;
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
