package ifold.job;

import ifold.check.PaperCollisions;
import ifold.mesh.IndexedPolygons;
import ifold.wrap.WrapExport;
import ifold.wrap.PaperInSpace;
import ifold.wrap.Seam;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * The collision check of folded paper, as the report gives it: the independent checker
 * ({@link PaperCollisions}) reads the paper's OBJ, the file exported where there is one, else
 * the same text made in memory, never the engine's own faces.
 */
public final class Collisions {
    private Collisions() {
    }

    /**
     * The most faces of paper and caps checked: the 1,280-triangle icosphere's 515,000 take 2.5 s;
     * beyond, the OBJ text made for the check and its arrays (about 1.9 kB a face) would cost
     * more memory than the wrap. (Long thin passes check slower: the cube at width 2e-4, 718,000
     * faces and caps, 23 s.)
     */
    public static final int MOST_FACES = 600_000;

    /** Why paper of no thickness is not checked, as both front ends say it. */
    public static final String NO_THICKNESS = "paper of no thickness (every layer lies in its plane: the layer order is the check)";

    /**
     * Why {@code strips} are not checked, or null where they are: paper of no thickness (its
     * layers all lie in their planes, where every pair would touch: whether they are stacked as
     * paper can be is the layer order's question), or more than {@link #MOST_FACES} faces.
     */
    public static String notChecked(List<PaperInSpace> strips, double thickness) {
        if (!(thickness > 0)) {
            return NO_THICKNESS;
        }
        long faces = 0;
        for (PaperInSpace strip : strips) {
            faces += strip.paperFaces().size() + strip.caps().size();
        }
        return faces > MOST_FACES ? faces + " faces of paper and caps, more than the " + MOST_FACES + " checked" : null;
    }

    /**
     * Checks {@code strips} of paper {@code thickness} thick, against {@code model}'s triangles
     * where there is a model (null for a fold script's planes); null where {@link #notChecked}
     * says why not.
     *
     * @param exported the OBJ written of these strips, or null to make its text here
     */
    public static PaperCollisions.Result check(List<PaperInSpace> strips, double thickness, IndexedPolygons model, Path exported)
            throws IOException {
        return check(strips, thickness, model, exported, PaperCollisions.Options.DEFAULT);
    }

    /** As {@link #check(List, double, IndexedPolygons, Path)}, listing as many crossings as {@code options} say. */
    public static PaperCollisions.Result check(List<PaperInSpace> strips, double thickness, IndexedPolygons model, Path exported,
            PaperCollisions.Options options) throws IOException {
        if (notChecked(strips, thickness) != null) {
            return null;
        }
        CharSequence text = exported != null ? Files.readString(exported) : WrapExport.objText("collision check", strips);
        return PaperCollisions.check(text, thickness, model == null ? new double[0] : modelTriangles(model), options);
    }

    /**
     * Checks the strips as {@link #check} does and adds the figures to a report's as
     * {@code collisions}, or where there is no check {@code collisions.notChecked} saying why:
     * what both front ends report.
     *
     * @return the check, or null where {@link #notChecked} says why not (reported as such)
     */
    public static PaperCollisions.Result addTo(Map<String, Object> figures, List<PaperInSpace> strips, double thickness,
            IndexedPolygons model, Path exported) throws IOException {
        PaperCollisions.Result result = check(strips, thickness, model, exported);
        put(figures, result, strips, thickness);
        return result;
    }

    /**
     * The check of {@code strips} as the viewer shows it, listing the first
     * {@link Scenes#SHOWN_CROSSINGS} crossing pairs; null where {@link #notChecked} says why not.
     */
    public static PaperCollisions.Result forScene(List<PaperInSpace> strips, double thickness, IndexedPolygons model) {
        try {
            return check(strips, thickness, model, null, new PaperCollisions.Options(Scenes.SHOWN_CROSSINGS,
                    PaperCollisions.Options.DEFAULT.threads()));
        } catch (IOException e) {
            throw new UncheckedIOException(e); // no file is read
        }
    }

