package ifold.zigzag;

import ifold.fold.FlapFold;
import ifold.fold.Fold;
import ifold.fold.FoldException;
import ifold.fold.Folder;
import ifold.fold.Paper;
import ifold.fold.PaperMotion;
import ifold.fold.Press;
import ifold.geom.SlantedEdges;
import ifold.geom.Tolerance;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.joml.Matrix4d;
import org.joml.Matrix4dc;
import org.joml.Vector3d;

/**
 * Covers a triangle with a strip of paper, the zig-zag way (the seed, section 2.2, after Demaine,
 * Demaine and Mitchell), and hides the excess under it.
 *
 * <p>In the plan frame of the start corner S (see {@link Triangle}) the edge opposite S, from P to
 * Q, lies on the x-axis and S at height h. The strip, of width w, lies in passes parallel to PQ:
 * pass i covers the band {@code h - (i+1)w <= y <= h - iw}, so the first pass holds S and there are
 * k = ⌈h/w⌉ passes; where h is not a multiple of w the last pass overlaps the edge PQ and its
 * excess is tucked under with the rest. Each pass runs from just beyond one slanted edge to just
 * beyond the other (a margin m past the farthest point of the edge over the turn's height), and
 * turns there with a pair of 45° folds: a valley fold lays the strip back across itself, running
 * along the edge, and a mountain fold one strip width further on lays it flat beside the pass it
 * left, running back. The two creases meet on the strip's inner edge, and every pass lies front
 * up at the height of the first; only the turns, outside the triangle, hold two layers.
 *
 * <p>The strip ends at the wanted corner by parity. Where the first pass may run either way it is
 * chosen so that the last one runs towards the wanted end. Where the strip comes in from a given
 * side (as it does on a polyhedron, from the triangle before), a last pass running the wrong way
 * is overlapped: a fold across the strip lays it back over itself, and it ends at the other
 * corner (Figure 5).
 *
 * <p>The excess, all of it outside the triangle, is then tucked under by the naïve method of the
 * seed: a mountain fold through all layers along the edge with paper farthest beyond it, again
 * and again until no paper lies outside. A tuck reflects the paper beyond an edge's line onto its
 * inner side, so a point s beyond it comes closer to the incentre (its squared distance drops by
 * 4rs, r the inradius) and tucks never cycle. Near a corner of angle θ, though, paper beyond one
 * of its edges lands beyond the other and is reflected back and forth about π/θ times, and every
 * tuck cuts all the layers its line crosses: a flat triangle with two sharp corners may need
 * more than {@link #MAX_TUCKS} tucks or {@link #MAX_FACES} faces, and that is an error, not a
 * silent result (in the tests, triangles with no angle under 10 degrees, and needles started at
 * their tip, finish; see docs/zigzag.md). The strip's length is bounded by the passes' lengths:
 * <pre>
 *   L  &lt;=  Σ_{i&lt;k} c(h - (i+2)w)  +  k·(2m + 2w + 3w·(|cot P| + |cot Q|))
 *           +  (overlapped ? |PQ| + 2m + w·(|cot P| + |cot Q|) : 0)
 * </pre>
 * where c(y) = |PQ|·(1 - max(0, y)/h) is the triangle's chord at height y: a pass spans the chord
 * at the lowest height of its two turns (3w of height at most, over which a slanted edge moves
 * sideways by 3w·|cot| of its angle) plus the margins, and each turn adds 2w of strip. As Σ c is
 * about area / w, the paper efficiency area / (L·w) tends to 1 as the strip narrows. A test checks
 * the bound on random triangles.
 */
public final class ZigZag {
    /** The most tucks before giving up: a few per edge suffice unless two corners are sharp (see the class notes). */
    public static final int MAX_TUCKS = 60;

    /** The most paper faces the tucks may make before giving up: tucking cuts through every layer. */
    public static final int MAX_FACES = 100_000;

    private ZigZag() {
    }

    /**
     * What to wrap and how.
     *
     * @param width the strip's width w, positive
     * @param thickness the paper's thickness, zero or more
     * @param start the corner (0, 1, 2 for A, B, C) the strip starts at
     * @param end the corner it ends at: one of the other two
     * @param enterFrom the corner on whose side the first pass begins, one of the other two; or
     *     -1 to let the planner choose so that no pass is overlapped
     */
    public record Options(double width, double thickness, int start, int end, int enterFrom) {
        public Options {
            if (!(width > 0) || !Double.isFinite(width)) {
                throw new IllegalArgumentException("the strip width must be a positive number, got " + width);
            }
            if (!(thickness >= 0) || !Double.isFinite(thickness)) {
                throw new IllegalArgumentException("the thickness must be zero or more, got " + thickness);
            }
            if (start < 0 || start > 2 || end < 0 || end > 2) {
                throw new IllegalArgumentException("corners are A, B or C");
            }
            if (start == end) {
                throw new IllegalArgumentException("the strip must end at another corner than its start "
                        + Triangle.name(start));
            }
            if (enterFrom != -1 && (enterFrom < 0 || enterFrom > 2 || enterFrom == start)) {
                throw new IllegalArgumentException("the strip comes in beside one of the corners other than the start "
                        + Triangle.name(start));
            }
        }
    }

