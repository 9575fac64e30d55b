package ifold.geom;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class PolygonTriangulatorTest {

    private static double signedArea(double[] xyz, int a, int b, int c) {
        return 0.5 * ((xyz[3 * b] - xyz[3 * a]) * (xyz[3 * c + 1] - xyz[3 * a + 1])
                - (xyz[3 * b + 1] - xyz[3 * a + 1]) * (xyz[3 * c] - xyz[3 * a]));
    }

    /** Triangulates and checks that every triangle is positive and the areas add up. */
    private static void check(double[] xyz, int size, double expectedArea) {
        int[] polygon = new int[size];
        for (int i = 0; i < size; i++) {
            polygon[i] = i;
        }
        int[] triangles = new int[3 * size];
        assertEquals(size - 2, PolygonTriangulator.triangulate(xyz, polygon, size, triangles));
        double area = 0;
        for (int t = 0; t < size - 2; t++) {
            double a = signedArea(xyz, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
            assertTrue(a > 1e-12, "triangle " + t + " has positive area, got " + a);
            area += a;
        }
        assertEquals(expectedArea, area, 1e-12);
    }

    @Test
    void comb() {
        // Three teeth: every naive fan from vertex 0 would leave the polygon.
        double[] xyz = {0, 0, 0, 5, 0, 0, 5, 3, 0, 4, 3, 0, 4, 1, 0, 3, 1, 0, 3, 3, 0, 2, 3, 0, 2, 1, 0,
            1, 1, 0, 1, 3, 0, 0, 3, 0};
        check(xyz, 12, 5 + 3 * 2);
    }

    @Test
    void collinearCornersMakeNoSlivers() {
        // A square with extra vertices on its sides.
        double[] xyz = {0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 2, 2, 0, 1, 2, 0, 0, 2, 0, 0, 1, 0};
        check(xyz, 8, 4);
    }

    @Test
    void clockwiseInputKeepsItsOrientationIn3d() {
        // A tilted quad: the triangles' normals must agree with the quad's Newell normal.
        double[] xyz = {0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 0, 0};
        int[] polygon = {0, 1, 2, 3};
        int[] triangles = new int[6];
        assertEquals(2, PolygonTriangulator.triangulate(xyz, polygon, 4, triangles));
        double[] normal = new double[3];
        Polygons.newellNormal(xyz, polygon, 4, normal);
        for (int t = 0; t < 2; t++) {
            double[] tn = new double[3];
            Polygons.newellNormal(xyz, new int[] {triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]}, 3, tn);
            assertTrue(tn[0] * normal[0] + tn[1] * normal[1] + tn[2] * normal[2] > 0);
        }
    }

    @Test
    void polygonWithoutAreaGivesNothing() {
        double[] xyz = {0, 0, 0, 1, 0, 0, 2, 0, 0, 3, 0, 0};
        assertEquals(0, PolygonTriangulator.triangulate(xyz, new int[] {0, 1, 2, 3}, 4, new int[6]));
    }
}
