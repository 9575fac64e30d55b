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
     * Whether model point p, on a triangle of outward normal n, lies within the widest creep zone
     * of the model's concave edges of a crept face on its plane (one truth 2 let stand back from
     * a concave edge): where layers joined at a crease creep by different amounts, the crease
     * opens a sliver no wider than that, which can run from the edge along the crease; a gap
     * any wider, or beside paper that did not creep, is a hole. Folds back to back on one
     * crease stand back from it by {@code foldCreep} (a thickness) at most: under their bends.
     */
    static boolean nearPaper(double[] p, double[] n, Faces geometry, List<TruthIsometry.ConcaveSide> concave, double top, double eps,
            Ints candidates, boolean[] crept, double foldCreep) {
        double widest = foldCreep;
        for (TruthIsometry.ConcaveSide side : concave) {
            widest = Math.max(widest, top * (side.mitre() + 1));
        }
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
            if (crept[f] && depthOver(geometry, f, p, n, top, eps) >= -widest - eps) {
                return true;
            }
        }
        return false;
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

    void checkCovered(TruthReport report, TruthModel model, Faces geometry, double eps, double top, int samples, long seed,
            List<TruthIsometry.ConcaveSide> concave, boolean[] crept, double foldCreep) {
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
            if (!covered && !inCreepZone(p, n, concave, top, eps) && !nearPaper(p, n, geometry, concave, top, eps, candidates, crept, foldCreep)) {
                uncovered++;
                report.add(WrapTruths.COVERED, "model point " + WrapTruths.point(p) + " of triangle " + (t + 1) + " lies under no paper face");
            }
        }
        if (uncovered > 0) {
            report.summary(WrapTruths.COVERED, uncovered + " of " + samples + " model points lie under no paper");
        }
    }
}
