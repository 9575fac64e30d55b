package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.sheet.HostFrame;
import ifold.sheet.Polygons2;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Where thick paper ends at the concave edges of its host: on the mitre, and on the walls of the
 * folds made along such an edge.
 *
 * <p>Over a concave edge the surface across rises towards the paper, by φ: a layer at height z
 * that ran up to the edge would run into the layers of the host across, which stack up from that
 * surface. Each layer ends where the plane halving the wedge of air above the edge (the mitre)
 * meets it, z·tan(φ/2) in from the edge ({@link HostFrame#mitred}); the layers of the host across
 * end on the same plane from the other side, and a layer going on across the edge bends there.
 *
 * <p>A fold along such an edge (a tuck folding a flap under along it) cannot stand out beyond the
 * edge as it does elsewhere: the surface across is in the way. Its bend is a wall across the
 * stack, standing in from the edge: a fold wrapping others about the edge stands nearer the edge
 * than those it wraps, a thickness a rank ({@link NestedBends}), and each wall at least as far in
 * as the mitre of its upper layer. So along an edge, the fold of rank r stands at C − r·T, C the
 * most any needs (its upper layer's mitre plus its rank in thicknesses). The layers of a fold, and
 * every layer between them, end on its wall where they would reach nearer the edge; paper in
 * another height goes on to its own mitre. The creases step back into the host (the creep of
 * thick paper); what the paper loses by it, at most the stack's height over tan(φ/2) plus the
 * ranks, is the price of thickness at a concave edge.
 *
 * <p>A cut between two convex hosts of one plane, on the line of a side running on past it, is
 * taken as a concave edge of no mitre ({@code BendRoom.CUT_MITRE}): across it lies the other
 * host's paper at the same heights, no room to stand out into, so folds nested along it stand
 * back into their own host, a thickness a rank, and no longer stand one inside another on the
 * cut's line, overlapping in its plane; the outermost half a thickness back ({@link #CUT_CLEARANCE}),
 * clear of the other host's paper. A fold that runs on beyond the cut along a convex
 * stretch of the same side stands out as before. A cut that is a whole edge of both hosts is
 * taken so too ({@code BendRoom.WHOLE_CUT_MITRE}), up to its ends, but for folds whose walls
 * other creases would run into ({@link #leaveOnCreaseWhereCrossed}: they stay on their crease;
 * walls stopped a tenth of a width short of reflex corners and of points where three or more
 * hosts meet before, their last stretch's nests on the cut's line). Its folds stand back half a
 * thickness ({@link #CUT_CLEARANCE}), and a thickness farther than each fold of the cut that
 * wraps them ({@link #cutWalls}), not by the most along the whole edge, nor by the most of the
 * folds chained to them by stretches that overlap or only touch: the other host's paper stands
 * back from the cut too, and a lone fold standing back as far as the deepest nest along the edge
 * left the surface beside the cut bare under its lower layer (the 14 × 6 torus's ring, 4
 * thicknesses by a spoke; figure3 by a spoke from an inner corner; figure3 along its own
 * triangles, whose passes tuck their ends along a spoke one after another, their stretches
 * touching end to end, a fold of levels 1 to 6 6.5 thicknesses back, chained to a nest of rank 6
 * by the corner (1.9, 0.1)).
 */
final class ConcaveWalls {
    /**
     * A fold's wall along edge {@code edge} of a host's polygon: from {@code from} to {@code to}
     * along the edge (from its first corner), for the levels {@code low} to {@code high}, standing
     * {@code in} from the edge's line; {@code line} is the edge (x, y of its first corner, dx, dy,
     * its length).
     */
    private record Wall(int edge, double from, double to, int low, int high, double in, double[] line) {
    }

    /**
     * The walls of one host that may hold one level, in the order they were made, with the edge
     * each stands along ({@code edges}, beside them, so that a wall along an edge the point is
     * far from is passed over without being read) and, for each edge of the host's polygon, how
     * far in the farthest of them stands (NaN: none along it).
     */
    private record LevelWalls(Wall[] walls, int[] edges, double[] farthest) {
        static final LevelWalls NONE = new LevelWalls(new Wall[0], new int[0], new double[0]);

        static LevelWalls of(List<Wall> walls, int edgesOfHost) {
            int[] edges = new int[walls.size()];
            double[] farthest = new double[edgesOfHost];
            java.util.Arrays.fill(farthest, Double.NaN);
            for (int i = 0; i < walls.size(); i++) {
                Wall wall = walls.get(i);
                edges[i] = wall.edge();
                farthest[wall.edge()] = Double.isNaN(farthest[wall.edge()]) ? wall.in() : Math.max(farthest[wall.edge()], wall.in());
            }
            return new LevelWalls(walls.toArray(new Wall[0]), edges, farthest);
        }

        /**
         * The edges whose farthest wall here could move frame point p (bit k for edge k): p lies
         * nearer the edge's line than that wall stands ({@link HostFrame#keepsFrom}, the test
         * {@link HostFrame#keepFrom} makes). Every edge where the polygon has more than 64.
         */
        long reaching(HostFrame frame, double[] p) {
            if (farthest.length > Long.SIZE) {
                return -1L;
            }
            long reach = 0;
            for (int k = 0; k < farthest.length; k++) {
                if (!Double.isNaN(farthest[k]) && frame.keepsFrom(k, farthest[k], p)) {
                    reach |= 1L << k;
                }
            }
            return reach;
        }
    }

    /**
     * A fold standing back from its crease: from (ax, ay) to (bx, by) on its host, its layers
     * {@code low} to {@code high} on the side away from (nx, ny), the way it would stand out,
     * {@code keep} back from the crease. Back to back with another on its crease line ({@link
     * NestedBends#backToBack}), half a thickness, its bend reaching the crease where the other's
     * does; or, nested on one line in folds that stand on it ({@code stepping}), a thickness for
     * each, its bend standing there too.
     */
    private record BackWall(double ax, double ay, double bx, double by, double nx, double ny, int low, int high, double keep,
            boolean stepping) {
    }

    private final double thickness;
    private final double tolerance;
    /**
     * The walls on each host that hold each level, in the order they were made: a host of a
     * big torus has hundreds of walls, and each point of paper placed looked through them all.
     */
    private final LevelWalls[][] wallsByLevel;
    /** The walls on each host along each edge of its polygon, by {@link #key} (for the pieces of paper, {@link #wallsAt}). */
    private final Map<Long, List<Wall>> wallsAlong = new HashMap<>();
    /**
     * The folds back to back on each host, by host (null where none): an array, as every point
     * of paper placed asks for its host's, and a map keyed by boxed hosts made an Integer a
     * point (4.6M on the 5,000-triangle torus).
     */
    private final BackWall[][] backWallsOf;
    /** Each bend's own wall where it steps back into its layers, nested on one line (null where it does not). */
    private final BackWall[] stepsBack;
    private final boolean[] along;
    /** How high each host's stack stands: the top of its highest layer (for the stops of convex edges, {@link HostFrame.Stop}). */
    private final double[] stackTop;
    /** By host and corner, whether the corner lies inside its face ({@link #cornersInFace}). */
    private final boolean[][] inFace;

    private ConcaveWalls(double thickness, double tolerance, List<List<Wall>> wallsOf, BackWall[][] backWallsOf, BackWall[] stepsBack,
            boolean[] along, double[] stackTop, HostFrame[] frames, boolean[][] inFace) {
        this.thickness = thickness;
        this.inFace = inFace;
        this.stepsBack = stepsBack;
        this.tolerance = tolerance;
        this.backWallsOf = backWallsOf;
        this.along = along;
        this.stackTop = stackTop;
        this.wallsByLevel = new LevelWalls[wallsOf.size()][];
        for (int h = 0; h < wallsOf.size(); h++) {
            List<Wall> walls = wallsOf.get(h) == null ? List.of() : wallsOf.get(h);
            int top = -1;
            for (Wall wall : walls) {
                wallsAlong.computeIfAbsent(key(h, wall.edge()), k -> new ArrayList<>()).add(wall);
                top = Math.max(top, wall.high());
            }
            List<List<Wall>> byLevel = new ArrayList<>();
            for (int level = 0; level <= top; level++) {
                byLevel.add(new ArrayList<>());
            }
            for (Wall wall : walls) {
                for (int level = Math.max(0, wall.low()); level <= wall.high(); level++) {
                    byLevel.get(level).add(wall);
                }
            }
            wallsByLevel[h] = new LevelWalls[top + 1];
            for (int level = 0; level <= top; level++) {
                wallsByLevel[h][level] = LevelWalls.of(byLevel.get(level), frames[h].corners().length / 2);
            }
        }
    }

    /**
     * The walls of {@code host} that may hold paper at {@code level} (a layer's, or a height
     * between two): those that hold the whole level nearest below it to rounding; a wall holds
     * whole levels from its low to its high, so one holding a height between two holds both.
     */
    private LevelWalls wallsNear(int host, double level) {
        LevelWalls[] byLevel = wallsByLevel[host];
        int k = (int) Math.floor(level + Tolerance.RELATIVE_EQUALITY);
        return k < 0 || k >= byLevel.length ? LevelWalls.NONE : byLevel[k];
    }

    private static final BackWall[] NO_BACK_WALLS = new BackWall[0];

    /**
     * The walls of {@code bends} that lie along a concave edge of their host, with the
     * {@code ranks} NestedBends gave them; {@code stackTop} is how high each host's stack stands,
     * {@code outs} how far each bend stands out from its crease, walls aside (0 for one along a
     * cut or a concave edge, which has no room there either way).
     */
    static ConcaveWalls of(List<NestedBends.Bend> bends, int[] ranks, int[] backToBack, HostFrame[] frames, double thickness,
            double tolerance, double[] stackTop, double[] outs) {
        boolean[] along = new boolean[bends.size()];
        int[] edgeOf = new int[bends.size()];
        // The most any fold along an edge needs, by host and edge: its upper layer's mitre plus its rank.
        Map<Long, Double> most = new HashMap<>();
        boolean[] onCut = new boolean[bends.size()];
        double[] need = new double[bends.size()];
        // Where each fold runs along its edge, from and to (the edge's start at 0, its end at its length).
        double[] from = new double[bends.size()];
        double[] to = new double[bends.size()];
        for (int k = 0; k < bends.size(); k++) {
            NestedBends.Bend bend = bends.get(k);
            HostFrame frame = frames[bend.host()];
            edgeOf[k] = concaveEdge(frame, bend, tolerance);
            if (edgeOf[k] < 0) {
                continue;
            }
            along[k] = true;
            double[] edge = frame.edge(edgeOf[k]);
            double sa = ((bend.ax() - edge[0]) * edge[2] + (bend.ay() - edge[1]) * edge[3]) / edge[4];
            double sb = ((bend.bx() - edge[0]) * edge[2] + (bend.by() - edge[1]) * edge[3]) / edge[4];
            from[k] = Math.min(sa, sb);
            to[k] = Math.max(sa, sb);
            double tan = frame.mitreAlong(edgeOf[k], bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance);
            need[k] = (bend.high() + 0.5) * thickness * tan + ranks[k] * thickness;
            onCut[k] = Math.abs(tan - BendRoom.WHOLE_CUT_MITRE) < BendRoom.CUT_MITRE / 2; // a whole cut: walls by nest
            if (tan <= HostFrame.CUT_TAN) {
                need[k] += CUT_CLEARANCE * thickness; // along a cut, either kind
            }
            if (!onCut[k]) {
                most.merge(key(bend.host(), edgeOf[k]), need[k], Math::max);
            }
        }
        // Where each wall would stand with every fold of the cut walled, to find the folds whose
        // walls another crease runs into; the nests of those left are taken again without them.
        boolean[][] inFace = cornersInFace(frames);
        double[] reach = cutWalls(bends, along, onCut, edgeOf, need, ranks, from, to, thickness, tolerance, frames, inFace);
        for (int k = 0; k < bends.size(); k++) {
            reach[k] += 0.5 * thickness; // the wall, and the half of the paper's thickness on its far side
        }
        // The levels each wall holds: its own, widened where a crease ends beside it.
        int[] lows = new int[bends.size()];
        int[] highs = new int[bends.size()];
        for (int k = 0; k < bends.size(); k++) {
            lows[k] = bends.get(k).low();
            highs[k] = bends.get(k).high();
        }
        leaveOnCreaseWhereCrossed(bends, outs, along, onCut, edgeOf, reach, frames, tolerance, thickness, lows, highs);
        double[] cutIn = cutWalls(bends, along, onCut, edgeOf, need, ranks, from, to, thickness, tolerance, frames, inFace);
        List<List<Wall>> wallsOf = new ArrayList<>(java.util.Collections.nCopies(frames.length, (List<Wall>) null));
        for (int k = 0; k < bends.size(); k++) {
            if (!along[k]) {
                continue;
            }
            NestedBends.Bend bend = bends.get(k);
            double[] edge = frames[bend.host()].edge(edgeOf[k]);
            double in = onCut[k] ? cutIn[k] : most.get(key(bend.host(), edgeOf[k])) - ranks[k] * thickness;
            if (wallsOf.get(bend.host()) == null) {
                wallsOf.set(bend.host(), new ArrayList<>());
            }
            // A fold along a whole cut up to a corner where another whole cut meets it holds its
            // layers up to that cut, not only beside its crease: at an obtuse corner the strip
            // beside the crease leaves out a sliver by the other cut, where its layers went unmoved.
            // Only at a corner inside the face: at a reflex corner of the face (the star prism's
            // inner corners, the cuts 108 degrees apart) the walls held so crossed the tips' paper.
            HostFrame frame = frames[bend.host()];
            int corners = frame.corners().length / 2;
            boolean fromCorner = onCut[k] && from[k] <= tolerance && wholeCut(frame, (edgeOf[k] + corners - 1) % corners)
                    && inFace[bend.host()][edgeOf[k]];
            boolean toCorner = onCut[k] && to[k] >= edge[4] - tolerance && wholeCut(frame, (edgeOf[k] + 1) % corners)
                    && inFace[bend.host()][(edgeOf[k] + 1) % corners];
            wallsOf.get(bend.host()).add(new Wall(edgeOf[k], fromCorner ? Double.NEGATIVE_INFINITY : from[k],
                    toCorner ? Double.POSITIVE_INFINITY : to[k], lows[k], highs[k], in, edge));
        }
        // Two folds back to back on one crease line cannot both stand on it: each stands back half
        // a thickness, its layers ending on its own side (where it does not already stand on a wall).
        List<List<BackWall>> backWallsOf = new ArrayList<>(java.util.Collections.nCopies(frames.length, (List<BackWall>) null));
        for (int k = 0; k < bends.size(); k++) {
            if (backToBack[k] < 0 || along[k] || along[backToBack[k]]) {
                continue;
            }
            NestedBends.Bend bend = bends.get(k);
            if (backWallsOf.get(bend.host()) == null) {
                backWallsOf.set(bend.host(), new ArrayList<>());
            }
            backWallsOf.get(bend.host())
                    .add(new BackWall(bend.ax(), bend.ay(), bend.bx(), bend.by(), bend.nx(), bend.ny(), bend.low(), bend.high(),
                            thickness / 2, false));
        }
        BackWall[] stepsBack = stepBack(bends, backToBack, frames, thickness, tolerance, outs, along);
        for (int k = 0; k < bends.size(); k++) {
            int host = bends.get(k).host();
            if (stepsBack[k] != null) {
                if (backWallsOf.get(host) == null) {
                    backWallsOf.set(host, new ArrayList<>());
                }
                backWallsOf.get(host).add(stepsBack[k]);
            }
        }
        BackWall[][] backWallsByHost = new BackWall[frames.length][];
        for (int h = 0; h < frames.length; h++) {
            backWallsByHost[h] = backWallsOf.get(h) == null ? null : backWallsOf.get(h).toArray(new BackWall[0]);
        }
        return new ConcaveWalls(thickness, tolerance, wallsOf, backWallsByHost, stepsBack, along, stackTop, frames, inFace);
    }

    /**
     * The folds that step back into their layers (null for the rest): nested on one line that is
     * no side of their host, none of them standing out ({@code outs}: no room beyond the line)
     * nor on a wall, nor back to back, each stands back a thickness for each such fold wrapping
     * it, its layers ending there and its bend standing there, as walls do at a concave edge. All
     * on their crease, their bends stood one inside another in the line's plane: figure3 by its
     * corner (1.1, -0.15), a fold of levels 0 to 3 from the corner, 35 thicknesses long, with no
     * room (it would stand out across the spoke's line from the corner), and the fold of levels 1
     * and 2 it wraps, 4 pairs in one plane. Nests along a side (a cut) are left as they are: where
     * they end at a corner beside another cut's walls, their levels interleaved, stepping back
     * crossed those walls (figure3, one start: 26 crossing pairs, 1.5 T deep, all but one within
     * 0.11 of (0.8, 1.05)). Nor one whose step would take its layers out of a bend wrapping them
     * ({@link #steppingOut}).
     */
    private static BackWall[] stepBack(List<NestedBends.Bend> bends, int[] backToBack, HostFrame[] frames, double thickness,
            double tolerance, double[] outs, boolean[] along) {
        BackWall[] stepsBack = new BackWall[bends.size()];
        Map<Integer, List<Integer>> onCrease = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            NestedBends.Bend bend = bends.get(k);
            if (!along[k] && !(outs[k] > 0) && backToBack[k] < 0 && sideAlong(frames[bend.host()], bend, tolerance) < 0) {
                onCrease.computeIfAbsent(bend.host(), h -> new ArrayList<>()).add(k);
            }
        }
        for (List<Integer> ofHost : onCrease.values()) {
            // By their lowest level: only folds lower begin can wrap a fold, and a host holds
            // thousands on the 5,000-triangle torus (every pair tried, 5 % of its run's time).
            int[] byLow = ofHost.stream().mapToInt(Integer::intValue).toArray();
            int[] lows = new int[byLow.length];
            sortByLow(byLow, bends);
            for (int i = 0; i < byLow.length; i++) {
                lows[i] = bends.get(byLow[i]).low();
            }
            for (int k : ofHost) {
                NestedBends.Bend bend = bends.get(k);
                int wrapping = 0;
                for (int i = 0; i < byLow.length && lows[i] < bend.low(); i++) {
                    NestedBends.Bend other = bends.get(byLow[i]);
                    if (other.high() > bend.high() && other.nx() * bend.nx() + other.ny() * bend.ny() > 0
                            && sameLine(other, bend, thickness * PaperInSpace.NEST_TOLERANCE) && overlapping(other, bend, tolerance)) {
                        wrapping++;
                    }
                }
                if (wrapping > 0 && !steppingOut(k, wrapping * thickness, bends, outs, tolerance)) {
                    stepsBack[k] = new BackWall(bend.ax(), bend.ay(), bend.bx(), bend.by(), bend.nx(), bend.ny(), bend.low(), bend.high(),
                            wrapping * thickness, true);
                }
            }
        }
        return stepsBack;
    }

    /** Sorts the bends' indices by their lowest level. */
    private static void sortByLow(int[] indices, List<NestedBends.Bend> bends) {
        long[] keyed = new long[indices.length];
        for (int i = 0; i < indices.length; i++) {
            keyed[i] = ((long) bends.get(indices[i]).low() << 32) | indices[i];
        }
        java.util.Arrays.sort(keyed);
        for (int i = 0; i < indices.length; i++) {
            indices[i] = (int) keyed[i];
        }
    }

    /**
     * Whether bend k's layers, stepping {@code keep} back from its crease, would step out of a
     * bend from its crease whose levels wrap k's: one of its host, its crease off k's line with an
     * end on k's crease, where the step takes them beyond that crease and the bend stands out less
     * than the step ({@code outs}; the
     * rings of 6 to 16 around by 6 across: by the corners of their hosts on the top, a fold of
     * levels 2 and 3 stepping a thickness back from its crease's end, where folds of levels 1 to
     * 6 and 0 to 7 standing out 0.74 and 1.48 thicknesses begin, crossed their bends).
     */
    private static boolean steppingOut(int k, double keep, List<NestedBends.Bend> bends, double[] outs, double tolerance) {
        NestedBends.Bend bend = bends.get(k);
        for (int j = 0; j < bends.size(); j++) {
            NestedBends.Bend other = bends.get(j);
            if (other.host() != bend.host() || other.low() >= bend.low() || other.high() <= bend.high()
                    || !onCrease(bend, other.ax(), other.ay(), tolerance) && !onCrease(bend, other.bx(), other.by(), tolerance)
                    || onCrease(bend, other.ax(), other.ay(), tolerance) && onCrease(bend, other.bx(), other.by(), tolerance)) {
                continue;
            }
            double beyond = -keep * (bend.nx() * other.nx() + bend.ny() * other.ny());
            if (beyond > tolerance && outs[j] < keep - tolerance) {
                return true;
            }
        }
        return false;
    }

    /**
     * By host and corner (corner k where edge k starts), whether the corner lies inside its face:
     * every host of its plane with a corner there is bounded there by whole cuts on both sides
     * (figure3's corners (0.8, 1.05) and (2.1, 1.15), where four and five cuts meet), rather than
     * by an edge of the face (the star prism's inner corners, reflex corners of its star faces,
     * where the tips' hosts meet the face's edges).
     */
    private static boolean[][] cornersInFace(HostFrame[] frames) {
        // The corners not between two whole cuts, filed by a cell of space NEAR across: each
        // corner between two is compared only with those in the cells about it, not with every
        // host's (a model of many cut faces would cost the square of its hosts).
        Map<Long, List<int[]>> open = new HashMap<>();
        for (int h = 0; h < frames.length; h++) {
            int n = frames[h].corners().length / 2;
            for (int c = 0; c < n; c++) {
                if (!(wholeCut(frames[h], c) && wholeCut(frames[h], (c + n - 1) % n))) {
                    double[] p = inSpace(frames[h], c);
                    open.computeIfAbsent(nearCell(p, 0, 0, 0), key -> new ArrayList<>()).add(new int[] {h, c});
                }
            }
        }
        boolean[][] inFace = new boolean[frames.length][];
        for (int h = 0; h < frames.length; h++) {
            int n = frames[h].corners().length / 2;
            inFace[h] = new boolean[n];
            for (int c = 0; c < n; c++) {
                inFace[h][c] = wholeCut(frames[h], c) && wholeCut(frames[h], (c + n - 1) % n) && cutsOnly(frames, frames[h], c, open);
            }
        }
        return inFace;
    }

    /** Corners of hosts this near in space are one ({@link #cornersInFace}). */
    private static final double NEAR = 100 * Tolerance.ON_PLANE;

    /** The cell NEAR across of point p moved by (dx, dy, dz) cells. */
    private static long nearCell(double[] p, int dx, int dy, int dz) {
        long x = (long) Math.floor(p[0] / NEAR) + dx;
        long y = (long) Math.floor(p[1] / NEAR) + dy;
        long z = (long) Math.floor(p[2] / NEAR) + dz;
        return (x * 0x9E3779B97F4A7C15L + y) * 0xC2B2AE3D27D4EB4FL + z;
    }

    /**
     * Whether no host of the plane of corner c of the frame has a corner there that is not
     * between whole cuts on both sides ({@code open}: such corners by {@link #nearCell}).
     */
    private static boolean cutsOnly(HostFrame[] frames, HostFrame frame, int c, Map<Long, List<int[]>> open) {
        double[] p = inSpace(frame, c);
        double[] normal = frame.normal();
        for (int dx = -1; dx <= 1; dx++) {
            for (int dy = -1; dy <= 1; dy++) {
                for (int dz = -1; dz <= 1; dz++) {
                    for (int[] corner : open.getOrDefault(nearCell(p, dx, dy, dz), List.of())) {
                        HostFrame other = frames[corner[0]];
                        double[] n2 = other.normal();
                        if (normal[0] * n2[0] + normal[1] * n2[1] + normal[2] * n2[2] < 1 - Tolerance.ON_PLANE) {
                            continue;
                        }
                        double[] q = inSpace(other, corner[1]);
                        double apart = Math.sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
                        if (apart <= NEAR) {
                            return false;
                        }
                    }
                }
            }
        }
        return true;
    }

    /** Corner c of the frame's polygon, in space. */
    private static double[] inSpace(HostFrame frame, int c) {
        double x = frame.corners()[2 * c];
        double y = frame.corners()[2 * c + 1];
        double[] o = frame.origin();
        return new double[] {o[0] + x * frame.ex()[0] + y * frame.ey()[0], o[1] + x * frame.ex()[1] + y * frame.ey()[1],
                o[2] + x * frame.ex()[2] + y * frame.ey()[2]};
    }

    /** Whether edge k of the frame's polygon is a whole cut, a cut between two hosts of a plane from end to end ({@code BendRoom.WHOLE_CUT_MITRE}). */
    private static boolean wholeCut(HostFrame frame, int k) {
        double[] stretches = frame.mitre() == null ? null : frame.mitre()[k];
        if (stretches == null) {
            return false;
        }
        for (int i = 0; i + 2 < stretches.length; i += 3) {
            if (Math.abs(stretches[i + 2] - BendRoom.WHOLE_CUT_MITRE) >= BendRoom.CUT_MITRE / 2) {
                return false;
            }
        }
        double[] edge = frame.edge(k);
        return withinStretches(stretches, 0, edge[4], Tolerance.ON_PLANE * edge[4]);
    }

    /** Whether both ends of b's crease lie on the line of a's, within {@code within}. */
    private static boolean sameLine(NestedBends.Bend a, NestedBends.Bend b, double within) {
        double dx = a.bx() - a.ax();
        double dy = a.by() - a.ay();
        double length = Math.sqrt(dx * dx + dy * dy);
        return Math.abs((b.ax() - a.ax()) * dy - (b.ay() - a.ay()) * dx) / length <= within
                && Math.abs((b.bx() - a.ax()) * dy - (b.by() - a.ay()) * dx) / length <= within;
    }

    /** Whether the creases of a and b, on one line, share more than the tolerance of it. */
    private static boolean overlapping(NestedBends.Bend a, NestedBends.Bend b, double tolerance) {
        double dx = a.bx() - a.ax();
        double dy = a.by() - a.ay();
        double length = Math.sqrt(dx * dx + dy * dy);
        double sa = ((b.ax() - a.ax()) * dx + (b.ay() - a.ay()) * dy) / length;
        double sb = ((b.bx() - a.ax()) * dx + (b.by() - a.ay()) * dy) / length;
        return Math.min(length, Math.max(sa, sb)) - Math.max(0, Math.min(sa, sb)) > tolerance;
    }

    /**
     * How far, in thicknesses, each fold along a cut stands back from it at the least (the
     * outermost of a nest; those it wraps a thickness a rank farther). Paper is a thickness thick,
     * and the walls of both hosts' outermost folds stood on the cut's line, in one plane: on the
     * whole cuts square_frame 128 of its 138 pairs, figure3 51 of 243, the rings 6 to 16 × 6 most
     * of theirs; on the cuts along a side's line t_prism 3 of 15, the polycube plus 16 of 60.
     */
    static final double CUT_CLEARANCE = 0.5;

    /**
     * Leaves on its crease each fold along a whole cut whose wall another crease of its host would
     * run into, or widens the levels the wall holds ({@code lows}, {@code highs}, below). Its wall, {@code reach} in from the cut with the half thickness beyond, moves the
     * paper of its levels there; a crease with one layer among those levels and the other not,
     * ending within that reach beside the wall, not square to the cut, would have the one layer's
     * end moved off it and the other left, the bend between them leaning through the wall. Such a
     * crease:
     * <ul>
     * <li>runs into the host from an end of the cut, ending on the fold's crease there (the line
     *     of the neighbour's side running on past a reflex corner: on the L prism a fold along
     *     y = 1 ending on a short fold along the diagonal, 3 crossing pairs, 0.28 T);
     * <li>runs along another cut from the same end, where three or more hosts meet, its fold
     *     wrapping more levels, and the bend of one of the two, its layers held back from the
     *     other's cut by different walls there, would slant through a wall along that cut ({@link
     *     #slantsThrough}). Of two such folds the one wrapping more stands back; with both on their
     *     crease figure3 had 342 pairs in one plane rather than 243. Elsewhere both stand back, their
     *     walls meeting in the corner of the two cuts (each holding paper up to the other cut, paper
     *     within both squashed into it, {@link #place}): figure3's nests there left on their crease
     *     stood in one plane, 124 of its 128 pairs (walled both before these, they crossed in 76
     *     pairs, 1.5 T);
     * </ul>
     * A crease ending within the reach, off the cut's line, beside the wall leaves the fold walled,
     * but the wall holds that crease's other layer too ({@code lows}, {@code highs}: its levels
     * widened to both), so that the bend stands square behind the wall rather than slanting from
     * its unheld layer at the crease's end through the wall's foot to its held layer. Figure3 by
     * its reflex corner (3.05, 0.9): a fold of levels 0 to 2, its crease from the cut's line 12.8
     * thicknesses from the corner to 2.6 in from it, beside the walls of a nest of levels 1 to 5
     * and 2 to 3 (3.5 and 4.5 thicknesses back, in a nest with others along the cut); walled with
     * their own levels, 2 crossing pairs (0.05 T); left on their crease, as before, 4 pairs in one
     * plane on the cut's line.
     * And a bend standing out from a crease at an end of the cut, not along a side, leaning over
     * the fold's span, stands over where the wall is (the L prism's top, at its reflex corner, a
     * fold square to the diagonal standing out 3 thicknesses along it: 3 crossing pairs, 0.35 T,
     * once walls stood half a thickness back), where it stands out at all ({@code outs}, as the
     * bends stand out before any wall is known): one with no room stands on its crease and meets
     * no wall (figure3's nest along the spoke from its reflex corner (1.1, -0.15), levels 0 to 9,
     * 4 to 7 and 5 to 6, was left on its crease for a rank-1 fold from the corner that stands out
     * 0 there: their walls on one line, 12 pairs in one plane). A fold along a side over a convex
     * edge stands out over that side, beyond the host, and meets no wall of the cut.
     */
    private static void leaveOnCreaseWhereCrossed(List<NestedBends.Bend> bends, double[] outs, boolean[] along,
            boolean[] onCut, int[] edgeOf, double[] reach, HostFrame[] frames, double tolerance, double thickness, int[] lows,
            int[] highs) {
        Map<Integer, List<Integer>> byHost = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            if (along[k] && onCut[k]) {
                byHost.computeIfAbsent(bends.get(k).host(), h -> new ArrayList<>());
            }
        }
        for (int j = 0; j < bends.size() && !byHost.isEmpty(); j++) {
            List<Integer> ofHost = byHost.get(bends.get(j).host());
            if (ofHost != null) {
                ofHost.add(j);
            }
        }
        boolean[] crossed = new boolean[bends.size()];
        for (int k = 0; k < bends.size(); k++) {
            if (along[k] && onCut[k]) {
                HostFrame frame = frames[bends.get(k).host()];
                crossed[k] = crossed(k, bends, outs, byHost.get(bends.get(k).host()), frame.edge(edgeOf[k]), reach, frame,
                        tolerance, along, onCut, edgeOf, thickness, lows, highs);
            }
        }
        for (int k = 0; k < bends.size(); k++) {
            along[k] &= !crossed[k];
        }
    }

    /**
     * Whether a crease of bend k's host (its bends {@code ofHost}) runs into k's wall, along edge
     * {@code edge} of its host, {@code reach} in from it ({@link #leaveOnCreaseWhereCrossed}).
     */
    private static boolean crossed(int k, List<NestedBends.Bend> bends, double[] outs, List<Integer> ofHost, double[] edge,
            double[] reaches, HostFrame frame, double tolerance, boolean[] along, boolean[] onCut, int[] edgeOf, double thickness,
            int[] lows, int[] highs) {
        double reach = reaches[k];
        NestedBends.Bend wall = bends.get(k);
        for (int j : ofHost) {
            NestedBends.Bend other = bends.get(j);
            if (j == k) {
                continue;
            }
            int side = sideAlong(frame, other, tolerance);
            double sideTan = side < 0 ? 0 : frame.mitreAlong(side, other.ax(), other.ay(), other.bx(), other.by(), tolerance);
            boolean alongACut = sideTan > 0 && sideTan <= HostFrame.CUT_TAN;
            if (side >= 0 && !alongACut) {
                continue; // along a side over a convex edge: it stands out beyond the host
            }
            boolean aOn = onCrease(wall, other.ax(), other.ay(), tolerance);
            boolean bOn = onCrease(wall, other.bx(), other.by(), tolerance);
            boolean aEnd = aOn && atEnd(edge, other.ax(), other.ay(), tolerance);
            boolean bEnd = bOn && atEnd(edge, other.bx(), other.by(), tolerance);
            if (aOn && bOn) {
                continue; // along the fold itself
            }
            if (side < 0 && outs[j] > 0 && (aEnd || bEnd) && leansOver(wall, other, aEnd)) {
                return true;
            }
            boolean lowHeld = other.low() >= wall.low() && other.low() <= wall.high();
            boolean highHeld = other.high() >= wall.low() && other.high() <= wall.high();
            if (lowHeld == highHeld) {
                continue; // both layers held, or neither: they stay together
            }
            if (aEnd || bEnd) {
                int wraps = other.high() - other.low();
                int ownWraps = wall.high() - wall.low();
                if (side < 0) {
                    return true; // into the host
                }
                if (wraps > ownWraps || wraps == ownWraps && j < k) {
                    // Along another cut wrapping more (or as many, and made first): both walled, where
                    // either's bend would run through a wall along the other's cut.
                    double cx = aEnd ? other.ax() : other.bx();
                    double cy = aEnd ? other.ay() : other.by();
                    if (slantsThrough(k, j, cx, cy, bends, reaches, along, onCut, edgeOf, ofHost, tolerance, thickness)
                            || slantsThrough(j, k, cx, cy, bends, reaches, along, onCut, edgeOf, ofHost, tolerance, thickness)) {
                        return true;
                    }
                }
            } else if (side < 0 && endsBesideWall(wall, other, edge, reach, frame, tolerance)) {
                // The wall holds the other layer too, so that the bend stands behind it.
                lows[k] = Math.min(lows[k], other.low());
                highs[k] = Math.max(highs[k], other.high());
            }
        }
        return false;
    }

    /**
     * Whether fold k's bend, walled along its cut from the corner (cx, cy) where fold j's cut meets
     * it, would run through a wall along j's cut. The walls along j's cut from that corner ({@code
     * reaches}, less the half thickness beyond each) hold k's layers back from j's cut, each as far
     * as the farthest wall holding it, and squash them into the corner of the two cuts' walls
     * short of that ({@link #place}); so k's bend runs from its lower layer, as far from j's cut as
     * that is held, to its upper layer, as far as that is, slanting across the walls standing
     * between. A wall there whose levels meet the heights the bend spans at its distance (above its
     * lower layer up to the slant, or from the slant up to its upper layer) is run through: on
     * figure3 by (2.1, 1.15), a fold of levels 0 to 3 from its lower layer unheld to its upper
     * layer 2.5 thicknesses back, through a wall of levels 1 to 5 standing 1.5 back (5 crossing
     * pairs, 0.06 T).
     */
    private static boolean slantsThrough(int k, int j, double cx, double cy, List<NestedBends.Bend> bends, double[] reaches,
            boolean[] along, boolean[] onCut, int[] edgeOf, List<Integer> ofHost, double tolerance, double thickness) {
        NestedBends.Bend fold = bends.get(k);
        double atLow = 0;
        double atHigh = 0;
        for (int g : ofHost) {
            NestedBends.Bend wall = bends.get(g);
            if (fromCorner(g, j, cx, cy, bends, along, onCut, edgeOf, tolerance)) {
                double in = reaches[g] - thickness / 2;
                atLow = wall.low() <= fold.low() && fold.low() <= wall.high() ? Math.max(atLow, in) : atLow;
                atHigh = wall.low() <= fold.high() && fold.high() <= wall.high() ? Math.max(atHigh, in) : atHigh;
            }
        }
        if (Math.abs(atHigh - atLow) <= tolerance) {
            return false; // it stands square: no slant
        }
        int span = fold.high() - fold.low();
        for (int g : ofHost) {
            NestedBends.Bend wall = bends.get(g);
            double in = reaches[g] - thickness / 2;
            if (!fromCorner(g, j, cx, cy, bends, along, onCut, edgeOf, tolerance) || in <= Math.min(atLow, atHigh) + tolerance
                    || in >= Math.max(atLow, atHigh) - tolerance) {
                continue;
            }
            double bottom = atLow < atHigh ? fold.low() : fold.high() - span * (in - atHigh) / (atLow - atHigh);
            double top = atLow < atHigh ? fold.low() + span * (in - atLow) / (atHigh - atLow) : fold.high();
            if (wall.low() < top - Tolerance.RELATIVE_EQUALITY && wall.high() > bottom + Tolerance.RELATIVE_EQUALITY) {
                return true;
            }
        }
        return false;
    }

    /** Whether fold g is walled along the same cut as fold j, its crease from the corner (cx, cy). */
    private static boolean fromCorner(int g, int j, double cx, double cy, List<NestedBends.Bend> bends, boolean[] along, boolean[] onCut,
            int[] edgeOf, double tolerance) {
        NestedBends.Bend wall = bends.get(g);
        return along[g] && onCut[g] && edgeOf[g] == edgeOf[j] && bends.get(g).host() == bends.get(j).host()
                && (Math.hypot(wall.ax() - cx, wall.ay() - cy) <= tolerance || Math.hypot(wall.bx() - cx, wall.by() - cy) <= tolerance);
    }

    /** Whether the bend {@code other}, its crease from an end of the wall's crease (its a end, or b), stands out over the wall's span. */
    private static boolean leansOver(NestedBends.Bend wall, NestedBends.Bend other, boolean fromA) {
        double cx = fromA ? other.ax() : other.bx();
        double cy = fromA ? other.ay() : other.by();
        // Into the span: towards the wall's end farther from that corner.
        boolean aFarther = Math.hypot(wall.ax() - cx, wall.ay() - cy) > Math.hypot(wall.bx() - cx, wall.by() - cy);
        double dx = (aFarther ? wall.ax() : wall.bx()) - cx;
        double dy = (aFarther ? wall.ay() : wall.by()) - cy;
        return other.nx() * dx + other.ny() * dy > 0;
    }

    /**
     * Whether an end of the crease of {@code other}, not square to the cut (edge {@code edge} of
     * the host) nor along it, lies off the cut's line, less than {@code reach} into the host,
     * beside the wall's crease.
     */
    private static boolean endsBesideWall(NestedBends.Bend wall, NestedBends.Bend other, double[] edge, double reach, HostFrame frame,
            double tolerance) {
        double jx = other.bx() - other.ax();
        double jy = other.by() - other.ay();
        double cosine = Math.abs(jx * edge[2] + jy * edge[3]) / (Polygons2.length(jx, jy) * edge[4]);
        if (cosine < SQUARE_COSINE || cosine > 1 - SQUARE_COSINE) {
            return false; // square to the cut, its held layer moved along it; or along the cut
        }
        // Into the host: the side of the edge's line its polygon lies on.
        double[] centre = centre(frame);
        double inward = Math.signum(inFrom(edge, centre[0], centre[1]));
        double wx = wall.bx() - wall.ax();
        double wy = wall.by() - wall.ay();
        double length = Polygons2.length(wx, wy);
        for (int end = 0; end < 2; end++) {
            double x = end == 0 ? other.ax() : other.bx();
            double y = end == 0 ? other.ay() : other.by();
            double s = ((x - wall.ax()) * wx + (y - wall.ay()) * wy) / length;
            double in = inward * inFrom(edge, x, y);
            if (s >= -tolerance && s <= length + tolerance && in > tolerance && in < reach) {
                return true;
            }
        }
        return false;
    }

    /** How far frame point (x, y) lies to the left of the edge (x, y of its first corner, dx, dy, its length). */
    private static double inFrom(double[] edge, double x, double y) {
        return ((x - edge[0]) * -edge[3] + (y - edge[1]) * edge[2]) / edge[4];
    }

    /** The middle of the frame's polygon's corners. */
    private static double[] centre(HostFrame frame) {
        double[] corners = frame.corners();
        int n = corners.length / 2;
        double[] centre = new double[2];
        for (int i = 0; i < n; i++) {
            centre[0] += corners[2 * i] / n;
            centre[1] += corners[2 * i + 1] / n;
        }
        return centre;
    }

    /** A crease within this cosine of square to a cut, or of along it, is taken so ({@link #endsBesideWall}). */
    private static final double SQUARE_COSINE = 0.02;

    /** The side of the frame's polygon the bend's crease lies along; -1 if none. */
    private static int sideAlong(HostFrame frame, NestedBends.Bend bend, double tolerance) {
        for (int k = 0; k < frame.corners().length / 2; k++) {
            if (frame.along(k, bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance)) {
                return k;
            }
        }
        return -1;
    }

    /** Whether frame point (x, y) is either end of the edge (x, y of its first corner, dx, dy, its length), to the tolerance. */
    private static boolean atEnd(double[] edge, double x, double y, double tolerance) {
        return Math.hypot(x - edge[0], y - edge[1]) <= tolerance || Math.hypot(x - edge[0] - edge[2], y - edge[1] - edge[3]) <= tolerance;
    }

    /** Whether frame point (x, y) lies on the bend's crease, to the tolerance. */
    private static boolean onCrease(NestedBends.Bend bend, double x, double y, double tolerance) {
        double dx = bend.bx() - bend.ax();
        double dy = bend.by() - bend.ay();
        double length = Math.sqrt(dx * dx + dy * dy);
        double s = ((x - bend.ax()) * dx + (y - bend.ay()) * dy) / length;
        double off = ((x - bend.ax()) * dy - (y - bend.ay()) * dx) / length;
        return Math.abs(off) <= tolerance && s >= -tolerance && s <= length + tolerance;
    }

    /**
     * How far in from its cut each fold along a whole cut stands ({@code onCut}, still
     * {@code along}): its own need less its rank (its upper layer's mitre and the clearance), and
     * a thickness farther in than each fold of the cut that wraps it (its levels strictly between
     * that fold's, their stretches overlapping by more than {@link #SHARED} of a thickness). A
     * fold that reaches a reflex corner of the face stands as far back as the most of the folds
     * chained to it ({@link #cutNests}), as all did before: the rules for walls meeting there
     * ({@link #leaveOnCreaseWhereCrossed}) were made so, and with the star prism's walls along
     * the cuts from its inner corners standing by their own nests, two of them with levels
     * interleaved met in the corner at half a thickness, and its paper crossed there (8 → 18
     * crossing pairs, WrappedPaperCollisionsTest).
     */
    private static double[] cutWalls(List<NestedBends.Bend> bends, boolean[] along, boolean[] onCut, int[] edgeOf, double[] need,
            int[] ranks, double[] from, double[] to, double thickness, double tolerance, HostFrame[] frames, boolean[][] inFace) {
        double[] in = new double[bends.size()];
        double[] nests = cutNests(bends, along, onCut, edgeOf, need, from, to);
        Map<Long, List<Integer>> byEdge = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            if (along[k] && onCut[k]) {
                byEdge.computeIfAbsent(key(bends.get(k).host(), edgeOf[k]), x -> new ArrayList<>()).add(k);
            }
        }
        for (List<Integer> group : byEdge.values()) {
            // Widest span of levels first: a fold wrapping another spans more levels.
            Integer[] sorted = group.toArray(new Integer[0]);
            java.util.Arrays.sort(sorted, (a, b) -> Integer.compare(bends.get(b).high() - bends.get(b).low(),
                    bends.get(a).high() - bends.get(a).low()));
            for (int i = 0; i < sorted.length; i++) {
                int k = sorted[i];
                NestedBends.Bend bend = bends.get(k);
                in[k] = need[k] - ranks[k] * thickness;
                if (atReflexCorner(frames[bend.host()], inFace[bend.host()], edgeOf[k], from[k], to[k], tolerance)) {
                    in[k] = nests[k] - ranks[k] * thickness;
                }
                for (int j = 0; j < i; j++) {
                    int o = sorted[j];
                    NestedBends.Bend outer = bends.get(o);
                    if (outer.low() < bend.low() && bend.high() < outer.high() && outer.nx() * bend.nx() + outer.ny() * bend.ny() > 0
                            && Math.min(to[o], to[k]) - Math.max(from[o], from[k]) > SHARED * thickness) {
                        in[k] = Math.max(in[k], in[o] + thickness);
                    }
                }
            }
        }
        return in;
    }

    /**
     * For each fold along a whole cut, the most any fold of its nest needs, the nest taken as
     * every fold of the edge chained to it by stretches that overlap or touch ({@link #cutWalls}
     * takes it for the folds that reach a reflex corner of the face).
     */
    private static double[] cutNests(List<NestedBends.Bend> bends, boolean[] along, boolean[] onCut, int[] edgeOf, double[] need,
            double[] from, double[] to) {
        double[] result = new double[bends.size()];
        Map<Long, List<Integer>> byEdge = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            if (along[k] && onCut[k]) {
                byEdge.computeIfAbsent(key(bends.get(k).host(), edgeOf[k]), x -> new ArrayList<>()).add(k);
            }
        }
        for (List<Integer> group : byEdge.values()) {
            int n = group.size();
            // The group's folds by where they begin along the edge.
            Integer[] sorted = group.toArray(new Integer[0]);
            java.util.Arrays.sort(sorted, (a, b) -> Double.compare(from[a], from[b]));
            int start = 0;
            double reach = Double.NEGATIVE_INFINITY;
            for (int i = 0; i <= n; i++) {
                if (i == n || (i > start && from[sorted[i]] > reach)) {
                    double nest = Double.NEGATIVE_INFINITY;
                    for (int j = start; j < i; j++) {
                        nest = Math.max(nest, need[sorted[j]]);
                    }
                    for (int j = start; j < i; j++) {
                        result[sorted[j]] = nest;
                    }
                    start = i;
                    reach = Double.NEGATIVE_INFINITY;
                }
                if (i < n) {
                    reach = Math.max(reach, to[sorted[i]]);
                }
            }
        }
        return result;
    }

    /**
     * Whether a fold along edge {@code edge} of a host's polygon, from {@code from} to {@code to}
     * along it, reaches an end of the edge that is a reflex corner of the face ({@code inFace}
     * false there: {@link #cornersInFace}).
     */
    private static boolean atReflexCorner(HostFrame frame, boolean[] inFace, int edge, double from, double to, double tolerance) {
        int corners = frame.corners().length / 2;
        return from <= tolerance && !inFace[edge] || to >= frame.edge(edge)[4] - tolerance && !inFace[(edge + 1) % corners];
    }

    /** How much of the cut two folds share before one wraps the other, in thicknesses: as {@code NestedBends} takes it. */
    private static final double SHARED = PaperInSpace.NEST_TOLERANCE * 0.05;

    /**
     * The walls on {@code host} along edge {@code edge} of its polygon that hold paper at
     * {@code level}: for each, how far in, and from where to where along the edge (three numbers
     * a wall, into {@code out}).
     */
    void wallsAt(int host, int edge, double level, List<double[]> out) {
        for (Wall wall : thickness > 0 ? wallsAlong.getOrDefault(key(host, edge), List.of()) : List.<Wall>of()) {
            if (level >= wall.low() - Tolerance.RELATIVE_EQUALITY && level <= wall.high() + Tolerance.RELATIVE_EQUALITY) {
                out.add(new double[] {wall.in(), wall.from() - tolerance, wall.to() + tolerance});
            }
        }
    }

    /**
     * The walls of {@code host} that hold paper at {@code level} (a layer's, or a height between
     * two, as {@link #place} takes them): for each, the edge of the host's polygon it stands
     * along, from and to where along it, and how far in (four numbers a wall, into {@code out}).
     */
    void wallsHolding(int host, double level, List<double[]> out) {
        if (!(thickness > 0)) {
            return;
        }
        for (Wall wall : wallsNear(host, level).walls()) {
            if (level >= wall.low() - Tolerance.RELATIVE_EQUALITY && level <= wall.high() + Tolerance.RELATIVE_EQUALITY) {
                out.add(new double[] {wall.edge(), wall.from(), wall.to(), wall.in()});
            }
        }
    }

    /** How far in from edge {@code edge} of {@code host}'s polygon its farthest wall stands (0 where none does). */
    double farthestWall(int host, int edge) {
        double farthest = 0;
        for (Wall wall : wallsAlong.getOrDefault(key(host, edge), List.of())) {
            farthest = Math.max(farthest, wall.in());
        }
        return farthest;
    }

    /**
     * Whether a fold back to back with another on {@code host} holds paper at {@code level} of a
     * face whose middle is (cx, cy): the face lies on the side the fold's layers end on.
     */
    boolean holdsBack(int host, double level, double cx, double cy) {
        BackWall[] backs = thickness > 0 ? backWallsOf[host] : null;
        for (BackWall back : backs == null ? NO_BACK_WALLS : backs) {
            double middle = -((cx - back.ax()) * back.nx() + (cy - back.ay()) * back.ny());
            if (!back.stepping() && level >= back.low() - Tolerance.RELATIVE_EQUALITY && level <= back.high() + Tolerance.RELATIVE_EQUALITY && middle > tolerance) {
                return true;
            }
        }
        return false;
    }

    /** Whether bend k stands back from its crease, back to back with another ({@link #place}). */
    static boolean standsBack(int[] backToBack, boolean[] alongWall, int k) {
        return backToBack[k] >= 0 && !alongWall[k] && !alongWall[backToBack[k]];
    }

    /** Whether bend k steps back into its layers, nested in folds on its line ({@link #place}). */
    boolean stepsBack(int k) {
        return stepsBack[k] != null;
    }

    /** Which bends stand on a wall at a concave edge. */
    boolean[] along() {
        return along.clone();
    }

    /** Whether bend k (in the list it was made of) stands on a wall at a concave edge. */
    boolean along(int k) {
        return along[k];
    }

    /**
     * Where paper at frame point (x, y) of {@code host} (framed by {@code frame}), at
     * {@code height}, lies: on its mitre, or on the wall of a fold whose layers hold it, where it
     * would reach nearer a concave edge; into {@code out} (x, y).
     */
    void place(int host, HostFrame frame, double x, double y, double height, double[] out) {
        place(host, frame, x, y, height, Double.NaN, Double.NaN, null, out);
    }

    /**
     * {@link #place} for a corner of a face of paper whose middle is (cx, cy): a fold back to back
     * with another moves its own layers' corners half a thickness back from the crease, on its
     * side of it (a corner on the crease belongs to the side its face lies on), before and after
     * the mitres; where a mitre then brings one back nearer the crease, it slides along the
     * mitre's line to where the two meet. A corner where the face goes over an edge to another host
     * ({@code over}: the other ends of its sheet edges that do, x, y pairs; null where none) first
     * keeps from the end of a convex edge that a face across the corner stops ({@link HostFrame#stopped}).
     */
    void place(int host, HostFrame frame, double x, double y, double height, double cx, double cy, double[] over, double[] out) {
        place(host, frame, x, y, height, cx, cy, over, Double.NaN, Double.NaN, out);
    }

    /**
     * {@link #place(int, HostFrame, double, double, double, double, double, double[], double[])}
     * for a corner of a piece of a face that lies wholly beside the same walls and stretches of
     * concave edges as its point (bx, by) (NaN: the corner's own place): a corner on the line
     * where a wall or a stretch ends is placed as the piece on its side is.
     */
    void place(int host, HostFrame frame, double x, double y, double height, double cx, double cy, double[] over, double bx, double by,
            double[] out) {
        out[0] = x;
        out[1] = y;
        if (thickness > 0) {
            // Paper going over a convex edge keeps from its end where a face across the corner rises (HostFrame.Stop).
            frame.stopped(stackTop, tolerance, over, out);
            x = out[0];
            y = out[1];
        }
        BackWall[] backs = thickness > 0 ? backWallsOf[host] : null;
        double level = height / thickness - 0.5;
        if (backs != null) {
            for (BackWall back : backs) {
                if (holds(back, level, cx, cy, x, y)) {
                    frame.keepFromLine(back.ax(), back.ay(), -back.nx(), -back.ny(), -1, back.keep(), out);
                }
            }
        }
        boolean own = Double.isNaN(bx);
        frame.mitred(out[0], out[1], bx, by, height, out);
        if (!(thickness > 0)) {
            return; // paper of no thickness stands nowhere but on its creases
        }
        // Where two cuts' walls meet at a corner, a move off one may bring the point nearer the other: again, as the mitres do.
        LevelWalls near = wallsNear(host, level);
        double startX = out[0];
        double startY = out[1];
        long cutEdges = 0; // the edges along cuts whose walls moved it (bit k for edge k)
        boolean walled = false; // whether a wall along a concave edge (not a cut's) moved it
        for (int round = 0; round < 4; round++) {
            boolean cutMoved = false;
            // Only the walls along edges the point lies near can move it: most lie near none, and
            // reading each of the level's walls (14 a point on the 5,000-triangle torus, 86
            // million in all) was a fifth of placing its paper.
            long reach = near.reaching(frame, out);
            for (int i = 0; i < near.walls().length && reach != 0; i++) {
                if ((reach & 1L << near.edges()[i]) == 0) {
                    continue;
                }
                Wall wall = near.walls()[i];
                if (level < wall.low() - Tolerance.RELATIVE_EQUALITY || level > wall.high() + Tolerance.RELATIVE_EQUALITY) {
                    continue;
                }
                double[] edge = wall.line();
                double wx = own ? out[0] : bx;
                double wy = own ? out[1] : by;
                if (own && !Double.isNaN(cx) && frame.mitreAt(wall.edge(), wx, wy) <= HostFrame.CUT_TAN) {
                    // Along a cut: a face beyond the end of the cut that only touches it with a corner is not beside it.
                    wx += 1e-3 * (cx - wx);
                    wy += 1e-3 * (cy - wy);
                }
                double s = ((wx - edge[0]) * edge[2] + (wy - edge[1]) * edge[3]) / edge[4];
                // Beside the wall, and beside a concave stretch of the edge: a fold along the whole of
                // a host's edge that is concave in part stands back only where the edge is concave.
                if (s >= wall.from() - tolerance && s <= wall.to() + tolerance) {
                    double tan = frame.mitreAt(wall.edge(), wx, wy);
                    if (tan > 0 && frame.keepFrom(wall.edge(), wall.in(), out)) {
                        cutMoved |= tan <= HostFrame.CUT_TAN;
                        walled |= tan > HostFrame.CUT_TAN;
                        cutEdges |= tan <= HostFrame.CUT_TAN && wall.edge() < Long.SIZE ? 1L << wall.edge() : 0;
                        reach = near.reaching(frame, out);
                    }
                }
            }
            if (!cutMoved) {
                break;
            }
        }
        if (cutEdges != 0) {
            intoCorner(host, frame, level, near, startX, startY, own ? startX : bx, own ? startY : by, out);
        } else if (walled) {
            keepFromEach(frame, level, near, height, bx, by, out);
        }
        if (backs != null) {
            for (BackWall back : backs) {
                if (holds(back, level, cx, cy, x, y)) {
                    slideAlongMitre(frame, back, height, back.keep(), out);
                }
            }
        }
    }

    /**
     * Paper at frame point {@code out} that the walls along concave edges moved: each wall moves it
     * straight in from its edge, and near a corner sharper than 90 degrees that brings it nearer
     * the other edge than its mitre, or than a wall along that edge holding its level. Mitred and
     * walled again, round by round, until it keeps from each; then where the two lines it still
     * falls short of meet.
     */
    private void keepFromEach(HostFrame frame, double level, LevelWalls near, double height, double bx, double by, double[] out) {
        if (frame.mitre() == null) {
            return;
        }
        boolean own = Double.isNaN(bx);
        int n = frame.corners().length / 2;
        double[] keep = new double[n];
        for (int round = 0; round < 4; round++) {
            java.util.Arrays.fill(keep, 0);
            double wx = own ? out[0] : bx;
            double wy = own ? out[1] : by;
            for (int k = 0; k < n; k++) {
                double tan = frame.mitreAt(k, wx, wy);
                keep[k] = tan > HostFrame.CUT_TAN ? height * tan : 0;
            }
            for (Wall wall : near.walls()) {
                if (level < wall.low() - Tolerance.RELATIVE_EQUALITY || level > wall.high() + Tolerance.RELATIVE_EQUALITY) {
                    continue;
                }
                double[] edge = wall.line();
                double s = ((wx - edge[0]) * edge[2] + (wy - edge[1]) * edge[3]) / edge[4];
                if (s >= wall.from() - tolerance && s <= wall.to() + tolerance && frame.mitreAt(wall.edge(), wx, wy) > HostFrame.CUT_TAN) {
                    keep[wall.edge()] = Math.max(keep[wall.edge()], wall.in());
                }
            }
            boolean moved = false;
            for (int k = 0; k < n; k++) {
                // Short by more than rounding: a move of 1e-16 reshaped a cap of the torus.
                moved |= keep[k] > 0 && frame.inside(k, out) < keep[k] * (1 - 1e-9) && frame.keepFrom(k, keep[k], out);
            }
            if (!moved) {
                return;
            }
        }
        // Two edges at a corner sharper than 90 degrees, each move off one bringing it nearer the other: where their lines meet.
        frame.meetNearest(keep, out);
    }

    /**
     * Paper at frame point (x, y), of a piece lying as its point (zx, zy) does, that walls along
     * whole cuts of its host moved: where the walls holding its level along two such cuts meeting
     * at a corner both reach (zx, zy), it lies where the two walls meet, squashed into their corner;
     * where one does, on that wall's line, or at that corner where the line lies within the other's
     * reach (into {@code out}). Moved off one wall and then off the other, square to each (the cuts
     * meet at 92° on figure3), paper within both came to rest wherever the second move left it,
     * pieces of one layer in a small fan around the corner, over its paper beyond (12 pairs in one
     * plane). Left as the moves placed it where walls along one cut, or along three, hold it.
     */
    private void intoCorner(int host, HostFrame frame, double level, LevelWalls near, double x, double y, double zx, double zy, double[] out) {
        int edgeA = -1;
        int edgeB = -1;
        double inA = 0;
        double inB = 0;
        for (Wall wall : near.walls()) {
            if (level < wall.low() - Tolerance.RELATIVE_EQUALITY || level > wall.high() + Tolerance.RELATIVE_EQUALITY) {
                continue;
            }
            double[] edge = wall.line();
            double s = ((zx - edge[0]) * edge[2] + (zy - edge[1]) * edge[3]) / edge[4];
            double tan = frame.mitreAt(wall.edge(), zx, zy);
            if (s < wall.from() - tolerance || s > wall.to() + tolerance || !(tan > 0) || tan > HostFrame.CUT_TAN) {
                continue;
            }
            double in = ((zx - edge[0]) * -edge[3] + (zy - edge[1]) * edge[2]) / edge[4];
            double startIn = ((x - edge[0]) * -edge[3] + (y - edge[1]) * edge[2]) / edge[4];
            if (Math.min(in, startIn) >= wall.in() - tolerance) {
                continue; // beyond the wall: it holds nothing here
            }
            if (edgeA < 0 || edgeA == wall.edge()) {
                inA = edgeA < 0 ? wall.in() : Math.max(inA, wall.in());
                edgeA = wall.edge();
            } else if (edgeB < 0 || edgeB == wall.edge()) {
                inB = edgeB < 0 ? wall.in() : Math.max(inB, wall.in());
                edgeB = wall.edge();
            } else {
                return; // three cuts: as the moves left it
            }
        }
        if (edgeB < 0 || !wholeCut(frame, edgeA) || !wholeCut(frame, edgeB)) {
            return;
        }
        int corners = frame.corners().length / 2;
        int corner = edgeB == (edgeA + 1) % corners ? edgeB : edgeA == (edgeB + 1) % corners ? edgeA : -1;
        if (corner >= 0 && !inFace[host][corner]) {
            return; // a reflex corner of the face (the star prism's): as the moves left it
        }
        double[] a = frame.edge(edgeA);
        double[] b = frame.edge(edgeB);
        // Inward unit normals: left of each edge, the polygon running counter-clockwise.
        double ax = -a[3] / a[4];
        double ay = a[2] / a[4];
        double bx = -b[3] / b[4];
        double by = b[2] / b[4];
        boolean withinA = inA - ((zx - a[0]) * ax + (zy - a[1]) * ay) > tolerance;
        boolean withinB = inB - ((zx - b[0]) * bx + (zy - b[1]) * by) > tolerance;
        if (!(withinA && withinB)) {
            // On one wall's line, where that lies beyond the other's reach.
            double needA = Math.max(0, inA - ((x - a[0]) * ax + (y - a[1]) * ay));
            double needB = Math.max(0, inB - ((x - b[0]) * bx + (y - b[1]) * by));
            double onAx = x + needA * ax;
            double onAy = y + needA * ay;
            if (inB - ((onAx - b[0]) * bx + (onAy - b[1]) * by) <= tolerance) {
                out[0] = onAx;
                out[1] = onAy;
                return;
            }
            double onBx = x + needB * bx;
            double onBy = y + needB * by;
            if (inA - ((onBx - a[0]) * ax + (onBy - a[1]) * ay) <= tolerance) {
                out[0] = onBx;
                out[1] = onBy;
                return;
            }
        }
        // Where the two walls' lines meet: n_A . p = cA and n_B . p = cB.
        double cA = inA + a[0] * ax + a[1] * ay;
        double cB = inB + b[0] * bx + b[1] * by;
        double det = ax * by - ay * bx;
        if (Math.abs(det) < Tolerance.ON_PLANE) {
            return; // the cuts on one line: as the moves left it
        }
        out[0] = (cA * by - ay * cB) / det;
        out[1] = (ax * cB - cA * bx) / det;
    }

    /**
     * Where a bend back to back with another has its apex: on its crease, halfway up (at
     * {@code height}), mitred by a concave edge and slid along the mitre's line back onto the
     * crease, where the other's apex is; bend k's, where it steps back into its layers ({@link
     * #stepBack}), on its wall.
     */
    void apex(int k, int host, HostFrame frame, double x, double y, double height, double[] out) {
        frame.mitred(x, y, height, out);
        if (thickness > 0 && stepsBack[k] != null) {
            slideAlongMitre(frame, stepsBack[k], height, stepsBack[k].keep(), out);
            return;
        }
        BackWall[] backs = thickness > 0 ? backWallsOf[host] : null;
        if (backs == null) {
            return;
        }
        for (BackWall back : backs) {
            if (back.stepping()) {
                continue; // its apex stands back with it (above)
            }
            double dx = back.bx() - back.ax();
            double dy = back.by() - back.ay();
            double length = Math.sqrt(dx * dx + dy * dy);
            double s = ((x - back.ax()) * dx + (y - back.ay()) * dy) / length;
            double off = (x - back.ax()) * back.nx() + (y - back.ay()) * back.ny();
            if (Math.abs(off) <= tolerance && s >= -tolerance && s <= length + tolerance) {
                slideAlongMitre(frame, back, height, 0, out);
                return;
            }
        }
    }

    /**
     * Whether the back-to-back fold's layers hold the paper point (x, y) as laid: its level, beside
     * its crease within half a thickness, of a face on its side.
     */
    private boolean holds(BackWall back, double level, double cx, double cy, double x, double y) {
        if (level < back.low() - Tolerance.RELATIVE_EQUALITY || level > back.high() + Tolerance.RELATIVE_EQUALITY) {
            return false;
        }
        double dx = back.bx() - back.ax();
        double dy = back.by() - back.ay();
        double length = Math.sqrt(dx * dx + dy * dy);
        double s = ((x - back.ax()) * dx + (y - back.ay()) * dy) / length;
        double inside = -((x - back.ax()) * back.nx() + (y - back.ay()) * back.ny());
        double middle = -((cx - back.ax()) * back.nx() + (cy - back.ay()) * back.ny());
        return middle > tolerance && s >= -tolerance && s <= length + tolerance && inside >= -tolerance && inside < back.keep();
    }

    /**
     * Moves a point that a concave edge's mitre holds along that mitre's line until it lies
     * {@code keep} in from the back-to-back fold's crease on its side (the mitre and the fold's
     * wall both kept); a point no mitre holds, straight there. A layer's corner on a side of its
     * host that stands farther back stays there: slid back towards the crease it would leave the
     * side, and the paper across that side would be joined to it over the gap.
     */
    private void slideAlongMitre(HostFrame frame, BackWall back, double height, double keep, double[] point) {
        double inside = -((point[0] - back.ax()) * back.nx() + (point[1] - back.ay()) * back.ny());
        double need = keep - inside;
        if (Math.abs(need) <= tolerance || keep > 0 && need < 0 && onSide(frame, point)) {
            return;
        }
        int corners = frame.corners().length / 2;
        double[] slid = null;
        double[] kept = new double[2];
        for (int k = 0; k < corners; k++) {
            double tan = frame.mitreAt(k, point[0], point[1]);
            if (!(tan > 0)) {
                continue;
            }
            double[] edge = frame.edge(k);
            double in = ((point[0] - edge[0]) * -edge[3] + (point[1] - edge[1]) * edge[2]) / edge[4];
            if (Math.abs(in - height * tan) > tolerance + Tolerance.RELATIVE_EQUALITY * height) {
                continue; // not on this edge's mitre
            }
            double tx = edge[2] / edge[4];
            double ty = edge[3] / edge[4];
            double towards = -(tx * back.nx() + ty * back.ny());
            if (Math.abs(towards) > 1e-3) {
                double[] along = {point[0] + need / towards * tx, point[1] + need / towards * ty};
                // Where two concave edges meet at the corner, slide along the mitre that keeps the other's.
                if (!frame.mitred(along[0], along[1], height, kept) || Math.hypot(kept[0] - along[0], kept[1] - along[1]) <= tolerance) {
                    point[0] = along[0];
                    point[1] = along[1];
                    return;
                }
                slid = slid == null ? along : slid;
            }
        }
        if (slid != null) {
            point[0] = slid[0];
            point[1] = slid[1];
            return;
        }
        point[0] -= need * back.nx();
        point[1] -= need * back.ny();
    }

    /** Whether frame point p lies on a side of the frame's polygon, within the tolerance. */
    private boolean onSide(HostFrame frame, double[] p) {
        for (int k = 0; k < frame.corners().length / 2; k++) {
            double[] edge = frame.edge(k);
            double s = ((p[0] - edge[0]) * edge[2] + (p[1] - edge[1]) * edge[3]) / edge[4];
            double off = ((p[0] - edge[0]) * edge[3] - (p[1] - edge[1]) * edge[2]) / edge[4];
            if (Math.abs(off) <= tolerance && s >= -tolerance && s <= edge[4] + tolerance) {
                return true;
            }
        }
        return false;
    }

    /** The concave edge of the frame's polygon that the bend's crease lies along, sharing more than the tolerance of it; -1 if none. */
    private static int concaveEdge(HostFrame frame, NestedBends.Bend bend, double tolerance) {
        if (frame.mitre() == null) {
            return -1;
        }
        for (int k = 0; k < frame.mitre().length; k++) {
            // Along a concave stretch of the edge, sharing more than the tolerance of it.
            if (!frame.concave(k) || !frame.along(k, bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance)
                    || frame.mitreAlong(k, bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance) == 0) {
                continue;
            }
            double[] edge = frame.edge(k);
            double sa = ((bend.ax() - edge[0]) * edge[2] + (bend.ay() - edge[1]) * edge[3]) / edge[4];
            double sb = ((bend.bx() - edge[0]) * edge[2] + (bend.by() - edge[1]) * edge[3]) / edge[4];
            if (Math.min(edge[4], Math.max(sa, sb)) - Math.max(0, Math.min(sa, sb)) > tolerance) {
                if (frame.mitreAlong(k, bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance) <= HostFrame.CUT_TAN
                        && !withinStretches(frame.mitre()[k], Math.min(sa, sb), Math.max(sa, sb), tolerance)) {
                    continue; // along a cut in part only: where it runs on beyond the cut, there is room
                }
                return k;
            }
        }
        return -1;
    }

    /** Whether from..to along an edge lies within its stretches (from, to, tan each), to the tolerance. */
    private static boolean withinStretches(double[] stretches, double from, double to, double tolerance) {
        double at = from;
        for (int round = 0; round < stretches.length / 3 && at < to - tolerance; round++) {
            for (int i = 0; i + 2 < stretches.length; i += 3) {
                if (stretches[i] <= at + tolerance && stretches[i + 1] > at) {
                    at = stretches[i + 1];
                }
            }
        }
        return at >= to - tolerance;
    }

    private static long key(int host, int edge) {
        return ((long) host << 32) | edge;
    }
}
