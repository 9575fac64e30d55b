package ifold.wrap;

import ifold.geom.SlantedEdges;
import ifold.geom.Tolerance;
import ifold.geom.Triangle;
import ifold.mesh.IndexedPolygons;
import ifold.refine.HamiltonianRefinement;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Sheet.Crease;
import ifold.sheet.Sheet.Placement;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Locale;

/**
 * Wraps a surface in one strip of paper per component, along the Hamiltonian path of its
 * refinement (Demaine, Demaine and Mitchell; the seed, section 2.5): the zig-zag method on every
 * triangle, a turn gadget and a fold over the shared edge to the next, and the excess tucked
 * under. The paper rests on hosts, the flat convex pieces of the surface ({@link HostPieces}):
 * the strip runs flat over the edges inside one and folds over the edges between two, and what
 * reaches past a host's edges is tucked under it once the strip leaves it.
 *
 * <p><b>Corners.</b> Each triangle t_i of a path is entered at the corner s_i opposite the edge
 * E_i it shares with t_{i+1}, so its passes run parallel to E_i and its last pass lies along E_i.
 * It leaves by the end e_i of E_i that is not on E_{i+1}; then s_{i+1} = e_i is again opposite
 * E_{i+1}, and every triangle of the path is entered the same way (the first at the corner
 * opposite E_0; the last leaves nowhere, its base is the edge opposite its start).
 *
 * <p><b>Passes.</b> In the frame of t_i, E_i on the x axis and s_i at height h, the first pass is
 * the band [h - w, h] and the last the band [0, w]; those between lie one strip width apart,
 * turning just beyond the slanted edges with a pair of 45° folds. Where h is not a multiple of
 * w, the last turn must shift the strip by less than a width, which two folds that keep the top
 * side up cannot do (they would have to cross inside the strip); that turn is two 90° turn
 * gadgets, four folds. The last triangle's passes all lie a width apart, the last one over its
 * base, and its excess is tucked like the rest.
 *
 * <p><b>From triangle to triangle.</b> Unfold t_{i+1} about E_i into t_i's plane: its first pass
 * is a band B that crosses E_i inside the edge (its top edge passes through s_{i+1} = e_i, and
 * w is at most its altitude), and it reaches back across E_i into t_i. The strip runs along
 * the last pass, folds back across itself beyond the slanted edge (valley), and a second fold
 * along the line that reflects the band [0, w] onto B sends it along B, top side up again: a
 * turn gadget whose creases both lie in the band [0, w] of t_i. Then the tail is folded over
 * E_i into t_{i+1}'s plane. The same two folds serve when the parity of the passes brings the
 * last one towards the wrong end of E_i: the fold back is then beyond the other slanted edge,
 * and the strip runs back over the whole last pass before it turns.
 *
 * <p><b>Tucks.</b> Once the strip has left t_i, the paper resting on t_i beyond one of its
 * edges (turns, the gadget's fold back) is tucked under with a fold along that edge, the edge
 * with paper farthest beyond it first, until none is left: only t_i's paper is cut and moved,
 * never the strip that crosses E_{i-1} or E_i, which rests on other triangles.
 */
public final class Wrap {
    /**
     * The fewest tucks on one triangle before giving up; a host with a corner sharper than
     * 0.72° gets more ({@link #maxTucks}).
     */
    public static final int MAX_TUCKS = 1000;

    /**
     * The most tucks on one triangle of a host whose smallest corner is {@code degrees}: the
     * naïve tucks bounce a flap between the edges of a corner of θ degrees about 180/θ times
     * (601 on a triangle of the 0.3° corner in docs/wrap.md), so four times that, and never
     * fewer than {@link #MAX_TUCKS}. Past it the tucks are running away, not converging.
     */
    public static int maxTucks(double degrees) {
        return (int) Math.min(Integer.MAX_VALUE / 2, Math.max(MAX_TUCKS, Math.ceil(4 * 180 / degrees)));
    }

    /**
     * What a face of paper costs a whole run of {@code ifold wrap} in resident memory, the sheet,
     * its steps, its geometry in space and its analysis together, measured: the 5,120-triangle
     * icosphere's 637,860 faces peak at 1.06 GiB, of which about 90 MiB are the start-up's (the
     * icosahedron's 1,731 faces peak at 98 MiB); bench/wrap.
     */
    public static final int BYTES_PER_FACE = 1_600;

    /**
     * The most faces of paper a wrap makes unless {@link Options#maxFaces} says otherwise: what
     * a gibibyte of memory holds at {@link #BYTES_PER_FACE} (671,088; a 1,280-triangle icosphere
     * takes 157,000, the 5,120-triangle one 638,000). A wrap whose floor under its faces passes
     * the limit is refused before any fold, and one whose faces cross the limit while folding is
     * stopped there.
     */
    public static final int DEFAULT_MAX_FACES = (int) ((1L << 30) / BYTES_PER_FACE);

    /** The sizes of model a wrap computes in doubles, across its bounding box ({@link Tolerance#SMALLEST_SIZE}). */
    public static final double SMALLEST_MODEL = Tolerance.SMALLEST_SIZE;

    /** See {@link #SMALLEST_MODEL}. */
    public static final double LARGEST_MODEL = Tolerance.LARGEST_SIZE;

    private Wrap() {
    }

    /**
     * The sharpest corner of a host whose tucks have been seen to finish, in degrees: a 0.1°
     * corner wraps (5,416 tucks), and a needle of 0.0115° corners tears the strip at every width.
     */
    static final double SHARPEST_TUCKED = 0.1;

    /**
     * The default thickness is the width over this: a strip as thin as good paper for its width
     * (a 2 cm strip of 0.25 mm card), so that the layers show in pictures of the whole model.
     */
    public static final int WIDTHS_A_THICKNESS = 80;

    /** The paper's thickness where none is given: the width over {@link #WIDTHS_A_THICKNESS}. */
    public static double defaultThickness(double width) {
        return width / WIDTHS_A_THICKNESS;
    }

    /**
     * What to wrap with. The constructor checks every value on its own (and the thickness
     * against a width given); {@link #wrap} checks the thickness against a default width, and
     * the width against the triangles.
     *
     * @param width the strip's width, or NaN for {@link #defaultWidth}
     * @param thickness the paper's thickness, or NaN for {@link #defaultThickness}; at most a quarter of the width
     * @param ends for paths of one triangle, where the strip starts, ends and comes in; null to
     *     let the planner choose (a path of several triangles sets them itself)
     * @param maxFaces the most faces of paper the wrap may make
     * @throws ParameterException naming the value out of range
     */
    public record Options(double width, double thickness, Ends ends, int maxFaces) {
        /** The widest strip of a lone triangle, over its altitude from the start: one pass. */
        public static final double LONE_WIDEST = 1;

        /** The narrowest strip of a lone triangle, over its altitude from the start: 400 passes, each a few folds to watch. */
        public static final double LONE_NARROWEST = 1.0 / 400;

