package ifold.print;

import ifold.geom.UnionFind;
import java.util.ArrayList;
import java.util.List;

/**
 * The creases one fold leaves, told apart: its edges on a page joined where they meet end to
 * end on one line (a crease cut by the flat edges across it), so that each crease apart, and not
 * each edge, gets its number.
 */
final class CreaseRuns {
    /** Ends closer than this, in millimetres on the page, meet. */
    private static final double MEET = 0.01;
    /** Directions closer than this (the sine of the angle between them) run on one line. */
    private static final double ALIGNED = 1e-3;

    private CreaseRuns() {
    }

    /** The longest edge of each run of {@code edges} (x1, y1, x2, y2 each). */
    static List<double[]> longestOfEach(List<double[]> edges) {
        int n = edges.size();
        int[] run = UnionFind.pieces(n);
        for (int i = 0; i < n; i++) {
            for (int j = i + 1; j < n; j++) {
                if (meet(edges.get(i), edges.get(j))) {
                    UnionFind.union(run, i, j);
                }
            }
        }
        List<double[]> longest = new ArrayList<>();
        int[] best = new int[n];
        java.util.Arrays.fill(best, -1);
        for (int i = 0; i < n; i++) {
            int r = UnionFind.find(run, i);
            if (best[r] < 0 || length(edges.get(i)) > length(edges.get(best[r]))) {
                best[r] = i;
            }
        }
        for (int i = 0; i < n; i++) {
            if (best[i] >= 0) {
                longest.add(edges.get(best[i]));
            }
        }
        return longest;
    }

    private static boolean meet(double[] a, double[] b) {
        boolean touch = close(a[0], a[1], b[0], b[1]) || close(a[0], a[1], b[2], b[3]) || close(a[2], a[3], b[0], b[1])
                || close(a[2], a[3], b[2], b[3]);
        if (!touch) {
            return false;
        }
        double cross = (a[2] - a[0]) * (b[3] - b[1]) - (a[3] - a[1]) * (b[2] - b[0]);
        return Math.abs(cross) <= ALIGNED * length(a) * length(b);
    }

    private static boolean close(double x1, double y1, double x2, double y2) {
        return Math.hypot(x1 - x2, y1 - y2) <= MEET;
    }

    private static double length(double[] e) {
        return Math.hypot(e[2] - e[0], e[3] - e[1]);
    }
}
