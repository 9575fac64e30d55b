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

    public double get(int i) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        return blocks[i >>> SHIFT][i & MASK];
    }

    public int size() {
        return size;
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
