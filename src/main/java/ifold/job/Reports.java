package ifold.job;

import ifold.geom.Tolerance;
import ifold.geom.Triangle;
import ifold.mesh.Defect;
import ifold.script.ScriptFolding;
import ifold.sheet.Sheet;
import ifold.wrap.LayerFloor;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.PaperInSpace;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The figures of a result, in the order and under the names the {@code --report} JSON gives
 * them: one builder per kind of job, so that the window's report panel and the command line's
 * file hold the same numbers.
 */
public final class Reports {
    private Reports() {
    }

    /**
     * Why a wrap is not to be trusted, or null: paper stretched by more than rounding should
     * leave ({@link Tolerance#RELATIVE_EQUALITY} of a face's size, or far along a long strip the
     * drift of its poses, {@link WrapAnalysis#stretch}) was made by arithmetic that could not hold
     * the model, and is no wrap of it, whatever else it got right.
     */
    public static String stretched(WrapAnalysis analysis) {
        if (!(analysis.stretch() > 1)) {
            return null;
        }
        return String.format(Locale.ROOT, "the paper came out stretched (isometry error %.1e of a face's size, %.3g times what"
                + " rounding allows there): rounding at the model's coordinates is coarser than its folds; a model with parts far"
                + " apart can be wrapped part by part", analysis.isometryError(), analysis.stretch());
    }

    /** A point in space as the messages write it: shortest round-trip decimals. */
    public static String point(double[] p) {
        return "(" + p[0] + ", " + p[1] + ", " + p[2] + ")";
    }

    /** The zig-zag demo's figures: the triangle as typed, its ends, the strip, its folds, layers and quality. */
    public static Map<String, Object> zigzag(String triangle, int start, int end, Wrap.Result result, WrapAnalysis analysis) {
        Sheet sheet = result.strips().get(0).sheet();
        int turns = result.count(Wrap.Kind.ZIGZAG_TURN);
        int overlaps = result.count(Wrap.Kind.OVERLAP);
        int tucks = result.count(Wrap.Kind.TUCK);
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("triangle", triangle);
        figures.put("start", Triangle.name(start));
        figures.put("end", Triangle.name(end));
        figures.put("stripLength", sheet.length());
        figures.put("stripWidth", sheet.width());
        figures.put("lengthOverWidth", sheet.length() / sheet.width()); // the wrap's strips say it so too
        figures.put("folds", turns + overlaps + tucks);
        figures.put("zigzagFolds", turns + overlaps);
        figures.put("tucks", tucks);
        figures.put("passes", passes(result));
        figures.put("lastPassOverlapped", overlaps > 0);
        figures.put("maxLayers", analysis.maxLayers());
        figures.put("stackLayers", analysis.stackLevels());
        figures.put("paperEfficiency", analysis.surfaceArea() / analysis.paperArea());
        figures.put("coverage", analysis.coverage());
        figures.put("paperOutsideArea", WrapAnalysis.outsideArea(result));
        figures.put("paperOutside", analysis.outsidePaper());
        figures.put("farthestFromTriangle", analysis.farthest());
        figures.put("isometryError", analysis.isometryError());
        figures.put("triangleArea", analysis.surfaceArea());
        figures.put("thickness", result.thickness());
        return figures;
    }

