package ifold.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** Points in a closed solid by the ray's parity: a cube, a cube with a cavity, an open box. */
class SolidInsideTest {
    /** The cube [lo, hi]^3 as 12 triangles. */
    private static double[] cube(double lo, double hi) {
        double[] unit = {
            0, 0, 0, 1, 1, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 1, 1, 0,
            0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1, 1,
            0, 0, 0, 1, 0, 0, 1, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1,
            0, 1, 0, 1, 1, 1, 1, 1, 0, 0, 1, 0, 0, 1, 1, 1, 1, 1,
            0, 0, 0, 0, 0, 1, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 1, 0,
            1, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1};
        double[] out = new double[unit.length];
        for (int i = 0; i < unit.length; i++) {
            out[i] = lo + (hi - lo) * unit[i];
        }
        return out;
    }

    private static double[] concat(double[] a, double[] b) {
        double[] out = Arrays.copyOf(a, a.length + b.length);
        System.arraycopy(b, 0, out, a.length, b.length);
        return out;
    }

    @Test
    void randomPointsAgreeWithTheCube() {
        SolidInside solid = new SolidInside(cube(0, 1), 12);
        assertEquals(12, solid.closedTriangleCount(), "setup: the cube is closed");
        SplittableRandom random = new SplittableRandom(5);
        for (int k = 0; k < 20_000; k++) {
            double x = random.nextDouble(-0.5, 1.5);
            double y = random.nextDouble(-0.5, 1.5);
            double z = random.nextDouble(-0.5, 1.5);
            boolean expected = x > 0 && x < 1 && y > 0 && y < 1 && z > 0 && z < 1;
            assertEquals(expected, solid.inside(x, y, z), x + " " + y + " " + z);
        }
    }

    @Test
    void pointsOnTheSurfaceAndOnItsLinesAreDecided() {
        SolidInside solid = new SolidInside(cube(0, 1), 12);
        // On a face, an edge, a corner: not inside.
        assertFalse(solid.inside(0.5, 0.5, 1));
        assertFalse(solid.inside(1, 0.5, 1));
        assertFalse(solid.inside(1, 1, 1));
        // Inside on the diagonals the triangles are cut along, and at the centre.
        assertTrue(solid.inside(0.5, 0.5, 0.5));
        assertTrue(solid.inside(0.25, 0.25, 0.25));
        assertTrue(solid.inside(0.999999, 0.000001, 0.5));
        assertFalse(solid.inside(1.000001, 0.5, 0.5));
    }

    @Test
    void aCavityIsOutsideAndAnOpenBoxBoundsNothing() {
        SolidInside hollow = new SolidInside(concat(cube(0, 1), cube(0.25, 0.75)), 24);
        assertEquals(24, hollow.closedTriangleCount());
        assertFalse(hollow.inside(0.5, 0.5, 0.5), "in the cavity");
        assertTrue(hollow.inside(0.1, 0.1, 0.1), "in the shell");
        double[] open = Arrays.copyOf(cube(0, 1), 9 * 11);
        SolidInside box = new SolidInside(open, 11);
        assertEquals(0, box.closedTriangleCount(), "a box without one triangle is open");
        assertFalse(box.inside(0.5, 0.5, 0.5));
        // A closed cube beside the open box: only the cube counts.
        SolidInside both = new SolidInside(concat(open, cube(2, 3)), 23);
        assertEquals(12, both.closedTriangleCount());
        assertTrue(both.inside(2.5, 2.5, 2.5));
        assertFalse(both.inside(0.5, 0.5, 0.5));
    }
}
