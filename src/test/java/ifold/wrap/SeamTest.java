package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.check.PaperCollisions;
import ifold.check.WrapTruths;
import ifold.job.Collisions;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.io.MeshReaders;
import ifold.refine.CycleCoverPath;
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

    /**
     * A wrap along the model's own triangles may leave some of it bare, where a wrap along the
     * refinement does not; the seam keeps no such wrap ({@link Seam#covers}). The shared
     * dodecahedron along its 36 own triangles from their first start: 0.01 % bare.
     */
    @Test
    void aWrapThatLeavesTheModelBareDoesNotCoverIt() throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        HalfedgeMesh dodecahedron = mesh(MeshReaders.read(SharedMeshes.ROOT.resolve("polyhedra").resolve("dodecahedron.off")));
        HamiltonianRefinement.Result own = ifold.refine.CycleCoverPath.of(dodecahedron);
        PlacedWrap bare = PlacedWrap.of(Wrap.wrap(own, DEFAULTS));
        assertTrue(bare.analysis().coverage() < 1 - 1e-6, "coverage " + bare.analysis().coverage());
        assertFalse(Seam.covers(bare));
        PlacedWrap refined = PlacedWrap.of(Wrap.wrap(HamiltonianRefinement.refine(dodecahedron), DEFAULTS));
        assertTrue(Seam.covers(refined));
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
        // The first start failing, the strip along the cube's own triangles (fewer faces) is kept
        // where it wraps; where it fails too, the wrap fails with the first start's message.
        Seam.Chosen own = Seam.wrap(refinement, DEFAULTS.withMaxFaces(limit - 1), Wrap.Watcher.NONE);
        assertTrue(ownTriangles(own.result()), "the own triangles' strip, whose faces fit");
        int ownFaces = own.result().strips().get(0).sheet().faceCount();
        assertTrue(ownFaces < limit - 1, ownFaces + " faces");
        Wrap.WrapException first = org.junit.jupiter.api.Assertions.assertThrows(Wrap.WrapException.class,
                () -> Seam.wrap(refinement, DEFAULTS.withMaxFaces(100), Wrap.Watcher.NONE));
        assertTrue(first.getMessage().contains("more than the limit of 100 faces"), first.getMessage());
        assertTrue(first.getMessage().contains("of 58 on the path") || first.getMessage().contains("passes"), "the refinement's failure: " + first.getMessage());
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
    void aStartWhosePaperCollidesIsKeptOnlyWhereEveryStartsDoes() throws Exception {
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.cube())).refinement();
        List<Integer> tried = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE).layersTried();
        assertEquals(List.of(15, 16, 13, 14), tried, "the cube's starts, as measured");
        // A check finding the fewest layers' paper colliding: the next fewest is kept. The check is
        // asked of the first start, and then of each with fewer layers than the one kept so far.
        List<Integer> asked = new ArrayList<>();
        // (The starts along the cube's own triangles, tried after, are found colliding here: see theCubeFollowsItsOwnTriangles...)
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> {
            if (ownTriangles(result)) {
                return 1;
            }
            int layers = placed.analysis().maxLayers();
            asked.add(layers);
            return layers == 13 ? 5 : 0;
        });
        assertEquals(List.of(15, 13, 14), asked);
        assertEquals(14, chosen.placed().analysis().maxLayers());
        assertEquals(0.75, chosen.along());
        assertEquals(java.util.Arrays.asList(0, null, 5, 0), chosen.collisionsTried());
        // Every start colliding: each is asked, and the fewest layers kept, then the fewest collisions.
        asked.clear();
        chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> {
            if (ownTriangles(result)) {
                return 100;
            }
            asked.add(placed.analysis().maxLayers());
            return 100 - placed.analysis().maxLayers();
        });
        assertEquals(tried, asked);
        assertEquals(13, chosen.placed().analysis().maxLayers());
        assertEquals(java.util.Arrays.asList(85, 84, 87, 86), chosen.collisionsTried());
        // A start unchecked (-1) counts as sound; with no check the fewest layers are kept (the
        // own triangles' starts are kept only where the check finds them sound: never without one).
        assertEquals(13, Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> -1).placed().analysis().maxLayers());
        assertEquals(13, Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE).placed().analysis().maxLayers());
    }

    /**
     * A surface with a boundary is tried along its own triangles too: figure3 (one flat,
     * non-convex face, its boundary all round) makes 16 layers along them from both starts,
     * against 20 at best along the refinement; the first start's paper crosses itself (12 pairs
     * at caps), the second's is sound and kept, with every truth (it left the surface by its cuts
     * bare until the walls of folds along a cut stood back no farther than their own nests ask:
     * docs/wrap.md, Limits). A hundred thousand points find the surface by its cuts under the
     * bends of folds standing back half a thickness from them, or bare no wider than the stack is
     * high beside folds nested along part of a cut (`ifold check` called 1 point of 2,000 bare,
     * and 7 of 100,000, until truth 4 measured the gap to crept slivers and allowed a cut's creep).
     */
    @Test
    void figure3FollowsItsOwnTrianglesThoughItHasABoundary() throws Exception {
        HalfedgeMesh figure3 = mesh(MeshReaders.read(Path.of("models", "figure3.off")));
        Seam.Chosen chosen = Seam.wrap(ifold.job.WrapPath.of(figure3).refinement(), DEFAULTS, Wrap.Watcher.NONE,
                ifold.job.Collisions.OF_SEAM);
        assertEquals(List.of(16, 16), chosen.ownLayersTried());
        assertEquals(List.of(12, 0), chosen.ownCollisionsTried());
        assertTrue(ownTriangles(chosen.result()), "kept along its own triangles");
        assertEquals(Seam.OWN_TRIED[1], chosen.along());
        assertEquals(16, chosen.placed().analysis().maxLayers());
        WrapTest.check(dir, chosen.result(), figure3, 1, 2000);
        WrapTest.check(dir, chosen.result(), figure3, 1, 100_000, 1);
    }

    /**
     * A big surface with holes follows its own triangles with the cut ones at the leaves of the
     * splices' tree halved, where that is likely to make fewer faces: the CGAL elephant with holes
     * (4,463 triangles), whose pieces round the incentres set a widest strip of 0.00107 and about
     * 752,778 faces at it, past the default limit, so that it was refused; its leaves halved (and
     * its slivers matched first), 0.00150 and within the limit (it wraps at the defaults, 9,343
     * triangles on the path).
     */
    @Test
    void aBigSurfaceWithHolesHalvesTheLeavesOfItsPathWhereThatFitsTheLimit() throws Exception {
        followsThePathThatFitsTheLimit("cgal_elephant-with-holes.off", "made " + HALVED_SLIVERS_FIRST,
                original -> CycleCoverPath.of(original, HALVED_SLIVERS_FIRST));
    }

    private static final CycleCoverPath.Way HALVED_SLIVERS_FIRST = new CycleCoverPath.Way(true, CycleCoverPath.Leaf.HALVED);

    /**
     * A big closed scan with slivers, which no way of making its path fits at the default width,
     * follows its own triangles run the other way round where that is likely to make fewest
     * faces: {@code igl_fertility.off} (9,000 triangles), whose slivers left across their longest
     * sides set a widest strip of 0.2543 and about 832,963 faces at it, past the default limit,
     * so that it was refused; run back, each is left across the side it was entered by, 0.4513
     * and about 592,978, within the limit (matched with the slivers first, each across its
     * longest side, 0.4134 and 624,334: wrapped so, 100 layers at most where run back it has 78).
     */
    @Test
    void aBigScanRunsItsPathBackWhereThatFitsTheLimit() throws Exception {
        followsThePathThatFitsTheLimit("igl_fertility.off", "made plainly, run back", original -> CycleCoverPath.of(original).reversed());
    }

    /**
     * The shared {@code model}, refused along its own triangles made the plain way (past the
     * default face limit at their widest strip), is wrapped along the {@code expected} path of
     * them, within it.
     */
    private static void followsThePathThatFitsTheLimit(String model, String what,
            java.util.function.Function<HalfedgeMesh, HamiltonianRefinement.Result> expected) throws Exception {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        HalfedgeMesh mesh = mesh(MeshReaders.read(SharedMeshes.ROOT.resolve("valid").resolve(model)));
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh).refinement();
        HamiltonianRefinement.Result own = Seam.ownInstead(refinement, DEFAULTS);
        HalfedgeMesh original = refinement.mesh().original();
        HamiltonianRefinement.Result path = expected.apply(original);
        assertEquals(path.mesh().faceCount(), own.mesh().faceCount(), what);
        for (int t = 0; t < path.mesh().faceCount(); t++) {
            for (int k = 0; k < 3; k++) {
                assertEquals(path.mesh().faceVertex(t, k), own.mesh().faceVertex(t, k), what + ": triangle " + t);
            }
        }
        HamiltonianRefinement.Result plain = CycleCoverPath.of(original);
        long plainFaces = Wrap.likelyFaces(plain, Wrap.widest(plain.mesh(), plain.componentStart()));
        long ownFaces = Wrap.likelyFaces(own, Wrap.widest(own.mesh(), own.componentStart()));
        assertTrue(plainFaces > Wrap.DEFAULT_MAX_FACES, plainFaces + " faces at the widest, made plainly");
        assertTrue(ownFaces <= Wrap.DEFAULT_MAX_FACES, ownFaces + " faces at the widest, " + what);
    }

    /**
     * The cube along its own triangles (ifold.refine.CycleCoverPath) makes 9 layers from both of
     * its starts, against 13 at best along the refinement; the independent checker finds its first
     * start's paper sound (5 collisions before caps over edges went over the bends beside them,
     * CrossingOverBends, measured 2026-12-06), so that one is kept, with every truth.
     */
    @Test
    void theCubeFollowsItsOwnTrianglesWhereTheirPaperIsSoundWithFewerLayers() throws Exception {
        HalfedgeMesh cube = mesh(Solids.cube());
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(cube).refinement();
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, ifold.job.Collisions.OF_SEAM);
        assertEquals(List.of(9, 9), chosen.ownLayersTried());
        // The second start, with as many layers as the first kept, is not checked.
        assertEquals(java.util.Arrays.asList(0, null), chosen.ownCollisionsTried());
        assertTrue(ownTriangles(chosen.result()), "kept along the refinement");
        assertEquals(Seam.OWN_TRIED[0], chosen.along());
        assertEquals(9, chosen.placed().analysis().maxLayers());
        WrapTest.check(dir, chosen.result(), cube, 1, 2000);
        PaperCollisions.Result collisions = PaperCollisions.check(Files.readString(dir.resolve("wrap.obj")), chosen.result().thickness());
        assertEquals(0, collisions.crossingPairs(), collisions.summary());
        // A check finding every start along the own triangles colliding keeps the refinement's best sound start.
        Seam.Chosen refined = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, (result, placed) -> ownTriangles(result) ? 3 : 0);
        assertTrue(!ownTriangles(refined.result()));
        assertEquals(13, refined.placed().analysis().maxLayers());
    }

    static boolean ownTriangles(Wrap.Result result) {
        return result.mesh() instanceof ifold.refine.RefinedMesh path && path.ownTriangles();
    }

    /**
     * A tall pentagonal pyramid over an irregular base (found by a newcomer's try, 2026-12-05),
     * whose path enters its apex twice: begun at the apex and rolled round it, its strip made 37
     * layers and 63 crossing pairs of caps within 0.2 of the apex, where its four other starts
     * make 54 and none, and the seam (asking the independent checker of each start, as the wrap
     * command does) kept a sound start of 54. Now the triangle the path comes back to the apex by
     * begins short of it too (StripFolding.rolledDrop): 22 layers, measured (2026-12-06), and
     * its paper sound, so the roll's start is kept.
     */
    @Test
    void anIrregularPyramidKeepsTheRollsStartItsPaperSound() throws Exception {
        PolygonSoup soup = new PolygonSoup();
        double[][] base = {{0, 0}, {1, 0}, {1.3, 0.8}, {0.4, 1.1}, {-0.2, 0.5}};
        for (double[] corner : base) {
            soup.addVertex(corner[0], corner[1], 0);
        }
        soup.addVertex(0.3, 0.5, 9);
        soup.addFace(new int[] {4, 3, 2, 1, 0}, 5, 0);
        for (int k = 0; k < 5; k++) {
            soup.addTriangle(k, (k + 1) % 5, 5);
        }
        HalfedgeMesh pyramid = mesh(soup);
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(pyramid).refinement();
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, ifold.job.Collisions.OF_SEAM);
        List<Integer> layers = chosen.layersTried();
        List<Integer> collisions = chosen.collisionsTried();
        assertEquals(Seam.TRIED.length + 1, layers.size(), "the roll's start is tried too: " + layers);
        int rolled = Seam.TRIED.length;
        assertTrue(layers.get(rolled) < Collections.min(layers.subList(0, rolled)), "the roll has fewest layers: " + layers);
        assertEquals(0, collisions.get(rolled), "the roll's paper is sound: " + collisions);
        assertEquals(Seam.rollShare(refinement), chosen.along(), "the roll's start is kept: " + layers);
        assertTrue(chosen.placed().analysis().maxLayers() <= 22, layers.toString());
        WrapTest.check(dir, chosen.result(), pyramid, refinement.componentCount(), 2000);
        PaperCollisions.Result check = PaperCollisions.check(Files.readString(dir.resolve("wrap.obj")), chosen.result().thickness());
        assertTrue(check.isClean(), check.summary());
    }

    @Test
    void aLongPathIsWrappedOnceFromItsOwnStart() throws Exception {
        // 288 triangles, refined into 1,438: more than a seam is tried for.
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.torus(3, 1, 16, 9))).refinement();
        assertTrue(refinement.mesh().faceCount() > Seam.MOST_TRIANGLES);
        assertEquals(1, Seam.tries(refinement, Double.NaN));
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE);
        assertEquals(0.0, chosen.along());
        assertEquals(List.of(), chosen.layersTried());
        assertSame(refinement, chosen.refinement());
    }

    /**
     * A big model that a way of making its path fits at the default width follows the way likely
     * to make fewest faces run forwards, though one run back would make fewer still (the
     * 5,120-triangle icosphere: 418,387 likely against 418,982); where none fits (a face limit under them all), each way is
     * weighed run back too, and the fewest of all followed.
     */
    @Test
    void aBigModelsPathIsRunBackOnlyWhereNoWayFits() throws Exception {
        HalfedgeMesh sphere = mesh(Solids.icosphere(4));
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(sphere).refinement();
        long forwards = Long.MAX_VALUE;
        long back = Long.MAX_VALUE;
        for (HamiltonianRefinement.Result way : CycleCoverPath.ways(refinement.mesh().original())) {
            forwards = Math.min(forwards, Wrap.likelyFaces(way));
            back = Math.min(back, Wrap.likelyFaces(way.reversed()));
        }
        assertTrue(back < forwards, "setup: run back, " + back + " faces likely against " + forwards);
        assertEquals(forwards, Wrap.likelyFaces(Seam.ownInstead(refinement, DEFAULTS)));
        Wrap.Options tight = new Wrap.Options(Double.NaN, Double.NaN, null, (int) forwards - 1);
        assertEquals(back, Wrap.likelyFaces(Seam.ownInstead(refinement, tight)));
    }

    /**
     * A big closed model is wrapped once, along its own triangles, which make fewer faces: the
     * 1,280-triangle icosphere's 1,364 triangles (its refinement's 6,398 likely to make 287,000
     * faces) likely make about 105,000. Every truth holds on the paper, and the independent check
     * finds it sound; the refinement would be folded where that wrap failed.
     */
    @Test
    void aBigClosedModelIsWrappedOnceAlongItsOwnTriangles(@TempDir Path dir) throws Exception {
        HalfedgeMesh sphere = mesh(Solids.icosphere(3));
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(sphere).refinement();
        assertTrue(sphere.faceCount() > Seam.MOST_TRIANGLES);
        HamiltonianRefinement.Result own = Seam.ownInstead(refinement, DEFAULTS);
        assertTrue(own != null && own.mesh().ownTriangles(), "along its own triangles");
        assertTrue(Wrap.likelyFaces(own) * 2 < Wrap.likelyFaces(refinement), Wrap.likelyFaces(own) + " against " + Wrap.likelyFaces(refinement));
        Seam.Chosen chosen = Seam.wrap(refinement, DEFAULTS, Wrap.Watcher.NONE, Collisions.OF_SEAM);
        assertTrue(chosen.refinement().mesh().ownTriangles(), "the own triangles' wrap is kept");
        assertEquals(own.mesh().faceCount(), chosen.result().strips().get(0).triangles());
        assertEquals(List.of(), chosen.layersTried(), "wrapped once");
        assertEquals(List.of(), chosen.ownLayersTried());
        WrapTest.check(dir, chosen.result(), sphere, 1, 300);
        PaperCollisions.Result check = PaperCollisions.check(Files.readString(dir.resolve("wrap.obj")), chosen.result().thickness());
        assertTrue(check.isClean(), check.summary());
        // Past the face limit along its own triangles, that failure is the wrap's at once: the
        // refinement, likely to make more, is not folded after it.
        Wrap.Options tight = new Wrap.Options(chosen.result().width(), Double.NaN, null, 70_000);
        java.util.Set<Integer> folded = new java.util.TreeSet<>();
        Wrap.Watcher watcher = new Wrap.Watcher() {
            @Override
            public void wrapped(int done, int total) {
                folded.add(total);
            }

            @Override
            public boolean stopped() {
                return false;
            }
        };
        Wrap.FaceLimitException limit = org.junit.jupiter.api.Assertions.assertThrows(Wrap.FaceLimitException.class,
                () -> Seam.wrap(refinement, tight, watcher, Collisions.OF_SEAM));
        assertTrue(limit.getMessage().contains(" of " + own.mesh().faceCount() + " on the path"), limit.getMessage());
        assertEquals(java.util.Set.of(own.mesh().faceCount()), folded, "only the own triangles were folded");
        // A model at most MOST_TRIANGLES is left to the tries of both paths, and an open one has no own path.
        assertEquals(null, Seam.ownInstead(ifold.job.WrapPath.of(mesh(Solids.icosphere(2))).refinement(), DEFAULTS));
    }

    /**
     * A short path wrapped with a narrow strip is wrapped once too: the cube at width 1e-4 (about
     * 600,000 faces likely) took 248 s and 1.56 GiB from four starts, 53 s and 1.13 GiB from one
     * (a machine busy with other work). At 0.001 (61,000 likely, 48,689 made) four are tried.
     */
    @Test
    void aShortPathLikelyToMakeManyFacesIsWrappedOnce() throws Exception {
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh(Solids.cube())).refinement();
        assertEquals(Seam.TRIED.length, Seam.tries(refinement, Double.NaN));
        assertEquals(Seam.TRIED.length, Seam.tries(refinement, 0.001));
        assertTrue(Wrap.likelyFaces(refinement, 3e-4) > Seam.MOST_FACES, "likely " + Wrap.likelyFaces(refinement, 3e-4));
        assertEquals(1, Seam.tries(refinement, 3e-4));
        // The estimate follows the faces made, from above, at widths the test can afford.
        for (double width : new double[] {0.01, 0.003}) {
            Wrap.Result wrapped = Wrap.wrap(refinement, new Wrap.Options(width, Double.NaN));
            long made = wrapped.strips().get(0).sheet().faceCount();
            long likely = Wrap.likelyFaces(refinement, width);
            assertTrue(likely >= made && likely < 2 * made, width + ": likely " + likely + ", made " + made);
        }
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
