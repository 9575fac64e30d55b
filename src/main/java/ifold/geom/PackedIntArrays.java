package ifold.geom;

import java.util.AbstractList;
import java.util.RandomAccess;

/**
 * A growing list of {@code int} arrays kept end to end in blocks, with where each begins: a
 * wrap's paper in space is millions of faces and caps of three or four corners, and an array
 * object for each cost more in headers and references than its corners, and the collector copied
 * each of them, one by one, as it aged (the 5,000-triangle torus: 2.8 million). {@link #get}
 * makes a new array of an element's values; {@link #length} and {@link #value} read it in place.
 * The list only grows.
 */
public final class PackedIntArrays extends AbstractList<int[]> implements RandomAccess {
    private final IntList values = new IntList();
    /** Where each array begins in {@link #values}, and one past the last. */
    private final IntList starts = new IntList();

    public PackedIntArrays() {
        starts.add(0);
    }

    /** Appends a copy of {@code array}. */
    @Override
    public boolean add(int[] array) {
        for (int value : array) {
            values.add(value);
        }
        starts.add(values.size());
        modCount++;
        return true;
    }

    /** A new array of the values of array i. */
    @Override
    public int[] get(int i) {
        int from = start(i);
        int[] array = new int[starts.get(i + 1) - from];
        for (int k = 0; k < array.length; k++) {
            array[k] = values.get(from + k);
        }
        return array;
    }

    @Override
    public int size() {
        return starts.size() - 1;
    }

    /** How many values array i holds. */
    public int length(int i) {
        return starts.get(i + 1) - start(i);
    }

    /** Value k of array i. */
    public int value(int i, int k) {
        int from = start(i);
        if (k < 0 || from + k >= starts.get(i + 1)) {
            throw new IndexOutOfBoundsException(k + " of " + length(i));
        }
        return values.get(from + k);
    }

    private int start(int i) {
        if (i < 0 || i >= size()) {
            throw new IndexOutOfBoundsException(i + " of " + size());
        }
        return starts.get(i);
    }
}
