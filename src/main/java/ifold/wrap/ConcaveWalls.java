package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.sheet.HostFrame;
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

    private final double thickness;
    private final double tolerance;
    /** The walls on each host, by host (null where none). */
    private final List<List<Wall>> wallsOf;
    private final boolean[] along;

    private ConcaveWalls(double thickness, double tolerance, List<List<Wall>> wallsOf, boolean[] along) {
        this.thickness = thickness;
        this.tolerance = tolerance;
        this.wallsOf = wallsOf;
        this.along = along;
    }

    /**
     * The walls of {@code bends} that lie along a concave edge of their host, with the
     * {@code ranks} NestedBends gave them.
     */
    static ConcaveWalls of(List<NestedBends.Bend> bends, int[] ranks, HostFrame[] frames, double thickness, double tolerance) {
        boolean[] along = new boolean[bends.size()];
        int[] edgeOf = new int[bends.size()];
        // The most any fold along an edge needs, by host and edge: its upper layer's mitre plus its rank.
        Map<Long, Double> most = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            NestedBends.Bend bend = bends.get(k);
            HostFrame frame = frames[bend.host()];
            edgeOf[k] = concaveEdge(frame, bend, tolerance);
            if (edgeOf[k] < 0) {
                continue;
            }
            along[k] = true;
            double tan = frame.mitreAlong(edgeOf[k], bend.ax(), bend.ay(), bend.bx(), bend.by(), tolerance);
            double need = (bend.high() + 0.5) * thickness * tan + ranks[k] * thickness;
            most.merge(key(bend.host(), edgeOf[k]), need, Math::max);
        }
        List<List<Wall>> wallsOf = new ArrayList<>(java.util.Collections.nCopies(frames.length, (List<Wall>) null));
        for (int k = 0; k < bends.size(); k++) {
            if (!along[k]) {
                continue;
            }
            NestedBends.Bend bend = bends.get(k);
            double[] edge = frames[bend.host()].edge(edgeOf[k]);
            double sa = ((bend.ax() - edge[0]) * edge[2] + (bend.ay() - edge[1]) * edge[3]) / edge[4];
            double sb = ((bend.bx() - edge[0]) * edge[2] + (bend.by() - edge[1]) * edge[3]) / edge[4];
            double in = most.get(key(bend.host(), edgeOf[k])) - ranks[k] * thickness;
            if (wallsOf.get(bend.host()) == null) {
                wallsOf.set(bend.host(), new ArrayList<>());
            }
            wallsOf.get(bend.host()).add(new Wall(edgeOf[k], Math.min(sa, sb), Math.max(sa, sb), bend.low(), bend.high(), in, edge));
        }
        return new ConcaveWalls(thickness, tolerance, wallsOf, along);
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
        frame.mitred(x, y, height, out);
        List<Wall> walls = wallsOf.get(host);
        if (walls == null || !(thickness > 0)) {
            return; // paper of no thickness stands nowhere but on its creases
        }
        double level = height / thickness - 0.5;
        for (Wall wall : walls) {
            if (level < wall.low() - Tolerance.RELATIVE_EQUALITY || level > wall.high() + Tolerance.RELATIVE_EQUALITY) {
                continue;
            }
            double[] edge = wall.line();
            double s = ((out[0] - edge[0]) * edge[2] + (out[1] - edge[1]) * edge[3]) / edge[4];
            // Beside the wall, and beside a concave stretch of the edge: a fold along the whole of
            // a host's edge that is concave in part stands back only where the edge is concave.
            if (s >= wall.from() - tolerance && s <= wall.to() + tolerance && frame.mitreAt(wall.edge(), out[0], out[1]) > 0) {
                frame.keepFrom(wall.edge(), wall.in(), out);
            }
        }
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
                return k;
            }
        }
        return -1;
    }

    private static long key(int host, int edge) {
        return ((long) host << 32) | edge;
    }
}