        public Options {
            if (!Double.isNaN(width) && !(width > 0 && Double.isFinite(width))) {
                throw new ParameterException("width", "must be a positive number, got " + width);
            }
            if (!Double.isNaN(thickness) && !(thickness >= 0 && Double.isFinite(thickness))) {
                throw new ParameterException("thickness", "must be zero or more, got " + thickness);
            }
            if (!Double.isNaN(width) && thickness > width / 4) {
                throw new ParameterException("thickness", "must be at most a quarter of the width " + width + ", got " + thickness);
            }
            if (maxFaces < 1) {
                throw new ParameterException("maxFaces", "must be at least 1, got " + maxFaces);
            }
        }

        public Options(double width, double thickness, Ends ends) {
            this(width, thickness, ends, DEFAULT_MAX_FACES);
        }

        public Options(double width, double thickness) {
            this(width, thickness, null);
        }

        /**
         * The options for wrapping the lone triangle {@code shape} (the single-triangle demo):
         * a width of NaN is a fifth of the altitude from the start corner, a thickness of NaN the
         * {@link #defaultThickness}. The width must lie between {@link #LONE_NARROWEST} and {@link #LONE_WIDEST}
         * times that altitude.
         *
         * @throws ParameterException naming the value out of range
         */
        public static Options loneTriangle(Triangle shape, Ends ends, double width, double thickness) {
            double altitude = shape.height(ends.start());
            double w = Double.isNaN(width) ? altitude / 5 : width;
            if (!(w > 0) || !Double.isFinite(w)) {
                throw new ParameterException("width", "must be a positive number, got " + w);
            }
            if (w > altitude * LONE_WIDEST) {
                throw new ParameterException("width", String.format(Locale.ROOT, "%s is wider than the altitude %.4g from the start "
                        + "corner: one pass of that width already covers the triangle", w, altitude));
            }
            if (w < altitude * LONE_NARROWEST) {
                throw new ParameterException("width", String.format(Locale.ROOT, "%s is under 1/400 of the altitude %.4g from the "
                        + "start corner: a lone triangle takes at most 400 passes", w, altitude));
            }
            return new Options(w, Double.isNaN(thickness) ? defaultThickness(w) : thickness, ends, DEFAULT_MAX_FACES);
        }

        /** These options with another limit on faces. */
        public Options withMaxFaces(int limit) {
            return new Options(width, thickness, ends, limit);
        }
    }

    /**
     * How a lone triangle is wrapped (the single-triangle demo, Figure 11 of the seed). Corners
     * are places 0, 1, 2 in the face's list of vertices.
     *
     * @param start the corner the strip starts at: its passes run parallel to the opposite edge
     * @param end the corner it ends at, one of the other two
     * @param enterFrom the corner beside which the first pass begins, one of the other two, as
     *     where the strip comes in from a triangle before; or -1 to begin on whichever side needs
     *     no overlap. Where the last pass then runs away from {@code end}, it is laid back over
     *     itself (Figure 5): a fold across the strip, and a pass back.
     */
    public record Ends(int start, int end, int enterFrom) {
        public Ends {
            if (start < 0 || start > 2) {
                throw new ParameterException("start", "corners are 0, 1 or 2, got " + start);
            }
            if (end < 0 || end > 2) {
                throw new ParameterException("end", "corners are 0, 1 or 2, got " + end);
            }
            if (start == end) {
                throw new ParameterException("end", "the strip must end at another corner than its start " + cornerName(start));
            }
            if (enterFrom != -1 && (enterFrom < 0 || enterFrom > 2 || enterFrom == start)) {
                throw new ParameterException("enterFrom", "the strip comes in beside one of the corners other than its start "
                        + cornerName(start));
            }
        }
    }

    /** What a step of the wrap does. */
    public enum Kind { ZIGZAG_TURN, TURN_GADGET, EDGE_CROSSING, OVERLAP, TUCK, END }

    /**
     * One fold of the wrap, for the report and the animation.
     *
     * @param kind what it is for
     * @param strip the strip folded
     * @param triangle the triangle (index in the refined mesh) being wrapped
     * @param pathIndex its place along its component's path, from 0
     * @param pathLength the triangles of that path
     * @param face the face it laid, or -1 for a tuck
     * @param tuck the tuck, or null
     * @param facesAfter the faces of the strip's sheet once it is made
     * @param tail for a fold of the tail, where the tail lay before and after it; else null
     * @param detail where in the triangle's work the fold comes, for a caption: "pass 2 of 5,
     *     45° valley fold", "tuck 3, along edge AB"
     */
    public record Step(Kind kind, int strip, int triangle, int pathIndex, int pathLength, int face, Sheet.Tuck tuck, int facesAfter,
            TailMove tail, String detail) {
        public String describe() {
            String what = switch (kind) {
                case ZIGZAG_TURN -> "zig-zag turn";
                case TURN_GADGET -> "turn gadget";
                case EDGE_CROSSING -> "fold over the edge to the next triangle";
                case OVERLAP -> "overlap: the last pass laid back over itself";
                case TUCK -> "tuck: excess folded under";
                case END -> "the strip ends";
            };
            String where = pathLength > 1 ? String.format(Locale.ROOT, "triangle %d of %d: ", pathIndex + 1, pathLength) : "";
            if ((kind == Kind.TUCK || kind == Kind.ZIGZAG_TURN) && detail != null && !detail.isEmpty()) {
                return where + detail; // "tuck 2: excess folded under along edge CA", "pass 3 of 5: turn, 45° valley fold"
            }
            return where + what + (detail == null || detail.isEmpty() ? "" : ", " + detail);
        }
    }

    /**
     * The tail's move in a fold: it swings about the new crease, from running on straight to
     * where the fold lays it.
     *
     * @param hostBefore the triangle it lay on before
     * @param before its pose there
     * @param hostAfter the triangle it lies on after
     * @param after its pose there
     * @param u0 where the crease meets the strip's edge v = 0, in paper coordinates
     * @param u1 and its edge v = w
     * @param over whether it swings over the paper (away from the surface) or under
     */
    public record TailMove(int hostBefore, Isometry2 before, int hostAfter, Isometry2 after, double u0, double u1, boolean over) {
    }

    /**
     * One strip.
     *
     * @param sheet its paper, folded
     * @param firstTriangle the first triangle of its path (refined mesh index)
     * @param triangles how many triangles it wraps
     * @param facesAfter for each triangle of its path, the faces of the sheet once it is wrapped,
     *     tucks and all (the sheet's faces are numbered as they are made)
     */
    public record Strip(Sheet sheet, int firstTriangle, int triangles, int[] facesAfter) {
    }

