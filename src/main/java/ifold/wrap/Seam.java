package ifold.wrap;

import ifold.geom.ParameterException;
import ifold.mesh.IndexedPolygons;
import ifold.refine.CycleCoverPath;
import ifold.refine.HamiltonianRefinement;
import java.util.ArrayList;
import java.util.List;

/**
 * Where each strip begins and ends: the seam of a wrap.
 *
 * <p>The walk round the refinement's spanning tree ends where it began, so each component's path
 * is a cycle, and its strip may begin at any triangle of it and run round to the one before.
 * Where the strip begins its excess is tucked beside the last triangle's, and the sequence of
 * tucks and turns after it follows from where that is: the most layers over a point moves with
 * the seam, and by no rule seen on the triangles there (the shared {@code square_frame}'s 158
 * starts give 24 or 25 in long runs along the path, 27 and 28 at four, with the seam's own
 * triangles alike on both). So a short path is wrapped from a few places round it, a quarter
 * of the way apart, and the wrap with the fewest layers is kept, the first tried where several
 * tie: the refinement's own start is tried first. A long path is wrapped once: each try would
 * cost as much as the wrap, and with thousands of triangles its most layers are the more likely
 * to lie at a crowded corner far from where it begins; a big model's one start follows
 * its own triangles where they are likely to make fewer faces ({@link #ownInstead}).
 *
 * <p>Fewest layers are not enough: a start may give paper that passes through itself where
 * another does not (an irregular pentagonal pyramid begun at its apex, rolled round it, made 37
 * layers and 63 crossing pairs of caps, where the other starts made 54 layers and none, until
 * its roll was mended: 22 and none). So
 * where a {@link PaperCheck} is given, a start whose paper collides is kept only where every
 * start's does. The check belongs to whoever calls: the seam folds paper, the independent
 * checker (which reads the exported file) judges it.
 */
public final class Seam {
    /** Refinements of more triangles than this, all their components' together, are wrapped from their own start alone. */
    public static final int MOST_TRIANGLES = 1_000;

    /**
     * Paths whose wrap is likely to make more faces of paper than this ({@link Wrap#likelyFaces})
     * are wrapped from their own start alone, however short: each try costs as much as the wrap,
     * and the seam holds the best start's paper while it folds the next. The cube at width 1e-4
     * (600 million widths of strip, about 600,000 faces) took 248 s and 1.56 GiB from four starts,
     * and takes 53 s and 1.13 GiB from one (both on a machine busy with other work).
     */
    public static final long MOST_FACES = 100_000;

    /** Where round each cyclic path the strip is tried beginning, as a share of the way round. */
    static final double[] TRIED = {0, 0.25, 0.5, 0.75};

    private Seam() {
    }

    /** What the seam asks of a start's paper besides its layers. */
    @FunctionalInterface
    public interface PaperCheck {
        /** No check: the start with fewest layers is kept, whatever its paper. */
        PaperCheck NONE = (result, placed) -> -1;

        /**
         * How many collisions {@code placed}, the paper of {@code result}, has (pairs crossing or
         * overlapping in one plane, crossings of the model, points inside it): 0 where it is
         * sound, -1 where it is not checked (taken as sound).
         */
        int collisions(Wrap.Result result, PlacedWrap placed);
    }

