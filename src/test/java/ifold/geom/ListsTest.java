package ifold.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The growing lists let go of the blocks before a point, and keep the rest. */
class ListsTest {

    @Test
    void valuesAfterWhereTheListLetGoAreKept() {
        DoubleList doubles = new DoubleList();
        IntList ints = new IntList();
        PackedIntArrays arrays = new PackedIntArrays();
        for (int k = 0; k < 20_000; k++) {
            doubles.add(k / 2.0);
            ints.add(k);
            arrays.add(new int[] {k, k + 1});
        }
        doubles.letGoBefore(9_000);
        ints.letGoBefore(9_000);
        arrays.letGoBefore(9_000);
        doubles.letGoBefore(12_000); // again, farther: each block once
        ints.letGoBefore(3_000); // not as far: nothing more
        for (int k = 12_000; k < 20_000; k++) {
            assertEquals(k / 2.0, doubles.get(k));
        }
        for (int k = 9_000; k < 20_000; k++) {
            assertEquals(k, ints.get(k));
            assertEquals(k + 1, arrays.get(k)[1]);
        }
        // The blocks wholly before are gone (two of 4,096 values of the ints, four of the arrays').
        assertThrows(NullPointerException.class, () -> ints.get(8_000));
        assertThrows(NullPointerException.class, () -> arrays.get(3_000));
        assertEquals(20_000, ints.size());
    }

    @Test
    void rangesAreAppendedAcrossBlocks() {
        DoubleList doubles = new DoubleList();
        IntList ints = new IntList();
        for (int k = 0; k < 10_000; k++) {
            doubles.add(k);
            ints.add(k);
        }
        DoubleList someDoubles = new DoubleList();
        IntList someInts = new IntList();
        someDoubles.add(-1);
        someInts.add(-1);
        // Ranges that start, end and cross blocks of 4,096 at other places in the two lists.
        someDoubles.addRange(doubles, 5, 4_100);
        someInts.addRange(ints, 5, 4_100);
        someDoubles.addRange(doubles, 8_000, 10_000);
        someInts.addRange(ints, 8_000, 10_000);
        assertEquals(1 + 4_095 + 2_000, someDoubles.size());
        assertEquals(someDoubles.size(), someInts.size());
        for (int k = 1; k < someInts.size(); k++) {
            int expected = k <= 4_095 ? k + 4 : 8_000 + k - 4_096;
            assertEquals(expected, someInts.get(k));
            assertEquals(expected, someDoubles.get(k));
        }
        assertThrows(IndexOutOfBoundsException.class, () -> someInts.addRange(ints, 9_000, 10_001));
    }

    @Test
    void arraysAreAppendedRenumbered() {
        PackedIntArrays arrays = new PackedIntArrays();
        arrays.add(new int[] {0, 1, 2});
        arrays.add(new int[] {2, 1});
        PackedIntArrays renumbered = new PackedIntArrays();
        renumbered.addNumbered(arrays, 1, new int[] {10, 11, 12});
        renumbered.addNumbered(arrays, 0, new int[] {10, 11, 12});
        org.junit.jupiter.api.Assertions.assertArrayEquals(new int[] {12, 11}, renumbered.get(0));
        org.junit.jupiter.api.Assertions.assertArrayEquals(new int[] {10, 11, 12}, renumbered.get(1));
        PackedIntArrays shifted = new PackedIntArrays();
        shifted.addShifted(arrays, 0, 1, 100); // 1 and up raised by 100, 0 kept
        org.junit.jupiter.api.Assertions.assertArrayEquals(new int[] {0, 101, 102}, shifted.get(0));
    }
}
