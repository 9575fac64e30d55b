package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.check.PaperCollisions;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshReaders;
import ifold.refine.HamiltonianRefinement;
import ifold.testing.SharedMeshes;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * The strip begun at several places round its path: the wrap kept is one of those tried, has
 * their fewest layers, and is as good paper as any wrap (every truth of {@link WrapTruths} on
 * its OBJ, its layer order from its FOLD file, no crossing pair by {@link PaperCollisions}).
 */
class SeamTest {
    @TempDir
    Path dir;

    private static final Wrap.Options DEFAULTS = new Wrap.Options(Double.NaN, Double.NaN);

    static HalfedgeMesh mesh(PolygonSoup soup) throws Exception {
        return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    /** Wraps the mesh from its best start, checks the wrap kept as paper, and returns it. */
    private Seam.Chosen wrapAndCheck(HalfedgeMesh mesh) throws Exception {
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh).refinement();
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE);
        assertSame(chosen.refinement().mesh(), chosen.result().mesh(), "the wrap kept is along the path kept");
        WrapTest.check(dir, chosen.result(), mesh, refinement.componentCount(), 2000);
        PaperCollisions.Result collisions = PaperCollisions.check(Files.readString(dir.resolve("wrap.obj")), chosen.result().thickness());
        assertEquals(0, collisions.crossingPairs(), collisions.summary());
        return chosen;
    }

    @Test
    void theCubeKeepsTheStartWithFewestLayers() throws Exception {
        HalfedgeMesh cube = mesh(Solids.cube());
        Seam.Chosen chosen = wrapAndCheck(cube);
        List<Integer> tried = chosen.layersTried();
        assertEquals(Seam.TRIED.length, tried.size(), "a short cyclic path is begun at every start tried");
        int fewest = Collections.min(tried);
        assertEquals(fewest, chosen.placed().analysis().maxLayers());
        // The first start with the fewest is kept: ties keep the refinement's own order.
        assertEquals(Seam.TRIED[tried.indexOf(fewest)], chosen.along());
        // Its measures are those of its paper, taken again.
        assertEquals(fewest, PlacedWrap.of(chosen.result()).analysis().maxLayers());
        // Each start wrapped alone gives the layers reported for it.
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(cube).refinement();
        for (int k = 0; k < Seam.TRIED.length; k++) {
            HamiltonianRefinement.Result begun = k == 0 ? refinement : refinement.begunAt(Seam.TRIED[k]);
            assertEquals(tried.get(k), PlacedWrap.of(Wrap.wrap(begun, DEFAULTS)).analysis().maxLayers(), "start " + Seam.TRIED[k]);
        }
        // On the cube the start matters: its four give different counts (15, 16, 13, 14 when written).
        assertTrue(Collections.max(tried) > fewest, "the cube's starts differ: " + tried);
    }

    @Test
    void aStartPastTheLimitOfFacesIsPassedOverInItsPlace() throws Exception {
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.cube())).refinement();
        // Each start's faces and layers alone; the limit then the first start's faces, which some others pass.
        int[] faces = new int[Seam.TRIED.length];
        int[] layers = new int[Seam.TRIED.length];
        for (int k = 0; k < Seam.TRIED.length; k++) {
            Wrap.Result alone = Wrap.wrap(k == 0 ? refinement : refinement.begunAt(Seam.TRIED[k]), DEFAULTS);
            faces[k] = alone.strips().get(0).sheet().faceCount();
            layers[k] = PlacedWrap.of(alone).analysis().maxLayers();
        }
        int limit = faces[0];
        List<Integer> expected = new ArrayList<>();
        for (int k = 0; k < Seam.TRIED.length; k++) {
            expected.add(faces[k] <= limit ? layers[k] : null);
        }
        assertTrue(expected.contains(null), "some start makes more faces than the first: " + java.util.Arrays.toString(faces));
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS.withMaxFaces(limit), Wrap.Watcher.NONE);
        assertEquals(expected, chosen.layersTried(), "each start in its place, null where it failed");
        int fewest = expected.stream().filter(java.util.Objects::nonNull).min(Integer::compare).orElseThrow();
        assertEquals(fewest, chosen.placed().analysis().maxLayers());
        assertEquals(Seam.TRIED[expected.indexOf(fewest)], chosen.along());
        // The first start failing is the wrap failing: its message, as a wrap from it alone gives.
        Wrap.WrapException first = org.junit.jupiter.api.Assertions.assertThrows(Wrap.WrapException.class,
                () -> Seam.wrap(refinement, DEFAULTS.withMaxFaces(limit - 1), Wrap.Watcher.NONE));
        assertTrue(first.getMessage().contains("more than the limit of " + (limit - 1) + " faces"), first.getMessage());
    }

    @Test
    void progressRunsOnceThroughEveryStartTried() throws Exception {
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.octahedron())).refinement();
        List<int[]> told = new ArrayList<>();
        Seam.wrap(refinement, DEFAULTS, new Wrap.Watcher() {
            @Override
            public void wrapped(int done, int total) {
                told.add(new int[] {done, total});
            }

            @Override
            public boolean stopped() {
                return false;
            }
        });
        // Out of the path's triangles, as a single wrap counts, and through them once.
        int triangles = refinement.mesh().faceCount();
        int[] last = told.get(told.size() - 1);
        assertEquals(triangles, last[0]);
        assertEquals(triangles, last[1]);
        assertTrue(told.size() >= Seam.TRIED.length * triangles / 2, "told as each try goes: " + told.size());
        for (int i = 1; i < told.size(); i++) {
            assertTrue(told.get(i)[0] >= told.get(i - 1)[0], "progress never goes back");
            assertEquals(last[1], told.get(i)[1]);
        }
    }

    @Test
    void aLongPathIsWrappedOnceFromItsOwnStart() throws Exception {
        // 288 triangles, refined into 1,438: more than a seam is tried for.
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.torus(3, 1, 16, 9))).refinement();
        assertTrue(refinement.mesh().faceCount() > Seam.MOST_TRIANGLES);
        assertEquals(1, Seam.tries(refinement));
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE);
        assertEquals(0.0, chosen.along());
        assertEquals(List.of(), chosen.layersTried());
        assertSame(refinement, chosen.refinement());
    }

    static Stream<String> polyhedra() {
        return WrapTest.polyhedra();
    }

    /** The shared polyhedra as the wrap command wraps them: the spike's 74 layers from every start. */
    @ParameterizedTest
    @MethodSource("polyhedra")
    void theSharedPolyhedraFromTheirBestStart(String name) throws Exception {
        Path file = SharedMeshes.ROOT.resolve("polyhedra").resolve(name);
        assumeTrue(Files.isRegularFile(file), "../shared/meshes is absent");
        Seam.Chosen chosen = wrapAndCheck(MeshBuilder.build(MeshReaders.read(file), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh());
        assertEquals(Collections.min(chosen.layersTried()), chosen.placed().analysis().maxLayers());
        if (!name.startsWith("spike")) {
            assertTrue(chosen.placed().analysis().maxLayers() <= 24, name + ": " + chosen.layersTried());
        }
    }
}
