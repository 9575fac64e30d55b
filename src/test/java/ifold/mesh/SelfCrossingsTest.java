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
}
