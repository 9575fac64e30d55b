package ifold.wrap;

import ifold.sheet.HostFrame;
import java.util.List;

/**
 * Where the strip crosses a convex edge of the model from a layer high on one host to a lower one
 * across, the cap over the edge (one quad from layer to layer) runs down through the wedge of air
 * beyond the edge, and the bends standing out there from the high side's folds along the same
 * edge (tucks of its earlier paper, their layers under the crossing's) are in its way. Such a cap
 * goes over them instead: from the high layer straight out to the mitre (the plane halving the
 * wedge), at that layer's height, and from there down to the low layer. Every bend of the high
 * side below that layer stays within the room on its side of the mitre (at height z, no farther
 * out than z·tan(φ/2)), so it lies under the first facet; the low side's paper and bends lie on
 * their own side of the mitre, under the second, which rises from the low layer. Other caps over
 * edges stay straight.
 *
 * <p>A path along the refinement's triangles crosses the model's edges only at tree edges, where
 * no fold of the host left stands out under the strip; along the model's own triangles
 * ({@code CycleCoverPath}) the strip crosses an edge between every two triangles, and the edge it
 * leaves a triangle by, or the edge it comes back over to a triangle cut for a splice, has had the
 * excess of that triangle's passes tucked under along it (the 320-triangle icosphere: 18 crossing
 * pairs of such caps, 0.26 to 0.92 T deep).
 */
final class CrossingOverBends {
    private final List<NestedBends.Bend> bends;
    private final double[] outs;
    private final HostFrame[] frames;
    private final double thickness;
    private final double tolerance;
    /** For each host, the bends on it that stand out beyond their crease (out > 0); null where none. */
    private final int[][] standing;

    /**
     * @param bends the flat folds ({@link NestedBends.Bend}: host, crease, the side it stands out to, levels)
     * @param outs how far each stands out beyond its crease
     * @param frames the hosts' frames
     * @param thickness the paper's thickness
     * @param tolerance how near a crease's ends lie to another's line to share it
     */
    CrossingOverBends(List<NestedBends.Bend> bends, double[] outs, HostFrame[] frames, double thickness, double tolerance) {
        this.bends = bends;
        this.outs = outs;
        this.frames = frames;
        this.thickness = thickness;
        this.tolerance = tolerance;
        int[] count = new int[frames.length];
        for (int k = 0; k < bends.size(); k++) {
            if (outs[k] > 0) {
                count[bends.get(k).host()]++;
            }
        }
        standing = new int[frames.length][];
        for (int k = 0; k < bends.size(); k++) {
            if (outs[k] > 0) {
                int host = bends.get(k).host();
                if (standing[host] == null) {
                    standing[host] = new int[count[host]];
                    count[host] = 0;
                }
                standing[host][count[host]++] = k;
            }
        }
    }

    /**
     * Whether the straight cap over the edge along one stretch of a crossing's crease runs through
     * a bend of {@code host} standing out beyond the edge: one whose crease lies on the crossing's
     * line, overlapping the stretch, standing out away from the crossing's face, with its layers
     * under the high one, and whose upper row (where its wall ends: out from the crease, as far
     * under its upper layer) the cap passes inside of.
     *
     * @param crease the crossing's crease on the host's frame, from a to b (ax, ay, bx, by), and a
     *     point of the crossing's face there (x, y)
     * @param t0 where the stretch begins along the crease (0 at a, 1 at b)
     * @param t1 where it ends
     * @param highFrom the high layer's point at t0 (space)
     * @param highTo at t1
     * @param lowFrom the low layer's point across at t0
     * @param lowTo at t1
     */
    boolean runsThrough(int host, double[] crease, double t0, double t1, double[] highFrom, double[] highTo, double[] lowFrom,
            double[] lowTo) {
        if (standing[host] == null || thickness <= 0) {
            return false;
        }
        HostFrame frame = frames[host];
        double ax = crease[0];
        double ay = crease[1];
        double length = Math.hypot(crease[2] - ax, crease[3] - ay);
        if (length <= tolerance || t1 - t0 <= 0) {
            return false;
        }
        double dx = (crease[2] - ax) / length;
        double dy = (crease[3] - ay) / length;
        for (int k : standing[host]) {
            NestedBends.Bend bend = bends.get(k);
            // On the crossing's line, both ends.
            double offA = (bend.ax() - ax) * dy - (bend.ay() - ay) * dx;
            double offB = (bend.bx() - ax) * dy - (bend.by() - ay) * dx;
            if (Math.abs(offA) > tolerance || Math.abs(offB) > tolerance) {
                continue;
            }
            // Standing out beyond the edge, away from the crossing's face.
            if (bend.nx() * (crease[4] - ax) + bend.ny() * (crease[5] - ay) >= 0) {
                continue;
            }
            double upper = (bend.high() + 0.5) * thickness;
            double row = upper - outs[k];
            double tA = ((bend.ax() - ax) * dx + (bend.ay() - ay) * dy) / length;
            double tB = ((bend.bx() - ax) * dx + (bend.by() - ay) * dy) / length;
            double from = Math.max(t0, Math.min(tA, tB));
            double to = Math.min(t1, Math.max(tA, tB));
            if ((to - from) * length <= tolerance) {
                continue;
            }
            for (int end = 0; end < 2; end++) {
                double w = ((end == 0 ? from : to) - t0) / (t1 - t0);
                double[] high = between(highFrom, highTo, w);
                double[] low = between(lowFrom, lowTo, w);
                double zHigh = frame.height(high);
                double zLow = frame.height(low);
                if (upper >= zHigh - thickness / 2 || zLow >= row) {
                    continue; // the bend wraps the crossing's layer, or the cap passes above its row
                }
                // How far out beyond the crease the cap is where it comes down to the row's height.
                double outLow = bend.nx() * (frame.localX(low) - frame.localX(high)) + bend.ny() * (frame.localY(low) - frame.localY(high));
                double outAtRow = outLow * (zHigh - row) / (zHigh - zLow);
                // Inside the corner by any amount: on a stretched octahedron a cap passing 0.005 T
                // inside a rank-2 bend's row crossed its facets 0.1 T deep.
                if (outAtRow < outs[k]) {
                    return true;
                }
            }
        }
        return false;
    }

