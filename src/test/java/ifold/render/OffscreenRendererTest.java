package ifold.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.Geometry;
import ifold.scene.Material;
import ifold.scene.PathView;
import ifold.scene.Scene;
import ifold.scene.SceneMesh;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/**
 * Offscreen rendering checked by pixels. Needs an X display: scripts/test runs the tests under
 * Xvfb; without one these tests are skipped.
 */
class OffscreenRendererTest {
    private static final int W = 160;
    private static final int H = 120;

    @BeforeAll
    static void needsDisplay() {
        String display = System.getenv("DISPLAY");
        assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
    }

    private static int pixel(byte[] rgb, int x, int y) {
        int i = 3 * (y * W + x);
        return (rgb[i] & 0xFF) << 16 | (rgb[i + 1] & 0xFF) << 8 | (rgb[i + 2] & 0xFF);
    }

    /** A red square facing the camera, filling the middle of the view. */
    private static Scene redSquare() {
        PolygonSoup square = new PolygonSoup();
        square.addVertex(-1, -1, 0);
        square.addVertex(1, -1, 0);
        square.addVertex(1, 1, 0);
        square.addVertex(-1, 1, 0);
        square.addFace(new int[] {0, 1, 2, 3}, 4, 0);
        square.setFaceColor(0, 0xFFFF0000);
        Scene scene = new Scene();
        scene.setBackground(0xFF000000 | 0x203040);
        scene.root().attach(new Geometry("square", SceneMesh.of(square), new Material(0xFFFFFFFF, 0xFF0000FF, true, false)));
        scene.frameAll();
        return scene;
    }

    @Test
    void backgroundWhereNothingIsAndTheModelsColourWhereItIs() throws Exception {
        Scene scene = redSquare();
        try (OffscreenRenderer renderer = new OffscreenRenderer(W, H, 4)) {
            byte[] rgb = renderer.render(scene);
            assertEquals(3 * W * H, rgb.length);
            assertEquals(0x203040, pixel(rgb, 2, 2), "corner shows the background");
            int centre = pixel(rgb, W / 2, H / 2);
            int red = centre >> 16 & 0xFF;
            int green = centre >> 8 & 0xFF;
            int blue = centre & 0xFF;
            assertTrue(red > 150 && green < 30 && blue < 30, "centre is lit red: " + Integer.toHexString(centre));
        }
    }

    /** Paper crossing paper lies between layers: drawn seen through, it shows over the square in front of it; else not. */
    @Test
    void whatIsSeenThroughShowsOverWhatLiesInFront() throws Exception {
        Scene scene = redSquare();
        // A small green square behind the red one (the camera looks down -z at z = 0).
        PolygonSoup behind = new PolygonSoup();
        behind.addVertex(-0.3, -0.3, -0.5);
        behind.addVertex(0.3, -0.3, -0.5);
        behind.addVertex(0.3, 0.3, -0.5);
        behind.addVertex(-0.3, 0.3, -0.5);
        behind.addFace(new int[] {0, 1, 2, 3}, 4, 0);
        behind.setFaceColor(0, 0xFF00FF00);
        Geometry hidden = new Geometry("behind", SceneMesh.of(behind), new Material(0xFFFFFFFF, 0xFFFFFFFF, true, false));
        scene.root().attach(hidden);
        try (OffscreenRenderer renderer = new OffscreenRenderer(W, H, 4)) {
            int covered = pixel(renderer.render(scene), W / 2, H / 2);
            assertTrue((covered >> 16 & 0xFF) > 150 && (covered >> 8 & 0xFF) < 30, "setup: the red square hides it: " + Integer.toHexString(covered));
            hidden.setSeenThrough(true);
            int shown = pixel(renderer.render(scene), W / 2, H / 2);
            assertTrue((shown >> 8 & 0xFF) > 150 && (shown >> 16 & 0xFF) < 30, "seen through the red: " + Integer.toHexString(shown));
        }
    }

    @Test
    void theBackOfThePaperHasItsOwnColour() throws Exception {
        Scene scene = redSquare();
        scene.camera().setOrientation(new org.joml.Quaterniond().rotationY(Math.PI)); // look from behind
        try (OffscreenRenderer renderer = new OffscreenRenderer(W, H, 4)) {
            int centre = pixel(renderer.render(scene), W / 2, H / 2);
            assertTrue((centre & 0xFF) > 150 && (centre >> 16 & 0xFF) < 30, "the back is blue: " + Integer.toHexString(centre));
        }
    }

    @Test
    void pathAnimationChangesTheExpectedPixels() throws Exception {
        var mesh = MeshBuilder.build(Solids.figure3(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        Geometry path = new Geometry("path", PathView.mesh(HamiltonianRefinement.refine(mesh)), Material.FACE_COLORS);
        Scene scene = new Scene();
        scene.root().attach(path);
        scene.frameAll();
        try (OffscreenRenderer renderer = new OffscreenRenderer(W, H, 4)) {
            path.setRevealed(0);
            byte[] none = renderer.render(scene);
            path.setRevealed(10);
            byte[] some = renderer.render(scene);
            path.setRevealed(Geometry.ALL);
            byte[] all = renderer.render(scene);
            int changedEarly = 0;
            int changedLate = 0;
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    changedEarly += pixel(none, x, y) != pixel(some, x, y) ? 1 : 0;
                    changedLate += pixel(some, x, y) != pixel(all, x, y) ? 1 : 0;
                }
            }
            assertTrue(changedEarly > 50, "revealing 10 triangles colours some pixels: " + changedEarly);
            assertTrue(changedLate > changedEarly, "the other 48 triangles colour more: " + changedLate);
            assertNotEquals(0, renderer.describe().length());
        }
    }
}