    /**
     * A wrap begun where it has fewest layers.
     *
     * @param refinement the path wrapped: the refinement begun at {@code along}
     * @param result the wrap along it
     * @param placed its paper in space and its measures
     * @param along where round the path it begins, from 0 (the refinement's own start) to 1
     * @param layersTried the most layers of each start tried, in the order of {@link #TRIED}, null
     *     for a start whose wrap failed (empty where one alone was tried)
     * @param collisionsTried the collisions the {@link PaperCheck} found on each start tried, in
     *     the same order, null for a start not checked (one with more layers than a sound start
     *     before it, one whose wrap failed, or one the check passed by); empty where one alone was tried
     * @param measureSeconds how long placing and measuring the wrap kept took (the other tries' count as wrapping)
     * @param collisions the collisions the {@link PaperCheck} found on the start kept; null where it was not checked
     */
    public record Chosen(HamiltonianRefinement.Result refinement, Wrap.Result result, PlacedWrap placed, double along,
            List<Integer> layersTried, List<Integer> collisionsTried, double measureSeconds, List<Integer> ownLayersTried,
            List<Integer> ownCollisionsTried, Integer collisions) {
        Chosen(HamiltonianRefinement.Result refinement, Wrap.Result result, PlacedWrap placed, double along, double measureSeconds) {
            this(refinement, result, placed, along, null, null, measureSeconds, null, null, null);
        }

        /** The most layers over any point of the wrap kept. */
        public int maxLayers() {
            return placed.analysis().maxLayers();
        }

        /**
         * Whether this wrap is better than {@code other}, as the seam chooses between its starts:
         * sound where the other's paper collides, else fewer layers.
         */
        public boolean betterThan(Chosen other) {
            boolean collides = collisions != null && collisions > 0;
            boolean otherCollides = other.collisions != null && other.collisions > 0;
            return collides != otherCollides ? !collides : maxLayers() < other.maxLayers();
        }
    }

    /** As {@link #wrap(HamiltonianRefinement.Result, Wrap.Options, Wrap.Watcher, PaperCheck)}, asking nothing of the paper. */
    public static Chosen wrap(HamiltonianRefinement.Result refinement, Wrap.Options options, Wrap.Watcher watcher) throws Wrap.WrapException {
        return wrap(refinement, options, watcher, PaperCheck.NONE);
    }

    /**
     * Wraps a big model along its own triangles where {@link #ownInstead} says so, from their own
     * start, and where that fails, as below.
     * Wraps the refinement from where it has fewest layers and its paper is sound: from each
     * start of {@link #TRIED} where {@link #tries} says so (a short path, one that is a cycle, a
     * wrap likely to be small), else from its own. Every cyclic component begins the same share of
     * the way round its path: one wrap's layers are its deepest strip's, and a start for each
     * component would take a wrap more to put together.
     * A start whose wrap fails (too many faces, a triangle the tucks cannot finish) is passed
     * over, unless it is the first and no path along the model's own triangles is tried: its
     * failure is the wrap's.
     * Of several starts, {@code check} is asked of the first and of each that would be kept for
     * its layers, or that may be kept because the paper kept so far collides: a sound start is
     * kept before one that collides, then the fewest layers, then (of starts that collide) the
     * fewest collisions, then the first tried.
     * Then, where {@link #ownPath} gives one, the strip along the model's own triangles from each
     * start of {@link #OWN_TRIED}: kept only where {@code check} finds it sound (0, not -1) and it
     * has fewer layers than the start kept, or every start kept so far collides; where the
     * refinement's first start failed, its first that wraps is kept as the first start would be.
     *
     * @throws Wrap.WrapException as {@link Wrap#wrap(HamiltonianRefinement.Result, Wrap.Options, Wrap.Watcher)}, from the refinement's own start
     * @throws ParameterException where no path takes the thickness asked (over a quarter of
     *     each one's default width), or a start refuses any other value
     */
    public static Chosen wrap(HamiltonianRefinement.Result refinement, Wrap.Options options, Wrap.Watcher watcher, PaperCheck check)
            throws Wrap.WrapException {
        return wrap(refinement, ownInstead(refinement, options), options, watcher, check);
    }

