package ifold.check;

import ifold.check.LayerOrder.Findings;
import ifold.check.LayerOrder.Kind;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * The rules of flat folding at the creases: every edge two faces share is a <em>taco</em> (both
 * in one plane, on one side of the edge: folded flat) or a <em>crossing</em> (the paper goes on
 * across the edge's line, flat or into another plane). Edges are grouped by the line in space
 * they lie on, and every two on a line whose spans overlap are tested.
 */
final class CreaseLayers {
    private CreaseLayers() {
    }

    /** An edge two faces share: its faces, its ends in space, its span on its line. */
    private static final class Edge {
        final int f;
        final int g;
        final boolean taco;
        final double[] a;
        final double[] b;
        double s0;
        double s1;

        Edge(int f, int g, boolean taco, double[] a, double[] b) {
            this.f = f;
            this.g = g;
            this.taco = taco;
            this.a = a;
            this.b = b;
        }
    }

    static void check(PlanarFaces faces, Findings findings) {
        List<Edge> edges = sharedEdges(faces);
        // Lines by direction (either way) and the point nearest the origin.
        NearKeys lines = new NearKeys(1e-6, 1e-6, 1e-6, 1e-6 * faces.size, 1e-6 * faces.size, 1e-6 * faces.size);
        double angle = 1e-7;
        double offset = 1e-7 * faces.size;
        double[] tolerances = {angle, angle, angle, offset, offset, offset};
        List<List<Edge>> onLine = new ArrayList<>();
        for (Edge edge : edges) {
            double[] key = lineKey(edge.a, edge.b, 1);
            int line = lines.find(key, tolerances);
            if (line < 0) {
                line = lines.find(lineKey(edge.a, edge.b, -1), tolerances);
            }
            if (line < 0) {
                line = lines.add(key);
                onLine.add(new ArrayList<>());
            }
            double[] t = lines.key(line);
            double sa = t[0] * edge.a[0] + t[1] * edge.a[1] + t[2] * edge.a[2];
            double sb = t[0] * edge.b[0] + t[1] * edge.b[1] + t[2] * edge.b[2];
            edge.s0 = Math.min(sa, sb);
            edge.s1 = Math.max(sa, sb);
            onLine.get(line).add(edge);
        }
        for (int line = 0; line < onLine.size(); line++) {
            List<Edge> list = onLine.get(line);
            list.sort(Comparator.comparingDouble(e -> e.s0));
            for (int i = 0; i < list.size(); i++) {
                Edge first = list.get(i);
                for (int j = i + 1; j < list.size() && list.get(j).s0 < first.s1 - faces.eps; j++) {
                    Edge second = list.get(j);
                    if (second.s1 <= first.s0 + faces.eps) {
                        continue;
                    }
                    if (first.taco) {
                        tacoAgainst(faces, first, second, findings);
                    } else if (second.taco) {
                        tacoAgainst(faces, second, first, findings);
                    } else {
                        crossings(faces, first, second, findings);
                    }
                }
            }
        }
        for (Edge edge : edges) {
            if (edge.taco) {
                facesThrough(faces, edge, findings);
            }
        }
    }

    /** Every edge of the paper that two faces of some area share. */
    private static List<Edge> sharedEdges(PlanarFaces faces) {
        FoldedState state = faces.state;
        LongIntTable first = new LongIntTable(state.faceVertices.length);
        List<Edge> edges = new ArrayList<>();
        for (int f = 0; f < state.faceCount; f++) {
            int start = state.faceStart[f];
            int corners = state.faceStart[f + 1] - start;
            for (int i = 0; i < corners; i++) {
                int a = state.faceVertices[start + i];
                int b = state.faceVertices[start + (i + 1) % corners];
                long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                int g = first.put(key, f, -1);
                if (g < 0 || g == f || faces.plane[f] < 0 || faces.plane[g] < 0) {
                    continue;
                }
                double[] pa = point(state, a);
                double[] pb = point(state, b);
                boolean taco = faces.plane[f] == faces.plane[g]
                        && side(faces, g, pa, pb) == side(faces, f, pa, pb);
                edges.add(new Edge(g, f, taco, pa, pb));
            }
        }
        return edges;
    }

    /** Which side of the line a → b face f lies on, in its plane seen from up: +1 left, -1 right. */
    private static int side(PlanarFaces faces, int f, double[] a, double[] b) {
        double[] n = faces.frames.get(faces.plane[f]);
        double tx = b[0] - a[0];
        double ty = b[1] - a[1];
        double tz = b[2] - a[2];
        double cx = faces.centroid[3 * f] - a[0];
        double cy = faces.centroid[3 * f + 1] - a[1];
        double cz = faces.centroid[3 * f + 2] - a[2];
        // (t × c) · up
        double s = (ty * cz - tz * cy) * n[0] + (tz * cx - tx * cz) * n[1] + (tx * cy - ty * cx) * n[2];
        return s > 0 ? 1 : -1;
    }

    /**
     * A taco (folded flat, faces f and g) and another edge on its line: paper going on across
     * the line on the taco's side must not lie between the taco's faces; another taco on that
     * side must have both faces between them or neither.
     */
    private static void tacoAgainst(PlanarFaces faces, Edge taco, Edge other, Findings findings) {
        int plane = faces.plane[taco.f];
        int tacoSide = side(faces, taco.f, taco.a, taco.b);
        if (other.taco) {
            if (faces.plane[other.f] != plane || side(faces, other.f, taco.a, taco.b) != tacoSide) {
                return;
            }
            int c = other.f;
            int d = other.g;
            if (c == taco.f || c == taco.g || d == taco.f || d == taco.g) {
                return;
            }
            int cIn = inside(faces, c, taco);
            int dIn = inside(faces, d, taco);
            if (cIn >= 0 && dIn >= 0 && cIn != dIn) {
                findings.add(Kind.TACO_TACO, new int[] {taco.f, taco.g, c, d}, "the flat folds of faces " + taco.f + "/"
                        + taco.g + " and " + c + "/" + d + " interleave along " + segment(taco, other));
            }
            return;
        }
        for (int z : new int[] {other.f, other.g}) {
            if (faces.plane[z] == plane && side(faces, z, taco.a, taco.b) == tacoSide && z != taco.f && z != taco.g
                    && faces.between(z, taco.f, taco.g)) {
                findings.add(Kind.TACO_TORTILLA, new int[] {taco.f, taco.g, z}, "face " + z + " goes on across the flat fold of faces "
                        + taco.f + "/" + taco.g + " from between them, along " + segment(taco, other));
            }
        }
    }

    /** 1 where face z lies between the taco's faces, 0 where not, -1 where the file does not say. */
    private static int inside(PlanarFaces faces, int z, Edge taco) {
        int first = faces.above(taco.f, z);
        int second = faces.above(z, taco.g);
        if (first == 0 || second == 0) {
            return -1;
        }
        return first == second ? 1 : 0;
    }

    /**
     * Two pieces of paper going on across one line, f1 → g1 and f2 → g2: where they go from the
     * same side of one plane to the same side of another, the order of f1 and f2 must be that
     * of g1 and g2, up counted the way the paper's top side carries it over.
     */
    private static void crossings(PlanarFaces faces, Edge one, Edge two, Findings findings) {
        int p1 = one.f;
        int q1 = one.g;
        int p2;
        int q2;
        if (sameSide(faces, one.f, two.f, one) && sameSide(faces, one.g, two.g, one)) {
            p2 = two.f;
            q2 = two.g;
        } else if (sameSide(faces, one.f, two.g, one) && sameSide(faces, one.g, two.f, one)) {
            p2 = two.g;
            q2 = two.f;
        } else {
            return;
        }
        if (p1 == p2 || q1 == q2) {
            return;
        }
        int before = faces.above(p1, p2);
        int after = faces.above(q1, q2);
        if (before == 0 || after == 0) {
            return;
        }
        // The up of q's plane that the paper's top side carries over from p's.
        int carried = faces.sigma[p1] * faces.sigma[q1];
        if (before != carried * after) {
            findings.add(Kind.CROSSING, new int[] {p1, q1, p2, q2}, "the paper of faces " + p1 + " → " + q1 + " and " + p2
                    + " → " + q2 + " changes places across " + segment(one, two));
        }
    }

    /** Whether faces x and y lie in one plane on one side of the edge's line. */
    private static boolean sameSide(PlanarFaces faces, int x, int y, Edge edge) {
        return faces.plane[x] == faces.plane[y] && side(faces, x, edge.a, edge.b) == side(faces, y, edge.a, edge.b);
    }

    /**
     * Faces of the taco's plane that its crease's line runs through, within the crease's span:
     * paper going on across the line, which must not lie between the taco's faces.
     */
    private static void facesThrough(PlanarFaces faces, Edge taco, Findings findings) {
        int plane = faces.plane[taco.f];
        double[] frame = faces.frames.get(plane);
        double ax = frame[3] * taco.a[0] + frame[4] * taco.a[1] + frame[5] * taco.a[2];
        double ay = frame[6] * taco.a[0] + frame[7] * taco.a[1] + frame[8] * taco.a[2];
        double bx = frame[3] * taco.b[0] + frame[4] * taco.b[1] + frame[5] * taco.b[2];
        double by = frame[6] * taco.b[0] + frame[7] * taco.b[1] + frame[8] * taco.b[2];
        double length = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
        if (!(length > faces.eps)) {
            return;
        }
        double ux = (bx - ax) / length;
        double uy = (by - ay) / length;
        for (int z : candidates(faces, plane, ax, ay, bx, by)) {
            if (z == taco.f || z == taco.g) {
                continue;
            }
            double[] polygon = faces.polygon[z];
            // How far the face reaches to either side of the line along the crease alone, not
            // at its far corners: a face whose side runs along the crease's line lies beside it,
            // but a slant of rounding (3e-9 rad on the 1.5 degree spike) put that side's far
            // end, 12.6 away, 4e-8 across the line, and the face "through" the crease.
            double[] reach = reachAcross(polygon, ax, ay, ux, uy, length);
            if (!(reach[1] > faces.eps && reach[0] < -faces.eps)) {
                continue;
            }
            double[] span = chord(polygon, ax, ay, ux, uy);
            if (Math.min(span[1], length) - Math.max(span[0], 0) > faces.eps && faces.between(z, taco.f, taco.g)) {
                findings.add(Kind.TACO_TORTILLA, new int[] {taco.f, taco.g, z}, "face " + z + " lies between faces " + taco.f
                        + " and " + taco.g + " across their flat fold along " + segment(taco, taco));
            }
        }
    }

    /**
     * The least and most distance, left of the line through (ax, ay) of unit direction
     * (ux, uy), of the part of a convex polygon within the crease's span along it (0 to
     * {@code length}); {+inf, -inf} where no part of it is.
     */
    static double[] reachAcross(double[] polygon, double ax, double ay, double ux, double uy, double length) {
        double least = Double.POSITIVE_INFINITY;
        double most = Double.NEGATIVE_INFINITY;
        int n = polygon.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double px = polygon[2 * i] - ax;
            double py = polygon[2 * i + 1] - ay;
            double qx = polygon[2 * j] - ax;
            double qy = polygon[2 * j + 1] - ay;
            double pAlong = ux * px + uy * py;
            double qAlong = ux * qx + uy * qy;
            double pAcross = ux * py - uy * px;
            double qAcross = ux * qy - uy * qx;
            if (pAlong >= 0 && pAlong <= length) {
                least = Math.min(least, pAcross);
                most = Math.max(most, pAcross);
            }
            // Where the edge p -> q meets the span's two ends.
            for (double end : new double[] {0, length}) {
                if ((pAlong - end) * (qAlong - end) < 0) {
                    double across = pAcross + (qAcross - pAcross) * (end - pAlong) / (qAlong - pAlong);
                    least = Math.min(least, across);
                    most = Math.max(most, across);
                }
            }
        }
        return new double[] {least, most};
    }

    /** The faces of a plane that share a cell of its grid with the segment, each once. */
    private static int[] candidates(PlanarFaces faces, int plane, double ax, double ay, double bx, double by) {
        PlanarFaces.Grid grid = faces.grid(plane);
        int[][] found = {new int[8]};
        int[] count = {0};
        int mark = faces.nextMark();
        grid.forPolygon(new double[] {ax, ay, bx, by}, key -> {
            int[] list = grid.cells.get(key);
            if (list == null) {
                return;
            }
            for (int i = 1; i <= list[0]; i++) {
                int z = list[i];
                if (faces.marks[z] == mark) {
                    continue;
                }
                faces.marks[z] = mark;
                if (count[0] == found[0].length) {
                    found[0] = Arrays.copyOf(found[0], 2 * count[0]);
                }
                found[0][count[0]++] = z;
            }
        });
        return Arrays.copyOf(found[0], count[0]);
    }

    /** Where the line through (ax, ay) of unit direction (ux, uy) runs inside a convex polygon: its parameters from and to. */
    private static double[] chord(double[] polygon, double ax, double ay, double ux, double uy) {
        double from = Double.NEGATIVE_INFINITY;
        double to = Double.POSITIVE_INFINITY;
        int n = polygon.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = polygon[2 * j] - polygon[2 * i];
            double ey = polygon[2 * j + 1] - polygon[2 * i + 1];
            // Inside is left of each edge: ex * (y - py) - ey * (x - px) >= 0 along a + s u.
            double at = ex * (ay - polygon[2 * i + 1]) - ey * (ax - polygon[2 * i]);
            double rate = ex * uy - ey * ux;
            if (Math.abs(rate) < 1e-300) {
                if (at < 0) {
                    return new double[] {0, -1};
                }
                continue;
            }
            double s = -at / rate;
            if (rate > 0) {
                from = Math.max(from, s);
            } else {
                to = Math.min(to, s);
            }
        }
        return new double[] {from, to};
    }

    /** Where two edges of one line overlap, in space. */
    private static String segment(Edge one, Edge two) {
        double[] t = {one.b[0] - one.a[0], one.b[1] - one.a[1], one.b[2] - one.a[2]};
        double length2 = t[0] * t[0] + t[1] * t[1] + t[2] * t[2];
        double lo = 0;
        double hi = 1;
        if (two != one) {
            double s = ((two.a[0] - one.a[0]) * t[0] + (two.a[1] - one.a[1]) * t[1] + (two.a[2] - one.a[2]) * t[2]) / length2;
            double e = ((two.b[0] - one.a[0]) * t[0] + (two.b[1] - one.a[1]) * t[1] + (two.b[2] - one.a[2]) * t[2]) / length2;
            lo = Math.max(0, Math.min(s, e));
            hi = Math.min(1, Math.max(s, e));
        }
        return at(one, lo) + "–" + at(one, hi);
    }

    private static String at(Edge edge, double s) {
        return String.format(Locale.ROOT, "(%.6g, %.6g, %.6g)", edge.a[0] + s * (edge.b[0] - edge.a[0]),
                edge.a[1] + s * (edge.b[1] - edge.a[1]), edge.a[2] + s * (edge.b[2] - edge.a[2]));
    }

    /** A line's key: its unit direction (times {@code sign}) and its point nearest the origin. */
    private static double[] lineKey(double[] a, double[] b, int sign) {
        double tx = b[0] - a[0];
        double ty = b[1] - a[1];
        double tz = b[2] - a[2];
        double length = Math.sqrt(tx * tx + ty * ty + tz * tz) * sign;
        tx /= length;
        ty /= length;
        tz /= length;
        double along = a[0] * tx + a[1] * ty + a[2] * tz;
        return new double[] {tx, ty, tz, a[0] - along * tx, a[1] - along * ty, a[2] - along * tz};
    }

    private static double[] point(FoldedState state, int v) {
        return new double[] {state.x(v), state.y(v), state.z(v)};
    }
}
