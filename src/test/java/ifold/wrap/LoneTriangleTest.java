package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.geom.ParameterException;
import ifold.geom.Triangle;
import ifold.mesh.PolygonSoup;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import java.nio.file.Path;
import java.util.List;
import java.util.Random;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** The zig-zag method on one triangle (the demo, Figure 11 of the seed): a wrap of a path of one triangle with its ends asked. */
class LoneTriangleTest {
    @TempDir
    Path dir;

    /** The demo's triangle: acute and scalene, altitude 8 from C. */
    private static final Triangle ACUTE = Triangle.planar(0, 0, 10, 0, 3.5, 8);

    @Test
    void theDemoTriangleIsWrapped() throws Exception {
        Wrap.Result result = wrapAndCheck(ACUTE, 1.6, 0.02, 2, 0, -1);
        assertEquals(8, result.count(Wrap.Kind.ZIGZAG_TURN), "⌈8 / 1.6⌉ = 5 passes, a pair of folds per turn");
        assertEquals(0, result.count(Wrap.Kind.OVERLAP));
        assertEquals(4, result.count(Wrap.Kind.TUCK));
    }

    @Test
    void theStripEndsAtEitherCornerForBothParities() throws Exception {
        // h = 8: width 2 gives 4 passes (even), width 1.8 gives 5 (odd, and not a multiple).
        for (double width : new double[] {2, 1.8}) {
            for (int end : new int[] {0, 1}) {
                for (int enterFrom : new int[] {-1, 0, 1}) {
                    Wrap.Result result = wrapAndCheck(ACUTE, width, 0.01, 2, end, enterFrom);
                    int passes = (int) Math.ceil(8 / width);
                    boolean overlapped = result.count(Wrap.Kind.OVERLAP) == 1;
                    // Entering beside corner A (0) means the first pass runs towards B; it must be
                    // overlapped exactly when the last pass would then run away from the end.
                    if (enterFrom >= 0) {
                        boolean lastRunsToB = (enterFrom == 0) == (passes % 2 == 1);
                        assertEquals(lastRunsToB != (end == 1), overlapped, "width " + width + " end " + end + " enter " + enterFrom);
                    } else {
                        assertFalse(overlapped, "free to choose: no overlap");
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
                wrapAndCheck(triangle, width, thickness, start, end, enterFrom);
            } catch (AssertionError | Wrap.WrapException e) {
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
    void aNarrowStripOfTwoHundredPassesWastesLittle() throws Exception {
        Wrap.Result result = wrapAndCheck(ACUTE, 0.04, 0.0005, 2, 0, -1);
        assertEquals(2 * 199, result.count(Wrap.Kind.ZIGZAG_TURN), "200 passes");
        Sheet sheet = result.strips().get(0).sheet();
        assertTrue(ACUTE.area() / (sheet.length() * sheet.width()) > 0.95, "efficiency tends to 1 as the strip narrows");
    }

    @Test
    void theScaleOfTheTriangleDoesNotMatter() throws Exception {
        for (double scale : new double[] {1e-6, 1e-3, 1e4}) {
            Triangle scaled = Triangle.planar(0, 0, 10 * scale, 0, 3.5 * scale, 8 * scale);
            Wrap.Result result = wrapAndCheck(scaled, 1.6 * scale, 0.02 * scale, 2, 0, -1);
            WrapAnalysis analysis = analyse(result);
            assertEquals(6, analysis.maxLayers(), "scale " + scale);
            assertEquals(4, result.count(Wrap.Kind.TUCK), "scale " + scale);
        }
    }

    @Test
    void paperOfNoThicknessIsWrappedToo() throws Exception {
        wrapAndCheck(ACUTE, 0.7, 0, 0, 1, -1);
    }

    @Test
    void flatTrianglesAreWrappedHoweverSharp() throws Exception {
        // Base corners of 3.4 degrees: the naive tucks bounce the paper between their edges, 90 times.
        Wrap.Result flat = wrapAndCheck(Triangle.planar(0, 0, 10, 0, 5, 0.3), 0.3 / 20, 0.0005, 2, 0, -1);
        assertTrue(flat.count(Wrap.Kind.TUCK) > 50, "many tucks: " + flat.count(Wrap.Kind.TUCK));
        // Of 0.23 degrees: more tucks than the 1,000 any triangle may take (it was refused there),
        // within the 4 x 180 / 0.23 its corner allows.
        Wrap.Result sharper = wrapAndCheck(Triangle.planar(0, 0, 10, 0, 5, 0.02), 0.02 / 20, 0.00004, 2, 0, -1);
        int tucks = sharper.count(Wrap.Kind.TUCK);
        assertTrue(tucks > StripFolding.MAX_TUCKS && tucks < StripFolding.maxTucks(0.229), "tucks: " + tucks);
    }

    @Test
    void theTucksAllowedGrowAsTheCornerSharpens() {
        assertEquals(StripFolding.MAX_TUCKS, StripFolding.maxTucks(60));
        assertEquals(StripFolding.MAX_TUCKS, StripFolding.maxTucks(0.72));
        assertEquals(2400, StripFolding.maxTucks(0.3));
        assertEquals(7200, StripFolding.maxTucks(0.1));
        assertTrue(StripFolding.maxTucks(0) > 1_000_000_000, "a degenerate corner is not a limit of zero");
    }

    @Test
    void aTriangleInSpaceIsWrappedOnItsFront() throws Exception {
        Triangle tilted = new Triangle(new Vector3d(1, 2, 3), new Vector3d(6, 1, 5), new Vector3d(2, 7, 4));
        Wrap.Result result = wrapAndCheck(tilted, 1, 0.01, 0, 2, -1);
        double[] n = result.frames()[0].normal();
        assertTrue(new Vector3d(n[0], n[1], n[2]).distance(tilted.normal()) < 1e-12, "the paper rests on the triangle's front");
    }

    @Test
    void aLoneTriangleTakesOneTo400Passes() {
        Triangle triangle = new Triangle(new Vector3d(0, 0, 0), new Vector3d(10, 0, 0), new Vector3d(4, 8, 0));
        Wrap.Ends ends = new Wrap.Ends(2, 0, -1);
        double altitude = triangle.height(2);
        Wrap.Options options = Wrap.Options.loneTriangle(triangle, ends, Double.NaN, Double.NaN);
        assertEquals(altitude / 5, options.width(), 1e-12, "a fifth of the altitude from the start by default");
        assertEquals(options.width() / 80, options.thickness(), 1e-15);
        Wrap.Options.loneTriangle(triangle, ends, altitude, 0); // one pass
        Wrap.Options.loneTriangle(triangle, ends, altitude / 400, 0); // 400 passes
        assertEquals("width", assertThrows(ParameterException.class,
                () -> Wrap.Options.loneTriangle(triangle, ends, altitude * 1.001, 0)).parameter());
        assertEquals("width", assertThrows(ParameterException.class,
                () -> Wrap.Options.loneTriangle(triangle, ends, altitude / 401, 0)).parameter());
        assertEquals("thickness", assertThrows(ParameterException.class,
                () -> Wrap.Options.loneTriangle(triangle, ends, 1, 0.3)).parameter());
        // The width as typed, 50 and not "50.0" (the window's width field said so).
        assertTrue(assertThrows(ParameterException.class, () -> Wrap.Options.loneTriangle(triangle, ends, 50, Double.NaN)).getMessage()
                .startsWith("50 is wider than the altitude 8.000"));
    }

    @Test
    void badEndsAreRefused() {
        assertEquals("end", assertThrows(ParameterException.class, () -> new Wrap.Ends(1, 1, -1)).parameter());
        assertEquals("start", assertThrows(ParameterException.class, () -> new Wrap.Ends(3, 1, -1)).parameter());
        assertEquals("enterFrom", assertThrows(ParameterException.class, () -> new Wrap.Ends(0, 1, 0)).parameter());
        assertThrows(IllegalArgumentException.class, () -> new Wrap.Ends(1, 1, -1));
        assertThrows(IllegalArgumentException.class, () -> new Wrap.Ends(0, 3, -1));
        assertThrows(IllegalArgumentException.class, () -> new Wrap.Ends(0, 1, 0));
        PolygonSoup square = new PolygonSoup();
        square.addVertex(0, 0, 0);
        square.addVertex(4, 0, 0);
        square.addVertex(4, 4, 0);
        square.addVertex(0, 4, 0);
        square.addTriangle(0, 1, 2);
        square.addTriangle(0, 2, 3);
        assertThrows(IllegalArgumentException.class,
                () -> Wrap.wrap(square, new int[] {0, 2}, new Wrap.Options(1, 0.01, new Wrap.Ends(0, 1, -1))),
                "a path of two triangles sets its own ends");
    }

    private static Wrap.Result wrap(Triangle triangle, double width, double thickness, int start, int end, int enterFrom)
            throws Wrap.WrapException {
        PolygonSoup path = new PolygonSoup();
        for (int i = 0; i < 3; i++) {
            path.addVertex(triangle.corner(i).x(), triangle.corner(i).y(), triangle.corner(i).z());
        }
        path.addTriangle(0, 1, 2);
        return Wrap.wrap(path, new int[] {0, 1}, new Wrap.Options(width, thickness, new Wrap.Ends(start, end, enterFrom)));
    }

    private static WrapAnalysis analyse(Wrap.Result result) {
        return WrapAnalysis.of(result, List.of(PaperInSpace.of(result.strips().get(0).sheet(), result.frames())));
    }

    /**
     * Wraps the triangle and checks every truth of a wrap on its OBJ, then what the zig-zag
     * itself promises: the strip ends beside the corner asked, no paper is left outside, and
     * its length keeps to the bound of docs/zigzag.md.
     */
    private Wrap.Result wrapAndCheck(Triangle triangle, double width, double thickness, int start, int end, int enterFrom)
            throws Exception {
        Wrap.Result result = wrap(triangle, width, thickness, start, end, enterFrom);
        PolygonSoup model = new PolygonSoup();
        for (int i = 0; i < 3; i++) {
            model.addVertex(triangle.corner(i).x(), triangle.corner(i).y(), triangle.corner(i).z());
        }
        model.addTriangle(0, 1, 2);
        WrapTest.check(dir, result, model, 1, 500);
        double size = Math.max(triangle.opposite(0), Math.max(triangle.opposite(1), triangle.opposite(2)));
        assertTrue(WrapAnalysis.outsideArea(result) <= 1e-9 * size * size, "no paper area outside: " + WrapAnalysis.outsideArea(result));

        // The strip's end, where it was laid (tucks then hide it under the triangle, near its
        // corner but not always nearest it), lies beside the corner asked.
        Sheet sheet = result.strips().get(0).sheet();
        HostFrame frame = result.frames()[0];
        double[] c = frame.corners();
        Isometry2 pose = sheet.tailPose();
        double ex = pose.x(sheet.length(), width / 2);
        double ey = pose.y(sheet.length(), width / 2);
        int other = 3 - start - end;
        double[] wanted = local(frame, triangle.corner(end));
        double[] unwanted = local(frame, triangle.corner(other));
        assertTrue(Math.hypot(ex - wanted[0], ey - wanted[1]) < Math.hypot(ex - unwanted[0], ey - unwanted[1]),
                "ends beside corner " + Triangle.name(end));

        // L <= Σ_{i<k} c(h - (i+2)w) + k(2m + 2w + 3w(|cot P| + |cot Q|)) + (overlapped ? |PQ| + 2m + w(|cot P| + |cot Q|) : 0).
        double base = c[2];
        double h = c[5];
        double slant = Math.abs(c[4] / h) + Math.abs((base - c[4]) / h);
        double margin = Math.max(width / 10, 2 * thickness);
        int k = PathPlan.passes(h, width);
        double bound = 0;
        for (int i = 0; i < k; i++) {
            bound += base * (1 - Math.max(0, h - (i + 2) * width) / h);
        }
        bound += k * (2 * margin + 2 * width + 3 * width * slant);
        bound += result.count(Wrap.Kind.OVERLAP) > 0 ? base + 2 * margin + width * slant : 0;
        assertTrue(sheet.length() <= bound * (1 + 1e-12), "L = " + sheet.length() + " within its bound " + bound);
        return result;
    }

    private static double[] local(HostFrame frame, org.joml.Vector3dc p) {
        double[] xyz = {p.x(), p.y(), p.z()};
        return new double[] {frame.localX(xyz), frame.localY(xyz)};
    }

    /** A triangle and the corner to start at. */
    record Case(Triangle triangle, int start) {
    }

    /**
     * Random cases. Every fifth is a needle, its sharp tip (3 to 10 degrees) the start; every
     * fifth a thin flat triangle (smallest angle 10 to 15 degrees); every fifth obtuse (up to
     * 150 degrees); the rest anything with no angle under 10 degrees.
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
            if (i % 5 == 3) {
                triangle = Triangle.planar(0, 0, 10, 0, 10 * random.nextDouble(), 0.5 + 2 * random.nextDouble());
            } else if (i % 5 == 2) {
                triangle = Triangle.planar(0, 0, 10, 0, 10 + 8 * random.nextDouble(), 1 + 4 * random.nextDouble());
            } else {
                triangle = Triangle.planar(10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble(),
                        10 * random.nextDouble(), 10 * random.nextDouble(), 10 * random.nextDouble());
            }
            if (random.nextInt(4) == 0) { // some clockwise: wrapped on their front, facing -z
                triangle = new Triangle(triangle.corner(0), triangle.corner(2), triangle.corner(1));
            }
            boolean thinEnough = i % 5 != 3 || triangle.smallestAngle() < 15;
            if (triangle.smallestAngle() >= 10 && triangle.largestAngle() <= 150 && thinEnough) {
                return new Case(triangle, random.nextInt(3));
            }
        }
    }
}
