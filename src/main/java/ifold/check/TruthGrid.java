package ifold.check;

import java.util.Arrays;
import java.util.HashMap;

/**
 * A sparse uniform grid of boxes in space (a sheet is the plane z = 0), for candidate lookups:
 * a query returns every object whose box meets the query box, each once, and perhaps a few
 * more (cells are hashed, and two cells may share a key); callers test candidates exactly.
 */
final class TruthGrid {
    private final double cell;
    private final HashMap<Long, int[]> cells = new HashMap<>();
    /** The query each object was last returned by, so that it is returned once. */
    private final int[] stamp;
    private int query;

    /** boxes: min x y z, max x y z of each of the n objects. */
    TruthGrid(double[] boxes, int n, double cell) {
        this.cell = cell;
        stamp = new int[n];
        HashMap<Long, Ints> lists = new HashMap<>();
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            for (long x = floor(boxes[o]); x <= floor(boxes[o + 3]); x++) {
                for (long y = floor(boxes[o + 1]); y <= floor(boxes[o + 4]); y++) {
                    for (long z = floor(boxes[o + 2]); z <= floor(boxes[o + 5]); z++) {
                        lists.computeIfAbsent(key(x, y, z), k -> new Ints()).add(i);
                    }
                }
            }
        }
        lists.forEach((k, list) -> cells.put(k, list.toArray()));
    }

    /**
     * A cell size for these boxes: the median of their largest extents (so that the rare big
     * box spans many cells but the many small ones few), at least least, grown until the
     * cells the boxes span stay few.
     */
    static double cellFor(double[] boxes, int n, double least) {
        double[] extents = new double[n];
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            extents[i] = Math.max(boxes[o + 3] - boxes[o], Math.max(boxes[o + 4] - boxes[o + 1], boxes[o + 5] - boxes[o + 2]));
        }
        Arrays.sort(extents);
        double cell = Math.max(n == 0 ? least : extents[n / 2], least);
        while (spans(boxes, n, cell) > 16.0 * n + 100_000) {
            cell *= 2;
        }
        return cell;
    }

    private static double spans(double[] boxes, int n, double cell) {
        double total = 0;
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            double count = 1;
            for (int d = 0; d < 3; d++) {
                count *= Math.floor(boxes[o + 3 + d] / cell) - Math.floor(boxes[o + d] / cell) + 1;
            }
            total += count;
        }
        return total;
    }

    private long floor(double x) {
        return (long) Math.floor(x / cell);
    }

    private static long key(long x, long y, long z) {
        return x * 0x9E3779B97F4A7C15L + y * 0xC2B2AE3D27D4EB4FL + z * 0x165667B19E3779F9L;
    }

    /** The objects whose boxes may meet [x0, x1] x [y0, y1] x [z0, z1], into out (cleared first). */
    void query(double x0, double y0, double z0, double x1, double y1, double z1, Ints out) {
        out.clear();
        query++;
        for (long x = floor(x0); x <= floor(x1); x++) {
            for (long y = floor(y0); y <= floor(y1); y++) {
                for (long z = floor(z0); z <= floor(z1); z++) {
                    int[] objects = cells.get(key(x, y, z));
                    if (objects == null) {
                        continue;
                    }
                    for (int i : objects) {
                        if (stamp[i] != query) {
                            stamp[i] = query;
                            out.add(i);
                        }
                    }
                }
            }
        }
    }
}
