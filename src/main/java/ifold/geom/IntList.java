package ifold.geom;

import java.util.Arrays;

/**
 * A growing list of {@code int}s without boxing: the indices a large wrap's paper is built from,
 * millions of them. Kept in blocks rather than one array doubled as it grows: a doubled array
 * is up to twice the list, and three times while it is copied. The first block starts small and
 * doubles up to a block's size: most lists a sheet edit makes hold a handful, and a block of
 * 4,096 for each, five an edit, had been most of a wrap's allocation.
 */
public final class IntList {
    private static final int SHIFT = 12;
    private static final int BLOCK = 1 << SHIFT;
    private static final int MASK = BLOCK - 1;
    private static final int FIRST = 8;
    private int[][] blocks = new int[4][];
    private int size;

    public void add(int value) {
        int block = size >>> SHIFT;
        if (block == blocks.length) {
            blocks = Arrays.copyOf(blocks, 2 * block);
        }
        if (blocks[block] == null) {
            blocks[block] = new int[block == 0 ? FIRST : BLOCK];
        } else if (block == 0 && size == blocks[0].length) {
            blocks[0] = Arrays.copyOf(blocks[0], 2 * size);
        }
        blocks[block][size & MASK] = value;
        size++;
    }

    /** {@code times} copies of {@code value}. */
    public void add(int value, int times) {
        for (int k = 0; k < times; k++) {
            add(value);
        }
    }

    public int get(int i) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        return blocks[i >>> SHIFT][i & MASK];
    }

    public void set(int i, int value) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        blocks[i >>> SHIFT][i & MASK] = value;
    }

    public int size() {
        return size;
    }

    public int[] toArray() {
        int[] out = new int[size];
        for (int at = 0; at < size; at += BLOCK) {
            System.arraycopy(blocks[at >>> SHIFT], 0, out, at, Math.min(BLOCK, size - at));
        }
        return out;
    }
}
