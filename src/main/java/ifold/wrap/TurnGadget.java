package ifold.wrap;

import ifold.geom.ParameterException;
import ifold.geom.Tolerance;
import ifold.mesh.PolygonSoup;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Sheet.Crease;
import ifold.sheet.Sheet.Placement;
import java.util.ArrayList;
import java.util.List;

/**
 * The turn gadget (the seed, Figures 1 and 2), on its own: turns a strip by any angle θ in
 * (0°, 180°) and keeps its top side up, as the wrap does between triangles. The strip runs along
 * +x on a table (the plane z = 0, the band 0 &lt;= y &lt;= w); a fold across it at u = p lays it
 * back over itself, back side up; a second fold, along a crease at (90° + θ/2) to the strip,
 * lays it over again and sets it running at θ from +x, top side up. That crease crosses the
 * strip from paper point (p + X, 0) to (p + X + w·tan(θ/2), w): the overhang X is how far beyond
 * the first fold the second one begins. X = 0 is the basic gadget (Figure 1), its two creases
 * touching at the strip's edge; any X &gt; 0 the generalised one (Figure 2), which lets the turn's
 * corner fall where the next triangle needs it.
 *
 * <p>The folds are made by the same engine as the wrap's ({@link Sheet}), and the result is a
 * {@link Wrap.Result} of one strip on one host, the table, so that it is drawn, measured and
 * written as a wrap is.
 */
public final class TurnGadget {
    private TurnGadget() {
    }

    /**
     * The gadget asked for: a strip of width {@code width}, turned by {@code angle} degrees with an
     * overhang of {@code overhang} widths, running 4 widths before the turn and 6 after it. The
     * turn crease runs w·tan(θ/2) along the strip: past {@link #MAX_ANGLE} that is over 1,000
     * widths, and below {@link #MIN_ANGLE} the two creases part by less than a millionth of the
     * width.
     *
     * @param thickness the paper's thickness, or NaN for the width over {@link #WIDTHS_A_THICKNESS}; at most a quarter of the width
     * @throws ParameterException naming the value out of range
     */
    public record Options(double angle, double overhang, double width, double thickness) {
        public static final double MIN_ANGLE = 0.01;
        /**
         * The default thickness is the width over this: thicker than a wrap's, since the gadget
         * is seen close, a few widths of strip, and its layers should show.
         */
        public static final int WIDTHS_A_THICKNESS = 50;
        public static final double MAX_ANGLE = 179.9;
        /** The most overhang, in strip widths. */
        public static final double MAX_OVERHANG = 100;

        public Options {
            if (!(angle >= MIN_ANGLE && angle <= MAX_ANGLE)) {
                throw new ParameterException("angle", String.format(java.util.Locale.ROOT, "must be from %s to %s degrees, got %s",
                        MIN_ANGLE, MAX_ANGLE, angle));
            }
            if (!(overhang >= 0 && overhang <= MAX_OVERHANG)) {
                throw new ParameterException("overhang", "must be between 0 and " + (int) MAX_OVERHANG + " strip widths, got "
                        + ParameterException.shown(overhang));
            }
            if (!(width > 0) || !Double.isFinite(width)) {
                throw new ParameterException("width", "must be a positive number, got " + ParameterException.shown(width));
            }
            if (Double.isNaN(thickness)) {
                thickness = width / WIDTHS_A_THICKNESS;
            }
            if (!(thickness >= 0) || !Double.isFinite(thickness) || thickness > width / 4) {
                throw new ParameterException("thickness", "must be zero or more and at most a quarter of the width, got "
                        + ParameterException.shown(thickness));
            }
        }
    }

    /** Makes the gadget {@code options} asks for. */
    public static Result turn(Options options) throws FoldException {
        double w = options.width();
        return turn(options.angle(), options.overhang() * w, w, options.thickness(), 4 * w, 6 * w);
    }

    /**
     * The gadget made.
     *
     * @param wrap the strip on its table: one strip, one host (a triangle holding all the paper,
     *     laid and unfolded)
     * @param angle the turn asked, in degrees
     * @param overhang X
     * @param length the strip's length
     */
    public record Result(Wrap.Result wrap, double angle, double overhang, double length) {
        public Sheet sheet() {
            return wrap.strips().get(0).sheet();
        }

        /**
         * The direction, in degrees from +x, in which the strip's end runs, measured on the
         * folded paper: the pose of the face that holds the end.
         */
        public double measuredAngle() {
            Isometry2 pose = endPose();
            return Math.toDegrees(Math.atan2(pose.dy(1, 0), pose.dx(1, 0)));
        }

        /** Whether the strip's end lies top side up, as it came in: its face's pose does not mirror. */
        public boolean endFacesUp() {
            return !endPose().mirrors();
        }

        private Isometry2 endPose() {
            Sheet sheet = sheet();
            for (int f = sheet.faceCount() - 1; f >= 0; f--) {
                for (int v : sheet.loop(f)) {
                    if (sheet.u(v) == sheet.length() && sheet.v(v) == 0) {
                        return sheet.pose(f);
                    }
                }
            }
            throw new IllegalStateException("the strip's end is on no face");
        }
    }

