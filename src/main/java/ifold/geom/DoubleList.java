package ifold.geom;

import java.util.Arrays;

/**
 * A growing list of {@code double}s without boxing or an array for each record: records of a
 * fixed stride laid end to end, in blocks rather than one array doubled as it grows (a doubled
 * array is up to twice the list, and three times while it is copied: the 5,000-triangle torus's
 * paper in space held 335 MB of arrays for 179 MB of points).
 */
public final class DoubleList {
    private static final int SHIFT = 12;
    private static final int BLOCK = 1 << SHIFT;
    private static final int MASK = BLOCK - 1;
    private double[][] blocks = new double[4][];
    private int size;

    public void add(double value) {
        int block = size >>> SHIFT;
        if (block == blocks.length) {
            blocks = Arrays.copyOf(blocks, 2 * block);
        }
        if (blocks[block] == null) {
            blocks[block] = new double[BLOCK];
        }
        blocks[block][size & MASK] = value;
        size++;
    }

    /** Appends values {@code from} to {@code to} - 1 of {@code source}, a block's stretch at a time. */
    public void addRange(DoubleList source, int from, int to) {
        if (from < 0 || to > source.size || from > to) {
            throw new IndexOutOfBoundsException(from + " to " + to + " of " + source.size);
        }
        while (from < to) {
            int block = size >>> SHIFT;
            if (block == blocks.length) {
                blocks = Arrays.copyOf(blocks, 2 * block);
            }
            if (blocks[block] == null) {
                blocks[block] = new double[BLOCK];
            }
            int n = Math.min(to - from, Math.min(BLOCK - (size & MASK), BLOCK - (from & MASK)));
            System.arraycopy(source.blocks[from >>> SHIFT], from & MASK, blocks[block], size & MASK, n);
            size += n;
            from += n;
        }
    }

    public double get(int i) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        return blocks[i >>> SHIFT][i & MASK];
    }

    public int size() {
        return size;
    }

    /**
     * Lets go of the blocks that hold only values before {@code index}: a list read once from
     * its start, copied elsewhere, is not held twice over meanwhile. Those values are gone.
     */
    public void letGoBefore(int index) {
        // From the last block wholly before it back to the first already let go: each block once.
        for (int block = Math.min(index >>> SHIFT, blocks.length) - 1; block >= 0 && blocks[block] != null; block--) {
            blocks[block] = null;
        }
    }

    public void set(int i, double value) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        blocks[i >>> SHIFT][i & MASK] = value;
    }

    /**
     * The values in one array, the list left empty: its blocks let go as they are copied, so that
     * a list of millions is not held twice over for longer than the copy.
     */
    public double[] drain() {
        double[] out = new double[size];
        for (int at = 0; at < size; at += BLOCK) {
            System.arraycopy(blocks[at >>> SHIFT], 0, out, at, Math.min(BLOCK, size - at));
            blocks[at >>> SHIFT] = null;
        }
        size = 0;
        return out;
    }

    public double[] toArray() {
        double[] out = new double[size];
        for (int at = 0; at < size; at += BLOCK) {
            System.arraycopy(blocks[at >>> SHIFT], 0, out, at, Math.min(BLOCK, size - at));
        }
        return out;
    }
}