    /**
     * The check the wrap command hands the seam ({@link Seam#wrap(ifold.refine.HamiltonianRefinement.Result,
     * ifold.wrap.Wrap.Options, ifold.wrap.Wrap.Watcher, Seam.PaperCheck)}): {@link #count} on a start's paper, against
     * the triangles it was folded on.
     */
    public static final Seam.PaperCheck OF_SEAM = (result, placed) -> count(placed.geometries(), result.thickness(), result.mesh());

    /**
     * How many collisions the seam counts against a start of a wrap ({@code Seam.PaperCheck}):
     * pairs crossing or overlapping in one plane, crossings of the model and points inside it, by
     * the independent checker on the OBJ text of {@code strips}; -1 where {@link #notChecked}
     * says why not.
     */
    public static int count(List<PaperInSpace> strips, double thickness, IndexedPolygons model) {
        PaperCollisions.Result result;
        try {
            result = check(strips, thickness, model, null, new PaperCollisions.Options(0, PaperCollisions.Options.DEFAULT.threads()));
        } catch (IOException e) {
            throw new UncheckedIOException(e); // no file is read
        }
        if (result == null) {
            return -1;
        }
        long count = (long) result.crossingPairs() + result.coplanarPairs() + result.modelCrossings() + result.pointsInside();
        return (int) Math.min(Integer.MAX_VALUE, count);
    }

    /**
     * Adds a check made already ({@link #check}, or null where none was) to a report's figures as
     * {@link #addTo} does.
     */
    public static void put(Map<String, Object> figures, PaperCollisions.Result result, List<PaperInSpace> strips, double thickness) {
        if (result != null) {
            figures.put("collisions", figures(result));
        } else {
            figures.put("collisions", Map.of("notChecked", notChecked(strips, thickness)));
        }
    }

    /** As {@link #addTo(Map, List, double, IndexedPolygons, Path)} on the OBJ's text made in memory. */
    public static PaperCollisions.Result addTo(Map<String, Object> figures, List<PaperInSpace> strips, double thickness,
            IndexedPolygons model) {
        try {
            return addTo(figures, strips, thickness, model, null);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // no file is read
        }
    }

    /** The report's figures of a check: pairs crossing (with caps, in one plane), the deepest in T and its faces, the model crossed, points inside. */
    public static Map<String, Object> figures(PaperCollisions.Result result) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("pairs", result.crossingPairs());
        figures.put("capPairs", result.capPairs());
        figures.put("coplanarPairs", result.coplanarPairs());
        figures.put("deepest", result.deepest() == null ? 0.0 : result.deepest().depth());
        if (result.deepest() != null) {
            figures.put("deepestFaces", List.of(result.deepest().faceA(), result.deepest().faceB()));
        }
        figures.put("modelCrossings", result.modelCrossings());
        figures.put("pointsInside", result.pointsInside());
        return figures;
    }

    /** The model's faces as triangles, nine numbers each (a fan of each face), as {@link PaperCollisions#check} takes them. */
    public static double[] modelTriangles(IndexedPolygons model) {
        int count = 0;
        for (int f = 0; f < model.faceCount(); f++) {
            count += model.faceSize(f) - 2;
        }
        double[] triangles = new double[9 * count];
        int t = 0;
        for (int f = 0; f < model.faceCount(); f++) {
            for (int k = 1; k + 1 < model.faceSize(f); k++) { // a fan: the model's faces are convex where the wrap has them
                int[] corners = {model.faceVertex(f, 0), model.faceVertex(f, k), model.faceVertex(f, k + 1)};
                for (int c = 0; c < 3; c++) {
                    for (int axis = 0; axis < 3; axis++) {
                        triangles[9 * t + 3 * c + axis] = model.coordinate(corners[c], axis);
                    }
                }
                t++;
            }
        }
        return triangles;
    }
}
