package ifold.job;

import ifold.geom.Triangle;
import ifold.mesh.PolygonSoup;
import ifold.sheet.Sheet;
import ifold.wrap.PlacedWrap;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.PaperInSpace;
import java.util.List;
import java.util.Map;

/**
 * The zig-zag demo, as {@code ifold demo zigzag} and the window's Fold, Zig-zag a triangle both
 * do it: one triangle wrapped by one strip (the seed's Figure 11), placed in space and analysed,
 * and the figures of its report. The front ends read what the user asked, run it, and present
 * what it returns.
 */
public final class ZigZagJob {
    private ZigZagJob() {
    }

    /**
     * @param triangle the triangle as typed ("0,0,10,0,3.5,8"): the report and the exports name it so
     * @param shape that triangle
     * @param options the strip: its ends, width and thickness ({@link Wrap.Options#loneTriangle})
     */
    public record Request(String triangle, Triangle shape, Wrap.Options options) {
    }

    /**
     * The triangle wrapped.
     *
     * @param figures the report's figures ({@link Reports#zigzag})
     * @param source what made it, as the exports' headers say: "demo zigzag --triangle 0,0,10,0,3.5,8"
     */
    public record Outcome(Wrap.Result result, List<PaperInSpace> geometries, WrapAnalysis analysis, Map<String, Object> figures,
            String source) {
        /** The strip's paper. */
        public Sheet sheet() {
            return result.strips().get(0).sheet();
        }
    }

    /**
     * Wraps the triangle.
     *
     * @throws Wrap.WrapException where the triangle cannot be wrapped at these options
     * @throws ifold.geom.ParameterException where a value given does not fit the triangle (a
     *     thickness too thin for its size)
     */
    public static Outcome run(Request request, Wrap.Watcher watcher) throws Wrap.WrapException {
        Triangle shape = request.shape();
        PolygonSoup path = new PolygonSoup();
        for (int i = 0; i < 3; i++) {
            path.addVertex(shape.corner(i).x(), shape.corner(i).y(), shape.corner(i).z());
        }
        path.addTriangle(0, 1, 2);
        Wrap.Result result = Wrap.wrap(path, new int[] {0, 1}, request.options(), watcher);
        PlacedWrap placed = PlacedWrap.of(result);
        Wrap.Ends ends = request.options().ends();
        Map<String, Object> figures = Reports.zigzag(request.triangle(), ends.start(), ends.end(), result, placed.analysis());
        return new Outcome(result, placed.geometries(), placed.analysis(), figures, "demo zigzag --triangle " + request.triangle());
    }
}
