package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Polycubes: their surfaces of unit squares, spheres where they should be, and the random ones grown the same from a seed. */
class PolycubesTest {
    @Test
    void theNamedShapesHaveTheSquaresTheirCubesShow() {
        // A box's surface: 2(ab + bc + ca) squares; the others counted by hand (6 a cube, less 2 a joined face).
        assertEquals(22, Polycubes.surface(Polycubes.box(3, 2, 1)).faceCount());
        assertEquals(6, Polycubes.surface(Polycubes.box(1, 1, 1)).faceCount());
        assertEquals(4 * 6 - 2 * 3, Polycubes.surface(Polycubes.l()).faceCount());
        assertEquals(4 * 6 - 2 * 3, Polycubes.surface(Polycubes.t()).faceCount());
        assertEquals(5 * 6 - 2 * 4, Polycubes.surface(Polycubes.plus()).faceCount());
        assertEquals(6 * 6 - 2 * 6, Polycubes.surface(Polycubes.staircase()).faceCount());
        for (List<int[]> shape : List.of(Polycubes.box(3, 2, 1), Polycubes.l(), Polycubes.t(), Polycubes.plus(), Polycubes.staircase())) {
            assertTrue(Polycubes.isSphere(Polycubes.surface(shape)));
        }
        assertThrows(IllegalArgumentException.class, () -> Polycubes.box(0, 1, 1));
    }

    /** Each square faces out: the surface encloses a positive volume, the cubes' count (the divergence theorem). */
    @Test
    void squaresFaceOutwards() {
        PolygonSoup soup = Polycubes.surface(Polycubes.staircase());
        double volume = 0;
        for (int f = 0; f < soup.faceCount(); f++) {
            double[] a = point(soup, soup.faceVertex(f, 0));
            for (int k = 1; k + 1 < soup.faceSize(f); k++) {
                double[] b = point(soup, soup.faceVertex(f, k));
                double[] c = point(soup, soup.faceVertex(f, k + 1));
                volume += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
            }
        }
        assertEquals(6, volume, 1e-12);
    }

    private static double[] point(PolygonSoup soup, int v) {
        return new double[] {soup.coordinate(v, 0), soup.coordinate(v, 1), soup.coordinate(v, 2)};
    }

    @Test
    void whatIsNoSphereIsToldApart() {
        // Two cubes along an edge alone; at a corner alone; a ring round a hole; a shell round a cavity.
        assertFalse(Polycubes.isSphere(Polycubes.surface(List.of(new int[] {0, 0, 0}, new int[] {1, 1, 0}))));
        assertFalse(Polycubes.isSphere(Polycubes.surface(List.of(new int[] {0, 0, 0}, new int[] {1, 1, 1}))));
        List<int[]> ring = new ArrayList<>();
        List<int[]> shell = new ArrayList<>();
        for (int x = 0; x < 3; x++) {
            for (int y = 0; y < 3; y++) {
                if (x != 1 || y != 1) {
                    ring.add(new int[] {x, y, 0});
                }
                for (int z = 0; z < 3; z++) {
                    if (x != 1 || y != 1 || z != 1) {
                        shell.add(new int[] {x, y, z});
                    }
                }
            }
        }
        assertFalse(Polycubes.isSphere(Polycubes.surface(ring)), "genus 1");
        assertFalse(Polycubes.isSphere(Polycubes.surface(shell)), "two spheres, one inside");
    }

    @Test
    void aRandomPolycubeIsASphereAndTheSameSeedGrowsTheSameOne() {
        List<int[]> a = Polycubes.random(50, 7);
        List<int[]> b = Polycubes.random(50, 7);
        assertEquals(50, a.size());
        for (int i = 0; i < a.size(); i++) {
            assertArrayEquals(a.get(i), b.get(i));
        }
        assertTrue(Polycubes.isSphere(Polycubes.surface(a)));
        assertFalse(Polycubes.random(50, 8).stream().map(java.util.Arrays::toString).toList()
                .equals(a.stream().map(java.util.Arrays::toString).toList()), "another seed, another polycube");
        // Grown past the shapes that would close a hole or a cavity: 300 cubes, still a sphere.
        assertTrue(Polycubes.isSphere(Polycubes.surface(Polycubes.random(300, 3))));
    }
}
