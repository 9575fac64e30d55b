package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class PlayerTest {
    /** An animation that only counts: where it was last put. */
    private static final class Counting implements Animation {
        double at = -1;

        @Override
        public int stepCount() {
            return 2878;
        }

        @Override
        public void apply(double position) {
            at = position;
        }
    }

    @Test
    void arrowStepsAreEqualFromWhereverThePlayStands() {
        Counting animation = new Counting();
        Player player = new Player(animation, 10);
        player.seek(913);
        player.step(1);
        double first = animation.at;
        player.step(1);
        double second = animation.at;
        player.step(-1);
        assertEquals(28, first - 913, 1e-9, "a hundredth of the animation a step");
        assertEquals(28, second - first, 1e-9);
        assertEquals(first, animation.at, 1e-9, "and back by the same");
    }
}
