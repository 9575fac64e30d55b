package ifold.wrap;

import static ifold.wrap.Wrap.position;
import static ifold.wrap.Wrap.cornersText;
import static ifold.wrap.Wrap.sq;

import ifold.geom.Tolerance;
import ifold.mesh.IndexedPolygons;
import ifold.refine.FacePreparation;
import ifold.sheet.HostFrame;
import ifold.wrap.Wrap.Ends;
import ifold.wrap.Wrap.TooWideException;
import ifold.wrap.Wrap.WrapException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleToLongFunction;

/**
 * How every triangle of one path is entered and left, and the planning of it: each triangle
 * entered at the corner opposite the edge it shares with the next and left by the end of that
 * edge not on the next one, its frame, how many passes a width gives it and which way they run,
 * and the faces of paper a width is likely to make ({@link Wrap} wraps the paths so planned).
 */
final class PathPlan {
    int first;
    int m;
    int[][] corners;
    /** Start corner of each triangle (a vertex id). */
    int[] start;
    /** The shared edge with the next triangle, as two vertex ids. */
    int[][] shared;
    HostFrame[] frames;
    /** Vertex ids at the frame's origin (x axis start) and at the end of the base. */
    int[] baseFrom;
    int[] baseTo;
    /** For a lone triangle: the ends asked, or null. */
    Ends ends;

    static List<PathPlan> plans(IndexedPolygons path, int[] componentStart, Ends ends) {
        List<PathPlan> plans = new ArrayList<>();
        for (int c = 0; c + 1 < componentStart.length; c++) {
            int m = componentStart[c + 1] - componentStart[c];
            if (ends != null && m != 1) {
                throw new IllegalArgumentException("the ends of a strip are asked for paths of one triangle only; this one has " + m);
            }
            plans.add(planCorners(path, componentStart[c], m, ends));
        }
        return plans;
    }

    /** {the widest strip the paths take, the triangle (refined mesh index) that sets it}. */
    static double[] narrowest(IndexedPolygons mesh, List<PathPlan> plans) {
        double widest = Double.POSITIVE_INFINITY;
        int narrowest = -1;
        for (PathPlan plan : plans) {
            for (int i = 0; i < plan.m; i++) {
                double h = i + 1 < plan.m || plan.m == 1 ? plan.frames[i].altitude() : lastAltitudeBound(mesh, plan);
                if (h < widest) {
                    widest = h;
                    narrowest = plan.first + i;
                }
            }
        }
        return new double[] {widest, narrowest};
    }

    /** Start corners and frames of every triangle of one path but the last's (which depends on the width). */
    static PathPlan planCorners(IndexedPolygons mesh, int first, int m, Ends ends) {
        PathPlan plan = new PathPlan();
        plan.ends = ends;
        plan.first = first;
        plan.m = m;
        plan.corners = new int[m][3];
        for (int i = 0; i < m; i++) {
            for (int k = 0; k < 3; k++) {
                plan.corners[i][k] = mesh.faceVertex(first + i, k);
            }
        }
        plan.shared = new int[Math.max(0, m - 1)][];
        for (int i = 0; i + 1 < m; i++) {
            plan.shared[i] = sharedEdge(plan.corners[i], plan.corners[i + 1]);
            if (plan.shared[i] == null) {
                throw new IllegalStateException("path triangles " + (first + i) + " and " + (first + i + 1) + " share no edge");
            }
        }
        plan.start = new int[m];
        plan.frames = new HostFrame[m];
        plan.baseFrom = new int[m];
        plan.baseTo = new int[m];
        if (m == 1) {
            plan.start[0] = ends != null ? plan.corners[0][ends.start()] : oppositeLongestEdge(mesh, plan.corners[0]);
            frame(mesh, plan, 0);
            return plan;
        }
        plan.start[0] = third(plan.corners[0], plan.shared[0]);
        for (int i = 0; i + 1 < m; i++) {
            if (plan.start[i] != third(plan.corners[i], plan.shared[i])) {
                throw new IllegalStateException("triangle " + (first + i) + " is not entered opposite its exit edge");
            }
            frame(mesh, plan, i);
            if (i + 2 < m) {
                // Leave by the end of E_i that is not on E_{i+1}: the next triangle is then entered opposite its exit.
                int[] next = plan.shared[i + 1];
                int[] edge = plan.shared[i];
                plan.start[i + 1] = edge[0] == next[0] || edge[0] == next[1] ? edge[1] : edge[0];
            }
        }
        return plan;
    }

