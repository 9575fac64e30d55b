package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.io.MeshReaders;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Surfaces that run through themselves, and surfaces that only touch where they share corners and edges. */
class SelfCrossingsTest {
    /** Triangles as given, 9 numbers each, no corners shared unless the numbers repeat exactly (then one vertex). */
    private static PolygonSoup triangles(double[]... corners) {
        PolygonSoup soup = new PolygonSoup();
        java.util.Map<String, Integer> vertices = new java.util.HashMap<>();
        for (double[] t : corners) {
            int[] face = new int[3];
            for (int k = 0; k < 3; k++) {
                String key = t[3 * k] + " " + t[3 * k + 1] + " " + t[3 * k + 2];
                final int at = k;
                face[k] = vertices.computeIfAbsent(key, x -> soup.addVertex(t[3 * at], t[3 * at + 1], t[3 * at + 2]));
            }
            soup.addFace(face, 3, 0);
        }
        return soup;
    }

    @Test
    void twoTrianglesThroughEachOtherCross() {
        assertArrayEquals(new int[] {0, 1}, SelfCrossings.first(triangles(new double[] {0, 0, 0, 2, 0, 0, 0, 2, 0},
                new double[] {0.5, 0.5, -1, 0.5, 0.5, 1, 1.5, 0.5, 0})));
    }

    @Test
    void twoTrianglesOneAboveTheOtherDoNot() {
        assertNull(SelfCrossings.first(triangles(new double[] {0, 0, 0, 2, 0, 0, 0, 2, 0}, new double[] {0, 0, 1e-6, 2, 0, 1e-6, 0, 2, 1e-6})));
    }

    @Test
    void overlapInOnePlaneIsACrossing() {
        assertArrayEquals(new int[] {0, 1}, SelfCrossings.first(triangles(new double[] {0, 0, 0, 2, 0, 0, 0, 2, 0},
                new double[] {0.5, 0.5, 0, 3, 0.5, 0, 0.5, 3, 0})));
    }

    @Test
    void neighboursThatShareAnEdgeOrACornerOnlyTouch() {
        // A square's two halves (flat), a roof (bent 90 degrees), and a fan around a corner.
        assertNull(SelfCrossings.first(triangles(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0}, new double[] {0, 0, 0, 1, 1, 0, 0, 1, 0})));
        assertNull(SelfCrossings.first(triangles(new double[] {0, 0, 0, 1, 0, 0, 0, 0, 1}, new double[] {1, 0, 0, 0, 0, 0, 0, 1, 0})));
        assertNull(SelfCrossings.first(triangles(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0}, new double[] {0, 0, 0, -1, 0, 0, -1, -1, 0.5})));
        assertNull(SelfCrossings.first(Solids.cube()), "a cube");
    }

    /** A face folded back onto its neighbour across their shared edge: the two lie on each other. */
    @Test
    void aNeighbourFoldedFlatOntoItsEdgeCrosses() {
        assertArrayEquals(new int[] {0, 1}, SelfCrossings.first(triangles(new double[] {0, 0, 0, 1, 0, 0, 0, 1, 0},
                new double[] {1, 0, 0, 0, 0, 0, 0.2, 0.5, 0})));
    }

    /** A scan of a rabbit whose surface passes through itself: its triangles 16 and 1094 cross (checked in exact arithmetic). */
    @Test
    void theSharedRabbitRunsThroughItself() throws Exception {
        Path rabbit = Path.of("..", "shared", "meshes", "valid", "trimesh_rabbit.obj");
        assumeTrue(Files.isRegularFile(rabbit), "../shared/meshes is absent");
        HalfedgeMesh mesh = MeshBuilder.build(MeshReaders.read(rabbit), new MeshBuilder.Options(false, true)).mesh();
        assertArrayEquals(new int[] {16, 1094}, SelfCrossings.first(mesh));
    }

    /**
     * Thin triangles fanning from a corner far from the origin, each a billionth wide: they only
     * share edges and their corner. (Shrunk towards their centres by a millionth, as this check
     * first did, neighbours moved by less than the coordinates' rounding and were taken for
     * crossing.)
     */
    @Test
    void aFanOfSliversAwayFromTheOriginOnlyTouches() {
        PolygonSoup fan = new PolygonSoup();
        int apex = fan.addVertex(10, 10, 10);
        int[] rim = new int[11];
        for (int k = 0; k <= 10; k++) {
            rim[k] = fan.addVertex(11, 10 + k * 1e-9, 10);
        }
        for (int k = 0; k < 10; k++) {
            fan.addFace(new int[] {apex, rim[k], rim[k + 1]}, 3, 0);
        }
        assertNull(SelfCrossings.first(fan));
    }

    /** A corner of one triangle on the edge of another (a T-junction) touches, it does not cross. */
    @Test
    void aCornerOnAnothersEdgeOnlyTouches() {
        assertNull(SelfCrossings.first(triangles(new double[] {0, 0, 0, 2, 0, 0, 1, 1, 0}, new double[] {1, 0, 0, 1, -1, 0.5, 2, -1, 0})));
    }

    /**
     * Many small triangles and one across them all, in separate places: the grid grows its cells
     * rather than file the big one in a million of them (it ran out of memory).
     */
    @Test
    void oneBigTriangleAmongManySmallOnesNeedsLittleMemory() {
        PolygonSoup soup = new PolygonSoup();
        for (int i = 0; i < 200; i++) {
            for (int j = 0; j < 200; j++) {
                int a = soup.addVertex(i, j, 0);
                int b = soup.addVertex(i + 1e-3, j, 0);
                int c = soup.addVertex(i, j + 1e-3, 0);
                soup.addFace(new int[] {a, b, c}, 3, 0);
            }
        }
        int a = soup.addVertex(0, 0, 5);
        int b = soup.addVertex(200, 0, 6);
        int c = soup.addVertex(0, 200, 7);
        soup.addFace(new int[] {a, b, c}, 3, 0);
        long before = Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory();
        assertNull(SelfCrossings.first(soup), "nothing crosses: the big one lies above the rest");
        long after = Runtime.getRuntime().totalMemory() - Runtime.getRuntime().freeMemory();
        org.junit.jupiter.api.Assertions.assertTrue(after - before < 512L << 20, "memory: " + ((after - before) >> 20) + " MiB");
    }
}