    /**
     * As {@link #wrap(HamiltonianRefinement.Result, Wrap.Options, Wrap.Watcher, PaperCheck)},
     * given {@code instead}, what {@link #ownInstead} gives for the refinement and {@code options}
     * (a caller that asked it already need not find the matching again).
     */
    public static Chosen wrap(HamiltonianRefinement.Result refinement, HamiltonianRefinement.Result instead, Wrap.Options options,
            Wrap.Watcher watcher, PaperCheck check) throws Wrap.WrapException {
        Exception insteadFailure = null;
        if (instead != null) {
            try {
                Chosen alone = placed(instead, Wrap.wrap(instead, options, watcher), 0);
                return new Chosen(instead, alone.result(), alone.placed(), 0, List.of(), List.of(), alone.measureSeconds(), List.of(),
                        List.of(), null);
            } catch (Wrap.FaceLimitException e) {
                // The refinement, likely to make more faces, would pass the limit too, after as
                // long again (the 5,120-triangle icosphere at width 0.004 stopped at triangle
                // 5,033 of 5,414, and the refinement at 16,295 of its 25,598).
                throw e;
            } catch (Wrap.WrapException e) {
                // Folded along the refinement instead; where that fails too, this failure is the
                // wrap's: the own triangles are the likelier to fit (igl_fertility.off's refusal
                // names their widest strip, 832,963 faces likely, not the refinement's 2.8 million).
                insteadFailure = e;
            } catch (ParameterException e) {
                insteadFailure = thicknessOnly(e);
            }
        }
        int tries = tries(refinement, options.width());
        List<Double> shares = new ArrayList<>();
        for (int k = 0; k < tries; k++) {
            shares.add(TRIED[k]);
        }
        double rolled = tries > 1 ? rollShare(refinement) : Double.NaN;
        if (!Double.isNaN(rolled)) {
            shares.add(rolled);
            tries++;
        }
        double needle = tries > 1 ? needleShare(refinement) : Double.NaN;
        int needleTry = -1;
        if (!Double.isNaN(needle)) {
            needleTry = tries;
            shares.add(needle);
            tries++;
        }
        Chosen best = null;
        boolean bestCollides = false;
        int bestFound = 0;
        Integer bestChecked = null; // what the check found on the best start, null where it was not checked
        List<Integer> layers = new ArrayList<>();
        List<Integer> collisions = new ArrayList<>();
        HamiltonianRefinement.Result own = ownPath(refinement, options.width());
        Exception firstFailure = null;
        for (int k = 0; k < tries; k++) {
            HamiltonianRefinement.Result begun = k == 0 ? refinement : refinement.begunAt(shares.get(k));
            Wrap.Result result;
            try {
                result = Wrap.wrap(begun, options, share(watcher, k, tries));
            } catch (Wrap.WrapException | ParameterException e) {
                Exception failure = e instanceof ParameterException p ? thicknessOnly(p) : e;
                if (k == 0 && own == null) {
                    throw thrown(insteadFailure != null ? insteadFailure : failure);
                }
                // A width too wide for the refinement's pieces may suit the own triangles, and a
                // thickness too thick for the refinement's default width their wider default (the
                // cube's --thickness 0.03: a quarter of the refinement's 0.064 is 0.016, of its own
                // triangles' 0.236, 0.059).
                firstFailure = k == 0 ? failure : firstFailure;
                layers.add(null); // kept in its place: the report lists the starts in order
                collisions.add(null);
                continue;
            }
            Chosen tried = placed(begun, result, shares.get(k));
            PlacedWrap placed = tried.placed();
            int most = placed.analysis().maxLayers();
            layers.add(most);
            if (k > 0 && k == needleTry && !covers(placed)) {
                // Rolled round a needle's tip, a start is kept only where its paper covers the
                // model, as the own triangles' are: the roll shares the refinement's faults (a
                // closed square pyramid's 3° needle, its base's triangulation leaving 5·10⁻⁸ bare
                // at a corner from every start, 18 layers where its own triangles' 44 cover).
                collisions.add(null);
                continue;
            }
            boolean fewer = best == null || most < best.placed().analysis().maxLayers();
            Integer found = null;
            if (tries > 1 && (fewer || bestCollides)) {
                found = check.collisions(result, placed);
                found = found < 0 ? null : found;
            }
            collisions.add(found);
            boolean collides = found != null && found > 0;
            boolean kept;
            if (best == null) {
                kept = true;
            } else if (collides != bestCollides) {
                kept = !collides;
            } else {
                // Of two that collide with as many layers, the one colliding less: each start was checked.
                kept = fewer || collides && most == best.placed().analysis().maxLayers() && found < bestFound;
            }
            if (kept) {
                best = tried;
                bestCollides = collides;
                bestFound = collides ? found : 0;
                bestChecked = found;
            }
        }
        // The path through the model's own triangles, where the refinement's starts were tried:
        // kept only where its paper covers the model, the check finds it sound and it has fewer
        // layers, or the refinement's paper collides from every start.
        List<Integer> ownLayers = new ArrayList<>();
        List<Integer> ownCollisions = new ArrayList<>();
        Exception ownFailure = null; // the own triangles' first failure
        if (own != null) {
            Wrap.Watcher quiet = stoppedBy(watcher);
            for (double share : OWN_TRIED) {
                HamiltonianRefinement.Result begun = share == 0 ? own : own.begunAt(share);
                Wrap.Result result;
                try {
                    result = Wrap.wrap(begun, options, quiet);
                } catch (Wrap.WrapException | ParameterException e) {
                    ownFailure = ownFailure == null ? (e instanceof ParameterException p ? thicknessOnly(p) : e) : ownFailure;
                    ownLayers.add(null);
                    ownCollisions.add(null);
                    continue;
                }
                Chosen tried = placed(begun, result, share);
                PlacedWrap placed = tried.placed();
                int most = placed.analysis().maxLayers();
                ownLayers.add(most);
                if (best == null) { // the refinement's first start failed: the own triangles' first that wraps
                    int found = check.collisions(result, placed);
                    ownCollisions.add(found >= 0 ? found : null);
                    best = tried;
                    bestCollides = found > 0;
                    bestChecked = found >= 0 ? found : null;
                    continue;
                }
                if (!bestCollides && most >= best.placed().analysis().maxLayers() || !covers(placed)) {
                    ownCollisions.add(null);
                    continue;
                }
                int found = check.collisions(result, placed);
                ownCollisions.add(found >= 0 ? found : null);
                if (found == 0 && (bestCollides || most < best.placed().analysis().maxLayers())) {
                    best = tried;
                    bestCollides = false;
                    bestChecked = 0;
                }
            }
        }
        if (best == null) {
            // Where the refinement refused the thickness, the own triangles' failure is the
            // wrap's: their wider width's refusal, or what stopped them once they took it (the
            // cube at --thickness 0.03 --max-faces 200: the face limit, not the thickness).
            throw thrown(ownFailure != null && firstFailure instanceof ParameterException ? ownFailure : firstFailure);
        }
        return new Chosen(best.refinement(), best.result(), best.placed(), best.along(),
                tries > 1 ? java.util.Collections.unmodifiableList(layers) : List.of(),
                tries > 1 ? java.util.Collections.unmodifiableList(collisions) : List.of(),
                best.measureSeconds(), java.util.Collections.unmodifiableList(ownLayers), java.util.Collections.unmodifiableList(ownCollisions), bestChecked);
    }

