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

    /**
     * A wrap drawn with less (only what is exposed, seams under a pixel left out, patches for
     * faces under a pixel) looks as it does drawn whole: near, mid-way through the folds and
     * from far away.
     */
    @Test
    void aWrapDrawnWithLessLooksAsItDoesDrawnWhole() throws Exception {
        var mesh = MeshBuilder.build(ifold.mesh.io.MeshReaders.read(java.nio.file.Path.of("models/cube.off")),
                MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        ifold.wrap.Wrap.Result result = ifold.wrap.Wrap.wrap(HamiltonianRefinement.refine(mesh),
                new ifold.wrap.Wrap.Options(Double.NaN, Double.NaN));
        java.util.List<ifold.wrap.PaperInSpace> geometries = new java.util.ArrayList<>();
        for (ifold.wrap.Wrap.Strip strip : result.strips()) {
            geometries.add(ifold.wrap.PaperInSpace.of(strip.sheet(), result.frames()));
        }
        Scene scene = new Scene();
        scene.root().attach(new Geometry("model", SceneMesh.of(mesh), Material.PAPER));
        ifold.scene.Animation animation = ifold.scene.WrapView.play(scene, result, geometries);
        Geometry[] paper = new Geometry[1];
        scene.root().visitGeometry(g -> paper[0] = g.name().equals("paper") ? g : paper[0]);
        SceneMesh layered = paper[0].mesh();
        assertTrue(layered.layers() != null && java.util.Arrays.stream(layered.layers().hiddenFrom()).filter(n -> n < Integer.MAX_VALUE).count() > 100,
                "setup: some of the cube's paper lies under other paper");
        SceneMesh whole = new SceneMesh(layered.positions(), layered.triangles(), layered.triangleColors(), layered.edges(),
                layered.edgeColors());
        int w = 320;
        int h = 240;
        try (OffscreenRenderer renderer = new OffscreenRenderer(w, h, 0)) {
            for (double at : new double[] {0.3, 0.6, 1.0}) {
                animation.apply(at * animation.stepCount());
                paper[0].setMesh(layered);
                byte[] less = renderer.render(scene);
                paper[0].setMesh(whole);
                byte[] all = renderer.render(scene);
                int differ = 0;
                for (int i = 0; i < w * h; i++) {
                    int most = 0;
                    for (int k = 0; k < 3; k++) {
                        most = Math.max(most, Math.abs((less[3 * i + k] & 0xFF) - (all[3 * i + k] & 0xFF)));
                    }
                    differ += most > 24 ? 1 : 0;
                }
                assertTrue(differ < w * h / 200, "at " + at + " of the animation, " + differ + " of " + w * h + " pixels differ");
            }
            // From far away the faces are under a pixel: patches in the paper's average colour.
            scene.camera().setDistance(scene.camera().distance() * 30);
            paper[0].setMesh(layered);
            double[] far = meanOfModel(renderer.render(scene), scene.background());
            paper[0].setMesh(whole);
            double[] farWhole = meanOfModel(renderer.render(scene), scene.background());
            assertTrue(far[3] > 20 && Math.abs(far[3] - farWhole[3]) <= 0.2 * farWhole[3], "the same pixels covered: " + far[3] + " and " + farWhole[3]);
            for (int k = 0; k < 3; k++) {
                assertEquals(farWhole[k], far[k], 24, "channel " + k + " of the mean colour, far away");
            }
        }
    }

    /** The mean red, green and blue of the pixels that are not the background, and how many they are. */
    private static double[] meanOfModel(byte[] rgb, int background) {
        double[] sum = new double[4];
        for (int i = 0; i < rgb.length / 3; i++) {
            int color = (rgb[3 * i] & 0xFF) << 16 | (rgb[3 * i + 1] & 0xFF) << 8 | (rgb[3 * i + 2] & 0xFF);
            if (color == (background & 0xFFFFFF)) {
                continue;
            }
            for (int k = 0; k < 3; k++) {
                sum[k] += rgb[3 * i + k] & 0xFF;
            }
            sum[3]++;
        }
        for (int k = 0; k < 3; k++) {
            sum[k] /= Math.max(1, sum[3]);
        }
        return sum;
    }

    /**
     * A mesh of many chunks, some out of view: the triangle seen at a pixel is still the one
     * there (its index read back), and the revealed ones are those before the count.
     */
    @Test
    void chunksOutOfViewLeaveEachTriangleItsIndexAndItsTurn() throws Exception {
        int n = 64; // 64 x 64 squares, 8,192 triangles, row by row
        PolygonSoup grid = new PolygonSoup();
        for (int y = 0; y <= n; y++) {
            for (int x = 0; x <= n; x++) {
                grid.addVertex(x, y, 0);
            }
        }
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++) {
                int a = y * (n + 1) + x;
                grid.addFace(new int[] {a, a + 1, a + n + 2, a + n + 1}, 4, 0);
                grid.setFaceColor(y * n + x, 0xFFFF0000);
            }
        }
        SceneMesh mesh = SceneMesh.of(grid);
        assertEquals(2 * n * n, mesh.triangleCount());
        Geometry geometry = new Geometry("grid", mesh, new Material(0xFFFFFFFF, 0xFF0000FF, true, false));
        Scene scene = new Scene();
        scene.setBackground(0xFF000000);
        scene.root().attach(geometry);
        scene.frameAll();
        int w = 160;
        int h = 120;
        try (OffscreenRenderer renderer = new OffscreenRenderer(w, h, 0)) {
            for (double zoom : new double[] {1, 0.15}) {
                // Close to square (40, 50): most chunks out of view.
                scene.camera().setTarget(new org.joml.Vector3d(zoom == 1 ? n / 2.0 : 40.5, zoom == 1 ? n / 2.0 : 50.5, 0));
                scene.camera().setDistance(zoom * 1.1 * n);
                int[] ids = renderer.renderIndices(scene);
                int checked = 0;
                for (int py = 0; py < h; py += 7) {
                    for (int px = 0; px < w; px += 7) {
                        int id = ids[py * w + px] - 1;
                        if (id < 0) {
                            continue;
                        }
                        // Where is the square of that triangle on screen? Its centre, projected, lies near the pixel.
                        int square = id / 2;
                        org.joml.Vector4d centre = new org.joml.Vector4d(square % n + 0.5, square / n + 0.5, 0, 1);
                        org.joml.Matrix4d clip = scene.camera().projectionMatrix((double) w / h, new org.joml.Matrix4d())
                                .mul(scene.camera().viewMatrix(new org.joml.Matrix4d()));
                        clip.transform(centre);
                        double sx = (centre.x / centre.w + 1) / 2 * w;
                        double sy = (1 - centre.y / centre.w) / 2 * h;
                        double square_px = zoom == 1 ? (double) h / (1.1 * n) * 1.0 : (double) h / (0.15 * 1.1 * n);
                        assertTrue(Math.abs(sx - px) < 2 * square_px + 2 && Math.abs(sy - py) < 2 * square_px + 2,
                                "pixel (" + px + ", " + py + ") reads triangle " + id + ", whose square is at (" + sx + ", " + sy + ")");
                        checked++;
                    }
                }
                assertTrue(checked > 100, "setup: the grid fills the view: " + checked);
            }
            // Revealed: the first 4,096 triangles, rows 0 to 31, in their colour; the rest hidden grey.
            scene.frameAll();
            geometry.setHiddenColor(0xFF808080);
            geometry.setRevealed(n * n);
            byte[] rgb = renderer.render(scene);
            int low = pixel(rgb, w / 2, h / 2 + h / 5); // row y < 32: the lower half of the grid, at the bottom of the picture
            int high = pixel(rgb, w / 2, h / 2 - h / 5);
            assertTrue((low >> 16 & 0xFF) > 150 && (low >> 8 & 0xFF) < 60, "revealed: red, " + Integer.toHexString(low));
            assertEquals(0x808080, high, "not yet revealed: the hidden grey");
        }
    }
}