    /**
     * The wrapped surface.
     *
     * @param mesh the refined mesh whose triangles hold the paper
     * @param frames each host's frame, with its convex polygon as corners: the hosts are the
     *     convex coplanar pieces of the mesh the paper rests on ({@link HostPieces})
     * @param hostOf the host of each triangle of the mesh
     * @param strips one per component
     * @param steps every fold in order
     * @param width the strip width
     * @param thickness the paper thickness
     * @param widest the widest strip the path takes
     */
    public record Result(IndexedPolygons mesh, HostFrame[] frames, int[] hostOf, List<Strip> strips, List<Step> steps, double width,
            double thickness, double widest) {
        public int count(Kind kind) {
            int n = 0;
            for (Step step : steps) {
                n += step.kind() == kind ? 1 : 0;
            }
            return n;
        }
    }

    /** A width the path cannot take, or a triangle the tucks cannot finish: the message names the triangle. */
    public static class WrapException extends Exception {
        private static final long serialVersionUID = 1L;

        public WrapException(String message) {
            super(message);
        }
    }

    /**
     * A strip too wide for a triangle of the path: an error in the width asked for, for this
     * model (a window marks its width field; the message names the triangle and the widest).
     */
    public static final class TooWideException extends WrapException {
        private static final long serialVersionUID = 1L;

        public TooWideException(String message) {
            super(message);
        }
    }

    /** A wrap that would make more faces of paper than {@link Options#maxFaces} allows. */
    public static final class FaceLimitException extends WrapException {
        private static final long serialVersionUID = 1L;

        public FaceLimitException(String message) {
            super(message);
        }
    }

    /** How every triangle of one path is entered and left. */
    private static final class PathPlan {
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
    }

    /**
     * The widest strip every triangle of the refinement's paths takes: the smallest altitude,
     * over the paths, from the corner each triangle is entered by (for the last triangle of a
     * path, the smaller of the two it may be entered by). The default width.
     */
    public static double widest(HamiltonianRefinement.Result refinement) {
        return widest(refinement.mesh(), refinement.componentStart());
    }

    /** {@link #widest(HamiltonianRefinement.Result)} for any path of triangles: see {@link #wrap(IndexedPolygons, int[], Options)}. */
    public static double widest(IndexedPolygons path, int[] componentStart) {
        return narrowest(path, plans(path, componentStart, null))[0];
    }

    /**
     * A third of the widest strip: every triangle then takes at least three passes, so that the
     * zig-zag shows, and the paper is used about twice as well as by the widest strip, whose
     * turns and gadgets outweigh the one or two passes most triangles would get.
     */
    public static double defaultWidth(HamiltonianRefinement.Result refinement) {
        return widest(refinement) / DEFAULT_PASSES;
    }

    /**
     * The faces of paper a wrap of the refinement's paths at the default width is likely to
     * make (as a width that would pass the face limit is told), from the passes its triangles
     * take, before any fold: to choose between two paths of one model.
     */
    public static long likelyFaces(HamiltonianRefinement.Result refinement) {
        List<PathPlan> plans = plans(refinement.mesh(), refinement.componentStart(), null);
        double width = narrowest(refinement.mesh(), plans)[0] / DEFAULT_PASSES;
        if (!(width > 0) || !Double.isFinite(width)) {
            return Long.MAX_VALUE;
        }
        return faces(plans, width, alone(HostPieces.of(refinement.mesh())), true);
    }

    /** The passes the narrowest triangle gets at the default width. */
    public static final int DEFAULT_PASSES = 3;

