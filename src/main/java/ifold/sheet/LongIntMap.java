package ifold.sheet;

import java.util.Arrays;

/**
 * A hash map from non-negative {@code long} keys to {@code int} values, open addressing with
 * linear probing: the sheet keys its creases by two vertex indices in one long, and a wrap makes
 * millions of them, which boxed keys and values would make several times bigger and slower
 * (the wrap's geometry keys the ends of its folds' creases by their cells too; the sheet's faces
 * by their edges are kept by vertex, {@link EdgeFaces}).
 * Removal shifts the following entries back, so probes never meet tombstones.
 */
public final class LongIntMap {
    /**
     * Slot i is {@code table[3i .. 3i + 2]}: the key's high and low halves and the value, side
     * by side, so that a lookup reads one place in memory, not a key here and its value in
     * another array (the sheet's maps of edges hold millions; reading them was a seventh of a
     * wrap's time, most of it waiting on memory). An empty slot's high half is negative: keys
     * are not.
     */
    private int[] table;
    private int size;
    /** 64 - log2(capacity): the top bits of the hash pick the slot. */
    private int shift;

    public LongIntMap() {
        this(6);
    }

    /** An empty map of 2^{@code log2Capacity} slots to begin with (a sheet edit's maps are mostly small, and made by the hundred thousand). */
    LongIntMap(int log2Capacity) {
        table = new int[3 << log2Capacity];
        shift = 64 - log2Capacity;
        Arrays.fill(table, -1);
    }

    /** The value of {@code key}, or {@code missing} if it has none. */
    public int get(long key, int missing) {
        int mask = capacity() - 1;
        int high = (int) (key >>> 32);
        int low = (int) key;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            int at = 3 * i;
            int h = table[at];
            if (h == high && table[at + 1] == low) {
                return table[at + 2];
            }
            if (h < 0) {
                return missing;
            }
        }
    }

    public void put(long key, int value) {
        if (key < 0) {
            throw new IllegalArgumentException("keys are non-negative, got " + key);
        }
        // Up to three quarters full: linear probing still finds a key in a probe or two, and
        // the sheet's maps of edges were a third of the memory its paper takes at half full.
        if (4 * (size + 1) > 3 * capacity()) {
            grow();
        }
        int mask = capacity() - 1;
        int high = (int) (key >>> 32);
        int low = (int) key;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            int at = 3 * i;
            if (table[at] == high && table[at + 1] == low) {
                table[at + 2] = value;
                return;
            }
            if (table[at] < 0) {
                table[at] = high;
                table[at + 1] = low;
                table[at + 2] = value;
                size++;
                return;
            }
        }
    }

    /** Removes {@code key}; returns its value, or {@code missing} if it had none. */
    int remove(long key, int missing) {
        int i = getSlot(key);
        if (i < 0) {
            return missing;
        }
        int value = table[3 * i + 2];
        int mask = capacity() - 1;
        // Shift back every entry of the run after i that could have lived at i.
        int hole = i;
        for (int j = (i + 1) & mask; table[3 * j] >= 0; j = (j + 1) & mask) {
            int home = slot(keyAt(j), mask);
            boolean movable = hole <= j ? (home <= hole || home > j) : (home <= hole && home > j);
            if (movable) {
                System.arraycopy(table, 3 * j, table, 3 * hole, 3);
                hole = j;
            }
        }
        table[3 * hole] = -1;
        table[3 * hole + 1] = -1;
        table[3 * hole + 2] = -1;
        size--;
        return value;
    }

    int size() {
        return size;
    }

    private int capacity() {
        return table.length / 3;
    }

    private long keyAt(int i) {
        return ((long) table[3 * i] << 32) | (table[3 * i + 1] & 0xFFFFFFFFL);
    }

    private int getSlot(long key) {
        int mask = capacity() - 1;
        int high = (int) (key >>> 32);
        int low = (int) key;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            int h = table[3 * i];
            if (h == high && table[3 * i + 1] == low) {
                return i;
            }
            if (h < 0) {
                return -1;
            }
        }
    }

    private void grow() {
        int[] old = table;
        int capacity = 2 * capacity();
        if (capacity > (1 << 29)) {
            throw new IllegalStateException("a map of more than " + (3L << 28) + " entries");
        }
        table = new int[3 * capacity];
        shift--;
        Arrays.fill(table, -1);
        size = 0;
        for (int at = 0; at < old.length; at += 3) {
            if (old[at] >= 0) {
                put(((long) old[at] << 32) | (old[at + 1] & 0xFFFFFFFFL), old[at + 2]);
            }
        }
    }

    private int slot(long key, int mask) {
        // Fibonacci hashing: the top bits of the product spread pairs of small indices evenly.
        return (int) ((key * 0x9E3779B97F4A7C15L) >>> shift) & mask;
    }
}
