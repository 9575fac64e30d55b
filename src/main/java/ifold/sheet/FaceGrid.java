package ifold.sheet;

import java.util.Arrays;

/**
 * The faces of one stack by the cells of a square grid that their bounding boxes touch: the
 * faces a new face may overlap, without looking at every face of the stack. A strip lays its
 * faces side by side, a width or so wide, so with cells of two widths a face touches a few
 * cells per width of its length, and the faces near a new one are the handful over those
 * cells: laying n faces on one host costs about n, where comparing each with all cost n².
 *
 * <p>A face stays listed where it was added: one that shrinks (a cut) is found as before and
 * told apart by the exact test; one that moves or leaves (a tuck) makes the stack drop its grid
 * and build it again when next asked. A face whose box would touch more than
 * {@link #MOST_CELLS} cells is kept on a list looked at every time.
 */
final class FaceGrid {
    static final int MOST_CELLS = 4096;
    private final double cell;
    private final LongIntMap bucketOf = new LongIntMap();
    /** Per bucket: its face count, then the faces. */
    private int[][] buckets = new int[16][];
    private int bucketCount;
    private int[] large = new int[4];
    private int largeCount;

    FaceGrid(double cell) {
        this.cell = cell;
    }

    /** Lists face f under the cells its box (min x, min y, max x, max y) touches. */
    void add(int f, double[] box) {
        long x0 = cellOf(box[0]);
        long y0 = cellOf(box[1]);
        long x1 = cellOf(box[2]);
        long y1 = cellOf(box[3]);
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > MOST_CELLS) {
            if (largeCount == large.length) {
                large = Arrays.copyOf(large, 2 * largeCount);
            }
            large[largeCount++] = f;
            return;
        }
        for (long x = x0; x <= x1; x++) {
            for (long y = y0; y <= y1; y++) {
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
            }
        }
    }

    /** What {@link #near} finds. */
    interface Visitor {
        void visit(int f);
    }

    /**
     * Calls {@code visitor} with the faces listed under the cells {@code box} touches and the
     * large ones; a face may come more than once (the caller marks those it has seen). A box
     * touching more cells than {@link #MOST_CELLS} returns false without a call: look at all.
     */
    boolean near(double[] box, Visitor visitor) {
        long x0 = cellOf(box[0]);
        long y0 = cellOf(box[1]);
        long x1 = cellOf(box[2]);
        long y1 = cellOf(box[3]);
        if ((x1 - x0 + 1) * (y1 - y0 + 1) > MOST_CELLS) {
            return false;
        }
        for (int i = 0; i < largeCount; i++) {
            visitor.visit(large[i]);
        }
        for (long x = x0; x <= x1; x++) {
            for (long y = y0; y <= y1; y++) {
                int b = bucketOf.get(key(x, y), -1);
                if (b >= 0) {
                    int[] bucket = buckets[b];
                    for (int k = 1; k <= bucket[0]; k++) {
                        visitor.visit(bucket[k]);
                    }
                }
            }
        }
        return true;
    }

    private long cellOf(double coordinate) {
        return (long) Math.floor(coordinate / cell);
    }

    /** Two cell indices in one non-negative long: 31 bits each, offset to be positive (a host is far fewer cells across). */
    private static long key(long x, long y) {
        return ((x + (1L << 30)) & 0x7fffffffL) << 31 | ((y + (1L << 30)) & 0x7fffffffL);
    }
}
