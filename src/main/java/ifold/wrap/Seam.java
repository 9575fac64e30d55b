package ifold.wrap;

import ifold.mesh.IndexedPolygons;
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
 * to lie at a crowded corner far from where it begins.
 */
public final class Seam {
    /** Refinements of more triangles than this, all their components' together, are wrapped from their own start alone. */
    public static final int MOST_TRIANGLES = 1_000;

    /** Where round each cyclic path the strip is tried beginning, as a share of the way round. */
    static final double[] TRIED = {0, 0.25, 0.5, 0.75};

    private Seam() {
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
     * @param measureSeconds how long placing and measuring the wrap kept took (the other tries' count as wrapping)
     */
    public record Chosen(HamiltonianRefinement.Result refinement, Wrap.Result result, PlacedWrap placed, double along,
            List<Integer> layersTried, double measureSeconds) {
    }

    /**
     * Wraps the refinement from where it has fewest layers: from each start of {@link #TRIED}
     * where its paths have at most {@link #MOST_TRIANGLES} triangles in all and one is a cycle,
     * else from its own. Every cyclic component begins the same share of the way round its path:
     * one wrap's layers are its deepest strip's, and a start for each component would take a
     * wrap more to put together.
     * A start whose wrap fails (too many faces, a triangle the tucks cannot finish) is passed
     * over, unless it is the first: its failure is the wrap's.
     *
     * @throws Wrap.WrapException as {@link Wrap#wrap(HamiltonianRefinement.Result, Wrap.Options, Wrap.Watcher)}, from the refinement's own start
     */
    public static Chosen wrap(HamiltonianRefinement.Result refinement, Wrap.Options options, Wrap.Watcher watcher) throws Wrap.WrapException {
        int tries = tries(refinement);
        List<Double> shares = new ArrayList<>();
        for (int k = 0; k < tries; k++) {
            shares.add(TRIED[k]);
        }
        double rolled = tries > 1 ? rollShare(refinement) : Double.NaN;
        if (!Double.isNaN(rolled)) {
            shares.add(rolled);
            tries++;
        }
        Chosen best = null;
        List<Integer> layers = new ArrayList<>();
        for (int k = 0; k < tries; k++) {
            HamiltonianRefinement.Result begun = k == 0 ? refinement : refinement.begunAt(shares.get(k));
            Wrap.Result result;
            try {
                result = Wrap.wrap(begun, options, share(watcher, k, tries));
            } catch (Wrap.WrapException e) {
                if (k == 0) {
                    throw e;
                }
                layers.add(null); // kept in its place: the report lists the starts in order
                continue;
            }
            long measuring = System.nanoTime();
            PlacedWrap placed = PlacedWrap.of(result);
            double seconds = (System.nanoTime() - measuring) * 1e-9;
            int most = placed.analysis().maxLayers();
            layers.add(most);
            if (best == null || most < best.placed().analysis().maxLayers()) {
                best = new Chosen(begun, result, placed, shares.get(k), null, seconds);
            }
        }
        return new Chosen(best.refinement(), best.result(), best.placed(), best.along(),
                tries > 1 ? java.util.Collections.unmodifiableList(layers) : List.of(),
                best.measureSeconds());
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
        int[] starts = refinement.componentStart();
        for (int c = 0; c + 1 < starts.length; c++) {
            int length = starts[c + 1] - starts[c];
            if (!refinement.cyclic(c) || length < 3) {
                continue;
            }
            for (int j = 0; j < length; j++) {
                int[] corners = corners(mesh, starts[c] + j);
                int[] exit = PathPlan.sharedEdge(corners, corners(mesh, starts[c] + (j + 1) % length));
                if (exit == null) {
                    continue;
                }
                int v = PathPlan.third(corners, exit);
                int[] before = corners(mesh, starts[c] + (j + length - 1) % length);
                if ((before[0] == v || before[1] == v || before[2] == v) && ApexRoll.sharpStart(mesh, corners, v)) {
                    return (double) j / length;
                }
            }
        }
        return Double.NaN;
    }

    private static int[] corners(IndexedPolygons mesh, int f) {
        return new int[] {mesh.faceVertex(f, 0), mesh.faceVertex(f, 1), mesh.faceVertex(f, 2)};
    }

    /** How many starts are tried: all of {@link #TRIED} for a short path with a cyclic component, else one. */
    public static int tries(HamiltonianRefinement.Result refinement) {
        if (refinement.mesh().faceCount() > MOST_TRIANGLES) {
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