    /** Which part of the method a fold belongs to. */
    public enum Phase { ZIGZAG, OVERLAP, TUCK, PRESS }

    /**
     * One fold of the plan.
     *
     * @param phase what it is for
     * @param description a line for the status bar
     * @param motion the fold, cut and ready to turn; or the press
     */
    public record Step(Phase phase, String description, PaperMotion motion) {
    }

    /**
     * The plan and the folds it makes.
     *
     * @param triangle the triangle
     * @param options what was asked
     * @param start the flat strip, placed along the first pass
     * @param steps the folds in order
     * @param passes how many passes the strip makes (the overlapping one included)
     * @param overlapped whether the last pass is laid back over itself to end at the wanted corner
     * @param length the strip's length L
     * @param margin how far beyond the edges the strip turns
     * @param planToSpace the plan frame's placement in space
     */
    public record Result(Triangle triangle, Options options, Paper start, List<Step> steps, int passes, boolean overlapped,
            double length, double margin, Matrix4dc planToSpace) {

        /** The paper folded to the end. */
        public Paper folded() {
            return steps.isEmpty() ? start : steps.get(steps.size() - 1).motion().at(1);
        }

        /** The paper after the folds of the zig-zag (and overlap), before any tuck. */
        public Paper laid() {
            for (int i = steps.size() - 1; i >= 0; i--) {
                Phase phase = steps.get(i).phase();
                if (phase == Phase.ZIGZAG || phase == Phase.OVERLAP) {
                    return steps.get(i).motion().at(1);
                }
            }
            return start;
        }

        public int count(Phase phase) {
            return (int) steps.stream().filter(s -> s.phase() == phase).count();
        }
    }

    /**
     * Plans the zig-zag and makes its folds.
     *
     * @throws FoldException if a fold cannot be made, or the tucks do not finish within {@link #MAX_TUCKS}
     */
    public static Result wrap(Triangle triangle, Options options) throws FoldException {
        int s = options.start();
        int p = (s + 1) % 3;
        int q = (s + 2) % 3;
        double[] plan = triangle.inPlan(s);
        double base = plan[2];
        double sx = plan[4];
        double h = plan[5];
        double w = options.width();
        double t = options.thickness();
        SlantedEdges edges = new SlantedEdges(base, sx, h);
        int passes = Math.max(1, (int) Math.ceil(h / w - 1e-9));
        // Just beyond the edges: far enough to see, and to clear the caps of the turns.
        double margin = Math.max(w / 10, 2 * t);

        int wantLast = options.end() == q ? 1 : -1;
        int lastIfFirstRight = (passes % 2 == 1) ? 1 : -1;
        int firstDirection;
        if (options.enterFrom() < 0) {
            firstDirection = wantLast * lastIfFirstRight;
        } else {
            firstDirection = options.enterFrom() == p ? 1 : -1;
        }
        boolean overlapped = firstDirection * lastIfFirstRight != wantLast;

        // Walk the strip: each pass maps paper u to plan x as x = x0 + d (u - u0).
        List<FlapFold> folds = new ArrayList<>();
        List<String> names = new ArrayList<>();
        int d = firstDirection;
        double top = h - w;
        double x0 = d > 0 ? edges.leftmost(top, h) - margin : edges.rightmost(top, h) + margin;
        double startX = x0;
        double u0 = 0;
        for (int i = 0; i + 1 < passes; i++) {
            double y0 = h - (i + 1) * w;
            double x1 = d > 0 ? edges.rightmost(y0 - w, y0 + w) + margin : edges.leftmost(y0 - w, y0 + w) - margin;
            double uA = u0 + d * (x1 - x0);
            double vUpper = d > 0 ? w : 0;
            double vLower = w - vUpper;
            folds.add(beyond(Fold.Kind.VALLEY, uA, vUpper, uA + w, vLower));
            names.add(String.format(Locale.ROOT, "pass %d of %d: turn, 45° valley fold", i + 1, passes));
            folds.add(beyond(Fold.Kind.MOUNTAIN, uA + w, vLower, uA + 2 * w, vUpper));
            names.add(String.format(Locale.ROOT, "pass %d of %d: turn, 45° mountain fold", i + 1, passes));
            u0 = uA + 2 * w;
            x0 = x1;
            d = -d;
        }
        double last = h - passes * w;
        double endX = d > 0 ? edges.rightmost(last, last + w) + margin : edges.leftmost(last, last + w) - margin;
        double length = u0 + d * (endX - x0);
        if (overlapped) {
            folds.add(beyond(Fold.Kind.VALLEY, length, 0, length, w));
            names.add("overlap: the last pass folded back over itself, to end at " + Triangle.name(options.end()));
            double backX = d > 0 ? edges.leftmost(last, last + w) - margin : edges.rightmost(last, last + w) + margin;
            length += Math.abs(endX - backX);
        }

        // Place the flat strip along the first pass, top side up, then in space.
        Matrix4d planToSpace = triangle.planToSpace(s);
        Matrix4d placement = new Matrix4d(planToSpace);
        if (firstDirection > 0) {
            placement.translate(startX, top, 0);
        } else {
            placement.translate(startX, h, 0).rotateZ(Math.PI);
        }
        Paper paper = Paper.strip(length, w, t).moved(placement);
        Paper start = paper;
        List<Step> steps = new ArrayList<>();
        for (int i = 0; i < folds.size(); i++) {
            Folder.Prepared prepared = Folder.prepare(paper, folds.get(i));
            Phase phase = overlapped && i == folds.size() - 1 ? Phase.OVERLAP : Phase.ZIGZAG;
            steps.add(new Step(phase, names.get(i), prepared));
            paper = prepared.at(1);
        }
        tuck(triangle, s, planToSpace, paper, steps);
        return new Result(triangle, options, start, List.copyOf(steps), passes + (overlapped ? 1 : 0), overlapped, length,
                margin, planToSpace);
    }