    /** The frame of path triangle i: its base (the exit edge, or the edge opposite its start) on the x axis, directed as the triangle runs. */
    static void frame(IndexedPolygons mesh, PathPlan plan, int i) {
        int[] c = plan.corners[i];
        int s = plan.start[i];
        int k = s == c[0] ? 0 : s == c[1] ? 1 : 2;
        int from = c[(k + 1) % 3];
        int to = c[(k + 2) % 3];
        plan.baseFrom[i] = from;
        plan.baseTo[i] = to;
        plan.frames[i] = HostFrame.onEdge(position(mesh, from), position(mesh, to), position(mesh, s));
    }

    /** For the bound on the default width: the smaller altitude of the last triangle over both ends it may be entered by. */
    static double lastAltitudeBound(IndexedPolygons mesh, PathPlan plan) {
        int last = plan.m - 1;
        double bound = Double.POSITIVE_INFINITY;
        for (int s : plan.shared[last - 1]) {
            plan.start[last] = s;
            frame(mesh, plan, last);
            bound = Math.min(bound, plan.frames[last].altitude());
        }
        return bound;
    }

    /**
     * The last triangle may be entered by either end of the edge before it: the one the passes
     * of the triangle before lead to, when it takes the width, so that no pass is run twice.
     */
    static void chooseLastStart(IndexedPolygons mesh, PathPlan plan, double width, double widest, double[] angleSums)
            throws WrapException {
        if (plan.m == 1) {
            if (plan.frames[0].altitude() < width * (1 - 1e-12)) {
                throw new TooWideException(tooWide(mesh, plan.first, 0, 1, width, plan.frames[0].altitude(), widest));
            }
            return;
        }
        int before = plan.m - 2;
        HostFrame frame = plan.frames[before];
        int passes = passes(frame.altitude(), width);
        int lastDirection = firstDirection(plan, before, width) * (passes % 2 == 1 ? 1 : -1);
        int preferred = lastDirection > 0 ? plan.baseTo[before] : plan.baseFrom[before];
        int other = preferred == plan.baseTo[before] ? plan.baseFrom[before] : plan.baseTo[before];
        if (sharpCorner(mesh, plan, preferred, angleSums) && !sharpCorner(mesh, plan, other, angleSums)) {
            // Not entered at a sharp vertex: the triangle before would leave by it, its last pass,
            // the fold back and this one's first pass each reaching round the vertex with a side
            // of the strip, about 180°/θ layers each where tucks bounce them in a corner of θ (on
            // the shared spike, 217 layers by its apex against 81); the triangle before takes a
            // pass more instead (StripFolding's evenedUp), its last pass running away from it.
            int swap = preferred;
            preferred = other;
            other = swap;
        } else if (!alongNeedle(mesh, plan, preferred) && alongNeedle(mesh, plan, other)) {
            // Entered so that its base runs along a needle's edge from its tip, the strip's end
            // rolled round the tip (ApexRoll.needleEnd); entered at the tip, its passes crossed
            // the needle there, each side of the strip about 180°/θ layers (a closed square
            // pyramid's 3° needle: 68). The triangle before takes a pass more (evenedUp).
            int swap = preferred;
            preferred = other;
            other = swap;
        }
        int last = plan.m - 1;
        for (int s : new int[] {preferred, other}) {
            plan.start[last] = s;
            frame(mesh, plan, last);
            if (plan.frames[last].altitude() >= width * (1 - 1e-12)) {
                return;
            }
        }
        throw new TooWideException(tooWide(mesh, plan.first + last, last, plan.m, width, plan.frames[last].altitude(), widest));
    }

