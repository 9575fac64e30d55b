package ifold.check;

import java.util.HashSet;

/**
 * Truth 3 of {@link WrapTruths}: faces that are neighbours on the sheet are neighbours in space,
 * or bridged by a cap.
 */
final class TruthNeighbours {
    private final WrapTruths wrap;

    TruthNeighbours(WrapTruths wrap) {
        this.wrap = wrap;
    }

    void checkNotTorn(TruthReport report, double eps, double capReach) {
        double[] a = new double[3];
        double[] b = new double[3];
        for (int s = 0; s < wrap.strips(); s++) {
            int[] paper = wrap.stripPaper.get(s);
            // Paper coordinates are good to about 1e-16 of the strip's length; edges closer than a
            // billionth of its width are the same line. (A billionth of a long strip's length would
            // take the edge of a sliver near the border for the border itself.)
            double tol = WrapTruths.RELATIVE * wrap.stripW[s] + 1e-13 * wrap.stripL[s];
            Ints edgeCorner = new Ints();
            Ints edgeFace = new Ints();
            for (int f : paper) {
                for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                    edgeCorner.add(c);
                    edgeFace.add(f);
                }
            }
            int edges = edgeCorner.size();
            if (edges == 0) {
                continue;
            }
            double[] boxes = new double[6 * edges];
            for (int e = 0; e < edges; e++) {
                int ta = wrap.cornerT[edgeCorner.get(e)];
                int tb = wrap.cornerT[nextCorner(edgeFace.get(e), edgeCorner.get(e))];
                boxes[6 * e] = Math.min(wrap.uv[2 * ta], wrap.uv[2 * tb]) - tol;
                boxes[6 * e + 1] = Math.min(wrap.uv[2 * ta + 1], wrap.uv[2 * tb + 1]) - tol;
                boxes[6 * e + 3] = Math.max(wrap.uv[2 * ta], wrap.uv[2 * tb]) + tol;
                boxes[6 * e + 4] = Math.max(wrap.uv[2 * ta + 1], wrap.uv[2 * tb + 1]) + tol;
            }
            TruthGrid grid = new TruthGrid(boxes, edges, TruthGrid.cellFor(boxes, edges, tol));
            int[] caps = capVertices(s);
            TruthGrid capGrid = wrap.tiling.pointGrid(caps, eps);
            Ints candidates = new Ints();
            Ints near = new Ints();
            HashSet<Long> reported = new HashSet<>();
            double[] shared = new double[4];
            for (int e = 0; e < edges; e++) {
                grid.query(boxes[6 * e], boxes[6 * e + 1], 0, boxes[6 * e + 3], boxes[6 * e + 4], 0, candidates);
                int f = edgeFace.get(e);
                for (int k = 0; k < candidates.size(); k++) {
                    int g = candidates.get(k);
                    int h = edgeFace.get(g);
                    if (g <= e || h == f || !sharedSegment(f, edgeCorner.get(e), h, edgeCorner.get(g), tol, shared)) {
                        continue;
                    }
                    if (wrap.surface.squashed(f) && wrap.surface.squashed(h)) {
                        continue; // paper squashed where two layers end by a concave edge: no bend between
                    }
                    for (int end = 0; end < 2; end++) {
                        double u = shared[2 * end];
                        double v = shared[2 * end + 1];
                        onSide(f, edgeCorner.get(e), u, v, a);
                        onSide(h, edgeCorner.get(g), u, v, b);
                        double apart = WrapTruths.distance(a, 0, b, 0);
                        if (apart <= eps) {
                            continue;
                        }
                        boolean capped = apart <= capReach && nearAny(capGrid, caps, a, eps, near) && nearAny(capGrid, caps, b, eps, near);
                        if (!capped && reported.add(((long) Math.min(f, h) << 32) | Math.max(f, h))) {
                            report.add(WrapTruths.NOT_TORN, wrap.face(f) + " and " + wrap.face(h) + " meet on the sheet along "
                                    + WrapTruths.point(shared[0], shared[1]) + " - " + WrapTruths.point(shared[2], shared[3]) + " but at " + WrapTruths.point(u, v)
                                    + " they are " + apart + " apart in space, at " + WrapTruths.point(a) + " and " + WrapTruths.point(b)
                                    + (apart > capReach ? ", more than a cap can bridge (" + capReach + ")" : ", with no cap there"));
                        }
                    }
                }
            }
        }
    }

    /**
     * Face f's point in space at sheet point (u, v) on its side from corner c: between the side's
     * two corners as they lie, as far along as the point is. Two sides lie on one line to the
     * shared segment's tolerance, which is wider along a long strip than the billionth of the face
     * by which the point was taken to lie on the side: beyond that, it was mapped through three
     * corners of the face, and a face whose corners are not its rigid image (squashed onto a wall,
     * standing back from a concave edge) put it elsewhere. The CGAL elephant with holes had 18
     * "tears" so, each between a piece along the strip's border and one squashed above it whose
     * side ran up from the border at a slope of 10⁻⁵.
     */
    void onSide(int f, int c, double u, double v, double[] out) {
        // A corner of the face at the point is where the face puts it, whichever side was paired
        // (the cow's sliver of a side 2.6e-9 long lay on the line of another side of its face to
        // the tolerance, and read along that one, its corner came out 2.6e-9 from its cap).
        double near = WrapTruths.RELATIVE * Math.max(wrap.surface.sheetSize(f), wrap.stripW[wrap.faceStrip[f]]);
        for (int k = wrap.faceStart[f]; k < wrap.faceStart[f + 1]; k++) {
            if (Math.hypot(wrap.uv[2 * wrap.cornerT[k]] - u, wrap.uv[2 * wrap.cornerT[k] + 1] - v) <= near) {
                System.arraycopy(wrap.xyz, 3 * wrap.cornerV[k], out, 0, 3);
                return;
            }
        }
        int n = nextCorner(f, c);
        int a = wrap.cornerT[c];
        int b = wrap.cornerT[n];
        double su = wrap.uv[2 * b] - wrap.uv[2 * a];
        double sv = wrap.uv[2 * b + 1] - wrap.uv[2 * a + 1];
        double along = Math.max(0, Math.min(1, ((u - wrap.uv[2 * a]) * su + (v - wrap.uv[2 * a + 1]) * sv) / (su * su + sv * sv)));
        for (int d = 0; d < 3; d++) {
            out[d] = wrap.xyz[3 * wrap.cornerV[c] + d] + along * (wrap.xyz[3 * wrap.cornerV[n] + d] - wrap.xyz[3 * wrap.cornerV[c] + d]);
        }
    }

    int nextCorner(int f, int c) {
        return c + 1 < wrap.faceStart[f + 1] ? c + 1 : wrap.faceStart[f];
    }

    /**
     * Whether the sheet edge of face f from corner cf and that of face g from corner cg lie on one
     * line and overlap over more than tol; if so, shared gets the overlap's ends u0 v0 u1 v1.
     */
    boolean sharedSegment(int f, int cf, int g, int cg, double tol, double[] shared) {
        int p0 = wrap.cornerT[cf];
        int p1 = wrap.cornerT[nextCorner(f, cf)];
        int q0 = wrap.cornerT[cg];
        int q1 = wrap.cornerT[nextCorner(g, cg)];
        double lp = Math.hypot(wrap.uv[2 * p1] - wrap.uv[2 * p0], wrap.uv[2 * p1 + 1] - wrap.uv[2 * p0 + 1]);
        double lq = Math.hypot(wrap.uv[2 * q1] - wrap.uv[2 * q0], wrap.uv[2 * q1 + 1] - wrap.uv[2 * q0 + 1]);
        // Measure along the longer edge: its direction is the better known.
        if (lq > lp) {
            int t = p0;
            p0 = q0;
            q0 = t;
            t = p1;
            p1 = q1;
            q1 = t;
            lp = lq;
        }
        if (!(lp > tol)) {
            return false;
        }
        double du = (wrap.uv[2 * p1] - wrap.uv[2 * p0]) / lp;
        double dv = (wrap.uv[2 * p1 + 1] - wrap.uv[2 * p0 + 1]) / lp;
        double s0 = 0;
        double s1 = 0;
        for (int k = 0; k < 2; k++) {
            int q = k == 0 ? q0 : q1;
            double ru = wrap.uv[2 * q] - wrap.uv[2 * p0];
            double rv = wrap.uv[2 * q + 1] - wrap.uv[2 * p0 + 1];
            if (Math.abs(du * rv - dv * ru) > tol) {
                return false;
            }
            if (k == 0) {
                s0 = du * ru + dv * rv;
            } else {
                s1 = du * ru + dv * rv;
            }
        }
        double lo = Math.max(0, Math.min(s0, s1));
        double hi = Math.min(lp, Math.max(s0, s1));
        if (!(hi - lo > tol)) {
            return false;
        }
        // The overlap ends at corners: take their own coordinates, not ones recomputed along the line.
        int from = lo == 0 ? p0 : s0 < s1 ? q0 : q1;
        int to = hi == lp ? p1 : s0 < s1 ? q1 : q0;
        // Lexicographic order, so that messages name a shared segment one way.
        if (wrap.uv[2 * to] < wrap.uv[2 * from] || wrap.uv[2 * to] == wrap.uv[2 * from] && wrap.uv[2 * to + 1] < wrap.uv[2 * from + 1]) {
            int t = from;
            from = to;
            to = t;
        }
        shared[0] = wrap.uv[2 * from];
        shared[1] = wrap.uv[2 * from + 1];
        shared[2] = wrap.uv[2 * to];
        shared[3] = wrap.uv[2 * to + 1];
        return true;
    }

    double sheetDistance(int ca, int cb) {
        int a = wrap.cornerT[ca];
        int b = wrap.cornerT[cb];
        return Math.hypot(wrap.uv[2 * b] - wrap.uv[2 * a], wrap.uv[2 * b + 1] - wrap.uv[2 * a + 1]);
    }

    /** The vertices of strip s's cap faces, each once. */
    int[] capVertices(int s) {
        Ints out = new Ints();
        HashSet<Integer> seen = new HashSet<>();
        for (int f : wrap.stripCaps.get(s)) {
            for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                if (seen.add(wrap.cornerV[c])) {
                    out.add(wrap.cornerV[c]);
                }
            }
        }
        return out.toArray();
    }

    boolean nearAny(TruthGrid grid, int[] vertices, double[] p, double eps, Ints near) {
        grid.query(p[0] - eps, p[1] - eps, p[2] - eps, p[0] + eps, p[1] + eps, p[2] + eps, near);
        for (int k = 0; k < near.size(); k++) {
            if (WrapTruths.distance(wrap.xyz, 3 * vertices[near.get(k)], p, 0) <= eps) {
                return true;
            }
        }
        return false;
    }
}
