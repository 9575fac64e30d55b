package ifold.job;

import ifold.check.PaperCollisions;
import ifold.geom.Triangle;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.IndexedPolygons;
import ifold.mesh.Topology;
import ifold.refine.HamiltonianRefinement;
import ifold.scene.Animation;
import ifold.scene.CollisionView;
import ifold.scene.Geometry;
import ifold.scene.Material;
import ifold.scene.PaperView;
import ifold.scene.PathView;
import ifold.scene.Scene;
import ifold.scene.SceneMesh;
import ifold.scene.Turntable;
import ifold.scene.WrapPlayback;
import ifold.scene.WrapView;
import ifold.script.ScriptFolding;
import ifold.wrap.Wrap;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.Locale;
import org.joml.Quaterniond;

/**
 * The scenes that show each kind of result, and their animations: the command line's viewer and
 * frames, and the window's view and exports, show the same. Each call fills a new scene, so
 * that a view and an export running at once never share one.
 */
public final class Scenes {
    private Scenes() {
    }

    /** The name of the geometry that shows the model (or the lone triangle) under the paper. */
    public static final String MODEL = "model";

    /** The name of the geometry that shows a model's refinement, coloured along its Hamiltonian path; hidden at first. */
    public static final String REFINEMENT = "refinement";

    /** The name of the geometry {@code ifold view} shows: the model or its refinement. */
    public static final String VIEWED = "viewed";

    /** Above this many triangles, {@code ifold view} draws no edges and does not antialias. */
    public static final int DENSE = 25_000;

    /** What {@code ifold view} shows: the model, its Hamiltonian refinement, or the path revealed on it. */
    public enum Show { MODEL, REFINEMENT, PATH }

    /**
     * A model's view, as {@code ifold view} shows it.
     *
     * @param geometry the model or its refinement, named {@link #VIEWED}
     * @param animation the path revealed triangle by triangle, or a turn around the model
     * @param caption the model's name and its counts: "torus.off: 48 -> 238 triangles"
     * @param samples the antialiasing samples for its frames: none on a dense mesh
     */
    public record View(Geometry geometry, Animation animation, String caption, int samples) {
    }

    /**
     * Fills {@code scene} with what {@code ifold view} shows of {@code mesh}: the model (its own
     * face colours, if it has them), or its refinement as paper, or the refinement coloured
     * along the path in {@code colors}, revealed triangle by triangle; a still view turns round.
     *
     * @param name the model's file name, for the caption
     * @param refinement the mesh's refinement; needed unless {@code show} is {@link Show#MODEL}
     */
    public static View view(Scene scene, String name, HalfedgeMesh mesh, HamiltonianRefinement.Result refinement, Show show,
            PathView.Colors colors) {
        Geometry geometry;
        String caption;
        if (show == Show.MODEL) {
            SceneMesh sceneMesh = SceneMesh.of(mesh);
            geometry = new Geometry(VIEWED, sceneMesh, mesh.hasFaceColors() ? Material.FACE_COLORS : Material.PAPER);
            caption = String.format(Locale.ROOT, "%s: %d faces, %d triangles", name, mesh.faceCount(), sceneMesh.triangleCount());
            // On a dense mesh the outlines would paint it black, and antialiasing cannot be seen on
            // triangles of a pixel or two, while both cost a software renderer dearly. A dense
            // refinement keeps its original edges, tree edges and path (without the Steiner
            // edges): they are what it shows.
            if (sceneMesh.triangleCount() > DENSE) {
                Material m = geometry.material();
                geometry.setMaterial(new Material(m.front(), m.back(), m.useFaceColors(), false));
            }
        } else {
            SceneMesh sceneMesh = PathView.mesh(refinement, colors, 5L * mesh.faceCount() > DENSE);
            geometry = new Geometry(VIEWED, sceneMesh, show == Show.PATH ? Material.FACE_COLORS : Material.PAPER);
            caption = String.format(Locale.ROOT, "%s: %d -> %d triangles", name, mesh.faceCount(), sceneMesh.triangleCount());
        }
        geometry.setClosed(Topology.of(mesh).boundaryLoops() == 0);
        scene.root().attach(geometry);
        // A three-quarter view from above reads as 3D at once, flat sheets included.
        scene.camera().setOrientation(new Quaterniond().rotateX(-0.6).rotateY(-0.5));
        scene.frameAll();
        Animation animation = show == Show.PATH ? PathView.reveal(geometry) : new Turntable(scene.camera());
        return new View(geometry, animation, caption, geometry.mesh().triangleCount() <= DENSE ? 4 : 0);
    }

