package ifold.check;

import java.util.Arrays;

/**
 * A uniform grid of axis-aligned boxes, for finding the pairs of boxes that meet: each box is
 * entered in every cell it spans, the entries sorted by cell, so that the boxes of a cell are one
 * run of {@link #entries}. A pair that shares several cells is met in each of them; it belongs to
 * one, the cell of the lowest corner of the two boxes' overlap, so that a caller tests it once
 * without remembering pairs. Since the cell coordinate is monotone in the value, that cell is,
 * along each axis, the larger of the two boxes' lowest cell coordinates ({@link #coordinate}).
 *
 * <p>The cell is a few times the median of the boxes' largest extents, so that the many small
 * boxes span a cell or two and the few large ones many, grown while the entries would be more
 * than about eight a box. The grid is dense in index but only occupied cells have entries.
 */
final class BoxGrid {
    /**
     * The cell, in median extents of the boxes. The pairs of a cell are swept along one axis
     * (PaperCollisions), so a cell may hold many boxes: on a wrap of 1.77M triangles, 4 took 3.4
     * s for the pairs and 0.55 s for the grid (3.1M entries), 1 took 4.3 and 1.5 (13.7M), 12 took
     * 5.0 and 0.8; 2.5 to 7 were all within a tenth of a second of 4.
     */
    private static final double CELL_PER_EXTENT = 4;
    /** Boxes spanning more cells than this on average grow the cell (a bound on memory, not on time). */
    private static final int ENTRIES_PER_BOX = 8;

    /** The cell's edge length, and the grid's lowest corner. */
    final double cell;
    private final double x0;
    private final double y0;
    private final double z0;
    /** Cells along each axis. */
    private final long nx;
    private final long ny;
    private final long nz;
    /** How far the cell index is shifted above the box index in an entry. */
    private final int shift;
    /** The entries, sorted: cell index << shift | box index. */
    final long[] entries;

    /**
     * @param boxes min x y z, max x y z of each of the n boxes (each min at most its max); a box
     *     of NaN is left out
     */
    BoxGrid(double[] boxes, int n) {
        double[] bounds = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
            Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double[] extents = new double[n];
        int kept = 0;
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            if (Double.isNaN(boxes[o])) {
                continue;
            }
            for (int axis = 0; axis < 3; axis++) {
                bounds[axis] = Math.min(bounds[axis], boxes[o + axis]);
                bounds[3 + axis] = Math.max(bounds[3 + axis], boxes[o + 3 + axis]);
            }
            extents[kept++] = Math.max(boxes[o + 3] - boxes[o], Math.max(boxes[o + 4] - boxes[o + 1], boxes[o + 5] - boxes[o + 2]));
        }
        extents = Arrays.copyOf(extents, kept);
        if (kept == 0) {
            Arrays.fill(bounds, 0);
        }
        x0 = bounds[0];
        y0 = bounds[1];
        z0 = bounds[2];
        double size = Math.max(bounds[3] - bounds[0], Math.max(bounds[4] - bounds[1], bounds[5] - bounds[2]));
        Arrays.sort(extents);
        shift = 64 - Long.numberOfLeadingZeros(Math.max(1, n));
        // Keep the cell index below 2^(63 - shift), so that entries stay positive and sort by cell.
        double cellCount = Math.pow(2, 63 - shift) / 2;
        double least = Math.max(size / Math.cbrt(cellCount), size * 1e-9);
        double c = Math.max(kept == 0 ? 1 : CELL_PER_EXTENT * extents[kept / 2], least);
        if (!(c > 0)) {
            c = 1;
        }
        while (spans(boxes, n, c) > (double) ENTRIES_PER_BOX * n + 100_000) {
            c *= 1.5;
        }
        cell = c;
        nx = (long) Math.floor((bounds[3] - x0) / c) + 1;
        ny = (long) Math.floor((bounds[4] - y0) / c) + 1;
        nz = (long) Math.floor((bounds[5] - z0) / c) + 1;
        long[] out = new long[(int) spans(boxes, n, c)];
        int k = 0;
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            if (Double.isNaN(boxes[o])) {
                continue;
            }
            long ix1 = ix(boxes[o + 3]);
            long iy1 = iy(boxes[o + 4]);
            long iz1 = iz(boxes[o + 5]);
            for (long x = ix(boxes[o]); x <= ix1; x++) {
                for (long y = iy(boxes[o + 1]); y <= iy1; y++) {
                    for (long z = iz(boxes[o + 2]); z <= iz1; z++) {
                        out[k++] = ((x * ny + y) * nz + z) << shift | i;
                    }
                }
            }
        }
        Arrays.parallelSort(out);
        entries = out;
    }

    /** How many entries the boxes make with cells of edge c (computed as ix, iy and iz compute them). */
    private double spans(double[] boxes, int n, double c) {
        double total = 0;
        for (int i = 0; i < n; i++) {
            int o = 6 * i;
            if (Double.isNaN(boxes[o])) {
                continue;
            }
            double count = 1;
            for (int axis = 0; axis < 3; axis++) {
                double origin = axis == 0 ? x0 : axis == 1 ? y0 : z0;
                count *= Math.floor((boxes[o + 3 + axis] - origin) / c) - Math.floor((boxes[o + axis] - origin) / c) + 1;
            }
            total += count;
        }
        return total;
    }

    private long ix(double x) {
        return (long) Math.floor((x - x0) / cell);
    }

    private long iy(double y) {
        return (long) Math.floor((y - y0) / cell);
    }

    private long iz(double z) {
        return (long) Math.floor((z - z0) / cell);
    }

    /** The cell coordinate along an axis (0, 1, 2: x, y, z) of a value, as the entries were made. */
    long coordinate(int axis, double value) {
        return axis == 0 ? ix(value) : axis == 1 ? iy(value) : iz(value);
    }

    /** The box index of an entry. */
    int box(long entry) {
        return (int) (entry & ((1L << shift) - 1));
    }

    /** The cell index of an entry. */
    long cellOf(long entry) {
        return entry >>> shift;
    }

    /** A cell's coordinate along an axis, from its index. */
    long coordinateOf(long cellIndex, int axis) {
        return axis == 2 ? cellIndex % nz : axis == 1 ? cellIndex / nz % ny : cellIndex / nz / ny;
    }

    /** The index just past the run of entries of the cell that entry {@code from} is in. */
    int runEnd(int from) {
        long cellIndex = entries[from] >>> shift;
        int end = from + 1;
        while (end < entries.length && entries[end] >>> shift == cellIndex) {
            end++;
        }
        return end;
    }
}
