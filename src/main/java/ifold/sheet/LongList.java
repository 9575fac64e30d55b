package ifold.sheet;

import java.util.Arrays;

/** A growing list of {@code long}s without boxing: a stack's order relations, of which a sheet folded again and again holds many. */
final class LongList {
    private long[] values = new long[8];
    private int size;

    void add(long value) {
        if (size == values.length) {
            values = Arrays.copyOf(values, 2 * size);
        }
        values[size++] = value;
    }

    void addAll(LongList other) {
        if (size + other.size > values.length) {
            values = Arrays.copyOf(values, Math.max(2 * values.length, size + other.size));
        }
        System.arraycopy(other.values, 0, values, size, other.size);
        size += other.size;
    }

    long get(int i) {
        return values[i];
    }

    void set(int i, long value) {
        values[i] = value;
    }

    /** Keeps the first {@code n} values. */
    void truncate(int n) {
        size = n;
    }

    int size() {
        return size;
    }
}