    /**
     * Where the layers are most and where they come from: the point in space, the strip and
     * path triangle (from 1), and the layers there by kind of paper.
     */
    public static Map<String, Object> deepest(WrapAnalysis.Deepest deepest) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("point", List.of(deepest.point()[0], deepest.point()[1], deepest.point()[2]));
        figures.put("strip", deepest.strip() + 1);
        figures.put("triangle", deepest.triangle() + 1);
        figures.put("layers", deepest.layers());
        figures.put("passes", deepest.passes());
        figures.put("turnGadgets", deepest.turnGadgets());
        figures.put("edgeCrossings", deepest.edgeCrossings());
        figures.put("tucks", deepest.tucks());
        return figures;
    }

    /**
     * The fewest layers any strip must have (LayerFloor): the floor, and the vertex it comes
     * from with the sum of its angles in degrees.
     */
    public static Map<String, Object> floor(LayerFloor floor) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("layers", floor.layers());
        figures.put("point", List.of(floor.point()[0], floor.point()[1], floor.point()[2]));
        figures.put("angleSumDegrees", Math.toDegrees(floor.angleSum()));
        return figures;
    }

    /** The passes of a lone triangle's strip: two turn folds between passes, and the overlap is a pass of its own. */
    public static int passes(Wrap.Result result) {
        return result.count(Wrap.Kind.ZIGZAG_TURN) / 2 + 1 + result.count(Wrap.Kind.OVERLAP);
    }

    /** The turn gadget's figures: the angle asked and measured, which side ends up, the strip and its layers. */
    public static Map<String, Object> turn(TurnGadget.Options options, TurnGadget.Result gadget, WrapAnalysis analysis) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("angle", options.angle());
        figures.put("measuredAngle", gadget.measuredAngle());
        figures.put("overhang", options.overhang() * options.width());
        figures.put("topSideUp", gadget.endFacesUp());
        figures.put("stripLength", gadget.length());
        figures.put("stripWidth", options.width());
        figures.put("thickness", options.thickness());
        figures.put("folds", gadget.wrap().count(Wrap.Kind.TURN_GADGET));
        figures.put("maxLayers", analysis.maxLayers());
        figures.put("stackLayers", analysis.stackLevels());
        figures.put("isometryError", analysis.isometryError());
        return figures;
    }

    /** The repairs made, by kind in the enum's order: {@code zero_area_face: 2}, as every report names them. */
    public static Map<String, Object> repairs(Map<Defect, Integer> repairs) {
        Map<String, Object> repaired = new LinkedHashMap<>();
        new TreeMap<>(repairs).forEach((defect, count) -> repaired.put(defect.name().toLowerCase(Locale.ROOT), count));
        return repaired;
    }

    /**
     * A model's wrap: the model and its repairs, the refinement, each strip, the folds by kind,
     * layers, areas and quality, the creases.
     *
     * @param model the model's name as the user gave it
     * @param inputTriangles the triangles of the model as built
     */
    public static Map<String, Object> wrap(String model, int inputTriangles, Map<Defect, Integer> repairs,
            WrapPath path, Wrap.Result result, WrapAnalysis analysis) {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("model", model);
        figures.put("method", path.hinge() ? "hinge" : "zigzag");
        figures.put("inputTriangles", inputTriangles);
        figures.put(path.hinge() ? "tour" : "preparation", path.figures());
        figures.put("refinedTriangles", path.pathTriangles());
        figures.put("hosts", result.frames().length);
        figures.put("components", path.components());
        figures.put("repairs", repairs(repairs));
        figures.put("width", result.width());
        figures.put("widestWidth", result.widest());
        figures.put("thickness", result.thickness());
        List<Object> strips = new ArrayList<>();
        double totalLength = 0;
        for (Wrap.Strip strip : result.strips()) {
            Map<String, Object> one = new LinkedHashMap<>();
            one.put("triangles", strip.triangles());
            one.put("length", strip.sheet().length());
            one.put("width", strip.sheet().width());
            one.put("lengthOverWidth", strip.sheet().length() / strip.sheet().width());
            one.put("faces", strip.sheet().faceCount());
            strips.add(one);
            totalLength += strip.sheet().length();
        }
        figures.put("strips", strips);
        figures.put("length", totalLength);
        Map<String, Object> folds = new LinkedHashMap<>();
        folds.put("zigzagTurns", result.count(Wrap.Kind.ZIGZAG_TURN));
        folds.put("turnGadgets", result.count(Wrap.Kind.TURN_GADGET));
        folds.put("edgeCrossings", result.count(Wrap.Kind.EDGE_CROSSING));
        folds.put("tucks", result.count(Wrap.Kind.TUCK));
        folds.put("diagonalTurns", result.count(Wrap.Kind.DIAGONAL_TURN));
        figures.put("folds", folds);
        figures.put("maxLayers", analysis.maxLayers());
        figures.put("stackLayers", analysis.stackLevels());
        figures.put("layersAtLeast", floor(LayerFloor.of(result.mesh())));
        if (analysis.deepest() != null) {
            figures.put("deepestLayers", deepest(analysis.deepest()));
        }
        figures.put("surfaceArea", analysis.surfaceArea());
        figures.put("paperArea", analysis.paperArea());
        figures.put("paperEfficiency", analysis.surfaceArea() / analysis.paperArea());
        figures.put("coverage", analysis.coverage());
        figures.put("paperOutsideArea", WrapAnalysis.outsideArea(result)); // as the zig-zag's report
        figures.put("paperOutside", analysis.outsidePaper());
        figures.put("farthestFromSurface", analysis.farthest());
        figures.put("isometryError", analysis.isometryError());
        figures.put("creep", analysis.creep());
        Map<String, Object> creases = new LinkedHashMap<>();
        creases.put("insideFaces", analysis.creasesInside());
        creases.put("insideFacesLength", analysis.creaseLengthInside());
        creases.put("alongEdges", analysis.creasesOnEdges());
        creases.put("alongEdgesLength", analysis.creaseLengthOnEdges());
        figures.put("creases", creases);
        return figures;
    }

    /** A fold script's figures: its folds, the paper's faces, creases, layers and area, the isometry. */
    public static Map<String, Object> script(ScriptFolding.Result result, PaperInSpace folded) {
        Sheet sheet = result.sheet();
        int creases = 0;
        double area = 0;
        for (int f = 0; f < sheet.faceCount(); f++) {
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                area += sheet.u(a) * sheet.v(b) - sheet.u(b) * sheet.v(a);
                if (sheet.crease(a, b) != null && (sheet.faceAcross(a, b) < f)) {
                    creases++; // each crease edge once, from the later of its two faces
                }
            }
        }
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("folds", result.steps().size());
        figures.put("thickness", sheet.thickness());
        figures.put("vertices", folded.vertexCount());
        figures.put("faces", sheet.faceCount());
        figures.put("capFacets", folded.caps().size());
        figures.put("creases", creases);
        figures.put("planes", result.frames().length);
        figures.put("maxLayers", WrapAnalysis.maxLayers(sheet, result.frames().length));
        figures.put("stackLayers", sheet.stackLevels());
        figures.put("paperArea", area / 2);
        figures.put("isometryError", WrapAnalysis.isometryError(folded, sheet.width()));
        return figures;
    }
}
