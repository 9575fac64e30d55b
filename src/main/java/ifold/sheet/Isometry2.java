package ifold.sheet;

/**
 * A rigid motion of the plane, possibly mirroring: {@code (x, y) = M (u, v) + t} with M
 * orthogonal. It places a piece of paper, given in paper coordinates (u, v), in the 2D frame of
 * the triangle it rests on. A mirroring motion shows the paper's bottom side up.
 *
 * <p>Immutable. Composition renormalises M, so a pose built from ten thousand folds is still an
 * exact isometry to rounding: folding never stretches paper, not even by drift.
 */
public final class Isometry2 {
    public static final Isometry2 IDENTITY = new Isometry2(1, 0, 0, 1, 0, 0);

    final double m00;
    final double m01;
    final double m10;
    final double m11;
    final double tx;
    final double ty;

    private Isometry2(double m00, double m01, double m10, double m11, double tx, double ty) {
        this.m00 = m00;
        this.m01 = m01;
        this.m10 = m10;
        this.m11 = m11;
        this.tx = tx;
        this.ty = ty;
    }

    /** Paper axis u runs along {@code (cos, sin)} of {@code angle}, v to its left (mirrored: to its right). */
    public static Isometry2 placement(double originX, double originY, double angle, boolean mirrored) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        return mirrored ? new Isometry2(c, s, s, -c, originX, originY) : new Isometry2(c, -s, s, c, originX, originY);
    }

    /** The reflection in the line through (px, py) with direction (dx, dy). */
    public static Isometry2 reflection(double px, double py, double dx, double dy) {
        double length = Math.hypot(dx, dy);
        if (!(length > 0)) {
            throw new IllegalArgumentException("a reflection needs a line with a direction");
        }
        double c = dx / length;
        double s = dy / length;
        // Reflection matrix for the line direction at angle a: [cos 2a, sin 2a; sin 2a, -cos 2a].
        double c2 = c * c - s * s;
        double s2 = 2 * c * s;
        double tx = px - (c2 * px + s2 * py);
        double ty = py - (s2 * px - c2 * py);
        return new Isometry2(c2, s2, s2, -c2, tx, ty);
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
        return new Isometry2(c, -s, s, c, a2x - (c * ax - s * ay), a2y - (s * ax + c * ay));
    }

    public double x(double u, double v) {
        return m00 * u + m01 * v + tx;
    }

    public double y(double u, double v) {
        return m10 * u + m11 * v + ty;
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

    /** {@code this} after {@code first}: first applies first, then this. */
    public Isometry2 after(Isometry2 first) {
        double a = m00 * first.m00 + m01 * first.m10;
        double b = m00 * first.m01 + m01 * first.m11;
        double c = m10 * first.m00 + m11 * first.m10;
        double d = m10 * first.m01 + m11 * first.m11;
        double x = m00 * first.tx + m01 * first.ty + tx;
        double y = m10 * first.tx + m11 * first.ty + ty;
        // Renormalise: the first column to unit length, the second perpendicular to it with
        // the sign it has (rotation or mirror), so that rounding never builds up into a stretch.
        double length = Math.hypot(a, c);
        a /= length;
        c /= length;
        boolean mirror = a * d - b * c < 0;
        b = mirror ? c : -c;
        d = mirror ? -a : a;
        return new Isometry2(a, b, c, d, x, y);
    }

    public Isometry2 inverse() {
        // M is orthogonal: its inverse is its transpose.
        return new Isometry2(m00, m10, m01, m11, -(m00 * tx + m10 * ty), -(m01 * tx + m11 * ty));
    }

    @Override
    public String toString() {
        return "Isometry2[" + m00 + " " + m01 + " " + tx + "; " + m10 + " " + m11 + " " + ty + "]";
    }
}