    /**
     * Whether the last triangle of {@code plan}, entered at vertex s, has its base along a needle's
     * edge from its tip, where the strip's end is rolled ({@link ApexRoll#needleEnd}).
     */
    private static boolean alongNeedle(IndexedPolygons mesh, PathPlan plan, int s) {
        int[] c = plan.corners[plan.m - 1];
        int k = s == c[0] ? 0 : s == c[1] ? 1 : 2;
        int a = c[(k + 1) % 3];
        int b = c[(k + 2) % 3];
        return ApexRoll.needleEnd(mesh, c, a, b) || ApexRoll.needleEnd(mesh, c, b, a);
    }

    /**
     * Whether the last triangle of {@code plan} has a true sharp corner at vertex v, an end of the
     * edge before it: v is a sharp vertex ({@link LayerFloor#sharp}) and the triangle's angle
     * there is under the preparation's target, which no preparation widens (a lone flat
     * triangle's corners, of 50° and more, are sharp vertices but not such corners).
     */
    private static boolean sharpCorner(IndexedPolygons mesh, PathPlan plan, int v, double[] angleSums) {
        if (!LayerFloor.sharp(angleSums[v])) {
            return false;
        }
        int[] c = plan.corners[plan.m - 1];
        int k = v == c[0] ? 0 : v == c[1] ? 1 : 2;
        double angle = LayerFloor.angle(mesh, v, c[(k + 1) % 3], c[(k + 2) % 3]);
        return Math.toDegrees(angle) < FacePreparation.TARGET_ANGLE;
    }

    /**
     * The faces of paper the paths make at {@code width}, from the passes each triangle takes:
     * the fewest, or ({@code likely}) about as many as they are likely to make, for a width to
     * suggest. A triangle sharing its host with others lays at least 2 faces a pass (each turn
     * between two passes and its turn gadget lay two; likely 3 a pass and 30 a triangle); one
     * alone on its host at least 3 a pass and 6 besides (its crossing and its tucks cut more;
     * likely 5 and 25). A floor: a wrap refused by it could never fit. Measured over the models
     * and widths from the widest to a thirtieth of it: 2.3 to 11 a pass, and beyond 2 a pass, 5
     * to 320 a triangle on shared hosts; 4.3 to 15 a pass, 12 to 290 a triangle alone.
     */
    static long faces(List<PathPlan> plans, double width, boolean[] alone, boolean likely) {
        long faces = 0;
        for (PathPlan plan : plans) {
            for (int i = 0; i < plan.m; i++) {
                long k = passes(plan.frames[i].altitude(), width);
                boolean lone = alone[plan.first + i];
                faces += likely ? likelyFaces(k, lone) : lone ? 3 * k + 6 : 2 * k;
            }
        }
        return faces;
    }

    /** The faces a triangle of {@code k} passes likely makes, alone on its host or not (see {@link #faces}). */
    static long likelyFaces(long k, boolean alone) {
        return alone ? 5 * k + 25 : 3 * k + 30;
    }

    /**
     * The narrowest strip, between {@code width} and {@code widest}, likely to stay within
     * {@code limit} faces, to the nearest 0.1 %; NaN when even the widest is not.
     */
    static double narrowestFitting(List<PathPlan> plans, boolean[] alone, double width, double widest, int limit) {
        return narrowestFitting(w -> faces(plans, w, alone, true), width, widest, limit);
    }

    /**
     * The narrowest strip, between {@code width} and {@code widest}, whose {@code likely} faces
     * stay within {@code limit}, to the nearest 0.1 %; NaN when even the widest's do not.
     */
    static double narrowestFitting(DoubleToLongFunction likely, double width, double widest, int limit) {
        if (!(widest > width) || likely.applyAsLong(widest) > limit) {
            return Double.NaN;
        }
        double low = width;
        double high = widest;
        while (high > low * 1.001) {
            double middle = Math.sqrt(low * high);
            if (likely.applyAsLong(middle) > limit) {
                low = middle;
            } else {
                high = middle;
            }
        }
        return high;
    }

