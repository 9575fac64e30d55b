package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.check.PaperCollisions;
import ifold.job.Collisions;
import ifold.job.WrapPath;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.io.MeshReaders;
import ifold.testing.SharedMeshes;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * Hexagons fanned from their centre ({@code PlanarRegion.MOST_FAN_CORNERS}), wrapped as
 * {@code ifold wrap} wraps them (prepared, the best of its starts): the shared hex_prism had eight
 * thin triangles at the corner its hexagons' four triangles fan from, and 21 layers there. Fanned,
 * the bends on the line from a corner to the centre stood out into paper tucked between their
 * layers that left the corner at an angle (hex_prism 4 crossing pairs, a lone hexagon 2, an
 * irregular prism 4), until their rows stopped on that paper ({@link RowsOnPaper}); and two
 * folds back to back on such a line by a top corner of a prism 4 high met the crease at two
 * heights, their corners standing back where the truths saw no two folds meeting (until
 * {@code PaperInSpace}'s apexes met).
 */
class HexagonsTest {
    @TempDir
    Path dir;

    /** Wraps {@code mesh} as the command does, checks the five truths and the layer order, and the collisions of its OBJ. */
    private WrapAnalysis wrapAndCheck(HalfedgeMesh mesh, int samples) throws Exception {
        WrapPath path = WrapPath.of(mesh);
        assertTrue(path.preparation().centredRegions() > 0, "setup: hexagons fanned from their centre");
        Seam.Chosen chosen = Seam.wrap(path.refinement(), new Wrap.Options(Double.NaN, Double.NaN), Wrap.Watcher.NONE);
        WrapTest.check(dir, chosen.result(), mesh, 1, samples);
        PaperCollisions.Result collisions = PaperCollisions.check(Files.readString(dir.resolve("wrap.obj")),
                chosen.result().thickness(), Collisions.modelTriangles(mesh));
        assertEquals(0, collisions.crossingPairs(), collisions::summary);
        assertEquals(0, collisions.modelCrossings(), collisions::summary);
        assertEquals(0, collisions.pointsInside(), collisions::summary);
        return chosen.placed().analysis();
    }

    @Test
    void theSharedHexPrismHasAtMost19Layers() throws Exception {
        Path file = SharedMeshes.ROOT.resolve("polyhedra").resolve("hex_prism.off");
        assumeTrue(Files.isRegularFile(file), "../shared/meshes is absent");
        WrapAnalysis analysis = wrapAndCheck(build(MeshReaders.read(file)), 2000);
        assertTrue(analysis.maxLayers() <= 19, "layers " + analysis.maxLayers() + " (21 with its hexagons fanned from a corner)");
    }

    /**
     * A lone regular hexagon (17 layers cut from a corner), a regular prism 4 high (21) and an
     * irregular convex prism (20): fewer layers fanned, and no paper crossing.
     */
    @ParameterizedTest
    @ValueSource(strings = {"lone", "tall", "irregular"})
    void hexagonsFannedFromTheirCentreWrapWithoutCrossing(String shape) throws Exception {
        double[][] regular = new double[6][];
        for (int i = 0; i < 6; i++) {
            regular[i] = new double[] {Math.cos(i * Math.PI / 3), Math.sin(i * Math.PI / 3)};
        }
        double[][] irregular = {{1.2, 0}, {0.6, 0.9}, {-0.4, 1}, {-1.1, 0.1}, {-0.6, -0.8}, {0.5, -1}};
        PolygonSoup soup = switch (shape) {
            case "lone" -> hexagon(regular);
            case "tall" -> WrapTest.prism(regular, 4);
            default -> WrapTest.prism(irregular, 1.2);
        };
        int before = switch (shape) {
            case "lone" -> 17;
            case "tall" -> 21;
            default -> 20;
        };
        WrapAnalysis analysis = wrapAndCheck(build(soup), 2000);
        assertTrue(analysis.maxLayers() < before, "layers " + analysis.maxLayers() + ", " + before + " cut from a corner");
    }

    private static PolygonSoup hexagon(double[][] corners) {
        PolygonSoup soup = new PolygonSoup();
        for (double[] p : corners) {
            soup.addVertex(p[0], p[1], 0);
        }
        soup.addFace(new int[] {0, 1, 2, 3, 4, 5}, 6, 0);
        return soup;
    }

    private static HalfedgeMesh build(PolygonSoup soup) throws Exception {
        return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

}
