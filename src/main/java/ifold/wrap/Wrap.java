package ifold.wrap;

import static ifold.wrap.PathPlan.chooseLastStart;
import static ifold.wrap.PathPlan.faces;
import static ifold.wrap.PathPlan.frame;
import static ifold.wrap.PathPlan.likelyFaces;
import static ifold.wrap.PathPlan.narrowest;
import static ifold.wrap.PathPlan.narrowestFitting;
import static ifold.wrap.PathPlan.passes;
import static ifold.wrap.PathPlan.plans;
import static ifold.wrap.PathPlan.third;
import static ifold.wrap.PathPlan.tooWide;

import ifold.geom.ParameterException;
import ifold.geom.Tolerance;
import ifold.geom.Triangle;
import ifold.mesh.IndexedPolygons;
import ifold.refine.HamiltonianRefinement;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Tuck;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleToLongFunction;

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
                throw new ParameterException("width", "must be a positive number, got " + ParameterException.shown(width));
            }
            if (!Double.isNaN(thickness) && !(thickness >= 0 && Double.isFinite(thickness))) {
                throw new ParameterException("thickness", "must be zero or more, got " + ParameterException.shown(thickness));
            }
            if (!Double.isNaN(width) && thickness > width / 4) {
                throw new ParameterException("thickness", "must be at most a quarter of the width " + ParameterException.shown(width) + ", got "
                        + ParameterException.shown(thickness));
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
                throw new ParameterException("width", "must be a positive number, got " + ParameterException.shown(w));
            }
            if (w > altitude * LONE_WIDEST) {
                throw new ParameterException("width", String.format(Locale.ROOT, "%s is wider than the altitude %.4g from the start "
                        + "corner: one pass of that width already covers the triangle", ParameterException.shown(w), altitude));
            }
            if (w < altitude * LONE_NARROWEST) {
                throw new ParameterException("width", String.format(Locale.ROOT, "%s is under 1/400 of the altitude %.4g from the "
                        + "start corner: a lone triangle takes at most 400 passes", ParameterException.shown(w), altitude));
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

    /**
     * How a model is wrapped: the zig-zag way along the Hamiltonian path of its refinement (any
     * polyhedron), or by the hinge strip along a tour of its squares (a grid polyhedron).
     */
    public enum Method {
        ZIGZAG, HINGE;

        /** Its name as the command line takes it: zigzag, hinge. */
        public String word() {
            return name().toLowerCase(Locale.ROOT);
        }
    }

    /**
     * What a step of the wrap does, and the crease it leaves on the sheet ({@link Sheet.Crease}:
     * why the paper is creased there, which the sheet keeps for each crease): a step's kind
     * names the work, the crease its mark, so an overlap leaves a turn's crease and the strip's
     * end none.
     */
    public enum Kind {
        ZIGZAG_TURN(Sheet.Crease.TURN),
        /** The hinge strip's turn: a flat fold along a square's diagonal ({@link HingeStrip}). */
        DIAGONAL_TURN(Sheet.Crease.TURN), TURN_GADGET(Sheet.Crease.GADGET), EDGE_CROSSING(Sheet.Crease.CROSSING),
        OVERLAP(Sheet.Crease.TURN), TUCK(Sheet.Crease.TUCK), END(null);

        private final Sheet.Crease crease;

        Kind(Sheet.Crease crease) {
            this.crease = crease;
        }

        /** The crease a fold of this kind leaves; null for the strip's end. */
        public Sheet.Crease crease() {
            return crease;
        }
    }

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
    public record Step(Kind kind, int strip, int triangle, int pathIndex, int pathLength, int face, Tuck tuck, int facesAfter,
            TailMove tail, String detail) {
        public String describe() {
            String what = switch (kind) {
                case ZIGZAG_TURN -> "zig-zag turn";
                case TURN_GADGET -> "turn gadget";
                case EDGE_CROSSING -> "fold over the edge to the next triangle";
                case OVERLAP -> "overlap: the last pass laid back over itself";
                case TUCK -> "tuck: excess folded under";
                case END -> "the strip ends";
                case DIAGONAL_TURN -> "turn along the square's diagonal";
            };
            String where = pathLength > 1 ? String.format(Locale.ROOT, "%s %d of %d: ",
                    HingeStrip.hinge(detail) ? "pass" : "triangle", pathIndex + 1, pathLength) : "";
            if ((kind == Kind.TUCK || kind == Kind.ZIGZAG_TURN) && detail != null && !detail.isEmpty()) {
                return where + detail; // "tuck 2: excess folded under along edge CA", "pass 3 of 5: turn, 45° valley fold"
            }
            if (HingeStrip.hinge(detail)) {
                return where + detail; // "pass 7 of 12: turn left: fold along the square's diagonal"
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
     * @param method how it was wrapped: for the hinge strip, the path's triangles are the passes of its tour
     */
    public record Result(IndexedPolygons mesh, HostFrame[] frames, int[] hostOf, List<Strip> strips, List<Step> steps, double width,
            double thickness, double widest, Method method) {
        /** A zig-zag wrap. */
        public Result(IndexedPolygons mesh, HostFrame[] frames, int[] hostOf, List<Strip> strips, List<Step> steps, double width,
                double thickness, double widest) {
            this(mesh, frames, hostOf, strips, steps, width, thickness, widest, Method.ZIGZAG);
        }

        /** What one place of the path is called: a triangle of the zig-zag's, a pass of the hinge strip's tour. */
        public String unit() {
            return method == Method.HINGE ? "pass" : "triangle";
        }

        /** Its plural. */
        public String units() {
            return method == Method.HINGE ? "passes" : "triangles";
        }

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
     * Whether a wrap takes a model of {@code mesh}'s size, {@link #SMALLEST_MODEL} to
     * {@link #LARGEST_MODEL} across: of one it refuses, no frame (and so no widest strip) can be made.
     */
    public static boolean takesSize(IndexedPolygons mesh) {
        double across = across(mesh);
        return across >= SMALLEST_MODEL && across <= LARGEST_MODEL;
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
        return likelyFaces(refinement, Double.NaN);
    }

    /** As {@link #likelyFaces(HamiltonianRefinement.Result)} at {@code width}, NaN for the default. */
    public static long likelyFaces(HamiltonianRefinement.Result refinement, double width) {
        IndexedPolygons mesh = refinement.mesh();
        double across = across(mesh);
        if (!(across >= SMALLEST_MODEL && across <= LARGEST_MODEL)) {
            return Long.MAX_VALUE; // a model that a wrap refuses for its size: nothing to count (its frames could not be made)
        }
        List<PathPlan> plans = plans(mesh, refinement.componentStart(), null);
        double widest = narrowest(mesh, plans)[0];
        if (Double.isNaN(width)) {
            width = widest / DEFAULT_PASSES;
        }
        if (!(width > 0) || !Double.isFinite(width)) {
            return Long.MAX_VALUE;
        }
        return likelyFaces(mesh, plans, width, widest, LayerFloor.angleSums(mesh), HostPieces.of(mesh).alone());
    }

    /** The faces {@code plans} are likely to make at {@code width}, each last triangle entered as a wrap at that width enters it. */
    private static long likelyFaces(IndexedPolygons mesh, List<PathPlan> plans, double width, double widest, double[] angleSums, boolean[] alone) {
        for (PathPlan plan : plans) {
            try {
                chooseLastStart(mesh, plan, width, widest, angleSums);
            } catch (WrapException e) {
                return Long.MAX_VALUE; // too wide for it: no wrap to count
            }
        }
        return faces(plans, width, alone, true);
    }

    /**
     * The width a wrap takes where none is given: {@link #defaultWidth}, a third of the
     * {@code widest}, unless the paths are likely to make more than {@code maxFaces} faces at
     * it; then the narrowest wider strip likely to fit, up to the widest (where none fits, the
     * third, which the face limit then refuses, naming the widths). A big scan's narrowest
     * triangles set a strip so narrow that its big ones need thousands of passes: along its own
     * triangles the cow ({@code common3d_spot.obj}, 5,856 triangles) is likely to make 1,008,739
     * faces at a third of its widest strip, 452,114 at the widest. Strips wider than a third lay
     * the turns and tucks of neighbouring triangles together at corners, where the paper may
     * cross itself (docs/wrap.md, Limits): a wrap rather than a refusal. The faces are counted as
     * the refusal counts them, a sharp corner's tucks too ({@link CornerTucks}).
     */
    private static double fittingDefault(IndexedPolygons mesh, List<PathPlan> plans, boolean[] alone, double[] angleSums,
            CornerTucks cornerTucks, double widest, int maxFaces) {
        double third = widest / DEFAULT_PASSES;
        // As the refusal counts them (CornerTucks.refusal): a needle's tucks may be the most of its faces.
        DoubleToLongFunction likely = w -> {
            long faces = likelyFaces(mesh, plans, w, widest, angleSums, alone);
            return faces == Long.MAX_VALUE ? faces : faces + cornerTucks.likelyFaces(plans, w);
        };
        if (likely.applyAsLong(third) <= maxFaces) {
            return third;
        }
        double fits = narrowestFitting(likely, third, widest, maxFaces);
        return Double.isNaN(fits) ? third : fits;
    }

    /** The passes the narrowest triangle gets at the default width. */
    public static final int DEFAULT_PASSES = 3;

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
        HostPieces pieces = HostPieces.of(mesh);
        boolean[] alone = pieces.alone();
        double[] angleSums = LayerFloor.angleSums(mesh);
        CornerTucks cornerTucks = CornerTucks.of(mesh, pieces);
        double width = Double.isNaN(options.width()) ? fittingDefault(mesh, plans, alone, angleSums, cornerTucks, widest, options.maxFaces())
                : options.width();
        if (!(width > 0) || !Double.isFinite(width)) { // no triangle with an altitude to take a default from
            throw new WrapException("no triangle gives the strip a width: give one");
        }
        double thickness = Double.isNaN(options.thickness()) ? defaultThickness(width) : options.thickness();
        if (thickness > width / 4) {
            throw new ParameterException("thickness", "must be at most a quarter of the width " + ParameterException.shown(width) + ", got "
                        + ParameterException.shown(thickness));
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
            chooseLastStart(mesh, plan, width, widest, angleSums);
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
        long fewestFaces = faces(plans, width, alone, false);
        if (fewestFaces > options.maxFaces()) {
            double fits = narrowestFitting(plans, alone, width, widest, options.maxFaces());
            throw new FaceLimitException(String.format(Locale.ROOT, "a strip %.4g wide would need %,d passes and make about %,d faces "
                    + "of paper (at least %,d), more than the limit of %,d faces: triangle %s alone needs %,d passes; %s", width, passes,
                    faces(plans, width, alone, true), fewestFaces, options.maxFaces(), cornersText(mesh, most), mostPasses,
                    !Double.isNaN(fits) ? String.format(Locale.ROOT, "the narrowest strip that fits is about %.4g wide", fits)
                    : String.format(Locale.ROOT, "no strip the path takes fits: the widest, %.4g, which the narrowest triangle (%s) "
                    + "sets, would make about %,d", widest, cornersText(mesh, narrowest), faces(plans, widest, alone, true))));
        }
        // The tucks at a sharp corner grow as 1/θ and the passes' floor leaves them out: count
        // them too, or a needle folds its passes for a minute before its tucks pass the limit.
        if (fewestFaces + cornerTucks.fewestFaces() > options.maxFaces()) {
            throw new FaceLimitException(cornerTucks.refusal(mesh, plans, alone, width, widest, passes, fewestFaces, options.maxFaces()));
        }
        HostFrame[] frames = BendRoom.of(mesh, pieces.hostOf, pieces.frames(mesh, triangleFrames), tolerance, true);
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
            StripFolding folding = new StripFolding(mesh, plan, c, width, thickness, tolerance, steps, options.maxFaces(), pieces, frames,
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

    /** The model's size: its bounding box's diagonal (at least 1e-300). */
    public static double modelSize(IndexedPolygons mesh) {
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

    static double sq(double x) {
        return x * x;
    }

    static double[] position(IndexedPolygons mesh, int v) {
        return new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
    }

    /** The name of a lone triangle's corner at place {@code k} of its face: A, B, C, as the user gave them. */
    static String cornerName(int k) {
        return String.valueOf((char) ('A' + k));
    }

}
