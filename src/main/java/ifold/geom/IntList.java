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

    /** Appends values {@code from} to {@code to} - 1 of {@code source}, a block's stretch at a time. */
    public void addRange(IntList source, int from, int to) {
        if (from < 0 || to > source.size || from > to) {
            throw new IndexOutOfBoundsException(from + " to " + to + " of " + source.size);
        }
        while (from < to && size < BLOCK) {
            add(source.get(from++)); // the first block grows as it fills
        }
        while (from < to) {
            int block = size >>> SHIFT;
            if (block == blocks.length) {
                blocks = Arrays.copyOf(blocks, 2 * block);
            }
            if (blocks[block] == null) {
                blocks[block] = new int[BLOCK];
            }
            int n = Math.min(to - from, Math.min(BLOCK - (size & MASK), BLOCK - (from & MASK)));
            System.arraycopy(source.blocks[from >>> SHIFT], from & MASK, blocks[block], size & MASK, n);
            size += n;
            from += n;
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

    public int[] toArray() {
        int[] out = new int[size];
        for (int at = 0; at < size; at += BLOCK) {
            System.arraycopy(blocks[at >>> SHIFT], 0, out, at, Math.min(BLOCK, size - at));
        }
        return out;
    }
}
