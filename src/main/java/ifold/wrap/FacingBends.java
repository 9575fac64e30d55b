package ifold.wrap;

import ifold.geom.IntList;
import ifold.sheet.LongIntMap;
import ifold.sheet.Polygons2;
import java.util.Arrays;
import java.util.List;

/**
 * Bends that stand out towards a fold in front of them stand out no farther than halfway to its
 * crease.
 *
 * <p>A bend that wraps folds on its line steps out beyond them ({@link NestedBends}), into the
 * band in front of its crease. Another fold of the same host whose crease runs through that band,
 * facing back (its layers beyond its crease, its bend towards this one), with layers between this
 * one's, stands its wall there: the bend stepped out through it. At a corner of a host where a
 * pass's end is folded under along a crease from the corner and the next fold runs from the same
 * corner a few degrees off it, the tuck's outer bend (rank 1) stood out a thickness towards the
 * other's wall, which stood 0.2 to 2 T off its crease: 28 of 40 random star-shaped icosahedra
 * crossed so, up to 0.68 T deep. Each bend now stands out at most half the least distance to such
 * a crease along its own (the other, standing out towards it, takes the other half), and those it
 * wraps less still ({@link NestedBends#keepNested}).
 */
final class FacingBends {
    private FacingBends() {
    }

    /**
     * Limits how far each bend stands out ({@code out}, changed in place): to half the distance
     * from its crease to the nearest crease of a bend facing it in front of it, along its own
     * crease's span, where that is less than twice {@code out}.
     *
     * @param bends the flat folds, each in its host's frame
     * @param out how far each stands out beyond its crease (0: on its crease)
     * @param tolerance creases within this of a line are on it: such a crease is nested with the
     *     bend ({@link NestedBends}), not in front of it
     */
    static void keepApart(List<NestedBends.Bend> bends, double[] out, double tolerance) {
        double most = 0;
        double length = 0;
        for (int k = 0; k < bends.size(); k++) {
            most = Math.max(most, out[k]);
            length += length(bends.get(k));
        }
        if (!(most > 0)) {
            return;
        }
        // Cells about a crease long, and at least twice as wide as any bend's reach: each crease
        // lies in a few, and a bend's reach in the cells its own crease lies in and those beside.
        double cell = Math.max(4 * most, length / bends.size());
        LongIntMap heads = new LongIntMap();
        IntList entries = new IntList(); // bend, next entry of its cell (-1: none), each
        for (int j = 0; j < bends.size(); j++) {
            NestedBends.Bend bend = bends.get(j);
            long last = -1;
            int steps = (int) Math.ceil(2 * length(bend) / cell);
            for (int s = 0; s <= steps; s++) {
                double t = (double) s / steps;
                long key = cell(bend.host(), Math.floor((bend.ax() + t * (bend.bx() - bend.ax())) / cell),
                        Math.floor((bend.ay() + t * (bend.by() - bend.ay())) / cell));
                if (key != last) {
                    entries.add(j);
                    entries.add(heads.get(key, -1));
                    heads.put(key, entries.size() / 2 - 1);
                    last = key;
                }
            }
        }
        double[] limit = out.clone();
        int[] seen = new int[bends.size()];
        Arrays.fill(seen, -1);
        long[] walked = new long[36]; // the cells walked for the bend at hand, x and y each
        for (int k = 0; k < bends.size(); k++) {
            if (!(out[k] > 0)) {
                continue;
            }
            NestedBends.Bend bend = bends.get(k);
            int steps = (int) Math.ceil(2 * length(bend) / cell);
            // The cells round one step overlap those round the next in six of nine: each is walked once a bend.
            if (walked.length < 18 * (steps + 1)) {
                walked = new long[18 * (steps + 1)];
            }
            int walkedCount = 0;
            for (int s = 0; s <= steps; s++) {
                double t = (double) s / steps;
                long cx = (long) Math.floor((bend.ax() + t * (bend.bx() - bend.ax()) + out[k] * bend.nx()) / cell);
                long cy = (long) Math.floor((bend.ay() + t * (bend.by() - bend.ay()) + out[k] * bend.ny()) / cell);
                for (long i = cx - 1; i <= cx + 1; i++) {
                    for (long m = cy - 1; m <= cy + 1; m++) {
                        if (walkedBefore(walked, walkedCount, i, m)) {
                            continue;
                        }
                        walked[walkedCount++] = i;
                        walked[walkedCount++] = m;
                        for (int e = heads.get(cell(bend.host(), i, m), -1); e >= 0; e = entries.get(2 * e + 1)) {
                            int j = entries.get(2 * e);
                            if (seen[j] == k || j == k) {
                                continue;
                            }
                            seen[j] = k;
                            double gap = gap(bend, bends.get(j), tolerance);
                            if (gap < 2 * out[k]) {
                                limit[k] = Math.min(limit[k], gap / 2);
                            }
                        }
                    }
                }
            }
        }
        System.arraycopy(limit, 0, out, 0, out.length);
    }

    /**
     * The least distance in front of bend b's crease (on the side it stands out to) of other's
     * crease along b's span, where other faces b (stands out back towards it), its layers meet
     * b's between them, and its crease lies wholly in front there; infinity where not.
     */
    private static double gap(NestedBends.Bend b, NestedBends.Bend other, double tolerance) {
        if (other.host() != b.host() || Math.max(b.low(), other.low()) >= Math.min(b.high(), other.high())
                || b.nx() * other.nx() + b.ny() * other.ny() >= 0) {
            return Double.POSITIVE_INFINITY;
        }
        double length = length(b);
        double dx = (b.bx() - b.ax()) / length;
        double dy = (b.by() - b.ay()) / length;
        double ta = (other.ax() - b.ax()) * dx + (other.ay() - b.ay()) * dy;
        double tb = (other.bx() - b.ax()) * dx + (other.by() - b.ay()) * dy;
        double oa = (other.ax() - b.ax()) * b.nx() + (other.ay() - b.ay()) * b.ny();
        double ob = (other.bx() - b.ax()) * b.nx() + (other.by() - b.ay()) * b.ny();
        if (Math.max(ta, tb) <= 0 || Math.min(ta, tb) >= length) {
            return Double.POSITIVE_INFINITY; // beside b's span, not in front of it
        }
        double o0 = oa;
        double o1 = ob;
        if (ta != tb) {
            // Clipped to b's span: the offsets where other's crease enters and leaves it.
            double s0 = Math.max(0, Math.min(1, (0 - ta) / (tb - ta)));
            double s1 = Math.max(0, Math.min(1, (length - ta) / (tb - ta)));
            o0 = oa + Math.min(s0, s1) * (ob - oa);
            o1 = oa + Math.max(s0, s1) * (ob - oa);
        }
        double gap = Math.min(o0, o1);
        return gap > tolerance ? gap : Double.POSITIVE_INFINITY; // on b's line, behind it or across it
    }

    private static boolean walkedBefore(long[] walked, int count, long i, long m) {
        for (int w = 0; w < count; w += 2) {
            if (walked[w] == i && walked[w + 1] == m) {
                return true;
            }
        }
        return false;
    }

    private static double length(NestedBends.Bend bend) {
        return Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
    }

    private static long cell(int host, double cx, double cy) {
        return cell(host, (long) cx, (long) cy);
    }

    private static long cell(int host, long cx, long cy) {
        return ((cx * 0x9E3779B97F4A7C15L ^ cy) * 31 + host) & Long.MAX_VALUE; // a LongIntMap's keys are not negative
    }
}