    /**
     * {@code e} where it refuses a thickness, which one path's strip cannot take (over a quarter
     * of its default width) and another's may; thrown where it refuses anything else, whatever
     * the path.
     */
    private static ParameterException thicknessOnly(ParameterException e) {
        if (!"thickness".equals(e.parameter())) {
            throw e;
        }
        return e;
    }

    /** The failure of the paths tried, as the wrap's: a refusal of the thickness, or the wrap's own exception. */
    private static Wrap.WrapException thrown(Exception failure) {
        if (failure instanceof ParameterException p) {
            throw p;
        }
        return (Wrap.WrapException) failure;
    }

    /**
     * Whether a wrap's paper covers the whole model, as every wrap along the refinement does. One
     * along the model's own triangles may not, and a collision check does not see it: the shared
     * dodecahedron along its 36 own triangles from their first start leaves 0.01 % bare; with
     * splices that halved their triangles (tried in session 32, not kept), its 60 fanned from
     * their pentagons' centres made 10 layers against the refinement's 12 and left 0.018 % bare
     * (WrapTruths found three bare points of 20,000, two by its corners).
     */
    static boolean covers(PlacedWrap placed) {
        return placed.analysis().coverage() > 1 - COVERAGE_TOLERANCE;
    }

    /** The area of the model a wrap may leave bare, as a fraction: rounding's. */
    public static final double COVERAGE_TOLERANCE = 1e-9;

