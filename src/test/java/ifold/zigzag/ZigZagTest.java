package ifold.zigzag;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.fold.Paper;
import ifold.fold.PaperAnalysis;
import ifold.mesh.MeshValidator;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.joml.Matrix4d;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class ZigZagTest {
    /** The demo's triangle: acute and scalene. */
    private static final Triangle ACUTE = Triangle.planar(0, 0, 10, 0, 3.5, 8);

    @Test
    void theDemoTriangleIsWrapped() throws Exception {
        ZigZag.Result result = ZigZag.wrap(ACUTE, new ZigZag.Options(1.6, 0.02, 2, 0, -1));
        Paper laid = result.laid();
        Matrix4d toPlan = result.planToSpace().invert(new Matrix4d());
        assertEquals(2, Layers.stackLayers(laid, toPlan), "laid passes lie on the triangle, only the turns hold two layers");
        assertEquals(5, result.passes(), "⌈8 / 1.6⌉ passes");
        assertFalse(result.overlapped());
        assertEquals(8, result.count(ZigZag.Phase.ZIGZAG), "a pair of folds per turn");
        assertWrapped(result);
    }

    @Test
    void theStripEndsAtEitherCornerForBothParities() throws Exception {
        // h = 8: width 2 gives 4 passes (even), width 1.8 gives 5 (odd, and not a multiple).
        for (double width : new double[] {2, 1.8}) {
            for (int end : new int[] {0, 1}) {
                for (int enterFrom : new int[] {-1, 0, 1}) {
                    ZigZag.Result result = ZigZag.wrap(ACUTE, new ZigZag.Options(width, 0.01, 2, end, enterFrom));
                    assertWrapped(result);
                    int passes = (int) Math.ceil(8 / width);
                    // Entering beside corner A (0) means the first pass runs towards B; it must be
                    // overlapped exactly when the last pass would then run away from the end.
                    if (enterFrom >= 0) {
                        boolean lastRunsToB = (enterFrom == 0) == (passes % 2 == 1);
                        assertEquals(lastRunsToB != (end == 1), result.overlapped(), "width " + width + " end " + end);
                    } else {
                        assertFalse(result.overlapped());
                    }
                }
            }
        }
    }

    @Test
    void aHundredRandomTrianglesAreWrapped() throws Exception {
        Random random = new Random(20261123);
        int obtuse = 0;
        int thin = 0;
        int narrow = 0;
        for (int i = 0; i < 100; i++) {
            Case c = randomCase(random, i);
            Triangle triangle = c.triangle();
            int start = c.start();
            int end = (start + 1 + random.nextInt(2)) % 3;
            int enterFrom = random.nextInt(3) == 0 ? -1 : (start + 1 + random.nextInt(2)) % 3;
            double h = triangle.height(start);
            // Widths from h (one pass) down to h/50, some dividing h exactly.
            double divisions = i % 5 == 0 ? 1 + random.nextInt(50) : 1 + 49 * random.nextDouble();
            double width = h / divisions;
            double thickness = width * (0.002 + 0.048 * random.nextDouble());
            String what = "triangle " + i + ": " + triangle + ", start " + start + ", end " + end + ", enter " + enterFrom
                    + ", width h/" + divisions + ", thickness " + thickness;
            try {
                assertWrapped(ZigZag.wrap(triangle, new ZigZag.Options(width, thickness, start, end, enterFrom)));
            } catch (AssertionError | ifold.fold.FoldException e) {
                throw new AssertionError(what + ": " + e.getMessage(), e);
            }
            obtuse += triangle.largestAngle() > 90 ? 1 : 0;
            thin += triangle.smallestAngle() < 15 ? 1 : 0;
            narrow += divisions > 40 ? 1 : 0;
        }
        assertTrue(obtuse >= 20 && thin >= 30 && narrow >= 10, "the sample holds obtuse, thin and narrow cases: " + obtuse
                + ", " + thin + ", " + narrow);
    }

    @Test
    void aNarrowStripOfTwoHundredPassesIsWrappedAndWastesLittle() throws Exception {
        // A long sheet: its tolerances grow with it, and the tucks must agree with the fold engine's.
        ZigZag.Result result = ZigZag.wrap(ACUTE, new ZigZag.Options(0.04, 0.0005, 2, 0, -1));
        assertEquals(200, result.passes());
        assertWrapped(result);
        assertTrue(ZigZagReport.of(result).efficiency() > 0.95, "efficiency tends to 1 as the strip narrows");
    }

    @Test
    void theScaleOfTheTriangleDoesNotMatter() throws Exception {
        for (double scale : new double[] {1e-6, 1e-3, 1e4}) {
            Triangle scaled = Triangle.planar(0, 0, 10 * scale, 0, 3.5 * scale, 8 * scale);
            ZigZag.Result result = ZigZag.wrap(scaled, new ZigZag.Options(1.6 * scale, 0.02 * scale, 2, 0, -1));
            assertWrapped(result);
            ZigZagReport report = ZigZagReport.of(result);
            assertEquals(6, report.maxLayers(), "scale " + scale);
            assertEquals(1.0, report.coverage(), 0, "scale " + scale);
            assertEquals(4, report.tucks(), "scale " + scale);
        }
    }

    @Test
    void thinPaperIsWrappedToo() throws Exception {
        ZigZag.Result result = ZigZag.wrap(ACUTE, new ZigZag.Options(0.7, 0, 0, 1, -1));
        assertWrapped(result);
    }

    @Test
    void aFlatTriangleWithTwoSharpCornersIsRefusedClearly() {
        // Base corners of 3.4 degrees: the naive tucks bounce the paper between their edges.
        Triangle flat = Triangle.planar(0, 0, 10, 0, 5, 0.3);
        ifold.fold.FoldException e = assertThrows(ifold.fold.FoldException.class,
                () -> ZigZag.wrap(flat, new ZigZag.Options(0.3 / 20, 0.0005, 2, 0, -1)));
        assertTrue(e.getMessage().contains("3.4 degrees"), e.getMessage());
    }

    @Test
    void aTriangleInSpaceIsWrappedOnItsPlane() throws Exception {
        Triangle tilted = new Triangle(new Vector3d(1, 2, 3), new Vector3d(6, 1, 5), new Vector3d(2, 7, 4));
        ZigZag.Result result = ZigZag.wrap(tilted, new ZigZag.Options(1, 0.01, 0, 2, -1));
        assertWrapped(result);
        assertTrue(result.folded().normal().distance(tilted.normal()) < 1e-12, "the paper's top faces the triangle's front");
    }

    @Test
    void badOptionsAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(0, 0.01, 0, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(Double.NaN, 0.01, 0, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(1, -0.01, 0, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(1, 0.01, 1, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(1, 0.01, 0, 3, -1));
        assertThrows(IllegalArgumentException.class, () -> new ZigZag.Options(1, 0.01, 0, 1, 0));
        assertThrows(IllegalArgumentException.class, () -> Triangle.planar(0, 0, 1, 1, 2, 2));
    }

    /** A triangle and the corner to start at. */
    record Case(Triangle triangle, int start) {
    }

    /**
     * Random cases. Every fifth is a needle, its sharp tip (3 to 10 degrees) the start; every
     * fifth a thin flat triangle (smallest angle 10 to 15 degrees); every fifth obtuse (up to
     * 150 degrees); the rest anything with no angle under 10 degrees. The naive tucks cannot
     * finish a triangle with two sharper corners (see {@link #aFlatTriangleWithTwoSharpCornersIsRefusedClearly}).
     */
    static Case randomCase(Random random, int i) {
        if (i % 5 == 1) {
            double tip = Math.toRadians(3 + 7 * random.nextDouble());
            double length = 5 + 5 * random.nextDouble();
            double lean = (random.nextDouble() - 0.5) * tip; // the tip's bisector need not be upright
            Vector3d apex = new Vector3d(0, 0, 0);
            Vector3d left = new Vector3d(length * Math.cos(Math.PI / 2 + lean + tip / 2), length * Math.sin(Math.PI / 2 + lean + tip / 2), 0);
            Vector3d right = new Vector3d(length * Math.cos(Math.PI / 2 + lean - tip / 2), length * Math.sin(Math.PI / 2 + lean - tip / 2), 0);
            return new Case(new Triangle(apex, right, left), 0);
        }
        while (true) {
            Triangle triangle;
            double smallest = 10;
            if (i % 5 == 3) {
                triangle = Triangle.planar(0, 0, 10, 0, 10 * random.nextDouble(), 0.5 + 2 * random.nextDouble());
            } else if (i % 5 == 2) {
                triangle = Triangle.planar(0, 0, 10, 0, 10 + 8 * random.nextDouble(), 1 + 4 * random.nextDouble());
            } else {
                triangle = Triangle.planar(10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble(),
                        10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble());
            }
            if (triangle.normal().z < 0) { // keep the front up, for easy reading of failures
                triangle = new Triangle(triangle.corner(0), triangle.corner(2), triangle.corner(1));
            }
            boolean thinEnough = i % 5 != 3 || triangle.smallestAngle() < 15;
            if (triangle.smallestAngle() >= smallest && triangle.largestAngle() <= 150 && thinEnough) {
                return new Case(triangle, random.nextInt(3));
            }
        }
    }

    /** Every truth the issue asks of a wrapped triangle. */
    static void assertWrapped(ZigZag.Result result) throws Exception {
        Paper paper = result.folded();
        Triangle triangle = result.triangle();
        ZigZag.Options options = result.options();
        double w = options.width();
        double t = options.thickness();
        double size = Math.max(triangle.opposite(0), Math.max(triangle.opposite(1), triangle.opposite(2)));
        Matrix4d toPlan = result.planToSpace().invert(new Matrix4d());
        double[] plan = triangle.inPlan(options.start());

        assertTrue(PaperAnalysis.isometryError(paper) <= 1e-9, "isometric: " + PaperAnalysis.isometryError(paper));
        assertEquals(List.of(), MeshValidator.validate(paper.top()), "the top is a valid mesh");
        assertEquals(List.of(), MeshValidator.validate(paper.bottom()), "so is the bottom");
        assertEquals(result.length() * w, PaperAnalysis.paperArea(paper), 1e-9 * result.length() * w, "no paper lost");

        // Nothing outside: no vertex beyond an edge, no area outside, nothing deeper than the layers.
        // (Within the fold engine's tolerance, which grows with the sheet: 2e-9 of the strip's length.)
        double onEdge = 2e-9 * Math.max(size, result.length());
        for (int e = 0; e < 3; e++) {
            assertTrue(Outside.farthestBeyondEdge(paper, toPlan, plan, e) <= onEdge, "no paper beyond edge " + e);
        }
        assertTrue(Outside.area(paper, toPlan, plan) <= 3 * size * onEdge, "no paper area outside");
        int maxLayers = PaperAnalysis.maxLayers(paper);
        List<Vector3d> points = randomPoints(triangle, 400, new Random(7));
        for (Vector3d p : points) {
            maxLayers = Math.max(maxLayers, PaperAnalysis.layersAt(paper, p.x, p.y, p.z));
        }
        double farthest = Outside.farthestFromTriangle(paper, toPlan, plan);
        int stack = Layers.stackLayers(paper, toPlan);
        assertTrue(farthest <= stack * t + 1e-9 * size, "paper lies within layers × thickness of the triangle: "
                + farthest + " > " + stack + " × " + t);
        Layers.assertStackedAndPressed(paper, toPlan, size);

        // Coverage 1, and the layer count agrees with a count made on the sheet.
        for (Vector3d p : points) {
            int layers = PaperAnalysis.layersAt(paper, p.x, p.y, p.z);
            assertTrue(layers >= 1, "covered at " + p);
            int onSheet = layersOnSheet(paper, toPlan, p, 1e-7 * size);
            if (onSheet >= 0) {
                assertEquals(onSheet, layers, "layers at " + p);
            }
        }
        for (Vector3d p : ZigZagReport.samplePoints(triangle)) {
            assertTrue(PaperAnalysis.layersAt(paper, p.x, p.y, p.z) >= 1, "covered at grid point " + p);
        }

        // Before the tucks, the passes alone cover the triangle, as the plan says.
        Paper laid = result.laid();
        double h = plan[5];
        for (Vector3d p : points) {
            double y = toPlan.transformPosition(new Vector3d(p)).y;
            double fromBoundary = Math.abs(y / w - Math.rint(y / w)) * w;
            double offBoundary = Math.abs((h - y) / w - Math.rint((h - y) / w)) * w;
            if (Math.min(fromBoundary, offBoundary) < 1e-6 * Math.max(size, result.length())) {
                continue; // on the border of two passes: both counts may fairly differ
            }
            int expected = 0;
            for (int i = 0; i < result.passes() - (result.overlapped() ? 1 : 0); i++) {
                expected += y > h - (i + 1) * w && y < h - i * w ? 1 : 0;
            }
            if (result.overlapped() && y < h - (result.passes() - 2) * w) {
                expected++;
            }
            assertEquals(expected, PaperAnalysis.layersAt(laid, p.x, p.y, p.z), "passes over plan height " + y);
        }

        // The strip starts in the band of the start corner and ends beside the wanted corner.
        Vector3d start = planPoint(laid, toPlan, 0);
        assertTrue(start.y >= h - w - 1e-9 * size && start.y <= h + 1e-9 * size, "starts in the first band");
        int end = options.end();
        int other = 3 - options.start() - end;
        // (Before the tucks: they hide the end under the triangle, near its corner but not always nearest it.)
        Vector3d finish = planPoint(laid, toPlan, result.length());
        Vector3d wanted = toPlan.transformPosition(new Vector3d(triangle.corner(end)));
        Vector3d unwanted = toPlan.transformPosition(new Vector3d(triangle.corner(other)));
        assertTrue(finish.distance(wanted) < finish.distance(unwanted), "ends beside " + Triangle.name(end));

        // The length bound of the class notes.
        double base = plan[2];
        double cotP = plan[4] / h;
        double cotQ = (base - plan[4]) / h;
        double slant = Math.abs(cotP) + Math.abs(cotQ);
        int k = result.passes() - (result.overlapped() ? 1 : 0);
        double bound = 0;
        for (int i = 0; i < k; i++) {
            bound += base * (1 - Math.max(0, h - (i + 2) * w) / h);
        }
        bound += k * (2 * result.margin() + 2 * w + 3 * w * slant);
        bound += result.overlapped() ? base + 2 * result.margin() + w * slant : 0;
        assertTrue(result.length() <= bound * (1 + 1e-12), "L = " + result.length() + " within its bound " + bound);
    }

    /** Where paper point (u, w/2) lies, in the plan frame: the middle of the strip's end. */
    private static Vector3d planPoint(Paper paper, Matrix4d toPlan, double u) {
        Vector3d sum = new Vector3d();
        int count = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            for (int v : paper.face(f)) {
                if (Math.abs(paper.u(v) - u) < 1e-9 * Math.max(1, u)) {
                    sum.add(paper.x(v), paper.y(v), paper.z(v));
                    count++;
                }
            }
        }
        assertTrue(count > 0, "paper at u = " + u);
        return toPlan.transformPosition(sum.div(count));
    }

    /**
     * Layers over a point counted on the sheet: each face maps the point into paper coordinates
     * by its own rigid placement, and counts if its paper polygon holds the image. Returns -1
     * where the point lies within {@code margin} of a face's edge, where the two counts may
     * fairly differ.
     */
    private static int layersOnSheet(Paper paper, Matrix4d toPlan, Vector3d point, double margin) {
        Vector3d p = toPlan.transformPosition(new Vector3d(point));
        int layers = 0;
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.isCap(f)) {
                continue;
            }
            int[] face = paper.face(f);
            Vector3d a = toPlan.transformPosition(new Vector3d(paper.x(face[0]), paper.y(face[0]), paper.z(face[0])));
            Vector3d b = toPlan.transformPosition(new Vector3d(paper.x(face[1]), paper.y(face[1]), paper.z(face[1])));
            // Plan direction a -> b is paper direction a -> b turned by the face's placement.
            double planAngle = Math.atan2(b.y - a.y, b.x - a.x);
            double paperAngle = Math.atan2(paper.v(face[1]) - paper.v(face[0]), paper.u(face[1]) - paper.u(face[0]));
            boolean mirrored = isMirrored(paper, toPlan, face);
            double dx = p.x - a.x;
            double dy = p.y - a.y;
            double along = Math.hypot(dx, dy);
            double angle = Math.atan2(dy, dx) - planAngle;
            if (mirrored) {
                angle = -angle;
            }
            double u = paper.u(face[0]) + along * Math.cos(paperAngle + angle);
            double v = paper.v(face[0]) + along * Math.sin(paperAngle + angle);
            boolean inside = true;
            for (int i = 0; i < face.length; i++) {
                int c = face[i];
                int d = face[(i + 1) % face.length];
                double length = Math.hypot(paper.u(d) - paper.u(c), paper.v(d) - paper.v(c));
                double distance = ((paper.u(d) - paper.u(c)) * (v - paper.v(c)) - (paper.v(d) - paper.v(c)) * (u - paper.u(c))) / length;
                if (Math.abs(distance) < margin) {
                    return -1;
                }
                inside &= distance > 0;
            }
            layers += inside ? 1 : 0;
        }
        return layers;
    }

    /** Whether the face lies back up (its paper orientation reversed in the plan). */
    private static boolean isMirrored(Paper paper, Matrix4d toPlan, int[] face) {
        double twice = 0;
        for (int i = 0; i < face.length; i++) {
            Vector3d a = toPlan.transformPosition(new Vector3d(paper.x(face[i]), paper.y(face[i]), paper.z(face[i])));
            int j = face[(i + 1) % face.length];
            Vector3d b = toPlan.transformPosition(new Vector3d(paper.x(j), paper.y(j), paper.z(j)));
            twice += a.x * b.y - b.x * a.y;
        }
        return twice < 0; // faces are counter-clockwise on the sheet
    }

    private static List<Vector3d> randomPoints(Triangle triangle, int count, Random random) {
        List<Vector3d> points = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            double a = random.nextDouble();
            double b = random.nextDouble();
            if (a + b > 1) {
                a = 1 - a;
                b = 1 - b;
            }
            points.add(new Vector3d(triangle.corner(0)).mul(1 - a - b).fma(a, triangle.corner(1)).fma(b, triangle.corner(2)));
        }
        return points;
    }
}