    static int passes(double h, double width) {
        return Math.max(1, (int) Math.ceil(h / width - Tolerance.RELATIVE_EQUALITY));
    }

    /**
     * The direction (+1 along the frame's x axis, -1 against) of triangle i's first pass: away
     * from the edge the strip comes in over; on the first triangle, so that the last pass runs
     * towards the end the strip leaves by.
     */
    static int firstDirection(PathPlan plan, int i, double width) {
        if (i > 0) {
            int[] entry = plan.shared[i - 1];
            int other = entry[0] == plan.start[i] ? entry[1] : entry[0];
            return other == plan.baseFrom[i] ? 1 : -1;
        }
        if (plan.m == 1 && plan.ends != null) {
            Ends ends = plan.ends;
            int wantLast = lastDirectionToEnd(plan);
            int lastIfFirstPositive = passes(plan.frames[0].altitude(), width) % 2 == 1 ? 1 : -1;
            if (ends.enterFrom() < 0) {
                return wantLast * lastIfFirstPositive;
            }
            return plan.corners[0][ends.enterFrom()] == plan.baseFrom[0] ? 1 : -1;
        }
        if (plan.m <= 2) {
            return 1; // the end it leaves by is free (or there is none): it is chosen to fit
        }
        int passes = passes(plan.frames[0].altitude(), width);
        int exit = plan.start[1];
        int towardsExit = exit == plan.baseTo[0] ? 1 : -1;
        return towardsExit * (passes % 2 == 1 ? 1 : -1);
    }

    /** For a lone triangle with its ends asked: the direction its last pass must run to end at the corner asked. */
    static int lastDirectionToEnd(PathPlan plan) {
        return plan.corners[0][plan.ends.end()] == plan.baseTo[0] ? 1 : -1;
    }

    /**
     * Whether the last pass of a lone triangle is laid back over itself: its first pass was
     * set by the side the strip comes in from, and the parity of the passes then brings the
     * last one away from the end asked.
     */
    static boolean overlapped(PathPlan plan, double width) {
        if (plan.m != 1 || plan.ends == null) {
            return false;
        }
        int lastIfFirstPositive = passes(plan.frames[0].altitude(), width) % 2 == 1 ? 1 : -1;
        return firstDirection(plan, 0, width) * lastIfFirstPositive != lastDirectionToEnd(plan);
    }

    static int[] sharedEdge(int[] a, int[] b) {
        int[] shared = new int[2];
        int n = 0;
        for (int x : a) {
            for (int y : b) {
                if (x == y && n < 2) {
                    shared[n++] = x;
                }
            }
        }
        return n == 2 ? shared : null;
    }

    static int third(int[] corners, int[] edge) {
        for (int v : corners) {
            if (v != edge[0] && v != edge[1]) {
                return v;
            }
        }
        throw new IllegalStateException("a triangle with a repeated corner");
    }

    static int oppositeLongestEdge(IndexedPolygons mesh, int[] c) {
        int best = c[0];
        double longest = -1;
        for (int k = 0; k < 3; k++) {
            double[] a = position(mesh, c[(k + 1) % 3]);
            double[] b = position(mesh, c[(k + 2) % 3]);
            double length = Math.sqrt(sq(a[0] - b[0]) + sq(a[1] - b[1]) + sq(a[2] - b[2]));
            if (length > longest) {
                longest = length;
                best = c[k];
            }
        }
        return best;
    }

    /**
     * Why {@code width} is refused at a triangle, and the width every triangle takes: the first
     * triangle found too narrow need not be the narrowest, and a width it takes may still be
     * refused further on.
     */
    static String tooWide(IndexedPolygons mesh, int triangle, int pathIndex, int m, double width, double altitude,
            double widest) {
        return String.format(Locale.ROOT, "the strip width %s is too wide for triangle %d of %d on the path (%s): "
                + "its passes need a width of at most %s, and the whole path one of at most %s", width, pathIndex + 1, m,
                cornersText(mesh, triangle), altitude, widest);
    }
}
