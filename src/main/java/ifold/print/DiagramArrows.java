package ifold.print;

import java.io.IOException;

/**
 * The arrows of origami diagrams (Yoshizawa–Randlett), drawn on a panel: a fold's motion as an
 * arc from where the flap lies to where it lands, with a full head for a valley fold and a
 * hollow half head for a mountain fold; and the turn-over symbol, a looped arrow, where the view
 * shows the paper's other side.
 */
final class DiagramArrows {
    /** The shortest arrow drawn, in millimetres on the page: a small flap's is stretched to it. */
    static final double SHORTEST = 6;
    /** Shorter moves than this say nothing: the flap moves towards the eye. */
    private static final double NOTHING = 0.05;
    /** How far the arc bulges from its chord, as a share of the chord. */
    private static final double BULGE = 0.3;
    private static final int SEGMENTS = 16;

    private DiagramArrows() {
    }

    /**
     * The arc from {@code start} to {@code end} (points on the page, mm), bulging to the side
     * where {@code middle} (the flap half way) lies, or upwards where it lies on the chord.
     *
     * @return whether an arrow was drawn (not where the flap moves straight towards the eye)
     */
    static boolean fold(Canvas canvas, double[] start, double[] middle, double[] end, boolean valley) throws IOException {
        double dx = end[0] - start[0];
        double dy = end[1] - start[1];
        double length = Math.hypot(dx, dy);
        if (!(length > NOTHING)) {
            return false;
        }
        if (length < SHORTEST) {
            // A small flap's arrow, drawn as long as can be read: stretched about its middle, it
            // still starts on the flap's side of the crease and ends on the other.
            double grow = SHORTEST / length;
            double mx = (start[0] + end[0]) / 2;
            double my = (start[1] + end[1]) / 2;
            start = new double[] {mx - grow * dx / 2, my - grow * dy / 2};
            end = new double[] {mx + grow * dx / 2, my + grow * dy / 2};
            middle = new double[] {mx + grow * (middle[0] - mx), my + grow * (middle[1] - my)};
            dx *= grow;
            dy *= grow;
            length = SHORTEST;
        }
        double nx = -dy / length;
        double ny = dx / length;
        double off = (middle[0] - (start[0] + end[0]) / 2) * nx + (middle[1] - (start[1] + end[1]) / 2) * ny;
        double side = Math.abs(off) > 0.05 * length ? Math.signum(off) : (ny < 0 ? 1 : -1);
        // A quadratic Bezier whose control point lies twice the bulge out: its middle is a bulge out.
        double cx = (start[0] + end[0]) / 2 + side * nx * 2 * BULGE * length;
        double cy = (start[1] + end[1]) / 2 + side * ny * 2 * BULGE * length;
        double px = start[0];
        double py = start[1];
        for (int i = 1; i <= SEGMENTS; i++) {
            double t = (double) i / SEGMENTS;
            double qx = (1 - t) * (1 - t) * start[0] + 2 * t * (1 - t) * cx + t * t * end[0];
            double qy = (1 - t) * (1 - t) * start[1] + 2 * t * (1 - t) * cy + t * t * end[1];
            canvas.line(px, py, qx, qy, Ink.ARROW);
            px = qx;
            py = qy;
        }
        head(canvas, end, end[0] - cx, end[1] - cy, Math.min(3, 0.3 * length), valley ? 0 : side);
        return true;
    }

    /**
     * An arrow's head at {@code tip}, pointing along (dx, dy): a filled head (half 0), or a hollow
     * half head on the side {@code half} (+1 or -1 of the normal), the mountain fold's.
     */
    private static void head(Canvas canvas, double[] tip, double dx, double dy, double size, double half) throws IOException {
        double length = Math.hypot(dx, dy);
        double ux = dx / length;
        double uy = dy / length;
        double bx = tip[0] - size * ux;
        double by = tip[1] - size * uy;
        double wx = -uy * 0.45 * size;
        double wy = ux * 0.45 * size;
        if (half == 0) {
            canvas.fill(new double[] {tip[0], tip[1], bx + wx, by + wy, bx - wx, by - wy}, 0xFF000000);
            return;
        }
        // The barb on the arc's outer side, so that it stands clear of the paper.
        canvas.outline(new double[] {tip[0], tip[1], bx + half * wx, by + half * wy, bx, by}, Ink.ARROW);
    }

    /** The turn-over symbol, centred at (x, y), {@code radius} mm: a loop of arrow, open at the top, with its head, and the words. */
    static void turnOver(Canvas canvas, double x, double y, double radius) throws IOException {
        int segments = 20;
        double from = Math.toRadians(-60);
        double to = Math.toRadians(240);
        double px = x + radius * Math.cos(from);
        double py = y - radius * Math.sin(from);
        for (int i = 1; i <= segments; i++) {
            double a = from + (to - from) * i / segments;
            double qx = x + radius * Math.cos(a);
            double qy = y - radius * Math.sin(a);
            canvas.line(px, py, qx, qy, Ink.ARROW);
            px = qx;
            py = qy;
        }
        // The head along the loop's tangent at its end (anticlockwise on the page).
        double[] tip = {px, py};
        head(canvas, tip, -Math.sin(to), -Math.cos(to), 0.8 * radius, 0);
        canvas.text(x - radius - 0.5, y + radius + 3.2, 2.4, "turn over", false);
    }
}
