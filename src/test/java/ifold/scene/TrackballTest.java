package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class TrackballTest {

    /** Where the world point lands in the camera's frame. */
    private static Vector3d inCamera(Camera camera, Vector3d world) {
        return camera.viewMatrix(new Matrix4d()).transformPosition(new Vector3d(world));
    }

    @Test
    void horizontalDragTurnsAboutTheScreensVerticalAxis() {
        Camera camera = new Camera();
        camera.frame(new Vector3d(), 1);
        Trackball trackball = new Trackball(camera);
        Vector3d front = new Vector3d(0, 0, 1); // the point facing the viewer
        Vector3d before = inCamera(camera, front);
        trackball.begin(400, 300, 800, 600);
        trackball.rotateTo(500, 300, 800, 600);
        Vector3d after = inCamera(camera, front);
        assertTrue(after.x > before.x + 0.1, "dragging right moves the front to the right: " + after);
        assertEquals(before.y, after.y, 1e-12, "no vertical motion");
        Vector3d target = new Vector3d(0, 0, -camera.distance());
        assertEquals(before.distance(target), after.distance(target), 1e-12, "a turn about the target keeps distances to it");
    }

    @Test
    void dragBackToTheStartUndoesTheTurn() {
        Camera camera = new Camera();
        Trackball trackball = new Trackball(camera);
        trackball.begin(100, 100, 640, 480);
        trackball.rotateTo(600, 20, 640, 480);
        trackball.rotateTo(100, 100, 640, 480);
        assertEquals(0, camera.orientation().angle(), 1e-9);
    }

    @Test
    void zoomPanAndReset() {
        Camera camera = new Camera();
        camera.frame(new Vector3d(1, 2, 3), 2);
        Trackball trackball = new Trackball(camera);
        double distance = camera.distance();
        trackball.zoom(2);
        assertEquals(distance / 1.21, camera.distance(), 1e-9);
        trackball.begin(0, 0, 100, 100);
        trackball.panTo(50, 0, 100, 100);
        assertTrue(camera.target().x() < 1, "dragging right moves the scene right, so the target left");
        assertEquals(2, camera.target().y(), 1e-12);
        trackball.reset();
        assertEquals(distance, camera.distance(), 1e-12);
        assertEquals(1, camera.target().x(), 1e-12);
    }

    @Test
    void pointsOutsideTheBallStayOnTheSheet() {
        Vector3d p = Trackball.toSphere(10_000, 300, 800, 600, new Vector3d());
        assertEquals(1, p.length(), 1e-12);
        assertTrue(p.z > 0 && p.z < 0.01, "far outside: almost in the screen plane");
    }
}