    /** A flap fold of 180° along the crease through two paper points, the strip beyond it (larger u) moving. */
    private static FlapFold beyond(Fold.Kind kind, double u1, double v1, double u2, double v2) {
        // Right of the line, on the sheet seen from its top, is the direction (v2 - v1, u1 - u2).
        Fold.Side side = (v2 - v1) > 0 ? Fold.Side.RIGHT : Fold.Side.LEFT;
        return new FlapFold(kind, 180, u1, v1, u2, v2, side);
    }

    /** Mountain folds along the edges, the one with paper farthest beyond it first, until none sticks out. */
    private static void tuck(Triangle triangle, int start, Matrix4dc planToSpace, Paper paper, List<Step> steps)
            throws FoldException {
        Matrix4d toPlan = planToSpace.invert(new Matrix4d());
        double[] plan = triangle.inPlan(start);
        double scale = Math.max(triangle.opposite(0), Math.max(triangle.opposite(1), triangle.opposite(2)));
        // Paper closer to an edge's line than the fold engine's tolerance lies on it for a fold:
        // a tuck could not move it, and it is not outside.
        double tolerance = 2 * Tolerance.ON_PLANE * Math.max(scale, paper.size());
        double base = new Vector3d(triangle.corner(0)).dot(triangle.normal());
        for (int tucks = 0; ; tucks++) {
            int edge = -1;
            double farthest = tolerance;
            for (int e = 0; e < 3; e++) {
                double beyond = Outside.farthestBeyondEdge(paper, toPlan, plan, e);
                if (beyond > farthest) {
                    farthest = beyond;
                    edge = e;
                }
            }
            if (edge < 0) {
                return;
            }
            if (tucks == MAX_TUCKS || paper.faceCount() > MAX_FACES) {
                throw new FoldException(String.format(Locale.ROOT, "the excess is not hidden after %d tucks (%d faces): "
                        + "the naive tuck-under bounces paper between the edges of a corner as sharp as %.1f degrees; "
                        + "the tests finish every triangle with no angle under 10 (docs/zigzag.md)",
                        tucks, paper.faceCount(), triangle.smallestAngle()));
            }
            // Plan corners P, Q, S in order are counter-clockwise: the outside of edge e is on its right.
            int from = (start + 1 + edge) % 3;
            int to = (start + 2 + edge) % 3;
            Vector3d a = new Vector3d(triangle.corner(from));
            Vector3d b = new Vector3d(triangle.corner(to));
            Folder.Prepared prepared = Folder.prepare(paper, Fold.through(Fold.Kind.MOUNTAIN, 180, a, b, Fold.Side.RIGHT));
            steps.add(new Step(Phase.TUCK, String.format(Locale.ROOT, "tuck %d: mountain fold under along edge %s%s",
                    tucks + 1, Triangle.name(from), Triangle.name(to)), prepared));
            paper = prepared.at(1);
            Press.Pressed pressed = Press.press(paper, base);
            if (pressed.moved() > 0) {
                steps.add(new Step(Phase.PRESS, String.format(Locale.ROOT, "tuck %d: layers pressed flat", tucks + 1), pressed));
                paper = pressed.after();
            }
        }
    }
}
