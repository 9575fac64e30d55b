package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.Solids;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.joml.Vector4d;
import org.junit.jupiter.api.Test;

class SceneGraphTest {

    private static Geometry cube(String name) {
        return new Geometry(name, SceneMesh.of(Solids.cube()), Material.PAPER);
    }

    @Test
    void worldTransformsComposeAndFollowTheParent() {
        Node arm = new Node("arm");
        Geometry hand = cube("hand");
        arm.attach(hand);
        arm.setLocalTransform(new Matrix4d().translation(1, 0, 0));
        hand.setLocalTransform(new Matrix4d().rotationZ(Math.PI / 2));
        Vector3d p = hand.worldTransform().transformPosition(new Vector3d(1, 0, 0));
        assertEquals(1, p.x, 1e-12);
        assertEquals(1, p.y, 1e-12);
        // Moving the parent after the child's world was computed must move the child.
        arm.setLocalTransform(new Matrix4d().translation(5, 0, 0));
        p = hand.worldTransform().transformPosition(new Vector3d(1, 0, 0));
        assertEquals(5, p.x, 1e-12);
        assertEquals(1, p.y, 1e-12);
    }

    @Test
    void changesMarkTheSceneAndBoundsFollowTransforms() {
        Scene scene = new Scene();
        Geometry geometry = cube("cube");
        scene.root().attach(geometry);
        scene.clearChanged();
        assertFalse(scene.isChanged());
        geometry.setRevealed(3);
        assertTrue(scene.isChanged(), "a change deep down reaches the root");
        scene.clearChanged();
        geometry.setRevealed(3);
        assertFalse(scene.isChanged(), "setting the same value changes nothing");
        geometry.setLocalTransform(new Matrix4d().translation(10, 0, 0).scale(2));
        Bounds bounds = scene.bounds();
        assertEquals(10, bounds.min().x, 1e-12);
        assertEquals(12, bounds.max().x, 1e-12);
        geometry.setVisible(false);
        assertTrue(scene.bounds().isEmpty());
    }

    @Test
    void versionMovesOnlyWhenTheMeshChanges() {
        Geometry geometry = cube("cube");
        int before = geometry.version();
        geometry.setRevealed(1);
        geometry.setMaterial(Material.FACE_COLORS);
        assertEquals(before, geometry.version());
        geometry.setMesh(SceneMesh.of(Solids.tetrahedron()));
        assertEquals(before + 1, geometry.version());
    }

    @Test
    void sceneBoundToARenderThreadRefusesOtherThreads() throws InterruptedException {
        Scene scene = new Scene();
        Geometry geometry = cube("cube");
        scene.root().attach(geometry);
        scene.bindToThread(Thread.currentThread());
        geometry.setRevealed(2); // fine on the render thread
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread other = new Thread(() -> {
            try {
                geometry.setRevealed(5);
            } catch (Throwable t) {
                failure.set(t);
            }
        });
        other.start();
        other.join();
        assertTrue(failure.get() instanceof IllegalStateException, String.valueOf(failure.get()));
        assertEquals(2, geometry.revealed());
    }

    @Test
    void cyclesAreRefused() {
        Node a = new Node("a");
        Node b = new Node("b");
        a.attach(b);
        assertThrows(IllegalArgumentException.class, () -> b.attach(a));
        assertThrows(IllegalArgumentException.class, () -> a.attach(a));
    }

    @Test
    void polygonMeshIsTriangulatedButOutlinedByItsEdges() {
        SceneMesh cube = SceneMesh.of(Solids.cube());
        assertEquals(12, cube.triangleCount());
        assertEquals(12, cube.edgeCount(), "the cube's 12 edges, no diagonals");
    }

    @Test
    void frameAllPutsEverythingInView() {
        Scene scene = new Scene();
        Geometry geometry = cube("cube");
        geometry.setLocalTransform(new Matrix4d().translation(3, -2, 7).scale(4));
        scene.root().attach(geometry);
        scene.camera().setOrientation(new org.joml.Quaterniond().rotateX(0.4).rotateY(0.7));
        scene.frameAll();
        Matrix4d viewProjection = scene.camera().projectionMatrix(16.0 / 9, new Matrix4d())
                .mul(scene.camera().viewMatrix(new Matrix4d()));
        List<Vector4d> corners = new ArrayList<>();
        Bounds bounds = scene.bounds();
        for (int i = 0; i < 8; i++) {
            Vector3d min = bounds.min();
            Vector3d max = bounds.max();
            corners.add(new Vector4d((i & 1) == 0 ? min.x : max.x, (i & 2) == 0 ? min.y : max.y, (i & 4) == 0 ? min.z : max.z, 1));
        }
        for (Vector4d corner : corners) {
            viewProjection.transform(corner);
            for (double ndc : new double[] {corner.x / corner.w, corner.y / corner.w, corner.z / corner.w}) {
                assertTrue(ndc > -1 && ndc < 1, "corner inside the view volume: " + corner);
            }
        }
        Vector4d centre = new Vector4d(bounds.center(new Vector3d()), 1);
        viewProjection.transform(centre);
        assertEquals(0, centre.x / centre.w, 1e-9);
        assertEquals(0, centre.y / centre.w, 1e-9);
    }
}
