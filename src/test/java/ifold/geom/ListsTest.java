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
}
