package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A convex solid not designed for (docs/wrap.md, Limits, "Found trying shapes not designed
 * for"): a random frustum whose paper crossed itself in 5 pairs of caps, 0.99 T deep, from every
 * start the seam tries. On a side face, by its 94° corner at the top (where its slanted side
 * meets its edge along the top), a tuck along the slanted side folded under the paper reaching
 * past it, its fold running on past the corner; the tuck along the top then folded that stretch
 * of the fold under too, 7.6° off the slanted side. That fold (levels 1 to 4, standing out a
 * thickness round the fold it wraps) ran its row through the wall standing on the slanted side
 * (levels 1 to 18): its mitre lay 7.5 T from the corner, more than the 4 times its out that
 * mitres were held to.
 */
class RandomFrustumTest {
    @TempDir
    Path dir;

    /**
     * The frustum as a sweep of random solids drew it: an irregular hexagon about 2.1 across, its
     * top the base shrunk to 0.8 and raised 2.98; the reader cuts its long side faces into
     * triangles with corners of 1.7°.
     */
    static PolygonSoup frustum() {
        double[][] base = {{0.4707378510481084, 1.042293870530101}, {-0.30388307717256036, 1.1025541766109028},
            {-0.7192022028870948, 0.8892237223085989}, {-1.0774675867176233, -0.3834504355544673},
            {-0.6072393134435572, -0.9691393362992792}, {-0.5109146675139772, -1.0231993156140655}};
        double[][] top = {{0.5761402234061812, 0.8328385925269879}, {-0.04281592882864049, 0.8809892244366391},
            {-0.3746741560421553, 0.7105288194321345}, {-0.6609439370097883, -0.3063937437227981},
            {-0.28521088863179805, -0.7743849058572404}, {-0.20824326480719357, -0.8175812042885708}};
        double height = 2.9799062547194777;
        PolygonSoup soup = new PolygonSoup();
        for (double[] p : base) {
            soup.addVertex(p[0], p[1], 0);
        }
        for (double[] p : top) {
            soup.addVertex(p[0], p[1], height);
        }
        soup.addFace(new int[] {5, 4, 3, 2, 1, 0}, 6, 0);
        soup.addFace(new int[] {6, 7, 8, 9, 10, 11}, 6, 0);
        for (int k = 0; k < 6; k++) {
            int next = (k + 1) % 6;
            soup.addFace(new int[] {k, next, 6 + next, 6 + k}, 4, 0);
        }
        return soup;
    }

    /**
     * Wrapped as the wrap command does: no crossing pairs, every truth (measured, 2026-12-06: 23
     * layers from the start kept, 23, 23, 24 and 23 from the four starts, 0 collisions from each,
     * where each had 5 crossing pairs).
     */
    @Test
    void itsPaperCrossesNothingWhereATuckFoldsAnotherTucksFoldUnder() throws Exception {
        HalfedgeMesh model = MeshBuilder.build(frustum(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        assertEquals(20, model.faceCount(), "check the setup: two hexagons cut into 4 triangles each, six quads into 2");
        int layers = WrapTest.wrapAsTheCommandDoesAndCheck(dir, model);
        assertTrue(layers <= 23, layers + " layers");
    }
}
