package ifold.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** The test of a triangle's area gives one answer for a triangle, whichever corner it is read from. */
class TrianglesTest {
    /**
     * A sliver at the area threshold, to a thousandth: its third corner off the line of the
     * first two by 1e-12 of their distance, where rounding decides.
     */
    private static double[] sliver(Random random) {
        double[] xyz = new double[9];
        for (int k = 0; k < 6; k++) {
            xyz[k] = random.nextDouble();
        }
        double bx = xyz[3] - xyz[0];
        double by = xyz[4] - xyz[1];
        double bz = xyz[5] - xyz[2];
        double base = Math.sqrt(bx * bx + by * by + bz * bz);
        // Across the base: base x (0, 0, 1), made a unit.
        double nx = by;
        double ny = -bx;
        double across = Math.hypot(nx, ny);
        double height = Tolerance.DEGENERATE_AREA * base * (1 + 1e-3 * (random.nextDouble() - 0.5));
        double t = random.nextDouble();
        xyz[6] = xyz[0] + t * bx + height * nx / across;
        xyz[7] = xyz[1] + t * by + height * ny / across;
        xyz[8] = xyz[2] + t * bz;
        return xyz;
    }

    @Test
    void aSliverAtTheThresholdIsJudgedTheSameFromEveryCornerAndEitherWayRound() {
        Random random = new Random(42);
        int degenerate = 0;
        for (int i = 0; i < 20_000; i++) {
            double[] xyz = sliver(random);
            boolean verdict = Triangles.isDegenerate(xyz, 0, 1, 2);
            degenerate += verdict ? 1 : 0;
            for (int[] order : new int[][] {{1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}}) {
                assertEquals(verdict, Triangles.isDegenerate(xyz, order[0], order[1], order[2]), "sliver " + i);
            }
        }
        assertTrue(degenerate > 2_000 && degenerate < 18_000, "setup: slivers either side of the threshold: " + degenerate);
    }

    @Test
    void aSliverTheBuilderKeepsIsValid() throws InvalidMeshException {
        Random random = new Random(7);
        int kept = 0;
        for (int i = 0; i < 5_000; i++) {
            double[] xyz = sliver(random);
            PolygonSoup soup = new PolygonSoup();
            for (int v = 0; v < 3; v++) {
                soup.addVertex(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
            }
            soup.addTriangle(0, 1, 2);
            MeshBuilder.Result built = MeshBuilder.build(soup);
            if (built.mesh().faceCount() == 1) {
                kept++;
                assertEquals(java.util.List.of(), MeshValidator.validate(built.mesh()), "sliver " + i);
            }
        }
        assertTrue(kept > 500, "setup: slivers kept: " + kept);
    }
}
