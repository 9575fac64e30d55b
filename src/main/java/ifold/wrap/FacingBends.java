package ifold.wrap;

import ifold.io.Workers;
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
        int n = bends.size();
        double most = 0;
        double length = 0;
        for (int k = 0; k < n; k++) {
            most = Math.max(most, out[k]);
            length += length(bends.get(k));
        }
        if (!(most > 0)) {
            return;
        }
        // What the quick tests below read, in arrays: a bend meets a hundred others in its cells
        // (the 5,120-triangle icosphere: 17.5 million pairs), nearly all on another host, apart
        // in levels or not facing it.
        int[] host = new int[n];
        int[] low = new int[n];
        int[] high = new int[n];
        double[] nx = new double[n];
        double[] ny = new double[n];
        for (int k = 0; k < n; k++) {
            NestedBends.Bend bend = bends.get(k);
            host[k] = bend.host();
            low[k] = bend.low();
            high[k] = bend.high();
            nx[k] = bend.nx();
            ny[k] = bend.ny();
        }
        // Cells about a crease long, and at least twice as wide as any bend's reach: each crease
        // lies in a few, and a bend's reach in the cells its own crease lies in and those beside.
        // A cell's bends in a chain: its last entry by the cell, each entry's bend and the entry before.
        double cell = Math.max(4 * most, length / n);
        LongIntMap heads = new LongIntMap();
        int[] bendOf = new int[2 * n + 16];
        int[] before = new int[2 * n + 16];
        int entries = 0;
        for (int j = 0; j < n; j++) {
            NestedBends.Bend bend = bends.get(j);
            long last = -1;
            int steps = (int) Math.ceil(2 * length(bend) / cell);
            for (int s = 0; s <= steps; s++) {
                double t = (double) s / steps;
                long key = cell(bend.host(), Math.floor((bend.ax() + t * (bend.bx() - bend.ax())) / cell),
                        Math.floor((bend.ay() + t * (bend.by() - bend.ay())) / cell));
                if (key != last) {
                    if (entries == bendOf.length) {
                        bendOf = Arrays.copyOf(bendOf, 2 * entries);
                        before = Arrays.copyOf(before, 2 * entries);
                    }
                    bendOf[entries] = j;
                    before[entries] = heads.get(key, -1);
                    heads.put(key, entries++);
                    last = key;
                }
            }
        }
        // Each bend's limit is its own to write: the bends are shared out among the threads (on
        // two cores a seventh of placing the 5,000-triangle torus's paper ran here, on one).
        Grid grid = new Grid(bends, out, host, low, high, nx, ny, cell, heads, bendOf, before, tolerance);
        double[] limit = new double[n];
        Workers.forChunks(n, 4096, () -> new Scratch(n), (from, to, scratch) -> {
            for (int k = from; k < to; k++) {
                limit[k] = grid.limit(k, scratch);
            }
        });
        System.arraycopy(limit, 0, out, 0, out.length);
    }

    /** What a thread of {@link #keepApart} works in: the bend each other was last met for, and the cells stepped through. */
    private static final class Scratch {
        final int[] seen;
        long[] centres = new long[16]; // the distinct cells stepped through for the bend at hand, x and y each

        Scratch(int n) {
            seen = new int[n];
            Arrays.fill(seen, -1);
        }
    }

    /**
     * The bends in cells {@code cellSize} across by host (a cell's last entry by its key in
     * {@code heads}; each entry's bend and the entry before it), with the fields the quick tests read.
     */
    private record Grid(List<NestedBends.Bend> bends, double[] out, int[] host, int[] low, int[] high, double[] nx, double[] ny,
            double cellSize, LongIntMap heads, int[] bendOf, int[] before, double tolerance) {
        /** How far bend k may stand out: its out, or half the gap to the nearest bend facing it in front, where that is less. */
        double limit(int k, Scratch scratch) {
            double limit = out[k];
            if (!(out[k] > 0)) {
                return limit;
            }
            int[] seen = scratch.seen;
            NestedBends.Bend bend = bends.get(k);
            int steps = (int) Math.ceil(2 * length(bend) / cellSize);
            if (scratch.centres.length < 2 * (steps + 1)) {
                scratch.centres = new long[2 * (steps + 1)];
            }
            long[] centres = scratch.centres;
            int centreCount = 0;
            for (int s = 0; s <= steps; s++) {
                double t = (double) s / steps;
                long cx = (long) Math.floor((bend.ax() + t * (bend.bx() - bend.ax()) + out[k] * bend.nx()) / cellSize);
                long cy = (long) Math.floor((bend.ay() + t * (bend.by() - bend.ay()) + out[k] * bend.ny()) / cellSize);
                if (centreCount > 0 && centres[centreCount - 2] == cx && centres[centreCount - 1] == cy) {
                    continue;
                }
                // The cells round one step overlap those round the one before in six of nine:
                // each is walked once a bend, those round an earlier step passed over.
                for (long i = cx - 1; i <= cx + 1; i++) {
                    for (long m = cy - 1; m <= cy + 1; m++) {
                        if (besideEarlier(centres, centreCount, i, m)) {
                            continue;
                        }
                        for (int e = heads.get(cell(host[k], i, m), -1); e >= 0; e = before[e]) {
                            int j = bendOf[e];
                            if (seen[j] == k || j == k) {
                                continue;
                            }
                            seen[j] = k;
                            if (host[j] != host[k] || Math.max(low[k], low[j]) >= Math.min(high[k], high[j])
                                    || nx[k] * nx[j] + ny[k] * ny[j] >= 0) {
                                continue; // as gap() finds first: no facing fold
                            }
                            double gap = gap(bend, bends.get(j), tolerance);
                            if (gap < 2 * out[k]) {
                                limit = Math.min(limit, gap / 2);
                            }
                        }
                    }
                }
                centres[centreCount++] = cx;
                centres[centreCount++] = cy;
            }
            return limit;
        }
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

    /** Whether cell (i, m) lies beside or on one of the first {@code count / 2} cells in {@code centres}. */
    private static boolean besideEarlier(long[] centres, int count, long i, long m) {
        for (int c = 0; c < count; c += 2) {
            if (Math.abs(centres[c] - i) <= 1 && Math.abs(centres[c + 1] - m) <= 1) {
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
