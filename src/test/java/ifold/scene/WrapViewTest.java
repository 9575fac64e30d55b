package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Wrap;
import ifold.wrap.WrapGeometry;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The wrap's animation, headless: it lays the strip in order, follows it, and ends on the whole wrap. */
class WrapViewTest {
    @Test
    void theAnimationLaysTheStripInOrderAndEndsWithAllOfIt() throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(Solids.tetrahedron(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        Wrap.Result result = Wrap.wrap(HamiltonianRefinement.refine(mesh), new Wrap.Options(Double.NaN, Double.NaN));
        List<WrapGeometry> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(WrapGeometry.of(strip.sheet(), result.frames()));
        }
        WrapView.Strips strips = WrapView.strips(result, geometries);
        int paperFaces = geometries.get(0).paperFaces().size();
        assertTrue(strips.mesh().triangleCount() >= paperFaces, "every face drawn (fans of convex faces), and the caps");
        Scene scene = new Scene();
        scene.root().attach(new Geometry("model", SceneMesh.of(mesh), Material.PAPER));
        Geometry done = new Geometry("paper", strips.mesh(), WrapView.PAPER);
        done.setHiddenColor(0);
        Geometry current = new Geometry("folding", strips.mesh(), WrapView.PAPER);
        scene.root().attach(done);
        scene.root().attach(current);
        scene.frameAll();
        Animation animation = WrapView.animation(scene, done, current, strips, result);
        int last = -1;
        int shownWhileFolding = 0;
        org.joml.Vector3d firstTarget = null;
        boolean cameraMoved = false;
        for (int k = 0; k < 200; k++) {
            double position = k * 0.8 * animation.stepCount() / 200;
            animation.apply(position);
            assertTrue(done.revealed() >= last, "what is done stays done: " + done.revealed() + " after " + last);
            last = done.revealed();
            shownWhileFolding += current.mesh().triangleCount() > 0 ? 1 : 0;
            String line = animation.describe(position);
            assertTrue(line.matches("triangle \\d+ of 18: .*"), line);
            if (firstTarget == null) {
                firstTarget = new org.joml.Vector3d(scene.camera().target());
            } else {
                cameraMoved |= firstTarget.distance(scene.camera().target()) > 1e-3;
            }
        }
        assertEquals(200, shownWhileFolding, "the triangle being wrapped is always drawn");
        assertTrue(cameraMoved, "the camera follows the strip round the model");
        animation.apply(animation.stepCount());
        assertEquals(Geometry.ALL, done.revealed(), "at the end the whole wrap shows");
        assertEquals(0, current.mesh().triangleCount());
        assertTrue(animation.describe(animation.stepCount()).startsWith("wrapped: 1 strip over 18 triangles"));
    }
}
