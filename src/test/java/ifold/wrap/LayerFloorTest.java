package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.refine.HamiltonianRefinement;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/** The fewest layers any strip needs, ⌈π / (2Θ)⌉ at the vertex of the smallest angle sum Θ, against answers known by hand. */
class LayerFloorTest {
    private static HalfedgeMesh build(PolygonSoup soup) throws Exception {
        return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    /** A tetrahedron on a unit equilateral base whose three side faces have an apex of {@code degrees} (as bench/Corners.java). */
    static PolygonSoup spike(double degrees) {
        double inradius = 1 / (2 * Math.sqrt(3));
        double slant = 0.5 / Math.tan(Math.toRadians(degrees) / 2);
        double height = Math.sqrt(slant * slant - inradius * inradius);
        double circumradius = 1 / Math.sqrt(3);
        PolygonSoup soup = new PolygonSoup();
        for (int k = 0; k < 3; k++) {
            soup.addVertex(circumradius * Math.cos(2 * Math.PI * k / 3), circumradius * Math.sin(2 * Math.PI * k / 3), 0);
        }
        soup.addVertex(0, 0, height);
        soup.addTriangle(0, 2, 1);
        soup.addTriangle(0, 1, 3);
        soup.addTriangle(1, 2, 3);
        soup.addTriangle(2, 0, 3);
        return soup;
    }

    @Test
    void aCubesCornersNeedOneLayer() throws Exception {
        PolygonSoup soup = new PolygonSoup();
        for (int v = 0; v < 8; v++) {
            soup.addVertex(v & 1, (v >> 1) & 1, (v >> 2) & 1);
        }
        int[][] quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int[] q : quads) {
            soup.addFace(q, 4, 0);
        }
        LayerFloor floor = LayerFloor.of(build(soup));
        assertEquals(270, Math.toDegrees(floor.angleSum()), 1e-9);
        assertEquals(1, floor.layers());
    }

    @Test
    void aSpikesApexNeedsAQuarterTurnOverItsAngleSum() throws Exception {
        // Three faces of 1° at the apex: Θ = 3°, so 90° / 3° = 30 layers; of 7°: 21°, 90/21 = 4.29 → 5.
        LayerFloor sharp = LayerFloor.of(build(spike(1)));
        assertEquals(3, Math.toDegrees(sharp.angleSum()), 1e-9);
        assertEquals(30, sharp.layers());
        assertEquals(0, sharp.point()[0], 1e-12);
        assertEquals(0, sharp.point()[1], 1e-12);
        assertTrue(sharp.point()[2] > 50, "the apex");
        assertEquals(5, LayerFloor.of(build(spike(7))).layers());
        // The refinement keeps every vertex's angle sum: its new vertices lie inside faces or on edges.
        LayerFloor refined = LayerFloor.of(HamiltonianRefinement.refine(build(spike(1))).mesh());
        assertEquals(sharp.angleSum(), refined.angleSum(), 1e-12);
        assertArrayEquals(sharp.point(), refined.point(), 1e-12);
    }

    @Test
    void aBoundOfAWholeNumberIsNotRoundedUp() throws Exception {
        // One right isosceles triangle, an open surface: its 45° corners give exactly 90 / 45 = 2.
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(1, 0, 0);
        soup.addVertex(0, 1, 0);
        soup.addTriangle(0, 1, 2);
        LayerFloor floor = LayerFloor.of(build(soup));
        assertEquals(45, Math.toDegrees(floor.angleSum()), 1e-9);
        assertEquals(2, floor.layers());
    }

    /**
     * A wrap of a 3° spike (Θ = 9°, a floor of 10) and of a 1.5° one (issue 20's sharp
     * tetrahedron, Θ = 4.5°, a floor of 20) passes every truth, its layer order among them, and
     * counts at least the floor (WrapTest.check asserts it).
     */
    @ParameterizedTest
    @CsvSource({"3, 10", "1.5, 20"})
    void aSharpSpikesWrapHasAtLeastItsFloor(double apexDegrees, int floorLayers, @TempDir Path dir) throws Exception {
        HalfedgeMesh model = build(spike(apexDegrees));
        assertEquals(floorLayers, LayerFloor.of(model).layers());
        Wrap.Result result = Wrap.wrap(HamiltonianRefinement.refine(model), new Wrap.Options(Double.NaN, Double.NaN));
        WrapTest.check(dir, result, model, 1, 2000);
        List<PaperInSpace> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
        }
        assertTrue(WrapAnalysis.of(result, geometries).maxLayers() >= floorLayers);
    }
}
