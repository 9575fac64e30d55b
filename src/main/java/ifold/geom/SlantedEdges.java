package ifold.geom;

/**
 * A triangle in the plan frame of the zig-zag method: its base on the x axis from (0, 0) to
 * (base, 0), its apex at (sx, h). The passes run parallel to the base and turn beyond the two
 * slanted edges, the left one from (0, 0) to the apex and the right one from (base, 0) to it;
 * this gives where those edges are, over the heights a pass or a turn spans.
 *
 * @param base the base's length
 * @param sx the apex's x
 * @param h the apex's height, positive
 */
public record SlantedEdges(double base, double sx, double h) {
    /** x of the left edge at height y. */
    public double left(double y) {
        return sx * y / h;
    }

    /** x of the right edge at height y. */
    public double right(double y) {
        return base + (sx - base) * y / h;
    }

    /** The smallest x of the left edge over heights [from, to] clipped to the triangle's. */
    public double leftmost(double from, double to) {
        double lo = Math.max(0, from);
        double hi = Math.min(h, to);
        return Math.min(left(lo), left(hi));
    }

    /** The largest x of the right edge over heights [from, to] clipped to the triangle's. */
    public double rightmost(double from, double to) {
        double lo = Math.max(0, from);
        double hi = Math.min(h, to);
        return Math.max(right(lo), right(hi));
    }
}
