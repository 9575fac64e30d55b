package ifold.wrap;

import ifold.sheet.LongIntMap;
import java.util.Arrays;
import java.util.List;

/**
 * Rows of bends stopped on flat paper that leaves their crease's end at an angle.
 *
 * <p>A bend that wraps folds on its line stands out in front of its crease ({@link NestedBends}).
 * Paper lying between its layers may reach its crease from in front where the layer order lets
 * it, and a face that does so only at the crease's end, leaving it at an angle into the band the
 * bend stands out into, met the bend's row out there: on a lone hexagon fanned from its centre a
 * bend of rank 2 on the line from a corner to the centre stood out 0.41 T, and a face tucked
 * between its layers left the same corner 30 degrees off that line (2 crossing pairs, 0.24 T;
 * an irregular hexagonal prism 4, 0.93 T; the shared hex_prism 4, 1.00 T). Halving the distance to that paper, as
 * {@link FacingBends} does for a fold's crease, gives nothing: the paper reaches the crease at
 * its end. The row stops on the face's side instead, as it stops on another crease's wall at a
 * corner ({@link NestedBends#mitres}): the bend's end is cut along that side, and the bend keeps
 * to the wedge between the crease and the paper.
 */
final class RowsOnPaper {
    /**
     * Sides leaving within about 6 degrees of the crease are not mitred on, as creases are not
     * ({@code NestedBends.MITRED_SINE}): the mitre would lie far along the crease.
     */
    private static final double MITRED_SINE = 0.1;

    private final List<NestedBends.Bend> bends;
    private final double[] out;
    private final double[] past;
    private final double tolerance;
    /**
     * The ends of bends standing out, by cell twice the tolerance across (a point's ends within
     * the tolerance then lie in the four cells about it): each cell's last end, and each end the
     * one before.
     */
    private final LongIntMap heads = new LongIntMap();
    private final int[] before;
    private final boolean any;

    /**
     * Indexes the ends of the bends that stand out ({@code out} over 0), whose rows' stops
     * {@code past} (two an end, as {@link NestedBends#mitres} made them) the corners met stop
     * further in place.
     *
     * @param tolerance ends and corners within this of each other are at one point
     */
    RowsOnPaper(List<NestedBends.Bend> bends, double[] out, double[] past, double tolerance) {
        this.bends = bends;
        this.out = out;
        this.past = past;
        this.tolerance = tolerance;
        this.before = new int[2 * bends.size()];
        Arrays.fill(before, -1);
        boolean standing = false;
        for (int e = 0; e < 2 * bends.size(); e++) {
            if (out[e / 2] > 0 && tolerance > 0) {
                long key = cell(bends.get(e / 2).host(), Math.floor(x(e) / (2 * tolerance)), Math.floor(y(e) / (2 * tolerance)));
                before[e] = heads.get(key, -1);
                heads.put(key, e);
                standing = true;
            }
        }
        this.any = standing;
    }

    /** Whether any bend stands out: else no corner can stop a row. */
    boolean any() {
        return any;
    }

    /**
     * A corner (x, y) of a flat face of {@code host} at {@code level}, in the host's frame, its
     * sides leaving it towards (px, py) and (qx, qy): the face is convex, and lies in the wedge
     * between them. Each row of a bend ending there whose layers this face lies strictly between,
     * and which stands out towards the face, stops on the face's side nearer its crease, where
     * that side leaves the crease by at least about 6 degrees and at most square.
     */
    void corner(int host, int level, double x, double y, double px, double py, double qx, double qy) {
        endsAt(host, level, x, y, true, px, py, qx, qy);
    }

    /** Whether a bend's end standing out lies at (x, y) on {@code host}, with paper at {@code level} between its layers. */
    boolean near(int host, int level, double x, double y) {
        return endsAt(host, level, x, y, false, 0, 0, 0, 0);
    }

    /** Whether such an end lies at (x, y): the first found, or each stopped on the face's sides where {@code stopping}. */
    private boolean endsAt(int host, int level, double x, double y, boolean stopping, double px, double py, double qx, double qy) {
        if (!any) {
            return false;
        }
        boolean found = false;
        long cx = (long) Math.floor((x - tolerance) / (2 * tolerance));
        long cy = (long) Math.floor((y - tolerance) / (2 * tolerance));
        for (long i = cx; i <= cx + 1; i++) {
            for (long j = cy; j <= cy + 1; j++) {
                for (int e = heads.get(cell(host, i, j), -1); e >= 0; e = before[e]) {
                    if (meets(e, host, level, x, y)) {
                        if (!stopping) {
                            return true;
                        }
                        found = true;
                        stop(e, x, y, px, py, qx, qy);
                    }
                }
            }
        }
        return found;
    }

    private boolean meets(int e, int host, int level, double x, double y) {
        NestedBends.Bend bend = bends.get(e / 2);
        return bend.host() == host && bend.low() < level && level < bend.high() && Math.hypot(x(e) - x, y(e) - y) <= tolerance;
    }

    /** Stops end e's row on the nearer side of the face at corner (x, y) where it leaves into the bend's band. */
    private void stop(int e, double x, double y, double px, double py, double qx, double qy) {
        NestedBends.Bend bend = bends.get(e / 2);
        double sign = e % 2 == 0 ? 1 : -1;
        double dx = sign * (bend.bx() - bend.ax());
        double dy = sign * (bend.by() - bend.ay());
        double length = Math.hypot(dx, dy);
        // The turn of a direction from the crease (leaving this end) towards the side the bend
        // stands out on, in [0, 2 pi).
        double own = Math.atan2(dy, dx);
        int side = dx * bend.ny() - dy * bend.nx() > 0 ? 1 : -1;
        double p = turn(side, own, px - x, py - y);
        double q = turn(side, own, qx - x, qy - y);
        // The face's wedge runs from the smaller turn to the larger where they are less than a
        // half turn apart, else round through the crease's own direction: the face lies across
        // the crease's line there, where no mitre at its end keeps the bend off it.
        if (Math.abs(p - q) >= Math.PI) {
            return;
        }
        double nearer = Math.min(p, q);
        if (Math.sin(nearer) < MITRED_SINE || nearer > Math.PI / 2) {
            return;
        }
        // The row, out beyond the crease, meets that side out / tan(turn) in from the end.
        double in = out[e / 2] / Math.tan(nearer);
        if (in < length / 2) {
            past[e] = Math.min(past[e], -in);
        }
    }

    private static double turn(int side, double own, double dx, double dy) {
        double turn = side * (Math.atan2(dy, dx) - own);
        return turn - 2 * Math.PI * Math.floor(turn / (2 * Math.PI));
    }

    /** Where end e lies: bend e / 2's end a for even e, b for odd. */
    private double x(int e) {
        NestedBends.Bend bend = bends.get(e / 2);
        return e % 2 == 0 ? bend.ax() : bend.bx();
    }

    private double y(int e) {
        NestedBends.Bend bend = bends.get(e / 2);
        return e % 2 == 0 ? bend.ay() : bend.by();
    }

    private static long cell(int host, double cx, double cy) {
        return cell(host, (long) cx, (long) cy);
    }

    private static long cell(int host, long cx, long cy) {
        return ((cx * 0x9E3779B97F4A7C15L ^ cy) * 31 + host) & Long.MAX_VALUE; // a LongIntMap's keys are not negative
    }
}