    /**
     * The mitre of the edge from {@code host} to {@code across} under a crease of the host (given
     * as in {@link #runsThrough}): tan(φ/2) for the turn φ of a convex edge, how far out beyond the
     * edge the plane halving its wedge of air lies per height; 0 where the edge is flat or concave.
     */
    double mitre(int host, int across, double[] crease) {
        double[] n = frames[host].normal();
        double[] m = frames[across].normal();
        double cos = n[0] * m[0] + n[1] * m[1] + n[2] * m[2];
        double sin = Math.sqrt(Math.pow(n[1] * m[2] - n[2] * m[1], 2) + Math.pow(n[2] * m[0] - n[0] * m[2], 2)
                + Math.pow(n[0] * m[1] - n[1] * m[0], 2));
        double[] out = outward(host, crease);
        // Convex where the surface across turns its normal out, away from the host.
        return m[0] * out[0] + m[1] * out[1] + m[2] * out[2] > 0 ? sin / (1 + cos) : 0;
    }

    /** The direction in space, in the host's plane and square to the crease, away from the crossing's face. */
    private double[] outward(int host, double[] crease) {
        HostFrame frame = frames[host];
        double[] n = awayInPlane(crease);
        double[] ex = frame.ex();
        double[] ey = frame.ey();
        return new double[] {n[0] * ex[0] + n[1] * ey[0], n[0] * ex[1] + n[1] * ey[1], n[0] * ex[2] + n[1] * ey[2]};
    }

    /** The unit normal of the crease in its host's plane (x, y), pointing away from the crossing's face (given as in {@link #runsThrough}). */
    private static double[] awayInPlane(double[] crease) {
        double length = Math.hypot(crease[2] - crease[0], crease[3] - crease[1]);
        double nx = (crease[3] - crease[1]) / length;
        double ny = -(crease[2] - crease[0]) / length;
        if (nx * (crease[4] - crease[0]) + ny * (crease[5] - crease[1]) > 0) {
            nx = -nx;
            ny = -ny;
        }
        return new double[] {nx, ny};
    }

    /**
     * The point on the mitre over the edge at the height of {@code high}, a point of the high
     * layer's crease on {@code host}: {@code high} moved out beyond the crease (given as in
     * {@link #runsThrough}), away from the crossing's face, by its height times tan(φ/2), {@code slope}.
     */
    double[] overMitre(int host, double[] crease, double[] high, double slope) {
        HostFrame frame = frames[host];
        double[] n = awayInPlane(crease);
        double z = frame.height(high);
        double[] point = new double[3];
        frame.toSpace(frame.localX(high) + n[0] * z * slope, frame.localY(high) + n[1] * z * slope, z, point, 0);
        return point;
    }

    private static double[] between(double[] a, double[] b, double w) {
        return new double[] {a[0] + w * (b[0] - a[0]), a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2])};
    }
}