    /** A soft grey-blue: the white paper stands out on it, and the triangle's colour is darker still. */
    public static final int BACKGROUND = 0xFFD3DAE2;

    /** The lone triangle, solid and outlined in green, and the strip laid fold by fold over it, then turned round. */
    public static WrapPlayback zigzag(Scene scene, Triangle shape, Wrap.Result result, List<PaperInSpace> geometries) {
        scene.root().attach(solid(shape));
        scene.root().attach(outline(shape));
        scene.setLegend(List.of(WrapView.TOP_SIDE, WrapView.UNDERSIDE, new Scene.Swatch(WrapView.MODEL, "the triangle")));
        // The captions name edges by their corners ("tuck 2 along edge CA"): the frames name the corners.
        List<Scene.Label> corners = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            corners.add(new Scene.Label(String.valueOf((char) ('A' + i)), shape.corner(i).x(), shape.corner(i).y(), shape.corner(i).z()));
        }
        scene.setLabels(corners);
        return paper(scene, result, geometries, "wrapped: the strip covers the triangle, its excess tucked under");
    }

    /** What the four stages of the seed's Figure 11 show, labelled a to d as a printed figure is. */
    public static final List<String> FIGURE11_LABELS = List.of("a. the first turn: two 45° folds", "b. every pass laid",
            "c. the excess tucked under", "d. the underside");

    /**
     * The stages of the seed's Figure 11 re-made from a lone triangle's playback, as
     * {@link #FIGURE11_LABELS} name them: the first turn, every pass laid, the excess tucked
     * under (the wrapped triangle from above, as the final turn ends: the moment the last tuck
     * is made the camera is still under it, where it followed the tucks), the underside.
     */
    public static double[] figure11Stages(WrapPlayback playback, Wrap.Result result) {
        int laid = result.count(Wrap.Kind.ZIGZAG_TURN) + result.count(Wrap.Kind.OVERLAP);
        return new double[] {playback.positionAfter(Math.min(2, laid)), playback.positionAfter(laid), playback.stepCount(),
            playback.halfTurn()};
    }

    /** The turn gadget's strip folded on an empty table. */
    public static WrapPlayback turn(Scene scene, Wrap.Result result, List<PaperInSpace> geometries) {
        scene.setLegend(List.of(WrapView.TOP_SIDE, WrapView.UNDERSIDE));
        return paper(scene, result, geometries, "turned: the strip runs on at the angle asked, top side up");
    }

    /** The model, solid, and the strips laid over it along the path; then a turn around it. */
    public static WrapPlayback wrap(Scene scene, HalfedgeMesh mesh, Wrap.Result result, List<PaperInSpace> geometries) {
        Geometry solid = new Geometry(MODEL, SceneMesh.of(mesh), new Material(WrapView.MODEL, 0xFF4A5460, false, false));
        scene.root().attach(solid);
        // White paper on white: only its outlines showed where it stands out from the model (a
        // newcomer's trial of the cube's frames), as on the demos' table before it was grey-blue.
        scene.setBackground(BACKGROUND);
        // Blue-grey underside over a grey-blue model reads as a hole: the legend says which is which.
        scene.setLegend(List.of(WrapView.TOP_SIDE, WrapView.UNDERSIDE, new Scene.Swatch(WrapView.MODEL, "the model")));
        return WrapView.play(scene, result, geometries);
    }

    /** The most crossing pairs whose faces the viewer shows: beyond, the first ones in the file's order. */
    public static final int SHOWN_CROSSINGS = 100_000;

    /**
     * Adds the faces of paper that cross paper or the model, in red, seen through the paper
     * above them and hidden until asked for (the viewer's C): where a fold is impossible. The
     * collision checker reads the paper's OBJ text; its face numbers are the OBJ's.
     *
     * @return the geometry, or null for paper the checker does not check ({@link Collisions#notChecked})
     */
    public static Geometry collisions(Scene scene, List<PaperInSpace> strips, double thickness, IndexedPolygons model) {
        return collisions(scene, strips, Collisions.forScene(strips, thickness, model));
    }

    /**
     * As {@link #collisions(Scene, List, double, IndexedPolygons)}, from a check of the strips
     * already made (listing up to {@link #SHOWN_CROSSINGS}: {@link Collisions#forScene}); null
     * where there is none.
     */
    public static Geometry collisions(Scene scene, List<PaperInSpace> strips, PaperCollisions.Result result) {
        if (result == null) {
            return null;
        }
        Set<Integer> faces = new TreeSet<>();
        for (PaperCollisions.Crossing crossing : result.crossings()) {
            faces.add(crossing.faceA());
            faces.add(crossing.faceB());
        }
        for (PaperCollisions.Crossing crossing : result.intoModel()) {
            faces.add(crossing.faceA()); // faceB is the model's triangle
        }
        List<double[]> polygons = new ArrayList<>();
        for (int face : faces) {
            polygons.add(WrapExport.faceCorners(strips, face));
        }
        Geometry geometry = new Geometry(CollisionView.NAME, CollisionView.mesh(polygons), CollisionView.MATERIAL);
        geometry.setSeenThrough(true);
        geometry.setVisible(false);
        scene.root().attach(geometry);
        return geometry;
    }

    /**
     * Adds the refinement the wrap followed, its triangles lighter to darker along the path,
     * spanning-tree edges in green (as {@code ifold view --path} shows it), hidden: shown
     * instead of the model, it says which way the strip goes.
     */
    public static Geometry refinement(Scene scene, HamiltonianRefinement.Result refinement) {
        boolean dense = refinement.mesh().faceCount() > DENSE; // the view's threshold: edges too fine to tell apart
        Geometry refined = new Geometry(REFINEMENT, PathView.mesh(refinement, PathView.Colors.DARKNESS, dense), Material.FACE_COLORS);
        refined.setVisible(false);
        scene.root().attach(refined);
        return refined;
    }

    /** A fold script's paper, folding up, the camera framing it as it stands. */
    public static Animation script(Scene scene, ScriptFolding.Result result, PaperInSpace folded) {
        Geometry geometry = new Geometry("paper", PaperView.mesh(folded, result.sheet()), PaperView.MATERIAL);
        scene.root().attach(geometry);
        scene.camera().setOrientation(new Quaterniond().rotateX(-0.75).rotateZ(-0.35));
        Animation animation = PaperView.folding(geometry, result, folded, scene.camera());
        animation.apply(0);
        return animation;
    }

    /** A FOLD file's paper folded all at once, every crease together, the camera framing it as it stands. */
    public static Animation form(Scene scene, ifold.foldfile.FoldedForm.Result result, PaperInSpace folded) {
        Geometry geometry = new Geometry("paper", PaperView.mesh(folded, result.sheet()), PaperView.MATERIAL);
        scene.root().attach(geometry);
        scene.camera().setOrientation(new Quaterniond().rotateX(-0.75).rotateZ(-0.35));
        Animation animation = PaperView.formFolding(geometry, new PaperView.Motion(result.sheet(), result.frames(), result::motionAt,
                result.creases(), result.kind().words()), folded, scene.camera());
        animation.apply(0);
        return animation;
    }

    private static WrapPlayback paper(Scene scene, Wrap.Result result, List<PaperInSpace> geometries, String ending) {
        // White paper on a white background would not be seen where it leaves the triangle.
        scene.setBackground(BACKGROUND);
        return WrapView.play(scene, result, geometries, ending);
    }

    /**
     * The triangle itself, in the wrap's quiet model colour, seen from its front only: from
     * behind, the paper tucked under it shows through.
     */
    private static Geometry solid(Triangle triangle) {
        SceneMesh mesh = new SceneMesh(corners(triangle), new int[] {0, 1, 2}, new int[] {WrapView.MODEL}, new int[0], new int[0]);
        Geometry solid = new Geometry(MODEL, mesh, new Material(WrapView.MODEL, WrapView.MODEL, false, false));
        solid.setClosed(true);
        return solid;
    }

    /** The triangle's edges, drawn in green: the paper must cover them and end inside them. */
    private static Geometry outline(Triangle triangle) {
        int green = 0xFF1E8C3A;
        SceneMesh mesh = new SceneMesh(corners(triangle), new int[0], new int[0], new int[] {0, 1, 1, 2, 2, 0}, new int[] {green, green, green});
        return new Geometry("triangle", mesh, new Material(green, green, false, true));
    }

    private static double[] corners(Triangle triangle) {
        double[] positions = new double[9];
        for (int i = 0; i < 3; i++) {
            positions[3 * i] = triangle.corner(i).x();
            positions[3 * i + 1] = triangle.corner(i).y();
            positions[3 * i + 2] = triangle.corner(i).z();
        }
        return positions;
    }
}
