package ifold.sheet;

import java.util.Arrays;

/**
 * A hash map from non-negative {@code long} keys to {@code int} values, open addressing with
 * linear probing: the sheet keys its edges by two vertex indices in one long, and a wrap makes
 * millions of them, which boxed keys and values would make several times bigger and slower
 * (the wrap's geometry keys the ends of its folds' creases by their cells too).
 * Removal shifts the following entries back, so probes never meet tombstones.
 */
public final class LongIntMap {
    private static final long EMPTY = -1;
    private long[] keys;
    private int[] values;
    private int size;
    /** 64 - log2(capacity): the top bits of the hash pick the slot. */
    private int shift;

    public LongIntMap() {
        this(6);
    }

    /** An empty map of 2^{@code log2Capacity} slots to begin with (a sheet edit's maps are mostly small, and made by the hundred thousand). */
    LongIntMap(int log2Capacity) {
        keys = new long[1 << log2Capacity];
        values = new int[1 << log2Capacity];
        shift = 64 - log2Capacity;
        Arrays.fill(keys, EMPTY);
    }

    /** The value of {@code key}, or {@code missing} if it has none. */
    public int get(long key, int missing) {
        int mask = keys.length - 1;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            long k = keys[i];
            if (k == key) {
                return values[i];
            }
            if (k == EMPTY) {
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
        if (4 * (size + 1) > 3 * keys.length) {
            grow();
        }
        int mask = keys.length - 1;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            if (keys[i] == key) {
                values[i] = value;
                return;
            }
            if (keys[i] == EMPTY) {
                keys[i] = key;
                values[i] = value;
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
        int value = values[i];
        int mask = keys.length - 1;
        // Shift back every entry of the run after i that could have lived at i.
        int hole = i;
        for (int j = (i + 1) & mask; keys[j] != EMPTY; j = (j + 1) & mask) {
            int home = slot(keys[j], mask);
            boolean movable = hole <= j ? (home <= hole || home > j) : (home <= hole && home > j);
            if (movable) {
                keys[hole] = keys[j];
                values[hole] = values[j];
                hole = j;
            }
        }
        keys[hole] = EMPTY;
        size--;
        return value;
    }

    int size() {
        return size;
    }

    private int getSlot(long key) {
        int mask = keys.length - 1;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            long k = keys[i];
            if (k == key) {
                return i;
            }
            if (k == EMPTY) {
                return -1;
            }
        }
    }

    private void grow() {
        long[] oldKeys = keys;
        int[] oldValues = values;
        keys = new long[2 * oldKeys.length];
        values = new int[2 * oldKeys.length];
        shift--;
        Arrays.fill(keys, EMPTY);
        size = 0;
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldKeys[i] != EMPTY) {
                put(oldKeys[i], oldValues[i]);
            }
        }
    }

    private int slot(long key, int mask) {
        // Fibonacci hashing: the top bits of the product spread pairs of small indices evenly.
        return (int) ((key * 0x9E3779B97F4A7C15L) >>> shift) & mask;
    }
}
