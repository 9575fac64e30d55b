package ifold.geom;

import java.util.Arrays;

/** A growing list of {@code double}s without boxing or an array for each record: records of a fixed stride, laid end to end. */
public final class DoubleList {
    private double[] values;
    private int size;

    public DoubleList() {
        this(16);
    }

    public DoubleList(int capacity) {
        values = new double[Math.max(1, capacity)];
    }

    public void add(double value) {
        if (size == values.length) {
            values = Arrays.copyOf(values, 2 * size);
        }
        values[size++] = value;
    }

    public double get(int i) {
        if (i >= size) {
            throw new IndexOutOfBoundsException(i + " of " + size);
        }
        return values[i];
    }

    public int size() {
        return size;
    }

    public double[] toArray() {
        return Arrays.copyOf(values, size);
    }
}