    /** A start's wrap placed in space and measured, how long that took its {@link Chosen#measureSeconds}. */
    private static Chosen placed(HamiltonianRefinement.Result begun, Wrap.Result result, double along) {
        long measuring = System.nanoTime();
        PlacedWrap placed = PlacedWrap.of(result);
        return new Chosen(begun, result, placed, along, (System.nanoTime() - measuring) * 1e-9);
    }

    /**
     * The path through the model's own triangles that the seam tries after the refinement's
     * starts ({@link CycleCoverPath}), or null where it tries none: where the mesh the refinement
     * refined has at most {@link #MOST_TRIANGLES} triangles (closed or with a boundary: figure3's
     * strip along its own triangles, from halfway, has 16 layers rather than 20, its paper sound
     * and every truth kept, since the walls along its cuts stand back no farther than their own
     * nests ask, docs/wrap.md, Limits), and a wrap along them at {@code width}
     * (NaN for their default) is likely to make at most {@link #MOST_FACES} faces, along a cycle.
     */
    public static HamiltonianRefinement.Result ownPath(HamiltonianRefinement.Result refinement, double width) {
        if (refinement.mesh().ownTriangles() || refinement.mesh().original().faceCount() > MOST_TRIANGLES) {
            return null;
        }
        HamiltonianRefinement.Result own = CycleCoverPath.of(refinement.mesh().original());
        // No shorter than the refinement's, it is cut everywhere as the refinement is (a lone
        // triangle: its three pieces round the incentre), and trying it only tries the
        // refinement's other starts after its first has failed (a needle of 0.011 degrees, whose
        // first start's tucks fail at once, then tucked for minutes from the others).
        return own != null && own.mesh().faceCount() < refinement.mesh().faceCount() && tries(own, width) > 1 ? own : null;
    }

