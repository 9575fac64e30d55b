package ifold.sheet;

import java.util.Arrays;

/**
 * Faces by the cells of a square grid that their polygons meet: the faces a new face may
 * overlap, without looking at every face of a stack. A strip lays its faces side by side, a
 * width or so wide, so with cells of a few widths ({@link #cellFor}) a face meets a few
 * dozen cells, and the faces near a new one are the handful over those cells: laying n faces
 * on one host costs about n, where comparing each with all cost n². A face is entered in the
 * cells of its polygon row by row, not of its box: a pass 500 widths long at 45° meets about
 * a thousand cells of two widths, where its box touched 60,000 (and was looked at for every
 * new face).
 *
 * <p>A face stays listed where it was added: one that shrinks (a cut) is found as before and
 * told apart by the exact test; one that moves or leaves (a tuck) is found where it was too, and
 * passed over by the stack, which builds its grid again once such faces are as many as its own.
 * A face that would meet more than {@link #MOST_CELLS} cells is kept on a list looked at every
 * time.
 */
public final class FaceGrid {
    static final int MOST_CELLS = 4096;
    private final double cell;
    private final LongIntMap bucketOf = new LongIntMap();
    /** Per bucket: its face count, then the faces. */
    private int[][] buckets = new int[16][];
    private int bucketCount;
    private int[] large = new int[4];
    private int largeCount;
    /** For {@link #near}: the faces found so far. */
    private int[] found = new int[16];

    /** A grid of square cells {@code cell} across. */
    public FaceGrid(double cell) {
        if (!(cell > 0) || !Double.isFinite(cell)) {
            throw new IllegalArgumentException("a grid's cell must be a positive length, got " + cell);
        }
        this.cell = cell;
    }

    /** Entries a face may have on average before {@link #cellFor} grows the cell: a bound on memory and time. */
    private static final int ENTRIES_PER_FACE = 24;

