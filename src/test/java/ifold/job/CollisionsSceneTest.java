package ifold.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.check.PaperCollisions;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.CollisionView;
import ifold.scene.Geometry;
import ifold.scene.Scene;
import ifold.wrap.Wrap;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The viewer's crossing paper: the checker's faces, found in the paper by the OBJ's numbers, hidden until C. */
class CollisionsSceneTest {
    private final HalfedgeMesh cube;

    CollisionsSceneTest() throws Exception {
        cube = MeshBuilder.build(Solids.cube(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    /** The cube wrapped at the default width, with {@code thickness} (NaN for the default). */
    private Wrap.Result wrapCube(double thickness) throws Exception {
        return Wrap.wrap(HamiltonianRefinement.refine(cube), new Wrap.Options(Double.NaN, thickness));
    }

    private static List<PaperInSpace> strips(Wrap.Result result) {
        List<PaperInSpace> strips = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            strips.add(PaperInSpace.of(strip.sheet(), result.frames()));
        }
        return strips;
    }

    /** Two unit squares through each other, as an X: paper crossing itself, made by hand. */
    private static List<PaperInSpace> anX() {
        double[] xyz = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0, -0.5, 0.5, 1, -0.5, 0.5, 1, 0.5, 0.5, 0, 0.5};
        return List.of(new PaperInSpace(xyz, new double[16], List.of(new int[] {0, 1, 2, 3}, new int[] {4, 5, 6, 7}),
                new int[] {0, 1}, List.of(), new int[0]));
    }

    @Test
    void crossingFacesAreShownInRedWhenAskedFor() throws Exception {
        List<PaperInSpace> strips = anX();
        double thickness = 0.01;
        PaperCollisions.Result check = Collisions.check(strips, thickness, null, null);
        assertTrue(check.crossingPairs() > 0, "setup: the X crosses itself");
        Scene scene = new Scene();
        Geometry shown = Scenes.collisions(scene, strips, thickness, null);
        assertNotNull(shown);
        assertFalse(shown.isVisible(), "hidden until asked for");
        assertTrue(shown.isSeenThrough(), "drawn over the layers above it");
        // Every triangle of the geometry is a corner-for-corner copy of a face of the OBJ the checker read.
        PaperCollisions.Crossing deepest = check.deepest();
        double[] face = WrapExport.faceCorners(strips, deepest.faceA());
        double[] positions = shown.mesh().positions();
        boolean found = false;
        for (int v = 0; v + face.length <= positions.length && !found; v += 3) {
            boolean same = true;
            for (int k = 0; k < face.length && same; k++) {
                same = positions[v + k] == face[k];
            }
            found = same;
        }
        assertTrue(found, "the deepest crossing's face " + deepest.faceA() + " is among those shown");
        assertTrue(shown.mesh().triangleCount() >= 2, "both faces of a crossing at least");
        assertTrue(CollisionView.toggle(scene.root()));
        assertTrue(shown.isVisible(), "C shows it");
        CollisionView.toggle(scene.root());
        assertFalse(shown.isVisible(), "and C again hides it");
        assertFalse(CollisionView.toggle(new Scene().root()), "a scene without collisions has nothing to show");
    }

    @Test
    void theCubesWrapHasNothingToShow() throws Exception {
        Wrap.Result result = wrapCube(Double.NaN);
        List<PaperInSpace> strips = strips(result);
        assertTrue(Collisions.check(strips, result.thickness(), cube, null).isClean(), "the cube's paper crosses nothing");
        Geometry shown = Scenes.collisions(new Scene(), strips, result.thickness(), cube);
        assertEquals(0, shown.mesh().triangleCount(), "no face to show");
    }

    @Test
    void paperOfNoThicknessIsNotChecked() throws Exception {
        Wrap.Result result = wrapCube(0);
        assertEquals(0, result.thickness());
        assertNull(Scenes.collisions(new Scene(), strips(result), 0, cube));
    }

    @Test
    void aNumberNoFaceHasIsRefused() throws Exception {
        List<PaperInSpace> strips = strips(wrapCube(Double.NaN));
        int faces = strips.get(0).paperFaces().size() + strips.get(0).caps().size();
        WrapExport.faceCorners(strips, faces);
        assertThrows(IllegalArgumentException.class, () -> WrapExport.faceCorners(strips, faces + 1));
        assertThrows(IllegalArgumentException.class, () -> WrapExport.faceCorners(strips, 0));
    }
}
