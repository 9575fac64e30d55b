package ifold.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Truth 2 of {@link WrapTruths}: every paper face congruent to its paper polygon, but for thick
 * paper's corners that creep within the zone of a concave edge of the model, none nearer such an
 * edge than its mitre, and corners of two folds back to back on one crease line, whose bends
 * meet there (each stands back from the crease by no more than a thickness).
 */
final class TruthIsometry {
    private final WrapTruths wrap;

    TruthIsometry(WrapTruths wrap) {
        this.wrap = wrap;
    }

    /**
     * One side of a concave edge of the model: the edge from a to b on a triangle of outward unit
     * {@code normal}, whose neighbour across rises above its plane, turning by φ; {@code mitre}
     * is tan(φ/2).
     */
    record ConcaveSide(double[] normal, double[] a, double[] b, double mitre, double[] apex) {
        ConcaveSide(double[] normal, double[] a, double[] b, double mitre) {
            this(normal, a, b, mitre, null);
        }
    }

    /**
     * Each edge two triangles share, matched by its corners' coordinates, in the order the second
     * triangle's side is met: {t, k, u, l}, side k of t (met second) and side l of u. The sides
     * no other triangle shares (an open surface's border) go into {@code lone}, as {t, k}.
     */
    private static List<int[]> sharedEdges(TruthModel model, List<int[]> lone) {
        int n = model.corners.length / 9;
        Map<String, int[]> sides = new HashMap<>();
        List<int[]> shared = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                String a = Arrays.toString(corner(model, t, k));
                String b = Arrays.toString(corner(model, t, (k + 1) % 3));
                int[] other = sides.remove(b + a);
                if (other == null) {
                    sides.put(a + b, new int[] {t, k});
                } else {
                    shared.add(new int[] {t, k, other[0], other[1]});
                }
            }
        }
        lone.addAll(sides.values());
        return shared;
    }

    /** Every side of every concave edge of the model: edges are matched by their corners' coordinates. */
    static List<ConcaveSide> concaveSides(TruthModel model, double eps) {
        List<ConcaveSide> concave = new ArrayList<>();
        for (int[] edge : sharedEdges(model, new ArrayList<>())) {
            // Each side of the edge, the triangle across rising above its plane.
            for (int[] side : List.of(new int[] {edge[0], edge[1], edge[2]}, new int[] {edge[2], edge[3], edge[0]})) {
                int near = side[0];
                int far = side[2];
                double rise = 0;
                for (int c = 0; c < 3; c++) {
                    rise = Math.max(rise, model.height(near, model.corners, 9 * far + 3 * c));
                }
                if (rise > eps) {
                    double[] m = model.normal(near);
                    double[] o = model.normal(far);
                    double cos = Math.max(-1, Math.min(1, m[0] * o[0] + m[1] * o[1] + m[2] * o[2]));
                    concave.add(new ConcaveSide(m, corner(model, near, side[1]), corner(model, near, (side[1] + 1) % 3),
                            Math.sqrt((1 - cos) / Math.max(1 + cos, 1e-12)), corner(model, near, (side[1] + 2) % 3)));
                }
            }
        }
        return concave;
    }

    /**
     * Both sides of every cut the wrap may make: each edge between two coplanar triangles of a
     * plane region that is not convex (or has a hole), as a side of no mitre. The wrap cuts such
     * a region into convex hosts along edges of its triangles, and folds tucked along a cut stand
     * back from it into their host, a thickness a rank, as at a concave edge: across the cut lies
     * the neighbour host's paper at the same heights, no room to stand out into. Which of the
     * region's inner edges it cuts along is the wrap's choice; the model tells only that each
     * may be one. A convex region is one host, and its inner edges no cuts.
     */
    static List<ConcaveSide> cutSides(TruthModel model, double eps) {
        int n = model.corners.length / 9;
        int[] region = new int[n];
        for (int t = 0; t < n; t++) {
            region[t] = t;
        }
        List<int[]> inner = new ArrayList<>();
        List<int[]> borders = new ArrayList<>();
        List<int[]> open = new ArrayList<>(); // edges of an open surface
        for (int[] edge : sharedEdges(model, open)) {
            if (coplanar(model, edge[0], edge[2], eps)) {
                inner.add(edge);
                SolidInside.union(region, edge[0], edge[2]);
            } else {
                borders.add(new int[] {edge[0], edge[1]});
                borders.add(new int[] {edge[2], edge[3]});
            }
        }
        borders.addAll(open);
        // A region is convex when every corner of it lies on the inner side of every border edge's line.
        boolean[] notConvex = new boolean[n];
        Map<Integer, List<Integer>> members = new HashMap<>();
        for (int t = 0; t < n; t++) {
            members.computeIfAbsent(SolidInside.find(region, t), r -> new ArrayList<>()).add(t);
        }
        for (int[] border : borders) {
            int t = border[0];
            double[] a = corner(model, t, border[1]);
            double[] in = crossed(model.normal(t), minus(corner(model, t, (border[1] + 1) % 3), a));
            double length = Math.sqrt(times(in, in));
            for (int u : members.get(SolidInside.find(region, t))) {
                for (int k = 0; k < 3; k++) {
                    if (times(minus(corner(model, u, k), a), in) < -eps * length) {
                        notConvex[SolidInside.find(region, t)] = true;
                    }
                }
            }
        }
        List<ConcaveSide> cuts = new ArrayList<>();
        for (int[] edge : inner) {
            if (notConvex[SolidInside.find(region, edge[0])]) {
                cuts.add(new ConcaveSide(model.normal(edge[0]), corner(model, edge[0], edge[1]), corner(model, edge[0], (edge[1] + 1) % 3), 0));
                cuts.add(new ConcaveSide(model.normal(edge[2]), corner(model, edge[2], edge[3]), corner(model, edge[2], (edge[3] + 1) % 3), 0));
            }
        }
        return cuts;
    }

    /**
     * The least cosine between a convex edge and the normal of a face at its end that keeps
     * paper from that end ({@link #stopSides}): a face rising 30 degrees or more across the edge.
     * Looser than any wrap keeps to, so the truth does not hang on where a wrap draws that line;
     * the zone it allows is at most two stacks long.
     */
    static final double LEAST_STOP_COSINE = 0.5;

    /**
     * Both sides of the end of each convex edge where a face at that corner rises across the
     * wedge of air above the edge (a wall the edge runs into: a polycube's step, a pit's rim
     * on a scan), as a side of no mitre along the edge from the corner, as long as the stack
     * stands high ({@code top}) over the cosine between the edge and that face's normal. The
     * face's layers stand that far out along the edge, where paper bent over the edge would run
     * into them: the ends of creases along the edge keep from the corner by as much, and the
     * faces whose sides they end are shorter by as much, as paper creeps at a concave edge.
     */
    static List<ConcaveSide> stopSides(TruthModel model, double eps, double top) {
        int n = model.corners.length / 9;
        List<ConcaveSide> stops = new ArrayList<>();
        if (!(top > 0)) {
            return stops;
        }
        Map<String, List<Integer>> trianglesAt = new HashMap<>();
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                trianglesAt.computeIfAbsent(Arrays.toString(corner(model, t, k)), key -> new ArrayList<>()).add(t);
            }
        }
        for (int[] edge : sharedEdges(model, new ArrayList<>())) {
            int t = edge[0];
            int u = edge[2];
            double below = 0; // how far the far corner of u lies below t's plane: convex where it does
            for (int c = 0; c < 3; c++) {
                below = Math.min(below, model.height(t, model.corners, 9 * u + 3 * c));
            }
            if (below >= -eps) {
                continue; // flat or concave
            }
            double[] a = corner(model, t, edge[1]);
            double[] b = corner(model, t, (edge[1] + 1) % 3);
            for (double[][] ends : new double[][][] {{a, b}, {b, a}}) {
                stopsAt(model, trianglesAt.get(Arrays.toString(ends[0])), ends[0], ends[1], t, u, top, stops);
            }
        }
        return stops;
    }

    /** The stops ({@link #stopSides}) at corner {@code at} of the convex edge from there to {@code to} between triangles t and u. */
    private static void stopsAt(TruthModel model, List<Integer> around, double[] at, double[] to, int t, int u, double top,
            List<ConcaveSide> stops) {
        double[] along = minus(to, at);
        double length = Math.sqrt(times(along, along));
        double[] nt = model.normal(t);
        double[] nu = model.normal(u);
        double reach = 1e-3 * length;
        double[] over = new double[3]; // a point a little out over the edge, in the wedge of air above it
        for (int d = 0; d < 3; d++) {
            along[d] /= length;
            over[d] = at[d] + reach * (nt[d] + nu[d]);
        }
        double most = 0;
        double[] weights = new double[3];
        for (int w : around) {
            double cos = times(along, model.normal(w));
            if (w == t || w == u || !(cos >= LEAST_STOP_COSINE)) {
                continue;
            }
            model.barycentric(w, over, 0, weights);
            if (Math.min(weights[0], Math.min(weights[1], weights[2])) >= -1e-6) {
                most = Math.max(most, top / cos);
            }
        }
        if (most > 0) {
            double[] end = new double[3];
            for (int d = 0; d < 3; d++) {
                end[d] = at[d] + Math.min(most, length) * along[d];
            }
            stops.add(new ConcaveSide(nt, at, end, 0));
            stops.add(new ConcaveSide(nu, at, end, 0));
        }
    }

    private static double[] corner(TruthModel model, int t, int k) {
        return Arrays.copyOfRange(model.corners, 9 * t + 3 * k, 9 * t + 3 * k + 3);
    }

    /** Whether triangles t and u lie in one plane: each one's corners on the other's plane, the same way up. */
    private static boolean coplanar(TruthModel model, int t, int u, double eps) {
        if (times(model.normal(t), model.normal(u)) < 1 - 1e-9) {
            return false;
        }
        for (int c = 0; c < 3; c++) {
            if (Math.abs(model.height(t, model.corners, 9 * u + 3 * c)) > eps || Math.abs(model.height(u, model.corners, 9 * t + 3 * c)) > eps) {
                return false;
            }
        }
        return true;
    }

    /**
     * The vertices of paper where two folds stand back to back: two caps (bends) that share no
     * vertex but run along one segment in space (their apexes, where the bends meet on the
     * crease), and the other vertices of those caps (the corners of the folds' layers, which
     * may stand back from the crease by up to a thickness).
     */
    java.util.Set<Integer> backToBackCorners(double eps) {
        Map<String, List<Integer>> capsAlong = new HashMap<>();
        for (int f = 0; f < wrap.faces(); f++) {
            if (!wrap.faceCap[f]) {
                continue;
            }
            int start = wrap.faceStart[f];
            int end = wrap.faceStart[f + 1];
            for (int c = start; c < end; c++) {
                String a = rounded(wrap.cornerV[c], eps);
                String b = rounded(wrap.cornerV[c + 1 < end ? c + 1 : start], eps);
                capsAlong.computeIfAbsent(a.compareTo(b) < 0 ? a + b : b + a, k -> new ArrayList<>()).add(f);
            }
        }
        java.util.Set<Integer> corners = new java.util.HashSet<>();
        for (List<Integer> caps : capsAlong.values()) {
            for (int i = 0; i < caps.size(); i++) {
                for (int j = i + 1; j < caps.size(); j++) {
                    if (!shareVertex(caps.get(i), caps.get(j))) {
                        for (int f : new int[] {caps.get(i), caps.get(j)}) {
                            for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                                corners.add(wrap.cornerV[c]);
                            }
                        }
                    }
                }
            }
        }
        return corners;
    }

    private String rounded(int v, double eps) {
        return Math.round(wrap.xyz[3 * v] / eps) + "," + Math.round(wrap.xyz[3 * v + 1] / eps) + "," + Math.round(wrap.xyz[3 * v + 2] / eps) + ";";
    }

    private boolean shareVertex(int f, int g) {
        for (int a = wrap.faceStart[f]; a < wrap.faceStart[f + 1]; a++) {
            for (int b = wrap.faceStart[g]; b < wrap.faceStart[g + 1]; b++) {
                if (wrap.cornerV[a] == wrap.cornerV[b]) {
                    return true;
                }
            }
        }
        return false;
    }

    /** Truth 2; {@code crept} gets the faces let stand back from a concave edge, or from a crease where two folds stand back to back. */
    void checkIsometry(TruthReport report, List<ConcaveSide> concave, double thickness, int maxStack, double eps, boolean[] crept) {
        StringBuilder why = new StringBuilder();
        java.util.Set<Integer> backToBack = thickness > 0 ? backToBackCorners(1e-3 * thickness) : java.util.Set.of();
        SidesNear sides = thickness > 0 && !concave.isEmpty() ? new SidesNear(concave, (maxStack + 1) * thickness, eps) : null;
        for (int f = 0; f < wrap.faces(); f++) {
            if (!wrap.faceCap[f]) {
                why.setLength(0);
                double error = isometryError(f, why);
                Zones zones = sides != null ? zones(f, sides.near(f), thickness, maxStack, eps) : null;
                if (zones != null && zones.nearer() != null) {
                    report.add(WrapTruths.ISOMETRIC, wrap.face(f) + ": " + zones.nearer());
                }
                if (!(error <= WrapTruths.RELATIVE) && !withinDrift(f, error)) {
                    zones = atFolds(f, zones, backToBack, thickness);
                    crept[f] = zones != null && creptOnly(f, zones);
                    if (!crept[f]) {
                        report.add(WrapTruths.ISOMETRIC, wrap.face(f) + " is stretched: " + why + (zones == null || zones.widest() == 0 ? ""
                                : " (more than twice the " + zones.widest() + " its corners by a concave edge may creep)"));
                    }
                }
            }
        }
    }

    /**
     * The concave sides whose creep zone a face may reach, found through a grid of their zones'
     * boxes rather than by trying every side on every face (a scan: 510,097 faces against
     * thousands of sides took nine minutes). A face reaches a side's zone only with a corner
     * within the zone's width beside, before or beyond the edge and at most the stack's height
     * above its plane: within 1.5 widths and that height of the edge, so inside the edge's box
     * grown by as much. The sides come in the order of the list, as {@link #zones} takes them.
     */
    final class SidesNear {
        private final List<ConcaveSide> concave;
        private final TruthGrid grid;
        private final Ints candidates = new Ints();

        SidesNear(List<ConcaveSide> concave, double top, double eps) {
            this.concave = concave;
            int n = concave.size();
            double[] boxes = new double[6 * n];
            for (int i = 0; i < n; i++) {
                ConcaveSide side = concave.get(i);
                double grow = 1.5 * top * (side.mitre() + 1) + top + 2 * eps;
                for (int d = 0; d < 3; d++) {
                    boxes[6 * i + d] = Math.min(side.a()[d], side.b()[d]) - grow;
                    boxes[6 * i + 3 + d] = Math.max(side.a()[d], side.b()[d]) + grow;
                }
            }
            grid = new TruthGrid(boxes, n, TruthGrid.cellFor(boxes, n, WrapTruths.LEAST_CELL));
        }

        /** The sides whose zone face f's corners may reach, in the list's order. */
        List<ConcaveSide> near(int f) {
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                for (int d = 0; d < 3; d++) {
                    double x = wrap.xyz[3 * wrap.cornerV[c] + d];
                    box[d] = Math.min(box[d], x);
                    box[3 + d] = Math.max(box[3 + d], x);
                }
            }
            grid.query(box[0], box[1], box[2], box[3], box[4], box[5], candidates);
            int[] found = candidates.toArray();
            Arrays.sort(found);
            List<ConcaveSide> sides = new ArrayList<>(found.length);
            for (int i : found) {
                sides.add(concave.get(i));
            }
            return sides;
        }
    }

    /**
     * Where face f lies by the concave edges of the model: which corners lie in a creep zone
     * ({@code inZone}), the widest such zone, and the first corner nearer a concave edge than
     * its mitre on every plane of a concave side the face lies on (null if none). The face lies
     * on the plane of a side when all its corners stand equally high above it (a face squashed
     * to a sliver may lie on both sides' planes, and must keep to its mitre on one).
     */
    record Zones(boolean[] inZone, double widest, String nearer) {
    }

    Zones zones(int f, List<ConcaveSide> concave, double thickness, int maxStack, double eps) {
        int start = wrap.faceStart[f];
        int end = wrap.faceStart[f + 1];
        double size = Math.max(wrap.surface.sheetSize(f), wrap.stripW[wrap.faceStrip[f]]);
        double top = (maxStack + 1) * thickness;
        boolean[] inZone = new boolean[end - start];
        double widest = 0;
        // A face on a plane keeps to the mitre of every concave side of that plane (a room's floor
        // of both its walls); a squashed face may lie on two planes, and must keep to one's.
        List<ConcaveSide> planes = new ArrayList<>();
        List<String> nearerOn = new ArrayList<>();
        for (ConcaveSide side : concave) {
            double[] m = side.normal();
            double width = top * (side.mitre() + 1);
            double[] along = minus(side.b(), side.a());
            double length = Math.sqrt(times(along, along));
            for (int d = 0; d < 3; d++) {
                along[d] /= length;
            }
            double[] in = crossed(m, along); // in the plane, from the edge into the triangle
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            boolean near = false;
            for (int c = start; c < end; c++) {
                double[] p = minus(new double[] {wrap.xyz[3 * wrap.cornerV[c]], wrap.xyz[3 * wrap.cornerV[c] + 1], wrap.xyz[3 * wrap.cornerV[c] + 2]}, side.a());
                double height = times(p, m);
                low = Math.min(low, height);
                high = Math.max(high, height);
                double s = times(p, along);
                double inside = times(p, in);
                near |= s >= -width && s <= length + width && inside <= width && inside >= -width;
            }
            if (!near || high - low > WrapTruths.RELATIVE * size + eps || low < -eps || high > top + eps) {
                continue; // not on this side's plane (so not planar there), or not near its edge
            }
            String here = null;
            double[] middle = new double[3];
            for (int c = start; c < end; c++) {
                for (int d = 0; d < 3; d++) {
                    middle[d] += wrap.xyz[3 * wrap.cornerV[c] + d] / (end - start);
                }
            }
            double middleS = times(minus(middle, side.a()), along);
            for (int c = start; c < end; c++) {
                int v = wrap.cornerV[c];
                double[] p = minus(new double[] {wrap.xyz[3 * v], wrap.xyz[3 * v + 1], wrap.xyz[3 * v + 2]}, side.a());
                double s = times(p, along);
                double inside = times(p, in);
                if (s < -width || s > length + width || inside > width || inside < -width) {
                    continue;
                }
                inZone[c - start] = true;
                widest = Math.max(widest, width);
                double height = times(p, m);
                // The mitre stands beside the edge: round its ends the paper across turns away. A
                // face beyond an end that only touches it with a corner (from there into the face,
                // the paper runs on beyond the end) is not beside it.
                double into = s + 1e-3 * (middleS - s);
                boolean beside = s >= 0 && s <= length && into > 0 && into < length;
                if (here == null && beside && inside < height * side.mitre() - eps - 1e-6 * thickness) {
                    here = "vertex " + (v + 1) + " is " + inside + " in from a concave edge of the model, nearer than its mitre ("
                            + height + " high: " + height * side.mitre() + " in), running into the layers across";
                }
            }
            if (side.mitre() == 0) {
                continue; // a cut: paper runs on across it, and keeps from no mitre there
            }
            int plane = -1;
            for (int i = 0; i < planes.size() && plane < 0; i++) {
                double[] n = planes.get(i).normal();
                // One plane: the side's whole triangle on the plane's, not only its edge (the two
                // sides of a concave edge turning by under 4.5e-5 rad have normals within 1 - 1e-9).
                if (times(n, m) > 1 - 1e-9 && Math.abs(times(n, minus(side.a(), planes.get(i).a()))) <= eps
                        && Math.abs(times(n, minus(side.b(), planes.get(i).a()))) <= eps && Math.abs(times(n, minus(side.apex(), planes.get(i).a()))) <= eps) {
                    plane = i;
                }
            }
            if (plane < 0) {
                planes.add(side);
                nearerOn.add(here);
            } else if (nearerOn.get(plane) == null) {
                nearerOn.set(plane, here);
            }
        }
        String nearer = null;
        for (String onPlane : nearerOn) {
            if (onPlane == null) {
                return new Zones(inZone, widest, null);
            }
            nearer = nearer == null ? onPlane : nearer;
        }
        return new Zones(inZone, widest, nearer);
    }

    /** Face f's zones with its corners at folds back to back in a zone a thickness wide too; null where it has neither. */
    private Zones atFolds(int f, Zones zones, java.util.Set<Integer> backToBack, double thickness) {
        int start = wrap.faceStart[f];
        int end = wrap.faceStart[f + 1];
        boolean[] inZone = zones == null ? new boolean[end - start] : zones.inZone().clone();
        boolean any = false;
        for (int c = start; c < end; c++) {
            if (backToBack.contains(wrap.cornerV[c])) {
                inZone[c - start] = true;
                any = true;
            }
        }
        if (!any) {
            return zones;
        }
        return new Zones(inZone, Math.max(zones == null ? 0 : zones.widest(), thickness), zones == null ? null : zones.nearer());
    }

    /**
     * Whether face f, not congruent to its sheet polygon, is so only by corners standing back from
     * a concave edge: planar (its corners stand equally high above a concave side's plane, see
     * {@link #zones}, which holds for a face squashed to a sliver too, whose own normal is
     * rounding), its corners outside every creep zone congruent among themselves, and each pair
     * with a corner in a zone off its sheet distance by no more than twice the widest zone.
     */
    boolean creptOnly(int f, Zones zones) {
        if (zones.widest() == 0) {
            return false;
        }
        int start = wrap.faceStart[f];
        int end = wrap.faceStart[f + 1];
        double size = Math.max(wrap.surface.sheetSize(f), wrap.stripW[wrap.faceStrip[f]]);
        for (int a = start; a < end; a++) {
            for (int b = a + 1; b < end; b++) {
                double inSpace = WrapTruths.distance(wrap.xyz, 3 * wrap.cornerV[a], wrap.xyz, 3 * wrap.cornerV[b]);
                double onSheet = Math.hypot(wrap.uv[2 * wrap.cornerT[a]] - wrap.uv[2 * wrap.cornerT[b]], wrap.uv[2 * wrap.cornerT[a] + 1] - wrap.uv[2 * wrap.cornerT[b] + 1]);
                boolean zone = zones.inZone()[a - start] || zones.inZone()[b - start];
                if (!(Math.abs(inSpace - onSheet) <= (zone ? 2 * zones.widest() + WrapTruths.RELATIVE * size : WrapTruths.RELATIVE * size))) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * How far, relative to u, paper far along a long strip may stray from its sheet polygon: its
     * poses are composed fold after fold, each rounding by about 1e-16, and a million folds gather
     * about 1e-13 of u; ten times that (as the engine's sheet allows, Sheet.POSE_DRIFT).
     */
    static final double POSE_DRIFT = 1e-12;

    /** Whether face f's departure {@code error} ({@link #isometryError}) is no more than its poses' drift where it lies along the strip. */
    private boolean withinDrift(int f, double error) {
        double farthest = 0;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            farthest = Math.max(farthest, Math.abs(wrap.uv[2 * wrap.cornerT[c]]));
        }
        double size = Math.max(wrap.surface.sheetSize(f), wrap.stripW[wrap.faceStrip[f]]);
        return error * size <= POSE_DRIFT * farthest;
    }

    /**
     * Face f's worst departure from its sheet polygon, relative to its size (at least the strip's width): of a 3D distance from
     * the sheet distance between two corners, or of a corner from the face's plane. When why is
     * given, it gets the worst one in words.
     */
    double isometryError(int f, StringBuilder why) {
        int start = wrap.faceStart[f];
        int end = wrap.faceStart[f + 1];
        // A paper coordinate u on a strip of length L is a double good to about 1e-16 L: a sliver
        // far along a long strip cannot be exact to 1e-9 of its own size, only of the strip's width.
        double size = Math.max(wrap.surface.sheetSize(f), wrap.stripW[wrap.faceStrip[f]]);
        double worst = 0;
        for (int a = start; a < end; a++) {
            for (int b = a + 1; b < end; b++) {
                double inSpace = WrapTruths.distance(wrap.xyz, 3 * wrap.cornerV[a], wrap.xyz, 3 * wrap.cornerV[b]);
                double onSheet = Math.hypot(wrap.uv[2 * wrap.cornerT[a]] - wrap.uv[2 * wrap.cornerT[b]], wrap.uv[2 * wrap.cornerT[a] + 1] - wrap.uv[2 * wrap.cornerT[b] + 1]);
                double error = Math.abs(inSpace - onSheet) / size;
                if (!(error <= worst)) {
                    worst = error;
                    if (why != null) {
                        why.setLength(0);
                        why.append("vertices ").append(wrap.cornerV[a] + 1).append(" and ").append(wrap.cornerV[b] + 1).append(" are ")
                                .append(inSpace).append(" apart in space but ").append(onSheet).append(" on the sheet");
                    }
                }
            }
        }
        if (end - start == 3) {
            // Three corners lie on one plane, whatever they are: a sliver's own normal is rounding
            // (the CGAL elephant's triangle 6·10⁻⁹ high and 1.6·10⁻³ long put its far corner
            // 3.8·10⁻¹² off the plane so found, four billionths of its size).
            return worst;
        }
        double[] normal = wrap.newellNormal(f);
        double[] centre = wrap.centroid(f);
        for (int c = start; c < end; c++) {
            int v = wrap.cornerV[c];
            double off = Math.abs(normal[0] * (wrap.xyz[3 * v] - centre[0]) + normal[1] * (wrap.xyz[3 * v + 1] - centre[1])
                    + normal[2] * (wrap.xyz[3 * v + 2] - centre[2]));
            double error = off / size;
            if (!(error <= worst)) {
                worst = error;
                if (why != null) {
                    why.setLength(0);
                    why.append("vertex ").append(v + 1).append(" is ").append(off).append(" off the face's plane");
                }
            }
        }
        return worst;
    }

    static double[] minus(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double times(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] crossed(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }
}