    private static List<PathPlan> plans(IndexedPolygons path, int[] componentStart, Ends ends) {
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
    private static double[] narrowest(IndexedPolygons mesh, List<PathPlan> plans) {
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

    /**
     * Wraps every component of a refinement.
     *
     * @throws WrapException if the width is too wide for a triangle, or a triangle's excess cannot be tucked
     */
    public static Result wrap(HamiltonianRefinement.Result refinement, Options options) throws WrapException {
        return wrap(refinement.mesh(), refinement.componentStart(), options, Watcher.NONE);
    }

    /**
     * Like {@link #wrap(HamiltonianRefinement.Result, Options)}, told to {@code watcher} as it goes.
     *
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Result wrap(HamiltonianRefinement.Result refinement, Options options, Watcher watcher) throws WrapException {
        return wrap(refinement.mesh(), refinement.componentStart(), options, watcher);
    }

    /**
     * Who watches a wrap while it folds (a window's progress bar and its Cancel): told as each
     * triangle is wrapped, and asked at every fold whether to stop.
     */
    public interface Watcher {
        /** {@code done} of the {@code total} triangles of all paths are wrapped. */
        void wrapped(int done, int total);

        /** Whether to stop: the wrap then throws {@link java.util.concurrent.CancellationException} at its next fold. */
        boolean stopped();

        /** Nobody watches, nothing stops. */
        Watcher NONE = new Watcher() {
            @Override
            public void wrapped(int done, int total) {
            }

            @Override
            public boolean stopped() {
                return false;
            }
        };
    }

    /**
     * Wraps any path of triangles: {@code path}'s faces, triangles listed in path order, each
     * component's from {@code componentStart[c]} to {@code componentStart[c + 1]}, consecutive
     * ones sharing an edge (a Hamiltonian refinement's are; a single triangle is a path too).
     *
     * @throws WrapException if the width is too wide for a triangle, or a triangle's excess cannot be tucked
     * @throws IllegalStateException if consecutive triangles of a path share no edge
     */
    public static Result wrap(IndexedPolygons path, int[] componentStart, Options options) throws WrapException {
        return wrap(path, componentStart, options, Watcher.NONE);
    }

    /**
     * Like {@link #wrap(IndexedPolygons, int[], Options)}, told to {@code watcher} as it goes.
     *
     * @throws java.util.concurrent.CancellationException once the watcher says stop
     */
    public static Result wrap(IndexedPolygons path, int[] componentStart, Options options, Watcher watcher) throws WrapException {
        IndexedPolygons mesh = path;
        HostFrame[] triangleFrames = new HostFrame[mesh.faceCount()];
        double across = across(mesh);
        if (!(across >= SMALLEST_MODEL && across <= LARGEST_MODEL)) {
            throw new WrapException(String.format(Locale.ROOT, "the model is %.3g across, and a wrap computes models from %.0e to %.0e"
                    + " across: scale it into that range", across, SMALLEST_MODEL, LARGEST_MODEL));
        }
        double size = modelSize(mesh);
        double tolerance = Tolerance.ON_PLANE * size;
        List<PathPlan> plans = plans(path, componentStart, options.ends());
        double[] narrowestTriangle = narrowest(mesh, plans);
        double widest = narrowestTriangle[0];
        int narrowest = (int) narrowestTriangle[1];
        double width = Double.isNaN(options.width()) ? widest / DEFAULT_PASSES : options.width();
        if (!(width > 0) || !Double.isFinite(width)) { // no triangle with an altitude to take a default from
            throw new WrapException("no triangle gives the strip a width: give one");
        }
        double thickness = Double.isNaN(options.thickness()) ? defaultThickness(width) : options.thickness();
        if (thickness > width / 4) {
            throw new ParameterException("thickness", "must be at most a quarter of the width " + width + ", got " + thickness);
        }
        if (!Double.isNaN(options.thickness()) && thickness > 0 && thickness < tolerance) {
            // Layers closer than the tolerance are one to every test of the wrap: the caps joining
            // them vanish and the checks find coplanar paper (at 1e-300 the cube's OBJ came out in
            // 2,516 unconnected pieces). Only a thickness given is refused: the default thickness
            // is that thin only where the strip is a ten-millionth of the model, too narrow to fold.
            throw new ParameterException("thickness", String.format(Locale.ROOT, "must be 0 (paper without thickness) or at least %.3g,"
                    + " a billionth of the model's size, or the layers cannot be told apart; got %.3g", tolerance, thickness));
        }
        List<Strip> strips = new ArrayList<>();
        List<Step> steps = new ArrayList<>();
        for (int c = 0; c < plans.size(); c++) {
            PathPlan plan = plans.get(c);
            for (int i = 0; i + 1 < plan.m; i++) {
                if (plan.frames[i].altitude() < width * (1 - 1e-12)) {
                    throw new TooWideException(tooWide(mesh, plan.first + i, i, plan.m, width, plan.frames[i].altitude(), widest));
                }
            }
            chooseLastStart(mesh, plan, width, widest);
            for (int i = 0; i < plan.m; i++) {
                triangleFrames[plan.first + i] = plan.frames[i];
            }
        }
        // The passes are known before any fold, and so is a floor under the faces they make:
        // refuse a wrap too big to make rather than run out of memory or time in it (a sliver
        // sets the widest strip, and a big triangle then needs millions of passes of it).
        long passes = 0;
        int most = -1;
        int mostPasses = 0;
        for (PathPlan plan : plans) {
            for (int i = 0; i < plan.m; i++) {
                int k = passes(plan.frames[i].altitude(), width);
                passes += k;
                if (k > mostPasses) {
                    mostPasses = k;
                    most = plan.first + i;
                }
            }
        }
        HostPieces pieces = HostPieces.of(mesh);
        boolean[] alone = alone(pieces);
        long fewestFaces = faces(plans, width, alone, false);
        if (fewestFaces > options.maxFaces()) {
            double fits = narrowestFitting(plans, alone, width, widest, options.maxFaces());
            throw new FaceLimitException(String.format(Locale.ROOT, "a strip %.4g wide would need %d passes and make about %d faces "
                    + "of paper (at least %d), more than the limit of %d faces: triangle %s alone needs %d passes; %s", width, passes,
                    faces(plans, width, alone, true), fewestFaces, options.maxFaces(), cornersText(mesh, most), mostPasses,
                    !Double.isNaN(fits) ? String.format(Locale.ROOT, "the narrowest strip that fits is about %.4g wide", fits)
                    : String.format(Locale.ROOT, "no strip the path takes fits: the widest, %.4g, which the narrowest triangle (%s) "
                    + "sets, would make about %d", widest, cornersText(mesh, narrowest), faces(plans, widest, alone, true))));
        }
        HostFrame[] frames = BendRoom.of(mesh, pieces.hostOf, hostFrames(mesh, pieces, triangleFrames), tolerance);
        Isometry2[] toHost = new Isometry2[mesh.faceCount()];
        for (PathPlan plan : plans) {
            for (int i = 0; i < plan.m; i++) {
                HostFrame host = frames[pieces.hostOf[plan.first + i]];
                double[] a = position(mesh, plan.baseFrom[i]);
                double[] b = position(mesh, plan.baseTo[i]);
                toHost[plan.first + i] = Isometry2.taking(0, 0, plan.frames[i].baseLength(), 0, host.localX(a), host.localY(a),
                        host.localX(b), host.localY(b));
            }
        }
        for (int c = 0; c < plans.size(); c++) {
            PathPlan plan = plans.get(c);
            Folding folding = new Folding(mesh, plan, c, width, thickness, tolerance, steps, options.maxFaces(), pieces, frames,
                    toHost);
            try {
                folding.watch(watcher, plan.first, mesh.faceCount());
                strips.add(folding.fold());
            } catch (FoldException e) {
                // The sheet's refusals speak of creases and faces: say on which triangle.
                String message = e.getMessage();
                throw new WrapException(message.startsWith("triangle ") ? message : folding.where() + ": " + message);
            }
        }
        if (narrowest < 0) { // no triangles: no widest strip either
            widest = Double.NaN;
        }
        return new Result(mesh, frames, pieces.hostOf, List.copyOf(strips), List.copyOf(steps), width, thickness, widest);
    }

    private static boolean sameCorners(int[] corners, IndexedPolygons mesh, int t) {
        for (int v : corners) {
            if (v != mesh.faceVertex(t, 0) && v != mesh.faceVertex(t, 1) && v != mesh.faceVertex(t, 2)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Each host's frame: the frame of the first triangle of the path on it (a host of one
     * triangle keeps its triangle's frame), with the host's polygon for corners.
     */
    private static HostFrame[] hostFrames(IndexedPolygons mesh, HostPieces pieces, HostFrame[] triangleFrames) {
        HostFrame[] frames = new HostFrame[pieces.hostCount()];
        for (int t = 0; t < triangleFrames.length; t++) {
            int h = pieces.hostOf[t];
            if (frames[h] != null) {
                continue;
            }
            HostFrame f = triangleFrames[t];
            int[] corners = pieces.corners[h];
            if (corners.length == 3 && sameCorners(corners, mesh, t)) {
                frames[h] = f; // a host of one triangle: its frame and corners as the planner has them
                continue;
            }
            double[] xy = new double[2 * corners.length];
            for (int k = 0; k < corners.length; k++) {
                double[] p = position(mesh, corners[k]);
                xy[2 * k] = f.localX(p);
                xy[2 * k + 1] = f.localY(p);
            }
            frames[h] = new HostFrame(f.origin(), f.ex(), f.ey(), f.normal(), xy);
        }
        return frames;
    }

    /**
     * Why {@code width} is refused at a triangle, and the width every triangle takes: the first
     * triangle found too narrow need not be the narrowest, and a width it takes may still be
     * refused further on.
     */
    private static String tooWide(IndexedPolygons mesh, int triangle, int pathIndex, int m, double width, double altitude,
            double widest) {
        return String.format(Locale.ROOT, "the strip width %s is too wide for triangle %d of %d on the path (%s): "
                + "its passes need a width of at most %s, and the whole path one of at most %s", width, pathIndex + 1, m,
                cornersText(mesh, triangle), altitude, widest);
    }

    /** A triangle by its corners, six digits each: "(0.292893 0.292893 0.00000), (1.00000 0.00000 0.00000), ...". */
    public static String cornersText(IndexedPolygons mesh, int triangle) {
        StringBuilder text = new StringBuilder();
        for (int k = 0; k < 3; k++) {
            int v = mesh.faceVertex(triangle, k);
            text.append(k == 0 ? "" : ", ").append('(');
            for (int axis = 0; axis < 3; axis++) {
                text.append(axis == 0 ? "" : " ").append(String.format(Locale.ROOT, "%.6g", mesh.coordinate(v, axis)));
            }
            text.append(')');
        }
        return text.toString();
    }

    /** The largest side of the model's bounding box: unlike its diagonal, never squared, so never overflowing. */
    private static double across(IndexedPolygons mesh) {
        double across = 0;
        for (int axis = 0; axis < 3; axis++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int v = 0; v < mesh.vertexCount(); v++) {
                min = Math.min(min, mesh.coordinate(v, axis));
                max = Math.max(max, mesh.coordinate(v, axis));
            }
            across = Math.max(across, max - min);
        }
        return across;
    }

    private static double modelSize(IndexedPolygons mesh) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < mesh.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                min[axis] = Math.min(min[axis], mesh.coordinate(v, axis));
                max[axis] = Math.max(max[axis], mesh.coordinate(v, axis));
            }
        }
        return Math.max(1e-300, Math.sqrt(sq(max[0] - min[0]) + sq(max[1] - min[1]) + sq(max[2] - min[2])));
    }

    private static double sq(double x) {
        return x * x;
    }

    private static double[] position(IndexedPolygons mesh, int v) {
        return new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
    }

    /** Start corners and frames of every triangle of one path but the last's (which depends on the width). */
    private static PathPlan planCorners(IndexedPolygons mesh, int first, int m, Ends ends) {
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
    private static void frame(IndexedPolygons mesh, PathPlan plan, int i) {
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
    private static double lastAltitudeBound(IndexedPolygons mesh, PathPlan plan) {
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
    private static void chooseLastStart(IndexedPolygons mesh, PathPlan plan, double width, double widest) throws WrapException {
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

    /** Whether each triangle of the mesh is alone on its host (a curved surface's are). */
    private static boolean[] alone(HostPieces pieces) {
        int[] count = new int[pieces.hostCount()];
        for (int h : pieces.hostOf) {
            count[h]++;
        }
        boolean[] alone = new boolean[pieces.hostOf.length];
        for (int t = 0; t < alone.length; t++) {
            alone[t] = count[pieces.hostOf[t]] == 1;
        }
        return alone;
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
    private static long faces(List<PathPlan> plans, double width, boolean[] alone, boolean likely) {
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
    private static long likelyFaces(long k, boolean alone) {
        return alone ? 5 * k + 25 : 3 * k + 30;
    }

    /**
     * The narrowest strip, between {@code width} and {@code widest}, likely to stay within
     * {@code limit} faces, to the nearest 0.1 %; NaN when even the widest is not.
     */
    private static double narrowestFitting(List<PathPlan> plans, boolean[] alone, double width, double widest, int limit) {
        if (!(widest > width) || faces(plans, widest, alone, true) > limit) {
            return Double.NaN;
        }
        double low = width;
        double high = widest;
        while (high > low * 1.001) {
            double middle = Math.sqrt(low * high);
            if (faces(plans, middle, alone, true) > limit) {
                low = middle;
            } else {
                high = middle;
            }
        }
        return high;
    }

    static int passes(double h, double width) {
        return Math.max(1, (int) Math.ceil(h / width - 1e-9));
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
    private static int lastDirectionToEnd(PathPlan plan) {
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

    /** The name of a lone triangle's corner at place {@code k} of its face: A, B, C, as the user gave them. */
    private static String cornerName(int k) {
        return String.valueOf((char) ('A' + k));
    }

    private static int[] sharedEdge(int[] a, int[] b) {
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

    private static int third(int[] corners, int[] edge) {
        for (int v : corners) {
            if (v != edge[0] && v != edge[1]) {
                return v;
            }
        }
        throw new IllegalStateException("a triangle with a repeated corner");
    }

    private static int oppositeLongestEdge(IndexedPolygons mesh, int[] c) {
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

    /** The folding of one strip along one path. */
    private static final class Folding {
        private final IndexedPolygons mesh;
        private final PathPlan plan;
        private final int strip;
        private final double w;
        private final double thickness;
        private final double tolerance;
        private final double margin;
        private final List<Step> steps;
        private Sheet sheet;
        private int pathIndex;
        /** The caption's detail for the folds being made, and the pass they belong to. */
        private String detail = "";
        private final Map<String, String> details = new HashMap<>();
        private String passNote = "";
        private final int maxFaces;
        private Watcher watcher = Watcher.NONE;
        /** Triangles of earlier paths, and of all paths: for the watcher. */
        private int firstDone;
        private int totalTriangles;
        private final HostPieces pieces;
        private final HostFrame[] hostFrames;
        /** Per triangle of the mesh: from its frame (the planner's) into its host's (the sheet's). */
        private final Isometry2[] toHost;
        /** The triangle being wrapped's frame into its host's. */
        private Isometry2 intoHost;

        Folding(IndexedPolygons mesh, PathPlan plan, int strip, double width, double thickness, double tolerance, List<Step> steps,
                int maxFaces, HostPieces pieces, HostFrame[] hostFrames, Isometry2[] toHost) {
            this.pieces = pieces;
            this.hostFrames = hostFrames;
            this.toHost = toHost;
            this.maxFaces = maxFaces;
            this.mesh = mesh;
            this.plan = plan;
            this.strip = strip;
            this.w = width;
            this.thickness = thickness;
            this.tolerance = tolerance;
            // Just beyond the edges: far enough to see, and to clear the caps of the turns.
            this.margin = Math.max(width / 10, 2 * thickness);
            this.steps = steps;
        }

        Strip fold() throws FoldException, WrapException {
            int[] after = new int[plan.m];
            for (int i = 0; i < plan.m; i++) {
                pathIndex = i;
                intoHost = toHost[plan.first + i];
                wrapTriangle(i);
                // The paper is tucked once the strip leaves the host: until then the tail lies on it.
                int host = hostOf(i);
                if (i + 1 == plan.m || hostOf(i + 1) != host) {
                    tuckAll(i);
                    sheet.settle(host);
                }
                after[i] = sheet.faceCount();
                watcher.wrapped(firstDone + i + 1, totalTriangles);
            }
            return new Strip(sheet, plan.first, plan.m, after);
        }

        private int hostOf(int i) {
            return pieces.hostOf[plan.first + i];
        }

        /** The triangle being wrapped, in words: its place on the path and its corners, and the fold being made. */
        String where() {
            return String.format(Locale.ROOT, "triangle %d of %d on the path (%s)%s", pathIndex + 1, plan.m,
                    cornersText(mesh, plan.first + pathIndex), detail == null || detail.isEmpty() ? "" : ", " + detail);
        }

        private void wrapTriangle(int i) throws FoldException, WrapException {
            HostFrame frame = plan.frames[i];
            SlantedEdges edges = new SlantedEdges(frame.baseLength(), frame.apexX(), frame.altitude());
            double h = edges.h();
            boolean last = i == plan.m - 1;
            int k = passes(h, w);
            double[] bottom = new double[k];
            for (int j = 0; j < k; j++) {
                bottom[j] = h - (j + 1) * w;
            }
            if (!last) {
                int shortTurn = shortTurn(edges, k, firstDirection(plan, i, w), hostFrames[hostOf(i)].corners());
                for (int j = shortTurn + 1; j < k; j++) {
                    bottom[j] = (k - 1 - j) * w;
                }
            }
            int d = firstDirection(plan, i, w);
            int host = plan.first + i;
            if (i == 0) {
                double start = d > 0 ? edges.leftmost(bottom[0], bottom[0] + w) - margin : edges.rightmost(bottom[0], bottom[0] + w) + margin;
                Isometry2 pose = d > 0 ? Isometry2.placement(start, bottom[0], 0, false)
                        : Isometry2.placement(start, bottom[0] + w, Math.PI, false);
                sheet = new Sheet(w, thickness, tolerance, hostOf(i), intoHost.after(pose));
            } else {
                checkEntry(d, bottom[0]);
            }
            int passes = k + (last && overlapped(plan, w) ? 1 : 0);
            for (int j = 0; j + 1 < k; j++) {
                passNote = String.format(Locale.ROOT, "pass %d of %d", j + 1, passes);
                turn(edges, d, bottom[j], bottom[j + 1], host);
                d = -d;
            }
            passNote = String.format(Locale.ROOT, "pass %d of %d", k, passes);
            if (last) {
                double end = endOfPass(edges, d, bottom[k - 1]);
                if (overlapped(plan, w)) {
                    detail = "the strip turns back to end at corner " + cornerName(plan.ends.end());
                    tailFold(Kind.OVERLAP, host, end, 0, 0, 1, Placement.OVER, Crease.TURN);
                    d = -d;
                    end = endOfPass(edges, d, bottom[k - 1]);
                }
                detail = "";
                record(Kind.END, host, sheet.endTail(intoHost.x(end, 0), intoHost.y(end, 0), intoHost.dx(0, 1), intoHost.dy(0, 1)));
            } else {
                leave(i, edges, d);
            }
        }

        /**
         * Which turn of a triangle's k passes, the first running in direction d, shifts by less
         * than a width (the first pass runs along the apex, the last along the exit edge, the
         * rest a width apart): the one after pass j. Its gadget of four folds reaches two widths
         * beyond the slanted edge; where that lies on the host (a coplanar neighbour) it stays
         * flat there, where it lies beyond the host's edge it is tucked under, and at a corner of
         * the host tucked twice: the cube's faces had 17 of their 24 layers from gadgets of four
         * triangles fanning at one corner, each turning at the last pass, by the base's corner.
         * So: the turn nearest the middle whose gadget lies on the host; else the middle one.
         */
        private int shortTurn(SlantedEdges edges, int k, int d, double[] host) {
            int middle = (k - 2) / 2;
            int best = -1;
            for (int j = 0; j + 1 < k; j++) {
                int side = (j % 2 == 0) ? d : -d;
                double top = edges.h() - j * w;
                double low = Math.max(0, (k - 2 - j) * w);
                boolean onHost = true;
                for (double y : new double[] {low, top}) {
                    double x = side > 0 ? edges.right(y) : edges.left(y);
                    double beyond = x + side * (margin + 2 * w);
                    onHost &= insideConvex(host, intoHost.x(beyond, y), intoHost.y(beyond, y));
                }
                if (onHost && (best < 0 || Math.abs(j - middle) < Math.abs(best - middle))) {
                    best = j;
                }
            }
            return best < 0 ? middle : best;
        }

        /** Whether (x, y) lies inside the counter-clockwise convex polygon {@code c} (x, y pairs). */
        private static boolean insideConvex(double[] c, double x, double y) {
            int n = c.length / 2;
            for (int a = 0; a < n; a++) {
                int b = (a + 1) % n;
                if ((c[2 * b] - c[2 * a]) * (y - c[2 * a + 1]) - (c[2 * b + 1] - c[2 * a + 1]) * (x - c[2 * a]) < 0) {
                    return false;
                }
            }
            return true;
        }

        /** Where a pass in the band [y, y + w] running in direction d ends: just beyond the slanted edge ahead. */
        private double endOfPass(SlantedEdges edges, int d, double y) {
            return d > 0 ? edges.rightmost(y, y + w) + margin : edges.leftmost(y, y + w) - margin;
        }

        /** The tail came in over the edge before: it must lie along the first pass, running in direction d. */
        private void checkEntry(int d, double bottom) {
            Isometry2 pose = intoHost.inverse().after(sheet.tailPose());
            double along = pose.dx(1, 0);
            double across = pose.dy(1, 0);
            double edgeY = pose.y(sheet.tailStart(false), 0);
            double expected = d > 0 ? bottom : bottom + w;
            if (Math.abs(along - d) > 1e-6 || Math.abs(across) > 1e-6 || Math.abs(edgeY - expected) > 1e-6 * Math.max(1, w)) {
                throw new IllegalStateException(String.format(Locale.ROOT,
                        "the strip came into triangle %d off its first pass (direction %.3g %.3g, edge at %.6g, expected %.6g)",
                        pathIndex + 1, along, across, edgeY, expected));
            }
        }

        /** A turn beyond a slanted edge from the pass in band [y, y + w] running in direction d to the band [next, next + w]. */
        private void turn(SlantedEdges edges, int d, double y, double next, int host) throws FoldException, WrapException {
            double x1 = d > 0 ? edges.rightmost(next, y + w) + margin : edges.leftmost(next, y + w) - margin;
            double shift = y - next;
            if (Math.abs(shift - w) <= 1e-9 * w) {
                // A valley fold lays the strip back across itself along the edge, a mountain fold
                // one width on lays it flat beside the pass it left, running back.
                detail = passNote + ": turn, 45° valley fold";
                tailFold(Kind.ZIGZAG_TURN, host, x1, y + w, d, -1, Placement.OVER, Crease.TURN);
                detail = passNote + ": turn, 45° mountain fold";
                double[] corner = tailCorner(x1 + d * w, y);
                tailFold(Kind.ZIGZAG_TURN, host, corner[0], corner[1], -d, -1, Placement.UNDER, Crease.TURN);
                return;
            }
            // Two 90° turn gadgets: down a vertical band [x1, x1 + w] beyond the edge, then back
            // along the next pass; the fold across the vertical band sets where the next pass lies.
            double middle = x1 + d * w / 2;
            detail = passNote + ": shift by less than a width, two 90° gadgets";
            tailFold(Kind.TURN_GADGET, host, x1 + d * w, 0, 0, 1, Placement.OVER, Crease.GADGET);
            tailFold(Kind.TURN_GADGET, host, middle, y + w / 2, -d, -1, Placement.OVER, Crease.GADGET);
            tailFold(Kind.TURN_GADGET, host, 0, next, 1, 0, Placement.OVER, Crease.GADGET);
            tailFold(Kind.TURN_GADGET, host, middle, next + w / 2, -d, 1, Placement.UNDER, Crease.GADGET);
        }

        /** From the last pass of triangle i (band [0, w], direction d) into the first pass of triangle i + 1. */
        private void leave(int i, SlantedEdges edges, int d) throws FoldException, WrapException {
            HostFrame here = plan.frames[i];
            HostFrame there = plan.frames[i + 1];
            int host = plan.first + i;
            double[] a = position(mesh, plan.baseFrom[i]);
            double[] b = position(mesh, plan.baseTo[i]);
            Isometry2 development = Isometry2.taking(0, 0, here.baseLength(), 0,
                    there.localX(a), there.localY(a), there.localX(b), there.localY(b));
            Isometry2 back = development.inverse();
            int dNext = firstDirection(plan, i + 1, w);
            double centre = there.altitude() - w / 2;
            double cx = back.x(0, centre);
            double cy = back.y(0, centre);
            double ox = back.dx(dNext, 0);
            double oy = back.dy(dNext, 0);
            if (!(oy < 0)) {
                throw new IllegalStateException("the next triangle's first pass does not run away from the edge");
            }
            // The gadget's turn crease: through where the two bands' centre lines meet, along the
            // line that reflects the strip running back (-d) onto the next pass's direction.
            double t = (w / 2 - cy) / oy;
            double meetX = cx + t * ox;
            double lx = -d + ox;
            double ly = oy;
            double reach = Math.abs(w / 2 * lx / ly);
            double fold = d > 0 ? Math.max(edges.rightmost(0, w) + margin, meetX + reach)
                    : Math.min(edges.leftmost(0, w) - margin, meetX - reach);
            detail = "fold back across the strip";
            tailFold(Kind.TURN_GADGET, host, fold, 0, 0, 1, Placement.OVER, Crease.GADGET);
            detail = "turn to run along the next triangle's first pass";
            tailFold(Kind.TURN_GADGET, host, meetX, w / 2, lx, ly, Placement.OVER, Crease.GADGET);
            detail = "";
            int nextHost = hostOf(i + 1);
            if (nextHost == hostOf(i)) {
                // The next triangle lies in this one's plane, on the same host: the strip runs on
                // flat, over the paper it leaves, as it would over the edge.
                sheet.liftTail();
                return;
            }
            Isometry2 next = toHost[plan.first + i + 1];
            tailCross(Kind.EDGE_CROSSING, host, 0, 0, 1, 0, nextHost, next.after(development).after(intoHost.inverse()));
            // The crease over the edge must lie on the edge itself: paper beyond its ends would be
            // joined to paper on both triangles' excess, which no tuck could then fold away.
            Isometry2 pose = next.inverse().after(sheet.tailPose());
            double edgeLength = here.baseLength();
            // The first pass of the next triangle runs with one side through the corner the strip
            // enters by, an end of the edge: that side meets the edge at its end, to twice the
            // tolerance across the strip (a crease's end is snapped to the one before it within
            // the tolerance, and the corner is placed to it), which a side at a small angle θ to
            // the edge stretches along it by 1 / sin θ. Tori of 4,000 to 5,000 triangles met
            // corners 1.0 to 1.2 tolerances beyond their edges' ends, and were refused. Far along
            // a long strip, to the tolerance its poses' rounding has grown to (the cube at width
            // 1e-4 was refused here, three quarters of its 60,000 along).
            double sine = Math.abs(back.dy(pose.dx(1, 0), pose.dy(1, 0)));
            for (boolean side : new boolean[] {false, true}) {
                double u = sheet.tailStart(side);
                double slack = 2 * sheet.toleranceAt(u) / Math.max(sine, 1e-3);
                double v = side ? w : 0;
                double x = back.x(pose.x(u, v), pose.y(u, v));
                if (x < -slack || x > edgeLength + slack) {
                    throw new FoldException(String.format(Locale.ROOT,
                            "triangle %d of %d on the path (%s): the strip would cross the edge to the next triangle beyond its end",
                            i + 1, plan.m, cornersText(mesh, host)));
                }
            }
        }

        /**
         * Tucks the paper resting on triangle i's host beyond the host's edges under it, the edge
         * with paper farthest beyond it first.
         */
        private void tuckAll(int i) throws FoldException, WrapException {
            int host = hostOf(i);
            double[] c = hostFrames[host].corners();
            int n = c.length / 2;
            int limit = maxTucks(smallestAngle(c));
            for (int tucks = 0; ; tucks++) {
                int edge = -1;
                double farthest = sheet.tolerance();
                for (int e = 0; e < n; e++) {
                    double beyond = farthestBeyond(host, c, e);
                    if (beyond > farthest) {
                        farthest = beyond;
                        edge = e;
                    }
                }
                if (edge < 0) {
                    return;
                }
                if (tucks == limit) {
                    throw new WrapException(String.format(Locale.ROOT, "triangle %d of %d on the path (%s): the excess is not"
                            + " hidden after %d tucks: the naive tuck-under bounces paper between the edges of a corner as"
                            + " sharp as %.2g degrees; a narrower strip may help", i + 1, plan.m, cornersText(mesh, plan.first + i),
                            limit, smallestAngle(c)));
                }
                int from = edge;
                int to = (edge + 1) % n;
                Sheet.Tuck tuck;
                try {
                    tuck = sheet.tuck(host, c[2 * from], c[2 * from + 1], c[2 * to] - c[2 * from], c[2 * to + 1] - c[2 * from + 1]);
                } catch (FoldException e) {
                    double corner = smallestAngle(c);
                    if (corner >= SHARPEST_TUCKED) {
                        throw e;
                    }
                    // Say what to change: no width helps here (each tears, or passes the face limit).
                    throw new FoldException(String.format(Locale.ROOT, "%s; a corner of %.2g degrees is sharper than the naive"
                            + " tuck-under can hide paper in (iFold wraps corners of %s degrees and wider, at any width): widen it",
                            e.getMessage(), corner, SHARPEST_TUCKED));
                }
                steps.add(new Step(Kind.TUCK, strip, plan.first + i, pathIndex, plan.m, -1, tuck, sheet.faceCount(), null,
                        shared("tuck " + (tucks + 1) + ": excess folded under " + edgeName(i, host, from, to))));
                checkFaces();
            }
        }

        /** A lone triangle's edge by the corners the user named A, B and C; any other "an edge". */
        private String edgeName(int i, int host, int from, int to) {
            if (plan.m != 1) {
                return "along an edge";
            }
            int[] corners = pieces.corners[host];
            String a = null;
            String b = null;
            for (int k = 0; k < 3; k++) {
                a = plan.corners[i][k] == corners[from] ? cornerName(k) : a;
                b = plan.corners[i][k] == corners[to] ? cornerName(k) : b;
            }
            return a != null && b != null ? "along edge " + a + b : "along an edge";
        }

        /** A convex polygon's smallest angle in degrees, from its corners in its frame. */
        private static double smallestAngle(double[] c) {
            double smallest = 180;
            int n = c.length / 2;
            for (int k = 0; k < n; k++) {
                int a = (k + 1) % n;
                int b = (k + n - 1) % n;
                double ux = c[2 * a] - c[2 * k];
                double uy = c[2 * a + 1] - c[2 * k + 1];
                double vx = c[2 * b] - c[2 * k];
                double vy = c[2 * b + 1] - c[2 * k + 1];
                smallest = Math.min(smallest, Math.toDegrees(Math.abs(Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy))));
            }
            return smallest;
        }

        /** How far the paper on the host reaches beyond edge e of the triangle (corners counter-clockwise: outside is to the right). */
        private double farthestBeyond(int host, double[] c, int e) {
            int from = e;
            int to = (e + 1) % (c.length / 2);
            double dx = c[2 * to] - c[2 * from];
            double dy = c[2 * to + 1] - c[2 * from + 1];
            double length = Math.hypot(dx, dy);
            double nx = dy / length;
            double ny = -dx / length;
            double farthest = Double.NEGATIVE_INFINITY;
            for (int f : sheet.facesOn(host)) {
                double[] xy = sheet.placed(f);
                for (int k = 0; k < xy.length; k += 2) {
                    farthest = Math.max(farthest, nx * (xy[k] - c[2 * from]) + ny * (xy[k + 1] - c[2 * from + 1]));
                }
            }
            return farthest;
        }

        /** A flat fold of the tail, recorded as a step with where the tail lay before and after. */
        /**
         * Where the paper has the point (x, y) of the triangle's frame that a turn's two creases
         * share: the tail's start on the side nearest it, mapped by the tail's pose, where that
         * lies within a quarter width of it; else (x, y). The mountain crease goes
         * through the paper's own corner rather than the designed one: the two differ by rounding
         * in the poses, the engine snaps the crease's end to the corner, and each turn's fold about
         * a line that missed its crease by that much moved the paper on by it; over thousands of
         * passes (a 10 × 10 × 0.03 plate's triangles) the paper fell past a tolerance behind its
         * design, and the turn was refused as crossing the crease before it.
         */
        private double[] tailCorner(double x, double y) {
            Isometry2 pose = intoHost.inverse().after(sheet.tailPose());
            double[] best = {x, y};
            double nearest = w / 4; // the other side's start lies about a width away
            for (boolean side : new boolean[] {false, true}) {
                double u = sheet.tailStart(side);
                double v = side ? w : 0;
                double px = pose.x(u, v);
                double py = pose.y(u, v);
                double off = Math.hypot(px - x, py - y);
                if (off <= nearest) {
                    nearest = off;
                    best = new double[] {px, py};
                }
            }
            return best;
        }

        private void tailFold(Kind kind, int host, double px, double py, double dx, double dy, Placement next, Crease crease)
                throws FoldException, WrapException {
            int hostBefore = sheet.tailHost();
            Isometry2 before = sheet.tailPose();
            int face = sheet.foldTail(intoHost.x(px, py), intoHost.y(px, py), intoHost.dx(dx, dy), intoHost.dy(dx, dy), next, crease);
            recordTail(kind, host, face, hostBefore, before, next == Placement.OVER);
        }

        /** The fold of the tail over an edge onto the next triangle, recorded likewise. */
        private void tailCross(Kind kind, int host, double px, double py, double dx, double dy, int nextHost, Isometry2 development)
                throws FoldException, WrapException {
            int hostBefore = sheet.tailHost();
            Isometry2 before = sheet.tailPose();
            int face = sheet.crossTail(intoHost.x(px, py), intoHost.y(px, py), intoHost.dx(dx, dy), intoHost.dy(dx, dy), nextHost, development);
            recordTail(kind, host, face, hostBefore, before, true);
        }

        /** Tells {@code watcher} of this path's triangles as the {@code first}-th and on of {@code total}. */
        void watch(Watcher watcher, int first, int total) {
            this.watcher = watcher;
            this.firstDone = first;
            this.totalTriangles = total;
        }

        /**
         * Stops the wrap at the fold that takes the paper past the limit, before memory runs out,
         * saying what limit the whole path would likely need: the faces so far, over the share
         * of the path's passes and triangles folded (weighed as on a shared host, {@link #likelyFaces}).
         */
        private void checkFaces() throws FaceLimitException {
            if (watcher.stopped()) {
                throw new java.util.concurrent.CancellationException("the wrap was stopped");
            }
            if (sheet.faceCount() > maxFaces) {
                double done = 0;
                double all = 0;
                for (int i = 0; i < plan.m; i++) {
                    double weight = likelyFaces(passes(plan.frames[i].altitude(), sheet.width()), false);
                    all += weight;
                    done += i <= pathIndex ? weight : 0;
                }
                long whole = (long) Math.ceil(sheet.faceCount() * all / done);
                long enough = (long) Math.ceil(whole * 1.1 / 1000) * 1000; // a tenth to spare, in thousands
                throw new FaceLimitException(String.format(Locale.ROOT, "the strip has %d faces of paper on triangle %d of %d on the "
                        + "path (%s), more than the limit of %d faces; at this rate the whole path makes about %d, and a limit "
                        + "of %d (about %d MiB) would likely let it finish", sheet.faceCount(), pathIndex + 1, plan.m,
                        cornersText(mesh, plan.first + pathIndex), maxFaces, whole, enough, enough * BYTES_PER_FACE >> 20));
            }
        }

        private void recordTail(Kind kind, int host, int face, int hostBefore, Isometry2 before, boolean over) throws FaceLimitException {
            checkFaces();
            TailMove move = new TailMove(hostBefore, before, sheet.tailHost(), sheet.tailPose(), sheet.tailStart(false),
                    sheet.tailStart(true), over);
            steps.add(new Step(kind, strip, host, pathIndex, plan.m, face, null, sheet.faceCount(), move, shared(detail)));
        }

        private void record(Kind kind, int host, int face) throws FaceLimitException {
            checkFaces();
            steps.add(new Step(kind, strip, host, pathIndex, plan.m, face, null, sheet.faceCount(), null, shared(detail)));
        }

        /**
         * One copy of each caption detail: a wrap records hundreds of thousands of steps, and
         * their details are a few dozen texts ("pass 2 of 5: turn, 45° valley fold"), each made
         * anew by its fold; the copies were a twentieth of the memory the paper takes.
         */
        private String shared(String text) {
            return text == null ? null : details.computeIfAbsent(text, t -> t);
        }
    }
}
