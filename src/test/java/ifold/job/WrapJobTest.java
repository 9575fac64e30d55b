package ifold.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;

import ifold.mesh.MeshBuilder;
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

    private static boolean ownTriangles(Wrap.Result result) {
        return result.mesh() instanceof ifold.refine.RefinedMesh path && path.ownTriangles();
    }
}
