package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The sheet's edge map agrees with a HashMap through puts, overwrites and removals, growing as it goes. */
class LongIntMapTest {
    @Test
    void agreesWithAHashMap() {
        SplittableRandom random = new SplittableRandom(7);
        LongIntMap map = new LongIntMap();
        Map<Long, Integer> reference = new HashMap<>();
        for (int op = 0; op < 200_000; op++) {
            // Keys as the sheet makes them: two small vertex indices in one long, so that many collide.
            long key = ((long) random.nextInt(300) << 32) | random.nextInt(300);
            int kind = random.nextInt(10);
            if (kind < 6) {
                int value = random.nextInt(1_000_000);
                map.put(key, value);
                reference.put(key, value);
            } else if (kind < 9) {
                Integer expected = reference.remove(key);
                assertEquals(expected == null ? -1 : expected, map.remove(key, -1), "remove " + key);
            } else {
                Integer expected = reference.get(key);
                assertEquals(expected == null ? -1 : expected, map.get(key, -1), "get " + key);
            }
            assertEquals(reference.size(), map.size());
        }
        for (Map.Entry<Long, Integer> entry : reference.entrySet()) {
            assertEquals((int) entry.getValue(), map.get(entry.getKey(), -1));
        }
        assertThrows(IllegalArgumentException.class, () -> map.put(-5, 1));
    }
}
