package ifold.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Seam;
import ifold.wrap.Wrap;
import org.junit.jupiter.api.Test;

/** What the wrap job tells of the seam's choice. */
class WrapJobTest {
    private static final Wrap.Options DEFAULTS = new Wrap.Options(Double.NaN, Double.NaN);

    @Test
    void aStartPassedOverForItsCollisionsIsSaid() throws Exception {
        HamiltonianRefinement.Result refinement = WrapPath.of(MeshBuilder.build(Solids.cube(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh())
                .refinement();
        // The cube's starts make 15, 16, 13 and 14 layers; a check finding 5 collisions in the 13's paper keeps the 14
        // (and 1 in each start along the cube's own triangles, which are then passed over too, but not said: they are not the refinement's).
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE,
                (result, placed) -> ownTriangles(result) ? 1 : placed.analysis().maxLayers() == 13 ? 5 : 0);
        assertEquals("cube.off: begun where its paper is sound: a start with 13 layers, not 14, was passed over,"
                + " the collision check finding 5 collisions in its paper", WrapJob.passedOver("cube.off", chosen));
        // Nothing passed over: nothing said, whether the paper was checked or not.
        assertNull(WrapJob.passedOver("cube.off", Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> ownTriangles(result) ? 1 : 0)));
        assertNull(WrapJob.passedOver("cube.off", Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE)));
        // Every start colliding, the fewest layers kept: none was passed over for its paper.
        assertNull(WrapJob.passedOver("cube.off", Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> 1)));
    }

    /**
     * The other path is tried where thin triangles fan in a plane near the deepest point: at a
     * cone's base fanned from its centre, not at its apex (its faces turn there) nor at a long
     * box's corner, where thin triangles meet too but the prepared faces were as many layers or more.
     */
    @Test
    void aFanOfThinTrianglesInAPlaneIsFoundWhereItLies() throws Exception {
        PolygonSoup cone = new PolygonSoup();
        for (int s = 0; s < 24; s++) {
            cone.addVertex(Math.cos(2 * Math.PI * s / 24), Math.sin(2 * Math.PI * s / 24), 0);
        }
        int apex = cone.addVertex(0, 0, 1);
        int centre = cone.addVertex(0, 0, 0);
        for (int s = 0; s < 24; s++) {
            cone.addTriangle(s, (s + 1) % 24, apex);
            cone.addTriangle(centre, (s + 1) % 24, s);
        }
        WrapPath path = WrapPath.of(MeshBuilder.build(cone, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh());
        assertFalse(path.prepared(), "along the model's own triangles, likely fewer faces");
        assertTrue(path.fanNear(new double[] {0.01, 0.02, 0}, 0.05));
        assertFalse(path.fanNear(new double[] {0.01, 0.02, 0}, 0.01), "out of reach");
        assertFalse(path.fanNear(new double[] {0, 0, 0.99}, 0.05), "the apex: its faces turn");
        assertTrue(path.other().prepared());
        WrapPath box = WrapPath.of(MeshBuilder.build(Solids.box(30, 1, 1), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh());
        assertFalse(box.prepared());
        assertTrue(box.other() != null, "its faces prepared");
        assertFalse(box.fanNear(new double[] {0.02, 0, 1}, 0.5), "a solid's corner");
        assertFalse(box.fanNear(new double[] {15, 0.5, 1}, 0.5), "the middle of a face: no vertex there");
    }

    private static boolean ownTriangles(Wrap.Result result) {
        return result.mesh() instanceof ifold.refine.RefinedMesh path && path.ownTriangles();
    }
}