    /**
     * The path through the model's own triangles that a big model is wrapped along instead of the
     * refinement, from its one start, or null where it is not: where the mesh the refinement
     * refined has more than {@link #MOST_TRIANGLES} triangles (wrapped from one start, unchecked:
     * no start of either path is tried against the other), and the path along its triangles
     * (on a surface with a boundary, some of them cut as the refinement cuts them; made whichever
     * {@link CycleCoverPath.Way} is likely to make fewest faces) is likely to
     * make fewer faces at {@code options}' width ({@link Wrap#likelyFaces};
     * the refinement's are taken at the default where none is given). Its 5n − 2 pieces become
     * about 1.1n triangles, each wider: the 5,000-triangle torus's likely faces 1,328,052 →
     * 390,447, the 5,120-triangle icosphere's 1,155,633 → 418,982, the cow's
     * ({@code common3d_spot.obj}) 4,774,632 → 1,008,739. Where the refinement is likely to make
     * more than {@link #HOPELESS} times the face limit, no wrap of either fits and the matching
     * is not sought (1.4 s on the 99,938 triangles of {@code common3d_nefertiti.obj}, its
     * refinement likely to make 1,400 times the limit).
     */
    public static HamiltonianRefinement.Result ownInstead(HamiltonianRefinement.Result refinement, Wrap.Options options) {
        if (refinement.mesh().ownTriangles() || refinement.mesh().original().faceCount() <= MOST_TRIANGLES) {
            return null;
        }
        long refined = Wrap.likelyFaces(refinement, options.width());
        if (refined > (long) HOPELESS * options.maxFaces() && refined != Long.MAX_VALUE) {
            return null;
        }
        // Of the ways to make the path (CycleCoverPath.Way), the one likely to make fewest faces:
        // its narrowest triangle sets the widest strip. Cut triangles at the leaves of the
        // splices' tree halved: the elephant with holes' 0.00107 -> 0.00151, 752,778 likely
        // faces at its widest, past the limit, -> about 370,000; slivers matched across their
        // longest sides first: igl_fertility.off's 0.2543 -> 0.4134, 832,963 -> 624,334. Unchecked
        // here, as the big model's wrap is, where figure3's short path with its leaves halved
        // crossed itself from both starts: the seam's short paths keep the plain way.
        HamiltonianRefinement.Result own = null;
        long faces = Long.MAX_VALUE;
        List<HamiltonianRefinement.Result> ways = CycleCoverPath.ways(refinement.mesh().original());
        for (HamiltonianRefinement.Result path : ways) {
            long likely = Wrap.likelyFaces(path, options.width());
            if (likely < faces) {
                own = path;
                faces = likely;
            }
        }
        if (faces > options.maxFaces()) {
            // No way fits at the width asked (the default: a third of its widest), and the strip
            // is widened to fit (at a width given, the wrap refused): each way run back too, each
            // triangle left across the side it was entered by, may take fewer passes or be wider
            // at its narrowest (igl_fertility.off's plain way: its widest 0.2543 -> 0.4513,
            // 1,930,445 faces likely at a third of it -> 1,210,416, fewer than any way run
            // forwards). Not where one fits: the layers change with the way round as with the
            // way, by chance (the 64 x 32 UV sphere's 48 -> 66, by its pole).
            for (HamiltonianRefinement.Result way : ways) {
                HamiltonianRefinement.Result back = way.reversed();
                long likely = Wrap.likelyFaces(back, options.width());
                if (likely < faces) {
                    own = back;
                    faces = likely;
                }
            }
        }
        return own != null && faces < refined ? own : null;
    }

    /**
     * How many times the face limit a refinement's wrap may be likely to make for the path along
     * the model's own triangles to be sought ({@link #ownInstead}): on the closed scans and
     * solids measured its likely faces at the default were 2.3 to 5.2 times fewer, and at its
     * widest strip 5 to 16 times (the cow 10.6, the CGAL elephant 5.1, {@code igl_fertility.off} 6.7).
     */
    static final int HOPELESS = 20;

    /** Where round the path through the model's own triangles its strip is tried beginning. */
    static final double[] OWN_TRIED = {0, 0.5};

    /** A watcher that is told nothing but is asked whether to stop: the tries along the own triangles, after the refinement's progress is full. */
    public static Wrap.Watcher stoppedBy(Wrap.Watcher watcher) {
        return new Wrap.Watcher() {
            @Override
            public void wrapped(int done, int total) {
            }

            @Override
            public boolean stopped() {
                return watcher.stopped();
            }
        };
    }

    /**
     * Where round its path a strip is begun so that its end is rolled round a spike's apex
     * (docs/wrap.md, Limits, "What 24 layers at the spike's apex would take"): the share of the
     * way round of the first triangle entered at a true sharp vertex, its corner there under the
     * preparation's target, whose triangle before has a corner there too (the path then ends on
     * that one, its base running from the vertex); NaN where no cyclic path has one. Tried
     * besides {@link #TRIED}: none of those begins there on the shared spike.
     */
    static double rollShare(HamiltonianRefinement.Result refinement) {
        IndexedPolygons mesh = refinement.mesh();
        double[] share = {Double.NaN};
        eachExit(refinement, (start, j, length, corners, exit) -> {
            int v = PathPlan.third(corners, exit);
            int[] before = corners(mesh, start + (j + length - 1) % length);
            if ((before[0] == v || before[1] == v || before[2] == v) && ApexRoll.sharpStart(mesh, corners, v)) {
                share[0] = (double) j / length;
                return false;
            }
            return true;
        });
        return share[0];
    }

