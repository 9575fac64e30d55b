package ifold.geom;

import java.util.Arrays;

/** A growing list of {@code int}s without boxing: the indices a large wrap's paper is built from, millions of them. */
public final class IntList {
    private int[] values;
    private int size;

    public IntList() {
        this(16);
    }

    public IntList(int capacity) {
        values = new int[Math.max(1, capacity)];
    }

    public void add(int value) {
        if (size == values.length) {
            values = Arrays.copyOf(values, 2 * size);
        }
        values[size++] = value;
    }

    /** {@code times} copies of {@code value}. */
    public void add(int value, int times) {
        if (size + times > values.length) {
            values = Arrays.copyOf(values, Math.max(2 * values.length, size + times));
        }
        Arrays.fill(values, size, size + times, value);
        size += times;
    }

    public int get(int i) {
        if (i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        return values[i];
    }

    public void set(int i, int value) {
        if (i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        values[i] = value;
    }

    public int size() {
        return size;
    }

    public int[] toArray() {
        return Arrays.copyOf(values, size);
    }
}