    /**
     * A cell size for the first {@code n} polygons: four times their median narrow width (twice
     * the area over the perimeter: a strip's width for a long pass), grown while the faces would
     * meet more than {@link #ENTRIES_PER_FACE} cells each on average, and at least {@code least}.
     * Cells of a fixed two widths made a pass of length L meet L / w cells: at a width of 1/2000
     * of the model, a thousand hash probes a face.
     */
    public static double cellFor(double[][] polygons, int n, double least) {
        double[] narrow = new double[n];
        double area = 0;
        double perimeter = 0;
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            double[] p = polygons[i];
            double[] box = Polygons2.bounds(p);
            minX = Math.min(minX, box[0]);
            minY = Math.min(minY, box[1]);
            maxX = Math.max(maxX, box[2]);
            maxY = Math.max(maxY, box[3]);
            double a = Math.abs(Polygons2.twiceArea(p, p.length / 2)) / 2;
            double around = Polygons2.perimeter(p, p.length / 2);
            area += a;
            perimeter += around;
            narrow[i] = around > 0 ? 2 * a / around : 0;
        }
        if (n == 0) {
            return least;
        }
        Arrays.sort(narrow);
        double span = Math.max(maxX - minX, maxY - minY);
        double c = Math.max(Math.max(least, 4 * narrow[n / 2]), Math.max(span / (1 << 20), Double.MIN_NORMAL));
        // The cells a face meets: about its area, a share of its outline, and one.
        while (area / (c * c) + perimeter / c + n > ENTRIES_PER_FACE * (double) n && c < span) {
            c *= 1.5;
        }
        return c;
    }

    /** Lists face f under the cells its polygon (x0 y0 x1 y1 …, convex) meets. */
    public void add(int f, double[] polygon) {
        if (cellCount(polygon) > MOST_CELLS) {
            if (largeCount == large.length) {
                large = Arrays.copyOf(large, 2 * largeCount);
            }
            large[largeCount++] = f;
            return;
        }
        forCells(polygon, (x, y) -> {
            long key = key(x, y);
            int b = bucketOf.get(key, -1);
            if (b < 0) {
                if (bucketCount == buckets.length) {
                    buckets = Arrays.copyOf(buckets, 2 * bucketCount);
                }
                b = bucketCount++;
                buckets[b] = new int[5];
                bucketOf.put(key, b);
            }
            int[] bucket = buckets[b];
            if (bucket[0] + 1 == bucket.length) {
                bucket = Arrays.copyOf(bucket, 2 * bucket.length);
                buckets[b] = bucket;
            }
            bucket[++bucket[0]] = f;
        });
    }

    /**
     * The faces listed under the cells {@code polygon} meets and the large ones, each once, in
     * ascending order; null where the polygon meets more cells than {@link #MOST_CELLS}: look at
     * all.
     */
    public int[] near(double[] polygon) {
        if (cellCount(polygon) > MOST_CELLS) {
            return null;
        }
        int[] n = {0};
        for (int i = 0; i < largeCount; i++) {
            take(large[i], n);
        }
        forCells(polygon, (x, y) -> {
            int b = bucketOf.get(key(x, y), -1);
            if (b >= 0) {
                int[] bucket = buckets[b];
                for (int k = 1; k <= bucket[0]; k++) {
                    take(bucket[k], n);
                }
            }
        });
        // A face listed in several of the cells comes once: sorted, then the repeats dropped (an
        // array of marks by face would be as long as the sheet's faces, for each stack's grid).
        Arrays.sort(found, 0, n[0]);
        int distinct = 0;
        for (int i = 0; i < n[0]; i++) {
            if (distinct == 0 || found[i] != found[distinct - 1]) {
                found[distinct++] = found[i];
            }
        }
        return Arrays.copyOf(found, distinct);
    }

    private void take(int f, int[] n) {
        if (n[0] == found.length) {
            found = Arrays.copyOf(found, 2 * n[0]);
        }
        found[n[0]++] = f;
    }

    private interface CellVisitor {
        void visit(long x, long y);
    }

    /** The cells a polygon meets: those of its box where that is few, else counted row by row. */
    private long cellCount(double[] polygon) {
        double[] box = Polygons2.bounds(polygon);
        long boxCells = (cellOf(box[2]) - cellOf(box[0]) + 1) * (cellOf(box[3]) - cellOf(box[1]) + 1);
        if (boxCells <= MOST_CELLS) {
            return boxCells;
        }
        long[] count = {0};
        forRows(polygon, (row, from, to) -> count[0] += to - from + 1);
        return count[0];
    }

    private void forCells(double[] polygon, CellVisitor visitor) {
        forRows(polygon, (row, from, to) -> {
            for (long x = from; x <= to; x++) {
                visitor.visit(x, row);
            }
        });
    }

    private interface RowVisitor {
        void visit(long row, long from, long to);
    }

    /**
     * Each row of cells the polygon meets, with its first and last column: those between the
     * least and the most x of the polygon's edges within the row (a convex polygon's part of it),
     * a hair wider so that rounding loses no cell.
     */
    private void forRows(double[] polygon, RowVisitor visitor) {
        int n = polygon.length / 2;
        double low = Double.POSITIVE_INFINITY;
        double high = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < n; i++) {
            low = Math.min(low, polygon[2 * i + 1]);
            high = Math.max(high, polygon[2 * i + 1]);
        }
        double hair = cell * 1e-9;
        long first = cellOf(low - hair);
        long last = cellOf(high + hair);
        for (long row = first; row <= last; row++) {
            double bottom = row == first ? Double.NEGATIVE_INFINITY : row * cell - hair;
            double top = row == last ? Double.POSITIVE_INFINITY : (row + 1) * cell + hair;
            double least = Double.POSITIVE_INFINITY;
            double most = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                int j = (i + 1) % n;
                double ax = polygon[2 * i];
                double ay = polygon[2 * i + 1];
                double bx = polygon[2 * j];
                double by = polygon[2 * j + 1];
                if (Math.max(ay, by) < bottom || Math.min(ay, by) > top) {
                    continue;
                }
                double fromX = ax;
                double toX = bx;
                if (ay != by) { // the edge's part within the row, between its crossings of the row's lines
                    double t0 = Math.max(0, Math.min(1, (bottom - ay) / (by - ay)));
                    double t1 = Math.max(0, Math.min(1, (top - ay) / (by - ay)));
                    fromX = ax + (bx - ax) * t0;
                    toX = ax + (bx - ax) * t1;
                }
                least = Math.min(least, Math.min(fromX, toX));
                most = Math.max(most, Math.max(fromX, toX));
            }
            if (least <= most) {
                visitor.visit(row, cellOf(least - hair), cellOf(most + hair));
            }
        }
    }

    private long cellOf(double coordinate) {
        return (long) Math.floor(coordinate / cell);
    }

    /** Two cell indices in one non-negative long: 31 bits each, offset to be positive (a host is far fewer cells across). */
    private static long key(long x, long y) {
        return ((x + (1L << 30)) & 0x7fffffffL) << 31 | ((y + (1L << 30)) & 0x7fffffffL);
    }
}