    /**
     * Where round its path a strip is begun so that its end is rolled round a needle's tip at a
     * vertex that is no spike ({@link ApexRoll#needleEnd}): the share of the way round of the
     * triangle after the first whose base runs along the needle's edge from its tip, so that the
     * path ends on that one, its last pass along the needle into the tip; of several, the
     * sharpest tip's (the first of those as sharp), whose tucks would pile the most; NaN where no
     * cyclic path has one. None of {@link #TRIED} need begin there: an open square pyramid with a
     * needle face of 3° at its apex of 285° laid 60 layers from each, 59 of them tucks at the tip
     * (16 from this start).
     */
    static double needleShare(HamiltonianRefinement.Result refinement) {
        IndexedPolygons mesh = refinement.mesh();
        double[] sharpest = {Double.POSITIVE_INFINITY};
        double[] share = {Double.NaN};
        eachExit(refinement, (start, j, length, corners, exit) -> {
            for (int end = 0; end < 2; end++) {
                double corner = ApexRoll.needleCorner(mesh, corners, exit[end], exit[1 - end]);
                if (corner < sharpest[0]) {
                    sharpest[0] = corner;
                    share[0] = (double) ((j + 1) % length) / length;
                }
            }
            return true;
        });
        return share[0];
    }

    /** What {@link #eachExit} is told of a triangle of a cyclic path: where it lies round the path, its corners, the edge it leaves by. */
    private interface Exit {
        /** @return whether to go on to the next triangle */
        boolean visit(int componentStart, int j, int length, int[] corners, int[] exit);
    }

    /** Each triangle of each cyclic component of three or more, in path order, with the edge it shares with the next. */
    private static void eachExit(HamiltonianRefinement.Result refinement, Exit visitor) {
        IndexedPolygons mesh = refinement.mesh();
        int[] starts = refinement.componentStart();
        for (int c = 0; c + 1 < starts.length; c++) {
            int length = starts[c + 1] - starts[c];
            if (!refinement.cyclic(c) || length < 3) {
                continue;
            }
            for (int j = 0; j < length; j++) {
                int[] corners = corners(mesh, starts[c] + j);
                int[] exit = PathPlan.sharedEdge(corners, corners(mesh, starts[c] + (j + 1) % length));
                if (exit != null && !visitor.visit(starts[c], j, length, corners, exit)) {
                    return;
                }
            }
        }
    }

    private static int[] corners(IndexedPolygons mesh, int f) {
        return new int[] {mesh.faceVertex(f, 0), mesh.faceVertex(f, 1), mesh.faceVertex(f, 2)};
    }

    /**
     * How many starts are tried: all of {@link #TRIED} for a short path with a cyclic component
     * whose wrap at {@code width} (NaN for the default) is likely to make at most
     * {@link #MOST_FACES} faces, else one.
     */
    public static int tries(HamiltonianRefinement.Result refinement, double width) {
        if (refinement.mesh().faceCount() > MOST_TRIANGLES || Wrap.likelyFaces(refinement, width) > MOST_FACES) {
            return 1;
        }
        for (int c = 0; c < refinement.componentCount(); c++) {
            if (refinement.cyclic(c)) {
                return TRIED.length;
            }
        }
        return 1;
    }

    /**
     * The watcher of try k of {@code tries}: its progress a share of the whole, in turn, counted
     * out of the path's triangles still (a window says "of 58 triangles" of the cube's 58).
     */
    private static Wrap.Watcher share(Wrap.Watcher watcher, int k, int tries) {
        if (tries == 1) {
            return watcher;
        }
        return new Wrap.Watcher() {
            @Override
            public void wrapped(int done, int total) {
                watcher.wrapped((int) (((long) k * total + done) / tries), total);
            }

            @Override
            public boolean stopped() {
                return watcher.stopped();
            }
        };
    }
}
