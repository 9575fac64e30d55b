package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import ifold.wrap.Wrap;
import ifold.wrap.PaperInSpace;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The wrap's animation, headless: it lays the strip in order, follows it, and ends on the whole wrap. */
class WrapViewTest {
    /**
     * A solid hides the paper under its strip; an open surface does not, and a strip on no
     * surface neither (the zig-zag demo's underside showed none of its tucks while every face
     * under other paper was left out).
     */
    @Test
    void onlyASolidHidesWhatLiesUnderItsPaper() {
        assertFalse(WrapView.seenFromBothSides(Solids.cube()));
        assertFalse(WrapView.seenFromBothSides(Solids.torus(3, 1, 9, 5)));
        ifold.mesh.PolygonSoup triangle = new ifold.mesh.PolygonSoup();
        triangle.addTriangle(triangle.addVertex(0, 0, 0), triangle.addVertex(1, 0, 0), triangle.addVertex(0, 1, 0));
        assertTrue(WrapView.seenFromBothSides(triangle), "a lone triangle");
        assertTrue(WrapView.seenFromBothSides(new ifold.mesh.PolygonSoup()), "an empty table");
    }

    @Test
    void theAnimationLaysTheStripInOrderAndEndsWithAllOfIt() throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(Solids.tetrahedron(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        Wrap.Result result = Wrap.wrap(HamiltonianRefinement.refine(mesh), new Wrap.Options(Double.NaN, Double.NaN));
        List<PaperInSpace> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
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

    private static Wrap.Result wrap(HalfedgeMesh mesh) throws Exception {
        return Wrap.wrap(HamiltonianRefinement.refine(mesh), new Wrap.Options(Double.NaN, Double.NaN));
    }

    private static HalfedgeMesh cube() throws Exception {
        return MeshBuilder.build(ifold.mesh.io.MeshReaders.read(java.nio.file.Path.of("models/cube.off")),
                MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    private static WrapPlayback playback(Scene scene, HalfedgeMesh mesh, Wrap.Result result) {
        List<PaperInSpace> geometries = new ArrayList<>();
        for (Wrap.Strip strip : result.strips()) {
            geometries.add(PaperInSpace.of(strip.sheet(), result.frames()));
        }
        scene.root().attach(new Geometry("model", SceneMesh.of(mesh), Material.PAPER));
        return WrapView.play(scene, result, geometries);
    }

    /** The captions shown at {@code fps} over {@code seconds}, as runs: each caption with how long it stays. */
    private static List<Map.Entry<String, Double>> captionRuns(Animation animation, double seconds, int fps) {
        List<Map.Entry<String, Double>> runs = new ArrayList<>();
        int frames = (int) Math.round(seconds * fps);
        for (int k = 0; k <= frames; k++) {
            String caption = animation.describe(animation.stepCount() * (double) k / frames);
            if (!runs.isEmpty() && runs.get(runs.size() - 1).getKey().equals(caption)) {
                runs.get(runs.size() - 1).setValue(runs.get(runs.size() - 1).getValue() + 1.0 / fps);
            } else {
                runs.add(new java.util.AbstractMap.SimpleEntry<>(caption, 1.0 / fps));
            }
        }
        return runs;
    }

    @Test
    void everyCaptionOfTheCubesWrapStaysLongEnoughToRead() throws Exception {
        HalfedgeMesh mesh = cube();
        Wrap.Result result = wrap(mesh);
        int path = result.strips().get(0).triangles();
        assertTrue(result.steps().size() > 800 && path > 50, "check the setup: eight hundred folds over some fifty triangles");
        WrapPlayback animation = playback(new Scene(), mesh, result);
        for (double seconds : new double[] {120, 30}) {
            animation.pace(seconds);
            List<Map.Entry<String, Double>> runs = captionRuns(animation, seconds, 30);
            // The last run is cut by the end of the movie, the first begins with it: each still whole.
            for (Map.Entry<String, Double> run : runs) {
                assertTrue(run.getValue() >= WrapView.CAPTION_SECONDS - 1.0 / 30, seconds + " s: '" + run.getKey() + "' for "
                        + run.getValue() + " s");
            }
            if (seconds == 120) {
                // The first triangle fold by fold, then each later one, or run of them, a step that says so.
                assertTrue(runs.get(0).getKey().startsWith("triangle 1 of " + path + ": "), runs.get(0).getKey());
                long firstTriangle = runs.stream().filter(r -> r.getKey().startsWith("triangle 1 of ")).count();
                assertTrue(firstTriangle > 10, "the first triangle's folds each shown: " + firstTriangle);
                assertTrue(runs.stream().anyMatch(r -> r.getKey().matches("triangles \\d+\u2013\\d+ of " + path
                        + ": each wrapped as triangle 1")), runs.toString());
                String lastRun = runs.stream().map(Map.Entry::getKey).filter(k -> k.contains("wrapped as triangle 1")).reduce((a, b) -> b).get();
                assertTrue(lastRun.contains("\u2013" + path + " of " + path) || lastRun.startsWith("triangle " + path + " of "),
                        "the runs go on to the last triangle: " + lastRun);
            }
        }
        // The folds keep their order whatever the pacing, and the folding ends where the final turn begins.
        for (int j = 0; j < result.steps().size(); j++) {
            assertTrue(animation.positionAfter(j + 1) > animation.positionAfter(j), "fold " + j);
        }
    }

    @Test
    void theCameraComesCloseToTheTriangleBeingWrappedAndBackToTheWholeModelBetween() throws Exception {
        HalfedgeMesh mesh = cube();
        Wrap.Result result = wrap(mesh);
        Scene scene = new Scene();
        WrapPlayback animation = playback(scene, mesh, result);
        int n = result.steps().size();
        Wrap.Strip strip = result.strips().get(0);
        int j = 0;
        int checked = 0;
        while (j < n) {
            int pathIndex = result.steps().get(j).pathIndex();
            int end = j;
            while (end < n && result.steps().get(end).pathIndex() == pathIndex) {
                end++;
            }
            double start = animation.positionAfter(j);
            double stop = animation.positionAfter(end);
            int face = strip.firstTriangle() + pathIndex;
            animation.apply((start + stop) / 2);
            double[] extent = extent(scene.camera(), result.mesh(), face);
            assertTrue(extent[1] - extent[0] >= 2.0 / 3, "triangle " + (pathIndex + 1) + " fills a third of the height: "
                    + (extent[1] - extent[0]) / 2);
            assertTrue(extent[0] > -1 && extent[1] < 1 && extent[2] > -1 && extent[3] < 1, "and is all in the frame");
            animation.apply(start);
            double[] whole = new double[] {1, -1, 1, -1};
            for (int f = 0; f < mesh.faceCount(); f++) {
                double[] e = extent(scene.camera(), mesh, f);
                whole[0] = Math.min(whole[0], e[0]);
                whole[1] = Math.max(whole[1], e[1]);
                whole[2] = Math.min(whole[2], e[2]);
                whole[3] = Math.max(whole[3], e[3]);
            }
            assertTrue(whole[0] > -1 && whole[1] < 1 && whole[2] > -1 && whole[3] < 1, "between triangles, the whole model in view at "
                    + (pathIndex + 1) + ": " + java.util.Arrays.toString(whole));
            checked++;
            j = end;
        }
        assertEquals(strip.triangles(), checked, "check the setup: every triangle of the path");
    }

    /** A face's extent in a 16:9 frame's normalised coordinates: bottom, top, left, right (-1 to 1 is in view). */
    private static double[] extent(Camera camera, ifold.mesh.IndexedPolygons mesh, int face) {
        org.joml.Matrix4d m = camera.projectionMatrix(16 / 9.0, new org.joml.Matrix4d()).mul(camera.viewMatrix(new org.joml.Matrix4d()));
        double[] e = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int c = 0; c < mesh.faceSize(face); c++) {
            int v = mesh.faceVertex(face, c);
            org.joml.Vector4d p = m.transform(new org.joml.Vector4d(mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2), 1));
            assertTrue(p.w > 0, "in front of the camera");
            e[0] = Math.min(e[0], p.y / p.w);
            e[1] = Math.max(e[1], p.y / p.w);
            e[2] = Math.min(e[2], p.x / p.w);
            e[3] = Math.max(e[3], p.x / p.w);
        }
        return e;
    }
}