    /**
     * Makes the gadget on a strip of width {@code width} that runs {@code lead} before the turn
     * and {@code tail} after it.
     *
     * @throws IllegalArgumentException for an angle outside (0, 180), a negative overhang or a
     *     bad size
     * @throws FoldException if a fold cannot be made
     */
    public static Result turn(double angleDegrees, double overhang, double width, double thickness, double lead, double tail)
            throws FoldException {
        if (!(angleDegrees > 0 && angleDegrees < 180)) {
            throw new IllegalArgumentException("the turn angle must be more than 0 and less than 180 degrees, got " + angleDegrees);
        }
        if (!(overhang >= 0) || !Double.isFinite(overhang)) {
            throw new IllegalArgumentException("the overhang must be zero or more, got " + overhang);
        }
        if (!(width > 0) || !(lead > 0) || !(tail > 0) || !Double.isFinite(width + lead + tail)) {
            throw new IllegalArgumentException("the strip needs a positive width and lengths");
        }
        if (!(thickness >= 0) || !Double.isFinite(thickness)) {
            throw new IllegalArgumentException("the thickness must be zero or more, got " + thickness);
        }
        double slant = width * Math.tan(Math.toRadians(angleDegrees / 2));
        double p = lead;
        double length = p + overhang + slant + tail;
        double tolerance = Tolerance.ON_PLANE * length;
        Sheet sheet = new Sheet(width, thickness, tolerance, TABLE, Isometry2.IDENTITY);
        List<Wrap.Step> steps = new ArrayList<>();
        // Across the strip at u = p: it runs back along -x, back side up.
        fold(sheet, steps, p, 0, 0, 1, "the fold across lays the strip back over itself");
        // The first fold took paper point (u, v) to (2p - u, v): the turn crease, from paper
        // (p + X, 0) to (p + X + slant, w), lies from (p - X, 0) towards (-slant, w) on the table.
        fold(sheet, steps, p - overhang, 0, -slant, width, String.format(java.util.Locale.ROOT,
                "the turn fold sets it running at %.4g°, top side up", angleDegrees));
        Isometry2 pose = sheet.tailPose();
        int last = sheet.endTail(pose.x(length, 0), pose.y(length, 0), pose.dx(0, 1), pose.dy(0, 1));
        steps.add(new Wrap.Step(Wrap.Kind.END, 0, TABLE, 0, 1, last, null, sheet.faceCount(), null, "on at the angle asked, top side up"));

        // The table: a triangle under all the paper, folded and as it came in.
        double[] box = {0, 0, length, width};
        for (int f = 0; f < sheet.faceCount(); f++) {
            double[] xy = sheet.placed(f);
            for (int k = 0; k < xy.length; k += 2) {
                box[0] = Math.min(box[0], xy[k]);
                box[1] = Math.min(box[1], xy[k + 1]);
                box[2] = Math.max(box[2], xy[k]);
                box[3] = Math.max(box[3], xy[k + 1]);
            }
        }
        // A triangle about the paper's middle (its incircle holds the paper's bounding circle): the
        // view that follows the triangle being folded then looks at the paper.
        double cx = (box[0] + box[2]) / 2;
        double cy = (box[1] + box[3]) / 2;
        double around = 2 * (Math.hypot(box[2] - box[0], box[3] - box[1]) / 2 + width);
        double[] corners = new double[6];
        for (int k = 0; k < 3; k++) {
            double angle = Math.PI / 2 + k * 2 * Math.PI / 3;
            corners[2 * k] = cx + around * Math.cos(angle);
            corners[2 * k + 1] = cy + around * Math.sin(angle);
        }
        HostFrame table = new HostFrame(new double[] {0, 0, 0}, new double[] {1, 0, 0}, new double[] {0, 1, 0},
                new double[] {0, 0, 1}, corners);
        PolygonSoup mesh = new PolygonSoup();
        for (int k = 0; k < 3; k++) {
            mesh.addVertex(corners[2 * k], corners[2 * k + 1], 0);
        }
        mesh.addTriangle(0, 1, 2);
        Wrap.Strip strip = new Wrap.Strip(sheet, TABLE, 1, new int[] {sheet.faceCount()});
        Wrap.Result wrap = new Wrap.Result(mesh, new HostFrame[] {table}, new int[] {TABLE}, List.of(strip), List.copyOf(steps), width, thickness,
                Double.NaN);
        return new Result(wrap, angleDegrees, overhang, length);
    }

    /** The one host: the table. */
    private static final int TABLE = 0;

    /** A fold of the tail over the paper it lies on (a valley fold of the strip's top as it lies then), recorded as a step. */
    private static void fold(Sheet sheet, List<Wrap.Step> steps, double px, double py, double dx, double dy, String detail)
            throws FoldException {
        Isometry2 before = sheet.tailPose();
        int face = sheet.foldTail(px, py, dx, dy, Placement.OVER, Crease.GADGET);
        Wrap.TailMove move = new Wrap.TailMove(TABLE, before, TABLE, sheet.tailPose(), sheet.tailStart(false), sheet.tailStart(true),
                true);
        steps.add(new Wrap.Step(Wrap.Kind.TURN_GADGET, 0, TABLE, 0, 1, face, null, sheet.faceCount(), move, detail));
    }
}
