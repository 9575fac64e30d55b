package ifold.sheet;

/**
 * A rigid motion of the plane, possibly mirroring: {@code x = X + M (p - A)} with M orthogonal.
 * It places a piece of paper, given in paper coordinates p = (u, v), in the 2D frame of the
 * triangle it rests on. A mirroring motion shows the paper's bottom side up.
 *
 * <p>The motion is kept about an anchor A with its image X rather than as {@code M p + t}: far
 * along a long strip u is large, and {@code M p + t} would cancel two large numbers into a small
 * one, losing digits in proportion to the strip's length. Anchored at a corner of the face it
 * places, every difference it takes is small.
 *
 * <p>Immutable. Composition renormalises M, so a pose built from ten thousand folds is still an
 * exact isometry to rounding: folding never stretches paper, not even by drift.
 */
public final class Isometry2 {
    public static final Isometry2 IDENTITY = new Isometry2(1, 0, 0, 1, 0, 0, 0, 0);

    final double m00;
    final double m01;
    final double m10;
    final double m11;
    /** The anchor A, in the motion's source coordinates. */
    final double au;
    final double av;
    /** The anchor's image X. */
    final double ax;
    final double ay;

    private Isometry2(double m00, double m01, double m10, double m11, double au, double av, double ax, double ay) {
        this.m00 = m00;
        this.m01 = m01;
        this.m10 = m10;
        this.m11 = m11;
        this.au = au;
        this.av = av;
        this.ax = ax;
        this.ay = ay;
    }

    /** Paper axis u runs along {@code (cos, sin)} of {@code angle} from (originX, originY), v to its left (mirrored: to its right). */
    public static Isometry2 placement(double originX, double originY, double angle, boolean mirrored) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        return mirrored ? new Isometry2(c, s, s, -c, 0, 0, originX, originY) : new Isometry2(c, -s, s, c, 0, 0, originX, originY);
    }

    /** The reflection in the line through (px, py) with direction (dx, dy). */
    public static Isometry2 reflection(double px, double py, double dx, double dy) {
        double length = Math.hypot(dx, dy);
        if (!(length > 0)) {
            throw new IllegalArgumentException("a reflection needs a line with a direction");
        }
        double c = dx / length;
        double s = dy / length;
        // Reflection matrix for the line direction at angle a: [cos 2a, sin 2a; sin 2a, -cos 2a];
        // every point of the line is its own image.
        double c2 = c * c - s * s;
        double s2 = 2 * c * s;
        return new Isometry2(c2, s2, s2, -c2, px, py, px, py);
    }

    /**
     * The orientation-preserving motion that takes a to a2 and the direction of b - a to that
     * of b2 - a2 (the two segments must have the same length for it to take b to b2).
     */
    public static Isometry2 taking(double ax, double ay, double bx, double by, double a2x, double a2y, double b2x, double b2y) {
        double from = Math.atan2(by - ay, bx - ax);
        double to = Math.atan2(b2y - a2y, b2x - a2x);
        double c = Math.cos(to - from);
        double s = Math.sin(to - from);
        return new Isometry2(c, -s, s, c, ax, ay, a2x, a2y);
    }

    /**
     * The motion with linear part [m00 m01; m10 m11] (orthogonal up to rounding: renormalised as
     * {@link #after} does) taking the anchor (au, av) to (ax, ay): a face placed by where its
     * corner lands and how its axes turn.
     */
    public static Isometry2 anchored(double m00, double m01, double m10, double m11, double au, double av, double ax, double ay) {
        double length = Math.hypot(m00, m10);
        if (!(length > 0) || !Double.isFinite(length)) {
            throw new IllegalArgumentException("an isometry needs a linear part that turns the plane, got " + m00 + " " + m01 + "; " + m10
                    + " " + m11);
        }
        double a = m00 / length;
        double c = m10 / length;
        boolean mirror = m00 * m11 - m01 * m10 < 0;
        return new Isometry2(a, mirror ? c : -c, c, mirror ? -a : a, au, av, ax, ay);
    }

    public double x(double u, double v) {
        return ax + m00 * (u - au) + m01 * (v - av);
    }

    public double y(double u, double v) {
        return ay + m10 * (u - au) + m11 * (v - av);
    }

    /** The image of direction (du, dv), x component. */
    public double dx(double du, double dv) {
        return m00 * du + m01 * dv;
    }

    public double dy(double du, double dv) {
        return m10 * du + m11 * dv;
    }

    /** Whether this motion turns paper over (its top side then faces the other way). */
    public boolean mirrors() {
        return m00 * m11 - m01 * m10 < 0;
    }

    /** The same motion kept about the anchor (u, v): exact for points near it. */
    public Isometry2 anchoredAt(double u, double v) {
        return new Isometry2(m00, m01, m10, m11, u, v, x(u, v), y(u, v));
    }

    /** {@code this} after {@code first}: first applies first, then this. */
    public Isometry2 after(Isometry2 first) {
        double a = m00 * first.m00 + m01 * first.m10;
        double b = m00 * first.m01 + m01 * first.m11;
        double c = m10 * first.m00 + m11 * first.m10;
        double d = m10 * first.m01 + m11 * first.m11;
        // first's anchor stays the anchor; its image moves by this motion, taken about this
        // motion's own anchor, which lies near it (both are where the paper is).
        double x = x(first.ax, first.ay);
        double y = y(first.ax, first.ay);
        // Renormalise: the first column to unit length, the second perpendicular to it with
        // the sign it has (rotation or mirror), so that rounding never builds up into a stretch.
        double length = Math.sqrt(a * a + c * c);
        a /= length;
        c /= length;
        boolean mirror = a * d - b * c < 0;
        b = mirror ? c : -c;
        d = mirror ? -a : a;
        return new Isometry2(a, b, c, d, first.au, first.av, x, y);
    }

    public Isometry2 inverse() {
        // M is orthogonal: its inverse is its transpose; the anchor and its image swap.
        return new Isometry2(m00, m10, m01, m11, ax, ay, au, av);
    }

    @Override
    public String toString() {
        return "Isometry2[" + m00 + " " + m01 + "; " + m10 + " " + m11 + "; (" + au + ", " + av + ") -> (" + ax + ", " + ay + ")]";
    }
}
