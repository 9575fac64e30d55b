package ifold.zigzag;

import ifold.fold.Paper;
import ifold.fold.PaperAnalysis;
import java.util.LinkedHashMap;
import java.util.Map;
import org.joml.Matrix4d;
import org.joml.Vector3d;

/**
 * The figures of a wrapped triangle, measured on the folded paper (not taken from the plan).
 *
 * @param length the strip's length L
 * @param width its width w
 * @param folds all folds (the presses that follow tucks are not folds)
 * @param zigzagFolds the turn folds (and the overlap's fold)
 * @param tucks the tuck-under folds
 * @param passes the passes over the triangle
 * @param overlapped whether the last pass was laid back over itself to end at the wanted corner
 * @param maxLayers the most layers over any sampled point ({@link PaperAnalysis#maxLayers}: face
 *     centroids and a grid over the paper): a lower bound, exact wherever the samples hit every overlap
 * @param efficiency the triangle's area over the strip's, L·w
 * @param coverage the fraction of sample points of the triangle under at least one layer
 * @param samples how many points of the triangle were sampled
 * @param paperOutside the paper area whose shadow lies outside the triangle
 * @param stackLayers how many levels the stack of paper has, from its top to its bottom: at least
 *     {@code maxLayers}, more where rigid pieces rest on pieces they do not themselves overlap
 * @param farthestFromTriangle the farthest any paper vertex lies from the triangle in space
 * @param isometryError the largest relative change of an edge's length against the sheet
 * @param triangleArea the triangle's area
 */
public record ZigZagReport(double length, double width, int folds, int zigzagFolds, int tucks, int passes, boolean overlapped,
        int maxLayers, int stackLayers, double efficiency, double coverage, int samples, double paperOutside, double farthestFromTriangle,
        double isometryError, double triangleArea) {

    /** Samples per edge of the triangular grid of coverage points. */
    private static final int GRID = 48;

    public static ZigZagReport of(ZigZag.Result result) {
        Paper paper = result.folded();
        Triangle triangle = result.triangle();
        Matrix4d toPlan = result.planToSpace().invert(new Matrix4d());
        double[] plan = triangle.inPlan(result.options().start());
        int covered = 0;
        int samples = 0;
        int deepest = PaperAnalysis.maxLayers(paper);
        for (Vector3d point : samplePoints(triangle)) {
            int layers = PaperAnalysis.layersAt(paper, point.x, point.y, point.z);
            covered += layers > 0 ? 1 : 0;
            samples++;
        }
        double area = triangle.area();
        double width = result.options().width();
        int turns = result.count(ZigZag.Phase.ZIGZAG) + result.count(ZigZag.Phase.OVERLAP);
        int tucks = result.count(ZigZag.Phase.TUCK);
        return new ZigZagReport(result.length(), width, turns + tucks, turns, tucks,
                result.passes(), result.overlapped(), deepest, stackLayers(paper), area / (result.length() * width),
                (double) covered / samples, samples, Outside.area(paper, toPlan, plan), Outside.farthestFromTriangle(paper, toPlan, plan),
                PaperAnalysis.isometryError(paper), area);
    }

    /**
     * Points spread over the triangle's inside: the centres of a triangular grid of
     * {@value #GRID} steps a side, none on an edge.
     */
    public static java.util.List<Vector3d> samplePoints(Triangle triangle) {
        java.util.List<Vector3d> points = new java.util.ArrayList<>();
        for (int i = 0; i < GRID; i++) {
            for (int j = 0; i + j < GRID; j++) {
                double a = (i + 1.0 / 3) / GRID;
                double b = (j + 1.0 / 3) / GRID;
                double c = 1 - a - b;
                points.add(new Vector3d(triangle.corner(0)).mul(a).fma(b, triangle.corner(1)).fma(c, triangle.corner(2)));
            }
        }
        return points;
    }

    /**
     * The levels of the stack: the distinct heights of the paper faces, in whole thicknesses
     * (the zig-zag's layers lie a whole number of thicknesses from the triangle).
     */
    private static int stackLayers(Paper paper) {
        if (paper.thickness() == 0) {
            return PaperAnalysis.maxLayers(paper);
        }
        java.util.TreeSet<Long> levels = new java.util.TreeSet<>();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f)) {
                levels.add(Math.round(paper.height(paper.face(f)[0]) / paper.thickness()));
            }
        }
        return levels.size();
    }

    /** The aspect ratio L / w. */
    public double aspect() {
        return length / width;
    }

    /** The figures by name, for JSON. */
    public Map<String, Object> figures() {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("stripLength", length);
        figures.put("stripWidth", width);
        figures.put("aspectRatio", aspect());
        figures.put("folds", folds);
        figures.put("zigzagFolds", zigzagFolds);
        figures.put("tucks", tucks);
        figures.put("passes", passes);
        figures.put("lastPassOverlapped", overlapped);
        figures.put("maxLayers", maxLayers);
        figures.put("stackLayers", stackLayers);
        figures.put("paperEfficiency", efficiency);
        figures.put("coverage", coverage);
        figures.put("coverageSamples", samples);
        figures.put("paperOutsideArea", paperOutside);
        figures.put("farthestFromTriangle", farthestFromTriangle);
        figures.put("isometryError", isometryError);
        figures.put("triangleArea", triangleArea);
        return figures;
    }
}
