package ifold.check;

import ifold.check.WrapTruths.Faces;
import java.util.List;
import java.util.SplittableRandom;

/**
 * Truth 4 of {@link WrapTruths}: random points of the model lie under paper (or, next to a
 * concave edge, within its creep zone).
 */
final class TruthCoverage {
    private final WrapTruths wrap;

    TruthCoverage(WrapTruths wrap) {
        this.wrap = wrap;
    }

    /**
     * Whether model point p, on a triangle of outward normal n, lies within the creep zone of a
     * concave edge: thick layers stand back from such an edge (truth 2), and the surface next to
     * it lies under the paper across, not under paper on its own plane.
     */
    static boolean inCreepZone(double[] p, double[] n, List<TruthIsometry.ConcaveSide> concave, double top, double eps) {
        for (TruthIsometry.ConcaveSide side : concave) {
            double[] m = side.normal();
            if (TruthIsometry.times(m, n) < 1 - 1e-9) {
                continue;
            }
            double width = top * (side.mitre() + 1);
            double[] along = TruthIsometry.minus(side.b(), side.a());
            double length = Math.sqrt(TruthIsometry.times(along, along));
            for (int d = 0; d < 3; d++) {
                along[d] /= length;
            }
            double[] q = TruthIsometry.minus(p, side.a());
            double s = TruthIsometry.times(q, along);
            double inside = TruthIsometry.times(q, TruthIsometry.crossed(m, along));
            if (Math.abs(TruthIsometry.times(q, m)) <= eps && s >= -width && s <= length + width && inside >= -eps && inside <= width) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether model point p, on a triangle of outward normal n, lies within {@code widest} of a
     * crept face on a plane parallel to its own (one truth 2 let stand back from a concave edge
     * or a cut between coplanar hosts): where layers joined at a crease creep by different
     * amounts, the crease opens a sliver no wider than the widest creep zone, which can run from
     * the edge along the crease; and a fold nested along a cut stands back a thickness for each
     * fold wrapping it along the whole of its crease, beyond where those folds end, over bare
     * surface no wider than that. A gap any wider, or beside paper that did not creep, is a hole.
     */
    boolean nearPaper(double[] p, double[] n, Faces geometry, double top, double eps, Ints candidates, boolean[] crept, double widest) {
        if (widest == 0) {
            return false;
        }
        double reach = top + eps;
        double around = widest + eps;
        geometry.grid.query(Math.min(p[0], p[0] + reach * n[0]) - around, Math.min(p[1], p[1] + reach * n[1]) - around,
                Math.min(p[2], p[2] + reach * n[2]) - around, Math.max(p[0], p[0] + reach * n[0]) + around,
                Math.max(p[1], p[1] + reach * n[1]) + around, Math.max(p[2], p[2] + reach * n[2]) + around, candidates);
        for (int k = 0; k < candidates.size(); k++) {
            int f = geometry.paper[candidates.get(k)];
            if (crept[f] && (depthOver(geometry, f, p, n, top, eps) >= -widest - eps || gapTo(f, p, n, top, eps) <= widest + eps)) {
                return true;
            }
        }
        return false;
    }

    /**
     * How far model point p, on a triangle of outward normal n, lies across from crept face f, seen
     * along n: 0 under it, else the distance to its nearest side; infinity where a corner of f is
     * not between 0 and {@code top} above p, or its corners are not equally high above p's plane
     * (to {@code eps}: f lies on a plane parallel to the triangle's). Unlike {@link #depthOver}
     * this does not ask f's own normal: the crept faces at a bend are often squashed to slivers
     * (the paper that went into the bend), whose normal is noise; they lie where the bend begins.
     */
    double gapTo(int f, double[] p, double[] n, double top, double eps) {
        int start = wrap.faceStart[f];
        int count = wrap.faceStart[f + 1] - start;
        // The corners seen along n, in a frame (e1, e2) of the plane across n through p.
        double[] e1 = TruthIsometry.crossed(n, Math.abs(n[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0});
        double l1 = Math.sqrt(TruthIsometry.times(e1, e1));
        for (int d = 0; d < 3; d++) {
            e1[d] /= l1;
        }
        double[] e2 = TruthIsometry.crossed(n, e1);
        double[] u = new double[count];
        double[] v = new double[count];
        double lowest = Double.POSITIVE_INFINITY;
        double highest = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < count; i++) {
            int c = 3 * wrap.cornerV[start + i];
            double[] r = {wrap.xyz[c] - p[0], wrap.xyz[c + 1] - p[1], wrap.xyz[c + 2] - p[2]};
            double height = TruthIsometry.times(r, n);
            lowest = Math.min(lowest, height);
            highest = Math.max(highest, height);
            if (height < -eps || height > top + eps || highest - lowest > eps) {
                return Double.POSITIVE_INFINITY;
            }
            u[i] = TruthIsometry.times(r, e1);
            v[i] = TruthIsometry.times(r, e2);
        }
        boolean inside = false;
        double nearest = Double.POSITIVE_INFINITY;
        for (int i = 0, j = count - 1; i < count; j = i++) {
            if ((v[i] > 0) != (v[j] > 0) && 0 < u[j] + (u[i] - u[j]) * (0 - v[j]) / (v[i] - v[j])) {
                inside = !inside;
            }
            double du = u[i] - u[j];
            double dv = v[i] - v[j];
            double lengthSquared = du * du + dv * dv;
            double t = lengthSquared == 0 ? 0 : Math.max(0, Math.min(1, -(u[j] * du + v[j] * dv) / lengthSquared));
            nearest = Math.min(nearest, Math.hypot(u[j] + t * du, v[j] + t * dv));
        }
        return inside ? 0 : nearest;
    }

    /**
     * How deep model point p, on a triangle of outward normal n, lies under paper face f, seen
     * along n (positive inside it, negative beyond its edges); minus infinity where f is not
     * parallel to the triangle, or not between 0 and {@code top} above it.
     */
    static double depthOver(Faces geometry, int f, double[] p, double[] n, double top, double eps) {
        if (!WrapTruths.parallel(geometry.normal(f), n)) {
            return Double.NEGATIVE_INFINITY;
        }
        double[] centre = geometry.centre(f);
        double height = n[0] * (centre[0] - p[0]) + n[1] * (centre[1] - p[1]) + n[2] * (centre[2] - p[2]);
        if (height < -eps || height > top + eps) {
            return Double.NEGATIVE_INFINITY;
        }
        return geometry.spaceDepth(f, new double[] {p[0] + height * n[0], p[1] + height * n[1], p[2] + height * n[2]});
    }

    /**
     * Truth 4. {@code concave}: the model's concave sides, whose creep zones lie under the paper
     * across; {@code creepWidth}: the widest gap beside crept paper that is no hole ({@link
     * #nearPaper}).
     */
    void checkCovered(TruthReport report, TruthModel model, Faces geometry, double eps, double top, int samples, long seed,
            List<TruthIsometry.ConcaveSide> concave, boolean[] crept, double creepWidth) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] p = new double[3];
        Ints candidates = new Ints();
        int uncovered = 0;
        for (int i = 0; i < samples; i++) {
            int t = model.pick(random.nextDouble());
            double r1 = Math.sqrt(random.nextDouble());
            double r2 = random.nextDouble();
            double[] n = model.normal(t);
            for (int d = 0; d < 3; d++) {
                p[d] = (1 - r1) * model.corners[9 * t + d] + r1 * (1 - r2) * model.corners[9 * t + 3 + d]
                        + r1 * r2 * model.corners[9 * t + 6 + d];
            }
            // Paper over p meets the segment from p up to the highest paper may lie.
            double reach = top + eps;
            geometry.grid.query(Math.min(p[0], p[0] + reach * n[0]) - eps, Math.min(p[1], p[1] + reach * n[1]) - eps,
                    Math.min(p[2], p[2] + reach * n[2]) - eps, Math.max(p[0], p[0] + reach * n[0]) + eps,
                    Math.max(p[1], p[1] + reach * n[1]) + eps, Math.max(p[2], p[2] + reach * n[2]) + eps, candidates);
            boolean covered = false;
            for (int k = 0; k < candidates.size() && !covered; k++) {
                covered = depthOver(geometry, geometry.paper[candidates.get(k)], p, n, top, eps) >= -eps;
            }
            if (!covered && !inCreepZone(p, n, concave, top, eps) && !nearPaper(p, n, geometry, top, eps, candidates, crept, creepWidth)) {
                uncovered++;
                report.add(WrapTruths.COVERED, "model point " + WrapTruths.point(p) + " of triangle " + (t + 1) + " lies under no paper face");
            }
        }
        if (uncovered > 0) {
            report.summary(WrapTruths.COVERED, uncovered + " of " + samples + " model points lie under no paper");
        }
    }
}
