package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Random;
import org.junit.jupiter.api.Test;

class EdgeSetTest {

    @Test
    void rankAndSelectAgreeWithCounting() {
        Random random = new Random(3);
        for (int length : new int[] {1, 63, 64, 65, 1000, 4099}) {
            boolean[] members = new boolean[length];
            for (int e = 0; e < length; e++) {
                members[e] = random.nextInt(3) == 0;
            }
            members[length - 1] = true;
            EdgeSet set = new EdgeSet(members);
            int count = 0;
            for (int e = 0; e < length; e++) {
                assertEquals(count, set.rank(e), "rank of " + e);
                assertEquals(members[e], set.contains(e));
                if (members[e]) {
                    assertEquals(e, set.select(count), "select " + count);
                    count++;
                }
            }
            assertEquals(count, set.size());
        }
    }
}
