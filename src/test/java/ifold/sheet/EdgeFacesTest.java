package ifold.sheet;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashMap;
import java.util.Map;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/**
 * The sheet's faces by edge agree with a HashMap through puts, overwrites and removals, for
 * vertices with few edges (kept in their own slots) and many (the rest kept aside).
 */
class EdgeFacesTest {
    @Test
    void agreesWithAHashMap() {
        SplittableRandom random = new SplittableRandom(11);
        EdgeFaces edges = new EdgeFaces();
        Map<Long, Integer> reference = new HashMap<>();
        for (int op = 0; op < 300_000; op++) {
            // Vertex a from a few hundred, b from a dozen: every vertex then has more edges
            // than its own slots hold, and edges move between its slots and the rest as
            // they are removed and put again.
            int a = random.nextInt(300);
            int b = random.nextInt(12);
            long key = Sheet.directed(a, b);
            int kind = random.nextInt(10);
            if (kind < 5) {
                int face = random.nextInt(1_000_000);
                edges.put(a, b, face);
                reference.put(key, face);
            } else if (kind < 8) {
                Integer expected = reference.remove(key);
                assertEquals(expected == null ? -1 : expected, edges.remove(a, b, -1), "remove " + a + " → " + b);
            } else {
                Integer expected = reference.get(key);
                assertEquals(expected == null ? -1 : expected, edges.get(a, b, -1), "get " + a + " → " + b);
            }
        }
        for (Map.Entry<Long, Integer> entry : reference.entrySet()) {
            int a = (int) (entry.getKey() >>> 32);
            int b = (int) (long) entry.getKey();
            assertEquals((int) entry.getValue(), edges.get(a, b, -1));
        }
    }

    @Test
    void aVertexWithManyEdgesKeepsThemAll() {
        EdgeFaces edges = new EdgeFaces();
        for (int b = 0; b < 20; b++) {
            edges.put(5, b, 100 + b);
        }
        // The first four went to its own slots, the rest aside; freeing a slot and putting an
        // edge kept aside again must not leave two answers for it.
        assertEquals(100, edges.remove(5, 0, -1));
        edges.put(5, 17, 7);
        assertEquals(7, edges.get(5, 17, -1));
        assertEquals(7, edges.remove(5, 17, -1));
        assertEquals(-1, edges.get(5, 17, -1));
        for (int b = 1; b < 20; b++) {
            assertEquals(b == 17 ? -1 : 100 + b, edges.get(5, b, -1), "5 → " + b);
        }
        assertEquals(-1, edges.get(5, 0, -1));
        assertEquals(-1, edges.get(6, 1, -1));
        assertEquals(-1, edges.get(1_000_000, 1, -1), "a vertex never seen");
        assertEquals(-1, edges.remove(1_000_000, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> edges.put(-1, 2, 3));
    }
}
