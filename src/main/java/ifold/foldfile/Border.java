package ifold.foldfile;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * A crease pattern's border edges ({@code B}), each on a side of the rectangle its vertices
 * span (moved to its corner at (0, 0)), and whether together they run all round it. iFold folds
 * that rectangle: a pattern on a triangle, say, whose hypotenuse is labelled anything but B or is
 * not given at all, would otherwise be folded as its bounding square.
 */
final class Border {
    private static final String[] SIDES = {"y = %s, from x = %s to %s", "x = %s, from y = %s to %s", "y = %s, from x = %s to %s",
        "x = %s, from y = %s to %s"};

    private final double length;
    private final double width;
    private final double tolerance;
    /** For each side (v = 0, u = L, v = W, u = 0): the intervals along it (of u or v) that its border edges cover. */
    private final List<List<double[]>> covered = List.of(new ArrayList<>(), new ArrayList<>(), new ArrayList<>(), new ArrayList<>());

    Border(double length, double width, double tolerance) {
        this.length = length;
        this.width = width;
        this.tolerance = tolerance;
    }

    /** Adds the border edge p-q; false where it lies on no side of the rectangle. */
    boolean add(double[] p, double[] q) {
        int side = near(p[1], 0) && near(q[1], 0) ? 0 : near(p[0], length) && near(q[0], length) ? 1
                : near(p[1], width) && near(q[1], width) ? 2 : near(p[0], 0) && near(q[0], 0) ? 3 : -1;
        if (side < 0) {
            return false;
        }
        int along = side % 2 == 0 ? 0 : 1;
        covered.get(side).add(new double[] {Math.min(p[along], q[along]), Math.max(p[along], q[along])});
        return true;
    }

    /**
     * Refuses a border that does not run all round the rectangle, naming the first stretch of a
     * side left open, in the file's coordinates ({@code box}: its lowest x and y, its highest).
     */
    void check(double[] box) throws CreasePattern.Refused {
        if (covered.stream().allMatch(List::isEmpty)) {
            throw new CreasePattern.Refused("no border edges (B): iFold folds a rectangular sheet, and the file must give its border");
        }
        for (int side = 0; side < 4; side++) {
            List<double[]> intervals = covered.get(side);
            intervals.sort(Comparator.comparingDouble(interval -> interval[0]));
            double extent = side % 2 == 0 ? length : width;
            double reach = 0;
            double[] gap = null;
            for (double[] interval : intervals) {
                if (interval[0] > reach + tolerance) {
                    gap = new double[] {reach, interval[0]};
                    break;
                }
                reach = Math.max(reach, interval[1]);
            }
            if (gap == null && reach < extent - tolerance) {
                gap = new double[] {reach, extent};
            }
            if (gap != null) {
                boolean alongX = side % 2 == 0;
                double at = side == 0 ? box[1] : side == 1 ? box[2] : side == 2 ? box[3] : box[0];
                double offset = alongX ? box[0] : box[1];
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "the sheet is not the rectangle (%s, %s)-(%s, %s) its vertices"
                        + " span: no border edge (B) runs along its side " + SIDES[side] + "; iFold folds rectangular sheets",
                        CreasePattern.fmt(box[0]), CreasePattern.fmt(box[1]), CreasePattern.fmt(box[2]), CreasePattern.fmt(box[3]),
                        CreasePattern.fmt(at), CreasePattern.fmt(gap[0] + offset), CreasePattern.fmt(gap[1] + offset)));
            }
        }
    }

    private boolean near(double a, double b) {
        return Math.abs(a - b) <= tolerance;
    }
}
