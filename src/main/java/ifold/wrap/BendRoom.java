package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * How far the bends of flat folds along each edge of a host may stand out beyond it: the room
 * that a thick fold's bend has before it meets the paper of the host across.
 *
 * <p>Over a convex edge whose neighbour turns away by φ, the paper of both hosts stacks up
 * towards the wedge of empty space above the edge, and the plane that halves that wedge (the
 * mitre) keeps the two sides apart: a bend at height z above its host stays on its own side
 * while it stands out no more than z·tan(φ/2). Flat paper of the host across lies beyond the
 * mitre already (it stands out of its own plane, not ours). A neighbour in the same plane (a
 * non-convex face cut into convex hosts) leaves no room at all; over a concave edge the
 * neighbour's surface rises towards the paper, and this limit does not apply (mitred concave
 * edges are a matter of the flat paper itself): the bend keeps its 45 degrees there, as it does
 * where no host lies across (the border of an open surface).
 *
 * <p>Where a convex edge ends at a corner of the surface that has a face across it in the wedge
 * of air over the edge (a polycube's convex edge running on as a concave one, or into a wall),
 * paper bent over the edge would run into that face's layers: the edge's hosts get a {@link
 * HostFrame.Stop} there, and the paper on the edge keeps from the corner as far as that face's
 * stack is high.
 */
final class BendRoom {
    private BendRoom() {
    }

    /**
     * Each host's frame with the room beyond its polygon's edges: for every edge of the mesh
     * between triangles of two hosts, the edge of each host's polygon it lies along gets at
     * most the slope tan(φ/2) of a convex turn φ (0 for coplanar hosts).
     *
     * @param mesh the triangles the hosts are made of
     * @param hostOf the host of each triangle
     * @param frames each host's frame, with its convex polygon as corners
     * @param tolerance how far off a polygon's edge a mesh edge may lie and still be on it
     */
    static HostFrame[] of(IndexedPolygons mesh, int[] hostOf, HostFrame[] frames, double tolerance) {
        return of(mesh, hostOf, frames, tolerance, false);
    }

    /**
     * As {@link #of(IndexedPolygons, int[], HostFrame[], double)}, with every cut between
     * coplanar hosts a stretch of no mitre ({@link #CUT_MITRE}), not only those on the line of a
     * side running on, where {@code wholeCuts} (false: only the cuts on the line of a side, as the
     * hinge strip has them).
     */
    static HostFrame[] of(IndexedPolygons mesh, int[] hostOf, HostFrame[] frames, double tolerance, boolean wholeCuts) {
        // Each host edge's stretches that limit bends (from, to and the slope) and its concave
        // stretches (from, to and tan(φ/2)), three numbers a stretch.
        List<List<List<Double>>> room = new ArrayList<>();
        List<List<List<Double>>> mitre = new ArrayList<>();
        for (int h = 0; h < frames.length; h++) {
            List<List<Double>> limits = new ArrayList<>();
            List<List<Double>> edges = new ArrayList<>();
            for (int k = 0; k < frames[h].corners().length / 2; k++) {
                limits.add(new ArrayList<>());
                edges.add(new ArrayList<>());
            }
            room.add(limits);
            mitre.add(edges);
        }
        Map<Long, Integer> firstSide = new HashMap<>();
        List<List<HostFrame.Stop>> stops = new ArrayList<>();
        for (int h = 0; h < frames.length; h++) {
            stops.add(new ArrayList<>());
        }
        List<List<Integer>> facesAt = facesAt(mesh);
        CoplanarHosts planes = CoplanarHosts.of(frames, tolerance);
        Map<Integer, List<Integer>> sharing = planes.shared();
        for (int t = 0; t < mesh.faceCount(); t++) {
            int n = mesh.faceSize(t);
            for (int k = 0; k < n; k++) {
                int u = mesh.faceVertex(t, k);
                int v = mesh.faceVertex(t, (k + 1) % n);
                long key = ((long) Math.min(u, v) << 32) | Math.max(u, v);
                Integer other = firstSide.remove(key);
                if (other == null) {
                    firstSide.put(key, t);
                } else if (hostOf[other] != hostOf[t]) {
                    limit(mesh, u, v, other, t, hostOf, frames, room, mitre, tolerance, wholeCuts);
                    limit(mesh, u, v, t, other, hostOf, frames, room, mitre, tolerance, wholeCuts);
                    for (int[] sides : new int[][] {{other, t}, {t, other}}) {
                        List<Integer> plane = sharing.get(planes.planeOf(hostOf[sides[0]]));
                        if (plane != null) {
                            mitreBeyond(mesh, u, v, sides[0], sides[1], plane, hostOf, frames, mitre, tolerance);
                        }
                    }
                    if (convex(frames[hostOf[other]], mesh, t, tolerance)) {
                        stop(mesh, facesAt, u, v, other, t, hostOf, frames, stops, tolerance);
                        stop(mesh, facesAt, v, u, other, t, hostOf, frames, stops, tolerance);
                    }
                }
            }
        }
        HostFrame[] limited = new HostFrame[frames.length];
        for (int h = 0; h < frames.length; h++) {
            double[][] stretches = stretches(mitre.get(h));
            limited[h] = frames[h].withEdges(stretches(room.get(h)), stretches)
                    .withStops(stops.get(h).isEmpty() ? null : stops.get(h).toArray(new HostFrame.Stop[0]));
        }
        if (wholeCuts) {
            // Where the face is cut into hosts at a stop's corner, the concave stretch the convex
            // one runs on as may be another host's (mitredOnPastStops). Not for the hinge strip,
            // whose every square is a host: its squares' paper so mitred crossed the caps over the
            // edges beside them (50 random cubes 4 pairs, 200 cubes 2, 0.1 T).
            for (int h = 0; h < frames.length; h++) {
                List<Integer> plane = sharing.get(planes.planeOf(h));
                if (limited[h].stops() == null || plane == null) {
                    continue;
                }
                HostFrame.Stop[] besides = limited[h].stops().clone();
                for (int i = 0; i < besides.length; i++) {
                    besides[i] = besides[i].beside(concaveBeside(limited, plane, h, besides[i], tolerance));
                }
                limited[h] = limited[h].withStops(besides);
            }
        }
        return limited;
    }

    /**
     * The frames with each concave stretch of an edge that runs on as a convex stretch at a
     * {@link HostFrame.Stop} mitred on over the convex stretch, with its own tan(φ/2), as far as
     * the stop keeps paper from the corner: the stack of the face across times the stop's slope
     * ({@code stackTop[wall] * slope}, as {@link HostFrame#stopped} keeps it).
     *
     * <p>At a polycube's vertex with 4 of its 8 octants filled, two lines of edges run from
     * concave to convex through it, and four faces meet: A and B across the concave stretch of
     * one line, the convex stretch of that line between B and C, and D across the other line
     * from A (convex) and from C (concave). A's folds tucked along its convex edge with D stand out
     * a thickness a rank into the wedge of air over that edge, and the layers of B stack up in
     * that wedge: B's paper ran on up to its edge with C past the corner, and those bends ran
     * through it (C's bends into D's paper likewise): 6 random cubes (seed 2) crossed in 52 pairs
     * of caps, 2 T deep, all by such a vertex. B's and D's layers now end on their mitres near the
     * corner as they do along the concave stretch, and the bends beside them stand clear. Paper
     * going over the convex edge there keeps from the corner already ({@link HostFrame#stopped}).
     *
     * <p>Where B's face is cut into hosts at the corner, the concave stretch is another host's:
     * the host of the convex stretch gets a mitre from the corner with that stretch's tan(φ/2)
     * (50 random cubes, seed 1: 356 crossing pairs and 4 points inside → 295 and none).
     *
     * @param frames the hosts' frames, with their stops and mitres
     * @param stackTop how high each host's stack stands (its top layer's upper side)
     * @param tolerance how far a stretch's end may lie from its stop's corner and still end there
     * @return the frames, those with a stretch mitred on replaced (the same array where none is)
     */
    static HostFrame[] mitredOnPastStops(HostFrame[] frames, double[] stackTop, double tolerance) {
        HostFrame[] mitred = frames;
        for (int h = 0; h < frames.length; h++) {
            HostFrame frame = frames[h];
            if (frame.stops() == null) {
                continue;
            }
            double[][] mitre = null;
            for (HostFrame.Stop stop : frame.stops()) {
                double keep = stackTop[stop.wall()] * stop.slope();
                if (!(keep > 0)) {
                    continue;
                }
                // The concave stretch on another host of the plane (the face cut into hosts at the
                // corner), on an edge along this one's line, ending at the corner.
                double tan = stop.beside();
                if (tan > HostFrame.CUT_TAN) {
                    if (mitre == null) {
                        mitre = frame.mitre() != null ? frame.mitre().clone() : new double[frame.corners().length / 2][];
                    }
                    double length = frame.edge(stop.edge())[4];
                    double[] old = mitre[stop.edge()] == null ? new double[0] : mitre[stop.edge()];
                    double[] more = java.util.Arrays.copyOf(old, old.length + 3);
                    more[old.length] = stop.toward() > 0 ? stop.at() : Math.max(0, stop.at() - keep);
                    more[old.length + 1] = stop.toward() > 0 ? Math.min(length, stop.at() + keep) : stop.at();
                    more[old.length + 2] = tan;
                    mitre[stop.edge()] = more;
                    continue;
                }
                double[] stretches = mitre != null ? mitre[stop.edge()] : frame.mitre() != null ? frame.mitre()[stop.edge()] : null;
                if (stretches == null) {
                    continue;
                }
                double length = frame.edge(stop.edge())[4];
                for (int i = 0; i + 2 < stretches.length; i += 3) {
                    // The concave stretch that ends at the stop, on the side the convex stretch does not run on to.
                    boolean before = stop.toward() > 0 && Math.abs(stretches[i + 1] - stop.at()) <= tolerance;
                    boolean after = stop.toward() < 0 && Math.abs(stretches[i] - stop.at()) <= tolerance;
                    if (!before && !after || stretches[i + 2] <= HostFrame.CUT_TAN) {
                        continue;
                    }
                    if (mitre == null) {
                        mitre = frame.mitre().clone();
                    }
                    double[] longer = mitre[stop.edge()].clone();
                    if (before) {
                        longer[i + 1] = Math.min(length, stop.at() + keep);
                    } else {
                        longer[i] = Math.max(0, stop.at() - keep);
                    }
                    mitre[stop.edge()] = longer;
                    stretches = longer;
                }
            }
            if (mitre != null) {
                if (mitred == frames) {
                    mitred = frames.clone();
                }
                mitred[h] = frame.withEdges(frame.room(), mitre);
            }
        }
        return mitred;
    }

    /**
     * tan(φ/2) of a concave stretch of another host of h's plane ({@code plane}, h among them) that ends at the stop's corner,
     * on an edge along the line of the stop's edge, on the side the convex stretch does not run
     * on to; 0 where none does (the concave stretch on h's own edge, or none at all).
     */
    private static double concaveBeside(HostFrame[] frames, List<Integer> plane, int h, HostFrame.Stop stop, double tolerance) {
        HostFrame frame = frames[h];
        double[] own = frame.edge(stop.edge());
        double[] c = new double[3];
        double[] d = new double[3];
        frame.toSpace(own[0] + own[2] / own[4] * stop.at(), own[1] + own[3] / own[4] * stop.at(), 0, c, 0);
        // A point on the line, on the concave side of the corner.
        frame.toSpace(own[0] + own[2] / own[4] * (stop.at() - stop.toward()), own[1] + own[3] / own[4] * (stop.at() - stop.toward()), 0, d, 0);
        double most = 0;
        for (int g : plane) {
            HostFrame other = frames[g];
            if (g == h || other.mitre() == null) {
                continue;
            }
            double cx = other.localX(c);
            double cy = other.localY(c);
            double dx = other.localX(d);
            double dy = other.localY(d);
            for (int k = 0; k < other.mitre().length; k++) {
                if (other.mitre()[k] == null || !other.along(k, cx, cy, dx, dy, tolerance)) {
                    continue;
                }
                double[] edge = other.edge(k);
                double sc = ((cx - edge[0]) * edge[2] + (cy - edge[1]) * edge[3]) / edge[4];
                double sd = ((dx - edge[0]) * edge[2] + (dy - edge[1]) * edge[3]) / edge[4];
                for (int i = 0; i + 2 < other.mitre()[k].length; i += 3) {
                    double from = other.mitre()[k][i];
                    double to = other.mitre()[k][i + 1];
                    // Ends at the corner and runs from it towards d.
                    boolean ends = sd > sc ? Math.abs(from - sc) <= tolerance && to > sc + tolerance
                            : Math.abs(to - sc) <= tolerance && from < sc - tolerance;
                    if (ends) {
                        most = Math.max(most, other.mitre()[k][i + 2]);
                    }
                }
            }
        }
        return most;
    }

    /** Each edge's stretches as an array (null for an edge with none), or null where no edge has any. */
    private static double[][] stretches(List<List<Double>> edges) {
        double[][] stretches = new double[edges.size()][];
        boolean any = false;
        for (int k = 0; k < stretches.length; k++) {
            if (!edges.get(k).isEmpty()) {
                stretches[k] = edges.get(k).stream().mapToDouble(Double::doubleValue).toArray();
                any = true;
            }
        }
        return any ? stretches : null;
    }

    /** The faces round each vertex of the mesh. */
    private static List<List<Integer>> facesAt(IndexedPolygons mesh) {
        List<List<Integer>> at = new ArrayList<>();
        for (int v = 0; v < mesh.vertexCount(); v++) {
            at.add(new ArrayList<>(6));
        }
        for (int t = 0; t < mesh.faceCount(); t++) {
            for (int k = 0; k < mesh.faceSize(t); k++) {
                at.get(mesh.faceVertex(t, k)).add(t);
            }
        }
        return at;
    }

    /**
     * Whether the cut along edge k of {@code near}'s polygon, through mesh edge (a, b), lies on
     * the line of a side that runs on past the cut: an edge of either host's polygon along it
     * reaches beyond the stretch the two share (the T prism's bar, whose underside edge runs on
     * from the stem on both sides). Where the cut is a whole edge of both hosts (a diagonal or a
     * spoke from a reflex corner) the folds along the sides at its ends end on its walls, and
     * walls standing back from the cut up to its ends moved their corners off their creases (the
     * L prism's diagonal: 11 crossing pairs, 0.9 T deep; the coarse tori's rings: 4 each, one
     * point): such a cut's walls stand back by their own nest's ranks ({@link #WHOLE_CUT_MITRE}),
     * and a fold at its end whose nest a crease from the end crosses stays on its crease
     * ({@link ConcaveWalls}).
     */
    private static boolean runsOnAsASide(HostFrame near, int k, HostFrame far, double[] a, double[] b, double tolerance) {
        double[] edge = near.edge(k);
        double fax = far.localX(a);
        double fay = far.localY(a);
        double fbx = far.localX(b);
        double fby = far.localY(b);
        for (int j = 0; j < far.corners().length / 2; j++) {
            if (!far.along(j, fax, fay, fbx, fby, tolerance)) {
                continue;
            }
            double[] other = far.edge(j);
            double[] from = new double[3];
            double[] to = new double[3];
            far.toSpace(other[0], other[1], 0, from, 0);
            far.toSpace(other[0] + other[2], other[1] + other[3], 0, to, 0);
            double sFrom = ((near.localX(from) - edge[0]) * edge[2] + (near.localY(from) - edge[1]) * edge[3]) / edge[4];
            double sTo = ((near.localX(to) - edge[0]) * edge[2] + (near.localY(to) - edge[1]) * edge[3]) / edge[4];
            double lo = Math.min(sFrom, sTo);
            double hi = Math.max(sFrom, sTo);
            // The stretch both share is [max(0, lo), min(length, hi)]: does either reach past it?
            return lo < -tolerance || hi > edge[4] + tolerance || lo > tolerance || hi < edge[4] - tolerance;
        }
        return false;
    }

    /** Whether triangle {@code far} turns away below the plane of {@code near}: a convex edge between them, not a flat one. */
    private static boolean convex(HostFrame near, IndexedPolygons mesh, int far, double tolerance) {
        boolean below = false;
        for (int k = 0; k < mesh.faceSize(far); k++) {
            double height = near.height(position(mesh, mesh.faceVertex(far, k)));
            if (height > tolerance) {
                return false;
            }
            below |= height < -tolerance;
        }
        return below;
    }

    /**
     * The least cosine between a convex edge and the normal of a face it leaves that stops paper
     * on it: a face rising at least 64 degrees over the edge's line, a wall (a polycube's at 90).
     * A stop keeps paper from the corner as far as that face's stack is high over the sine of its
     * rise, moving the ends of creases along the edge while the faces beside them stay: no longer
     * congruent to their paper. As the face lies flatter that grows without bound, and its layers
     * meet the edge's nearly as on one plane: at 0.1 a bumpy sphere's gentle corners (faces rising
     * 6 to 30 degrees) kept paper up to 6.7 stacks from them, its faces stretched, torn and
     * crossing; at 0.5 the elephant with holes kept 25 faces stretched by up to 30 % (at 0.9 none,
     * 343 more crossing pairs of its 22,114; every model of models/ and the shared polyhedra
     * wraps as at 0.5, its report and its check the same).
     */
    private static final double LEAST_COSINE = 0.9;

    /**
     * The stops at corner {@code at} of the convex mesh edge from there to {@code to} between
     * triangles {@code a} and {@code b}: a face round the corner, of a third host, whose plane
     * the edge leaves on its outer side, and over which the wedge of air above the edge lies
     * (the point a little out from the corner between the two faces' normals falls on it).
     */
    private static void stop(IndexedPolygons mesh, List<List<Integer>> facesAt, int at, int to, int a, int b, int[] hostOf,
            HostFrame[] frames, List<List<HostFrame.Stop>> stops, double tolerance) {
        double[] corner = position(mesh, at);
        double[] end = position(mesh, to);
        double[] along = new double[3];
        double length = 0;
        for (int i = 0; i < 3; i++) {
            along[i] = end[i] - corner[i];
            length += along[i] * along[i];
        }
        length = Math.sqrt(length);
        double[] na = frames[hostOf[a]].normal();
        double[] nb = frames[hostOf[b]].normal();
        double[] out = new double[3];
        for (int i = 0; i < 3; i++) {
            along[i] /= length;
            out[i] = na[i] + nb[i];
        }
        for (int w : facesAt.get(at)) {
            int wall = hostOf[w];
            if (wall == hostOf[a] || wall == hostOf[b]) {
                continue;
            }
            HostFrame frame = frames[wall];
            double[] n = frame.normal();
            double cos = along[0] * n[0] + along[1] * n[1] + along[2] * n[2];
            if (cos < LEAST_COSINE) {
                continue;
            }
            // A point a little out over the edge, dropped onto the face's plane.
            double reach = 1e-3 * length;
            double[] p = new double[3];
            for (int i = 0; i < 3; i++) {
                p[i] = corner[i] + reach * out[i];
            }
            // On the face, or on its border (a diagonal of a square face cut in two may run just there).
            if (!inside(mesh, w, frame, p, reach * 1e-3)) {
                continue;
            }
            for (int host : new int[] {hostOf[a], hostOf[b]}) {
                HostFrame near = frames[host];
                double cx = near.localX(corner);
                double cy = near.localY(corner);
                double ex = near.localX(end);
                double ey = near.localY(end);
                for (int k = 0; k < near.corners().length / 2; k++) {
                    if (near.along(k, cx, cy, ex, ey, tolerance)) {
                        double[] edge = near.edge(k);
                        double s = ((cx - edge[0]) * edge[2] + (cy - edge[1]) * edge[3]) / edge[4];
                        double toward = Math.signum((ex - cx) * edge[2] + (ey - cy) * edge[3]);
                        HostFrame.Stop stop = new HostFrame.Stop(k, s, toward, wall, 1 / cos);
                        if (!stops.get(host).contains(stop)) {
                            stops.get(host).add(stop);
                        }
                    }
                }
            }
        }
    }

    /** Whether point p, dropped onto the plane of triangle t (framed by {@code frame}), lies on it, or off it by no more than {@code margin}. */
    private static boolean inside(IndexedPolygons mesh, int t, HostFrame frame, double[] p, double margin) {
        double px = frame.localX(p);
        double py = frame.localY(p);
        int n = mesh.faceSize(t);
        double[] xs = new double[n];
        double[] ys = new double[n];
        double area = 0;
        for (int k = 0; k < n; k++) {
            double[] q = position(mesh, mesh.faceVertex(t, k));
            xs[k] = frame.localX(q);
            ys[k] = frame.localY(q);
        }
        for (int k = 0; k < n; k++) {
            area += xs[k] * ys[(k + 1) % n] - xs[(k + 1) % n] * ys[k];
        }
        double sign = Math.signum(area);
        for (int k = 0; k < n; k++) {
            double dx = xs[(k + 1) % n] - xs[k];
            double dy = ys[(k + 1) % n] - ys[k];
            double side = sign * (dx * (py - ys[k]) - dy * (px - xs[k])) / Math.hypot(dx, dy);
            if (side < -margin) {
                return false;
            }
        }
        return true;
    }

    /**
     * The mitre a cut between coplanar hosts carries (tan of a turn of none, to rounding): no
     * mitre for the paper itself ({@link HostFrame#CUT_TAN}), but a stretch that
     * {@link ConcaveWalls} stands the walls of nested folds back from, a thickness a rank, as at
     * a concave edge. There is no room across a cut to stand out into (the neighbour's paper lies
     * there at the same heights), and walls standing on the cut's line overlapped in its plane.
     */
    static final double CUT_MITRE = 1e-9;

    /**
     * The mitre of a cut that is a whole edge of both hosts: none for the paper, as
     * {@link #CUT_MITRE}, but told apart from it so that {@link ConcaveWalls} stands the folds
     * along it back by their own nest's ranks, not by the most along the whole edge.
     */
    static final double WHOLE_CUT_MITRE = 2 * CUT_MITRE;

    /** Limits the room of the edge of {@code near}'s host that mesh edge (u, v) lies along, by the turn to {@code far}'s host. */
    private static void limit(IndexedPolygons mesh, int u, int v, int near, int far, int[] hostOf, HostFrame[] frames,
            List<List<List<Double>>> room, List<List<List<Double>>> mitre, double tolerance, boolean wholeCuts) {
        HostFrame frame = frames[hostOf[near]];
        double slope = slope(frame, frames[hostOf[far]], mesh, far, tolerance);
        double concave = slope >= HostFrame.OPEN ? concaveTurn(frame, frames[hostOf[far]], mesh, far, tolerance) : 0;
        if (slope >= HostFrame.OPEN && concave <= 0) {
            return;
        }
        double[] a = position(mesh, u);
        double[] b = position(mesh, v);
        double ax = frame.localX(a);
        double ay = frame.localY(a);
        double bx = frame.localX(b);
        double by = frame.localY(b);
        for (int k = 0; k < frame.corners().length / 2; k++) {
            if (frame.along(k, ax, ay, bx, by, tolerance)) {
                // Along this mesh edge only: the host's edge may go on beyond it with another turn
                // (convex here, across a coplanar host there, concave further on).
                double[] edge = frame.edge(k);
                double sa = ((ax - edge[0]) * edge[2] + (ay - edge[1]) * edge[3]) / edge[4];
                double sb = ((bx - edge[0]) * edge[2] + (by - edge[1]) * edge[3]) / edge[4];
                List<Double> stretches = concave > 0 ? mitre.get(hostOf[near]).get(k) : room.get(hostOf[near]).get(k);
                stretches.add(Math.min(sa, sb));
                stretches.add(Math.max(sa, sb));
                stretches.add(concave > 0 ? concave : slope);
                if (slope == 0 && runsOnAsASide(frame, k, frames[hostOf[far]], a, b, tolerance)) {
                    List<Double> cut = mitre.get(hostOf[near]).get(k);
                    cut.add(Math.min(sa, sb));
                    cut.add(Math.max(sa, sb));
                    cut.add(CUT_MITRE);
                } else if (slope == 0 && wholeCuts) {
                    // A whole edge of both hosts (a diagonal or a spoke): walls by nest up to its
                    // ends, but for folds there that a crease from the end crosses (ConcaveWalls).
                    List<Double> cut = mitre.get(hostOf[near]).get(k);
                    cut.add(Math.min(sa, sb));
                    cut.add(Math.max(sa, sb));
                    cut.add(WHOLE_CUT_MITRE);
                }
            }
        }
    }

    /**
     * Gives the concave mesh edge (u, v) between triangle {@code near} and the rising triangle
     * {@code far} as a mitre to the other hosts of near's plane ({@code plane}) with an edge on
     * its line that ends where it begins, on near's side of the line, and a corner over the
     * concave edge's side of that end: a stretch beyond that
     * edge's end, which holds the host's paper beyond the end ({@link HostFrame#mitreAt}). A
     * non-convex face cut into convex hosts may put the cut through the end of a concave edge,
     * and the host beside the cut, whose own edge runs on along the concave edge's line, had no
     * mitre there: on a random polycube of 50 cubes (seed 1) a host's corner at the end of a
     * concave edge came under the face across, its layers there 0 to 17 thicknesses high and
     * as little as 0 in from the edge (40 corners nearer the edge than their mitre, truth 2).
     */
    private static void mitreBeyond(IndexedPolygons mesh, int u, int v, int near, int far, List<Integer> plane, int[] hostOf,
            HostFrame[] frames, List<List<List<Double>>> mitre, double tolerance) {
        HostFrame nearFrame = frames[hostOf[near]];
        if (slope(nearFrame, frames[hostOf[far]], mesh, far, tolerance) < HostFrame.OPEN) {
            return;
        }
        double concave = concaveTurn(nearFrame, frames[hostOf[far]], mesh, far, tolerance);
        if (!(concave > 0)) {
            return;
        }
        double[] a = position(mesh, u);
        double[] b = position(mesh, v);
        double[] middle = new double[3];
        for (int k = 0; k < mesh.faceSize(near); k++) {
            double[] corner = position(mesh, mesh.faceVertex(near, k));
            for (int d = 0; d < 3; d++) {
                middle[d] += corner[d] / mesh.faceSize(near);
            }
        }
        for (int host : plane) {
            if (host == hostOf[near]) {
                continue;
            }
            HostFrame frame = frames[host];
            double ax = frame.localX(a);
            double ay = frame.localY(a);
            double bx = frame.localX(b);
            double by = frame.localY(b);
            for (int k = 0; k < frame.corners().length / 2; k++) {
                if (!frame.along(k, ax, ay, bx, by, tolerance)) {
                    continue;
                }
                double[] edge = frame.edge(k);
                double sa = ((ax - edge[0]) * edge[2] + (ay - edge[1]) * edge[3]) / edge[4];
                double sb = ((bx - edge[0]) * edge[2] + (by - edge[1]) * edge[3]) / edge[4];
                double from = Math.min(sa, sb);
                double to = Math.max(sa, sb);
                boolean beforeStart = Math.abs(to) <= tolerance;
                boolean endsThere = beforeStart || Math.abs(from - edge[4]) <= tolerance;
                // A host that reaches over the edge's stretch: a polygon wholly beside its own edge
                // (a hinge strip's square at a reflex corner) only touches it at the corner, and
                // mitred there it moved only its side through the corner.
                boolean over = false;
                for (int c = 0; c < frame.corners().length / 2; c++) {
                    double sc = ((frame.corners()[2 * c] - edge[0]) * edge[2] + (frame.corners()[2 * c + 1] - edge[1]) * edge[3]) / edge[4];
                    over |= beforeStart ? sc < -tolerance : sc > edge[4] + tolerance;
                }
                // Near's side of the line: the host's inside, so that its paper moves in from the edge towards near's.
                double in = ((frame.localX(middle) - edge[0]) * -edge[3] + (frame.localY(middle) - edge[1]) * edge[2]) / edge[4];
                if (endsThere && over && in > tolerance) {
                    List<Double> stretches = mitre.get(host).get(k);
                    stretches.add(from);
                    stretches.add(to);
                    stretches.add(concave);
                }
            }
        }
    }

    /**
     * The room beyond an edge of {@code near} whose other side is triangle {@code far} of the
     * host framed by {@code across}: tan(φ/2) where the surface turns away by φ, 0 in the same
     * plane, {@link HostFrame#OPEN} where it turns up towards the paper (a concave edge).
     */
    private static double slope(HostFrame near, HostFrame across, IndexedPolygons mesh, int far, double tolerance) {
        double lowest = 0;
        for (int k = 0; k < mesh.faceSize(far); k++) {
            double height = near.height(position(mesh, mesh.faceVertex(far, k)));
            if (height > tolerance) {
                return HostFrame.OPEN; // concave: the neighbour rises above this host's plane
            }
            lowest = Math.min(lowest, height);
        }
        if (lowest >= -tolerance) {
            return 0; // the same plane
        }
        double[] n = near.normal();
        double[] m = across.normal();
        double cos = Math.max(-1, Math.min(1, n[0] * m[0] + n[1] * m[1] + n[2] * m[2]));
        return Math.min(HostFrame.OPEN, Math.sqrt((1 - cos) / (1 + cos)));
    }

    /**
     * Where triangle {@code far} of the host framed by {@code across} rises above {@code near}'s
     * plane (a concave edge, turning up by φ), tan(φ/2): the mitre halving the wedge of air
     * between the two; 0 where it does not rise.
     */
    private static double concaveTurn(HostFrame near, HostFrame across, IndexedPolygons mesh, int far, double tolerance) {
        boolean rises = false;
        for (int k = 0; k < mesh.faceSize(far); k++) {
            rises |= near.height(position(mesh, mesh.faceVertex(far, k))) > tolerance;
        }
        if (!rises) {
            return 0;
        }
        double[] n = near.normal();
        double[] m = across.normal();
        double cos = Math.max(-1, Math.min(1, n[0] * m[0] + n[1] * m[1] + n[2] * m[2]));
        // A wedge of air all but closed (the faces back to back) leaves paper no room: its
        // layers go as far in as the host lets them (HostFrame.keepFrom).
        // A turn so slight that its tan(φ/2) is under HostFrame.CUT_TAN is still a concave edge, not a
        // cut between coplanar hosts: its paper keeps from a mitre just over CUT_TAN, so that it is
        // not taken for a cut's and left on the edge's line, nearer than its own mitre (a bumpy
        // icosphere's edge turning by 1.7e-6 rad: layers 0.012 high on its line, 1e-8 short).
        return Math.max(2 * HostFrame.CUT_TAN, Math.min(1e6, Math.sqrt((1 - cos) / Math.max(1 + cos, Tolerance.COPLANAR_COSINE))));
    }

    private static double[] position(IndexedPolygons mesh, int v) {
        return new double[] {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
    }
}
