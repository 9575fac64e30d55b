package ifold.wrap;

import static ifold.geom.Vectors.cross;
import static ifold.geom.Vectors.dot;
import static ifold.geom.Vectors.sub;
import static ifold.geom.Vectors.unit;
import static ifold.wrap.Wrap.position;

import ifold.geom.Tolerance;
import ifold.mesh.IndexedPolygons;
import ifold.refine.FacePreparation;
import ifold.sheet.HostFrame;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The strip's end rolled round a spike's apex (docs/wrap.md, Limits, "What 24 layers at the
 * spike's apex would take"): where the path is begun at a triangle entered at a true sharp vertex
 * and ends on the one before, whose base runs from it, the last pass runs into the apex and the
 * strip goes on over each of the solid's edges there in turn, all its creases through the apex,
 * until it ends square through it ({@link StripFolding} folds it). Its corner lays 90°/Θ layers
 * there, Θ the vertex's angle sum, where a side of the strip tucked on each face lays 180°/θ on
 * each, θ the face's angle. These are the rules that decide where it is done and how far from the
 * apex it covers each face. The same roll ends the strip at a needle face's tip where the vertex
 * is no spike ({@link #needleEnd}): the last pass runs along the needle's edge into the tip and
 * covers the needle there, and the roll turns 90° over the wider faces beside it.
 */
final class ApexRoll {
    private ApexRoll() {
    }

    /**
     * Whether a path triangle of corners {@code corners} entered at v may have the strip's end
     * rolled round v: v a true sharp vertex of the model (angle sum under 90°), and the corner
     * there of the triangle's plane (the triangles at v in that plane) under the preparation's
     * target, which no preparation widens (the flat figure3's corner of 35°, a sharp vertex of
     * 70° summed over its two sides, is none).
     */
    static boolean sharpStart(IndexedPolygons mesh, int[] corners, int v) {
        int k = v == corners[0] ? 0 : v == corners[1] ? 1 : v == corners[2] ? 2 : -1;
        // Its own corner first: the walk of every face below is for the few that pass.
        if (k < 0 || Math.toDegrees(LayerFloor.angle(mesh, v, corners[(k + 1) % 3], corners[(k + 2) % 3])) >= FacePreparation.TARGET_ANGLE) {
            return false;
        }
        double[] normal = normal(mesh, corners[0], corners[1], corners[2]);
        double sum = 0;
        double inPlane = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int n = mesh.faceSize(f);
            for (int j = 0; j < n; j++) {
                if (mesh.faceVertex(f, j) == v) {
                    double angle = LayerFloor.angle(mesh, v, mesh.faceVertex(f, (j + 1) % n), mesh.faceVertex(f, (j + n - 1) % n));
                    sum += angle;
                    double[] other = normal(mesh, mesh.faceVertex(f, 0), mesh.faceVertex(f, 1), mesh.faceVertex(f, 2));
                    inPlane += dot(normal, other) > 1 - Tolerance.RELATIVE_EQUALITY ? angle : 0;
                }
            }
        }
        return LayerFloor.sharp(sum) && Math.toDegrees(inPlane) < FacePreparation.TARGET_ANGLE;
    }

    /**
     * Whether the strip may end rolled round vertex v where the last path triangle, of corners
     * {@code corners}, has its base from v to {@code other} and v is no true sharp vertex (angle
     * sum 90° or more; a spike's apex is rolled from the triangle entered there,
     * {@link #sharpStart}): the corner there of the triangle's plane (the triangles at v in that
     * plane, a needle face's tip) under the preparation's target, the base along that plane's
     * edge, the triangle across it in another plane, its far end short of the plane's corner, and
     * no edge at v sharper than {@link #SHARPEST_EDGE_ROLLED}. The last pass, along the base into v, then
     * covers the plane's whole width up to w / sin θ from v, θ that corner, and the roll turns
     * the strip's end over the solid's edges at v through 90° without coming back to the plane.
     * Tucked on the needle instead, a side of the strip passing its tip lays 180°/θ layers.
     */
    static boolean needleEnd(IndexedPolygons mesh, int[] corners, int v, int other) {
        return !Double.isNaN(needleCorner(mesh, corners, v, other));
    }

    /** The needle's corner at v, in radians, where {@link #needleEnd} holds; NaN where it does not. */
    static double needleCorner(IndexedPolygons mesh, int[] corners, int v, int other) {
        int k = v == corners[0] ? 0 : v == corners[1] ? 1 : v == corners[2] ? 2 : -1;
        if (k < 0 || other == v || Math.toDegrees(LayerFloor.angle(mesh, v, corners[(k + 1) % 3], corners[(k + 2) % 3])) >= FacePreparation.TARGET_ANGLE) {
            return Double.NaN;
        }
        double[] normal = normal(mesh, corners[0], corners[1], corners[2]);
        double sum = 0;
        double inPlane = 0;
        int across = 0;
        // The faces at v, each its normal and its neighbours of v, for the knives' edges below.
        List<double[]> normals = new ArrayList<>();
        List<int[]> sides = new ArrayList<>();
        double atOther = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int n = mesh.faceSize(f);
            boolean hasOther = false;
            int at = -1;
            for (int j = 0; j < n; j++) {
                if (mesh.faceVertex(f, j) == other) {
                    hasOther = true;
                    double[] faceNormal = normal(mesh, mesh.faceVertex(f, 0), mesh.faceVertex(f, 1), mesh.faceVertex(f, 2));
                    atOther += dot(normal, faceNormal) > 1 - Tolerance.RELATIVE_EQUALITY
                            ? LayerFloor.angle(mesh, other, mesh.faceVertex(f, (j + 1) % n), mesh.faceVertex(f, (j + n - 1) % n)) : 0;
                }
                at = mesh.faceVertex(f, j) == v ? j : at;
            }
            if (at < 0) {
                continue;
            }
            int after = mesh.faceVertex(f, (at + 1) % n);
            int before = mesh.faceVertex(f, (at + n - 1) % n);
            double angle = LayerFloor.angle(mesh, v, after, before);
            sum += angle;
            double[] faceNormal = normal(mesh, mesh.faceVertex(f, 0), mesh.faceVertex(f, 1), mesh.faceVertex(f, 2));
            boolean coplanar = dot(normal, faceNormal) > 1 - Tolerance.RELATIVE_EQUALITY;
            inPlane += coplanar ? angle : 0;
            if (hasOther && !sameTriangle(mesh, f, corners)) {
                across += coplanar ? 2 : 1;
            }
            normals.add(faceNormal);
            sides.add(new int[] {after, before});
        }
        // No edge at v too sharp to roll over, which the roll might have to cross (a tetrahedron
        // with a needle face is a sliver with a knife's edge, from the needle's tip to the tip of
        // the needle across its short edge; SHARPEST_EDGE_ROLLED).
        for (int a = 0; a < sides.size(); a++) {
            for (int b = a + 1; b < sides.size(); b++) {
                boolean shareEdge = sides.get(a)[0] == sides.get(b)[1] || sides.get(a)[1] == sides.get(b)[0];
                if (shareEdge && backToBack(normals.get(a), normals.get(b))) {
                    return Double.NaN;
                }
            }
        }
        // The base's far end inside the needle's edge, not at its corner (the plane's angle there
        // straight): the last pass then begins with a fold inside the needle, not beyond its
        // corner, where it was tucked once the roll had laid it and the strip tore (a square
        // pyramid's 3° needle: in two pieces in space).
        boolean farEndOnEdge = atOther > Math.PI * (1 - Tolerance.RELATIVE_EQUALITY);
        return !LayerFloor.sharp(sum) && across == 1 && farEndOnEdge && Math.toDegrees(inPlane) < FacePreparation.TARGET_ANGLE ? inPlane
                : Double.NaN;
    }

    /** Whether faces of unit normals a and b, sharing an edge, meet at under {@link #SHARPEST_EDGE_ROLLED}. */
    private static boolean backToBack(double[] a, double[] b) {
        return dot(a, b) < -Math.cos(Math.toRadians(SHARPEST_EDGE_ROLLED));
    }

    /**
     * The sharpest edge, in degrees between its faces, that the roll round a needle's tip may
     * cross: thick paper bent round an edge of δ stands out by its height over tan(δ / 2). Over
     * tet15b's 1.5° the roll's cap stood 0.062 off the surface; over an irregular pyramid's 23.5°
     * and 21.9° (its apex 0.2 off centre) 0.0030, twice what the paper's stack allows; rolls
     * over edges of 64° and wider were sound.
     */
    static final double SHARPEST_EDGE_ROLLED = 45;

    private static boolean sameTriangle(IndexedPolygons mesh, int f, int[] corners) {
        if (mesh.faceSize(f) != 3) {
            return false;
        }
        for (int j = 0; j < 3; j++) {
            int c = mesh.faceVertex(f, j);
            if (c != corners[0] && c != corners[1] && c != corners[2]) {
                return false;
            }
        }
        return true;
    }

    /**
     * How far from v the strip's end rolled round a needle's tip ({@link #needleEnd}) covers the
     * needle's host, the last triangle's: its last pass, along the base (the host's edge) into v,
     * covers the host's whole width to w / sin φ, φ the host's corner at v. The hosts the roll
     * crosses after it have corners as wide as their faces' and keep their own paper at v; none
     * is listed. Null where the base does not lie along the host's edge, or runs to the host's
     * corner, or the roll would cross an edge with no host across or one too sharp
     * ({@link #SHARPEST_EDGE_ROLLED}) before it has turned 90°.
     */
    static Map<Integer, Reach> needleCoverage(IndexedPolygons mesh, PathPlan plan, HostPieces pieces, HostFrame[] frames, int v, int last,
            double w) {
        double[] apex = position(mesh, v);
        int other = plan.baseFrom[last] == v ? plan.baseTo[last] : plan.baseFrom[last];
        double[] along = unit(sub(position(mesh, other), apex));
        int host = pieces.hostOf[plan.first + last];
        int[] cs = pieces.corners[host];
        int ka = indexOf(cs, v);
        if (ka < 0) {
            return null;
        }
        int before = cs[(ka + cs.length - 1) % cs.length];
        int after = cs[(ka + 1) % cs.length];
        boolean alongBefore = dot(along, unit(sub(position(mesh, before), apex))) > 1 - Tolerance.RELATIVE_EQUALITY;
        boolean alongAfter = dot(along, unit(sub(position(mesh, after), apex))) > 1 - Tolerance.RELATIVE_EQUALITY;
        if (alongBefore == alongAfter) {
            return null;
        }
        int out = alongBefore ? after : before;
        // The base's far end at the host's corner too, as needleCorner has it never: the host's
        // corners are the plane's, less any cut where a plane is split into convex hosts.
        if (other == (alongBefore ? before : after) || hostAcross(pieces, host, v, out) < 0) {
            return null;
        }
        double phi = angle(along, sub(position(mesh, out), apex));
        // The edges the roll crosses before it has turned 90°: none too sharp to roll over
        // (SHARPEST_EDGE_ROLLED; needleCorner asks it of every edge at v, this of the hosts').
        int across = host;
        int from = out;
        for (double at = phi; at < Math.PI / 2; ) {
            int crossed = across;
            across = hostAcross(pieces, across, v, from);
            if (across < 0 || backToBack(frames[crossed].normal(), frames[across].normal())) {
                return null;
            }
            int[] hc = pieces.corners[across];
            int k = indexOf(hc, v);
            if (k < 0) {
                return null;
            }
            int next = hc[(k + 1) % hc.length] == from ? hc[(k + hc.length - 1) % hc.length] : hc[(k + 1) % hc.length];
            at += angle(sub(position(mesh, from), apex), sub(position(mesh, next), apex));
            from = next;
        }
        // Entered by no crease: the roll leaves this host and turns 90° before it could come back.
        return Map.of(host, new Reach(w / Math.sin(Math.min(Math.PI / 2, phi)), 0, out));
    }

    /** The unit normal of the triangle a, b, c of {@code mesh}. */
    private static double[] normal(IndexedPolygons mesh, int a, int b, int c) {
        double[] pa = position(mesh, a);
        return unit(cross(sub(position(mesh, b), pa), sub(position(mesh, c), pa)));
    }

    /**
     * How far from the apex the roll covers a host round it.
     *
     * @param whole how far it covers the host's whole width: w / sin φ, φ the angle from the
     *     last pass's side at which the roll leaves the host's wedge the first time it has
     *     crossed all of it
     * @param entering how far along the host's edge the roll first crosses into it by the cap of
     *     that crease reaches: w / sin φ, φ the angle of that edge from the last pass's side (as
     *     far as the host before it is covered whole)
     * @param enteredBy the host's corner at the other end of that edge from the apex
     */
    record Reach(double whole, double entering, int enteredBy) {
    }

    /**
     * How far from apex v the roll of the strip's end (the last triangle's last pass along its
     * base into v, then over each edge at v in turn) covers each host round v ({@link Reach}).
     * Null where a host round v is not a plane's corner.
     */
    static Map<Integer, Reach> coverage(IndexedPolygons mesh, PathPlan plan, HostPieces pieces, int v, int last, double w) {
        double[] apex = position(mesh, v);
        int other = plan.baseFrom[last] == v ? plan.baseTo[last] : plan.baseFrom[last];
        double[] along = unit(sub(position(mesh, other), apex));
        double[] inward = sub(position(mesh, plan.start[last]), apex);
        int start = pieces.hostOf[plan.first + last];
        int[] cs = pieces.corners[start];
        int ka = indexOf(cs, v);
        if (ka < 0) {
            return null;
        }
        int out = -1;
        int back = -1;
        for (int c : new int[] {cs[(ka + 1) % cs.length], cs[(ka + cs.length - 1) % cs.length]}) {
            double[] d = sub(position(mesh, c), apex);
            if (dot(cross(along, d), cross(along, inward)) > 0) {
                out = c;
            } else {
                back = c;
            }
        }
        if (out < 0 || back < 0) {
            return null;
        }
        double phi = angle(along, sub(position(mesh, out), apex));
        double rest = angle(along, sub(position(mesh, back), apex));
        Map<Integer, Reach> covers = new HashMap<>();
        int host = start;
        int from = out;
        for (int round = 0; round < 64; round++) {
            host = hostAcross(pieces, host, v, from);
            if (host < 0) {
                return null;
            }
            int[] hc = pieces.corners[host];
            int k = indexOf(hc, v);
            if (k < 0) {
                return null;
            }
            int next = hc[(k + 1) % hc.length] == from ? hc[(k + hc.length - 1) % hc.length] : hc[(k + 1) % hc.length];
            double wedge = angle(sub(position(mesh, from), apex), sub(position(mesh, next), apex));
            double entering = w / Math.sin(Math.min(Math.PI / 2, phi));
            if (host == start) {
                covers.put(host, new Reach(w / Math.sin(Math.min(Math.PI / 2, phi + rest)), entering, from));
                return covers;
            }
            phi += wedge;
            covers.put(host, new Reach(w / Math.sin(Math.min(Math.PI / 2, phi)), entering, from));
            from = next;
        }
        return null;
    }

    /**
     * Whether the segment from apex v to vertex {@code end} of {@code mesh} runs along the edge
     * by which the roll first enters a host ({@link Reach#enteredBy}).
     */
    static boolean alongEntered(IndexedPolygons mesh, int v, Reach reach, int end) {
        double[] apex = position(mesh, v);
        double[] along = unit(sub(position(mesh, end), apex));
        return dot(along, unit(sub(position(mesh, reach.enteredBy()), apex))) > 1 - Tolerance.RELATIVE_EQUALITY;
    }

    private static int indexOf(int[] a, int x) {
        for (int k = 0; k < a.length; k++) {
            if (a[k] == x) {
                return k;
            }
        }
        return -1;
    }

    private static double angle(double[] a, double[] b) {
        return Math.atan2(Math.sqrt(dot(cross(a, b), cross(a, b))), dot(a, b));
    }

    /** The host other than {@code host} with the edge from corner a to corner b, -1 none. */
    static int hostAcross(HostPieces pieces, int host, int a, int b) {
        for (int h = 0; h < pieces.corners.length; h++) {
            if (h == host) {
                continue;
            }
            int[] cs = pieces.corners[h];
            for (int k = 0; k < cs.length; k++) {
                int x = cs[k];
                int y = cs[(k + 1) % cs.length];
                if (x == a && y == b || x == b && y == a) {
                    return h;
                }
            }
        }
        return -1;
    }

}
