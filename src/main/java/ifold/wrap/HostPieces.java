package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.IndexedPolygons;
import ifold.refine.RefinedMesh;
import ifold.sheet.HostFrame;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The hosts a wrap's paper rests on: convex pieces of the model's planes, each the union of
 * the path triangles in it. A cube's face is one piece however its refinement cuts it, so the
 * strip lies flat across the spokes of the refinement, and only what reaches past the face's
 * own edges is tucked: the 22.5° corners the refinement makes are no corners of the paper's.
 *
 * <p>Coplanar neighbours (normals within 1e-12, the far corner within 1e-9 of the model's size
 * of the plane) make one region; a convex region is one piece, any other is cut into convex
 * pieces by merging neighbours while their union stays convex (Hertel and Mehlhorn's greedy
 * decomposition, at most four times the fewest pieces), the two whose union has the widest
 * smallest corner first. Convex, because a tuck folds all the
 * piece's paper beyond the line of one of its edges: on a convex piece, nothing beyond that
 * line is over the piece.
 */
final class HostPieces {
    /** The host of each path triangle, numbered by first appearance along the path. */
    final int[] hostOf;
    /** Each host's corners, vertex ids of the path, counter-clockwise seen from outside, none in line with its neighbours. */
    final int[][] corners;

    private HostPieces(int[] hostOf, int[][] corners) {
        this.hostOf = hostOf;
        this.corners = corners;
    }

    /** The convex coplanar pieces of a path's triangles. */
    static HostPieces of(IndexedPolygons path) {
        Cells cells = path instanceof RefinedMesh refined ? Cells.ofParents(refined) : Cells.ofTriangles(path);
        cells.merge();
        int n = path.faceCount();
        int[] hostOf = new int[n];
        Arrays.fill(hostOf, -1);
        int[] hostOfPiece = new int[cells.count];
        Arrays.fill(hostOfPiece, -1);
        List<int[]> corners = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            int piece = cells.find(cells.cellOf(t));
            if (hostOfPiece[piece] < 0) {
                hostOfPiece[piece] = corners.size();
                corners.add(cells.corners(piece));
            }
            hostOf[t] = hostOfPiece[piece];
        }
        return new HostPieces(hostOf, corners.toArray(new int[0][]));
    }

    int hostCount() {
        return corners.length;
    }

    /**
     * Convex polygons of the model (its triangles to begin with, or a refinement's original
     * faces) merged into pieces, with a union-find over them.
     */
    private static final class Cells {
        final IndexedPolygons points;
        final int count;
        /** Each cell's boundary, vertex ids counter-clockwise; a merged cell's lives at its root. */
        final int[][] loop;
        final int[] parent;
        /** Neighbouring cells (a, b) across an edge, and the edge's ends. */
        final List<int[]> neighbours = new ArrayList<>();
        final double[][] normal;
        final double size;
        private final int[] cellOfTriangle;

        private Cells(IndexedPolygons points, int[][] loop, int[] cellOfTriangle) {
            this.points = points;
            this.count = loop.length;
            this.loop = loop;
            this.cellOfTriangle = cellOfTriangle;
            parent = new int[count];
            normal = new double[count][];
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY,
                Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int c = 0; c < count; c++) {
                parent[c] = c;
                normal[c] = normal(loop[c]);
                for (int v : loop[c]) {
                    for (int axis = 0; axis < 3; axis++) {
                        box[axis] = Math.min(box[axis], points.coordinate(v, axis));
                        box[axis + 3] = Math.max(box[axis + 3], points.coordinate(v, axis));
                    }
                }
            }
            size = Math.max(box[3] - box[0], Math.max(box[4] - box[1], box[5] - box[2]));
        }

        /** A refinement's triangles grouped by the original face they cut: the face is convex, a triangle. */
        static Cells ofParents(RefinedMesh refined) {
            HalfedgeMesh original = refined.original();
            int faces = original.faceCount();
            int[][] loop = new int[faces][];
            for (int f = 0; f < faces; f++) {
                loop[f] = new int[] {original.faceVertex(f, 0), original.faceVertex(f, 1), original.faceVertex(f, 2)};
            }
            int[] cellOf = new int[refined.faceCount()];
            for (int t = 0; t < cellOf.length; t++) {
                cellOf[t] = refined.parentFace(t);
            }
            Cells cells = new Cells(refined, loop, cellOf);
            for (int h = 0; h < original.halfedgeCount(); h += 2) {
                int twin = HalfedgeMesh.twin(h);
                if (original.isBoundary(h) || original.isBoundary(twin)) {
                    continue;
                }
                cells.neighbour(original.face(h), original.face(twin), original.fromVertex(h), original.toVertex(h));
            }
            return cells;
        }

        /** Any path's triangles, neighbours where they share two vertex ids. */
        static Cells ofTriangles(IndexedPolygons path) {
            int n = path.faceCount();
            int[][] loop = new int[n][];
            int[] cellOf = new int[n];
            for (int t = 0; t < n; t++) {
                loop[t] = new int[] {path.faceVertex(t, 0), path.faceVertex(t, 1), path.faceVertex(t, 2)};
                cellOf[t] = t;
            }
            Cells cells = new Cells(path, loop, cellOf);
            Map<Long, Integer> firstSide = new HashMap<>();
            for (int t = 0; t < n; t++) {
                for (int k = 0; k < 3; k++) {
                    int a = loop[t][k];
                    int b = loop[t][(k + 1) % 3];
                    long key = ((long) Math.min(a, b) << 32) | (Math.max(a, b) & 0xffffffffL);
                    Integer other = firstSide.putIfAbsent(key, t);
                    if (other != null && other != t) {
                        cells.neighbour(other, t, a, b);
                    }
                }
            }
            return cells;
        }

        int cellOf(int triangle) {
            return cellOfTriangle[triangle];
        }

        private void neighbour(int a, int b, int from, int to) {
            if (coplanar(a, b) && coplanar(b, a)) {
                neighbours.add(new int[] {a, b, from, to});
            }
        }

        /** Whether cell b lies in cell a's plane: the same normal, its corners on the plane. */
        private boolean coplanar(int a, int b) {
            double[] n = normal[a];
            double[] m = normal[b];
            if (!(n[0] * m[0] + n[1] * m[1] + n[2] * m[2] >= 1 - Tolerance.COPLANAR_COSINE)) {
                return false;
            }
            int o = loop[a][0];
            for (int v : loop[b]) {
                double off = 0;
                for (int axis = 0; axis < 3; axis++) {
                    off += (points.coordinate(v, axis) - points.coordinate(o, axis)) * n[axis];
                }
                if (!(Math.abs(off) <= Tolerance.ON_PLANE * size)) {
                    return false;
                }
            }
            return true;
        }

        int find(int c) {
            while (parent[c] != c) {
                parent[c] = parent[parent[c]];
                c = parent[c];
            }
            return c;
        }

        /**
         * Merges coplanar neighbours while their union stays convex, whole regions first: a
         * convex face cut into triangles any way comes back as one piece. The rest roundest
         * first ({@link #mergeRoundest}).
         */
        void merge() {
            // The regions: coplanar neighbours joined.
            int[] region = new int[count];
            for (int c = 0; c < count; c++) {
                region[c] = c;
            }
            for (int[] pair : neighbours) {
                int a = root(region, pair[0]);
                int b = root(region, pair[1]);
                if (a != b) {
                    region[Math.max(a, b)] = Math.min(a, b);
                }
            }
            // Each region of more than one cell, whole if its boundary is one convex loop.
            int[] size = new int[count];
            for (int c = 0; c < count; c++) {
                size[root(region, c)]++;
            }
            Map<Integer, List<Integer>> members = new HashMap<>();
            for (int c = 0; c < count; c++) {
                int r = root(region, c);
                if (size[r] > 1) {
                    members.computeIfAbsent(r, k -> new ArrayList<>()).add(c);
                }
            }
            for (List<Integer> cells : members.values()) {
                int[] whole = boundary(cells);
                if (whole != null && convex(whole, normal[cells.get(0)])) {
                    int root = cells.get(0);
                    for (int c : cells) {
                        parent[c] = root;
                        loop[c] = c == root ? whole : null;
                    }
                }
            }
            mergeRoundest();
        }

        /**
         * Merges, one pair at a time, the two neighbours whose union is convex and has the
         * widest smallest corner: a rectilinear face (a polycube's L, cut into squares and each
         * square into two triangles) comes back as rectangles, not as triangles with 45° corners
         * cut along a diagonal, where tucks bounce and the folds along the cut stand in one plane.
         */
        private void mergeRoundest() {
            // Each pair's union and its smallest corner, kept until either cell changes (its
            // root or that root's version): a merge touches only the pairs of the two cells, and
            // trying every pair's union anew after each merge made the cost grow as the square.
            int pairs = neighbours.size();
            int[][] unions = new int[pairs][];
            double[] smallest = new double[pairs];
            int[] rootA = new int[pairs];
            int[] rootB = new int[pairs];
            int[] versionA = new int[pairs];
            int[] versionB = new int[pairs];
            java.util.Arrays.fill(rootA, -1);
            int[] version = new int[count];
            while (true) {
                int best = -1;
                for (int k = 0; k < pairs; k++) {
                    int a = find(neighbours.get(k)[0]);
                    int b = find(neighbours.get(k)[1]);
                    if (a == b) {
                        continue;
                    }
                    if (rootA[k] != a || rootB[k] != b || versionA[k] != version[a] || versionB[k] != version[b]) {
                        int[] union = union(loop[a], loop[b]);
                        unions[k] = union != null && convex(union, normal[a]) ? union : null;
                        smallest[k] = unions[k] == null ? -1 : smallestCorner(unions[k], normal[a]);
                        rootA[k] = a;
                        rootB[k] = b;
                        versionA[k] = version[a];
                        versionB[k] = version[b];
                    }
                    if (unions[k] != null && (best < 0 || smallest[k] > smallest[best] + 1e-9)) {
                        best = k;
                    }
                }
                if (best < 0) {
                    return;
                }
                int a = rootA[best];
                int b = rootB[best];
                parent[b] = a;
                loop[a] = unions[best];
                loop[b] = null;
                version[a]++;
            }
        }

        /** The smallest corner of a convex loop in degrees, its vertices in line with their neighbours passed over. */
        private double smallestCorner(int[] l, double[] n) {
            int count = l.length;
            double smallest = 180;
            for (int k = 0; k < count; k++) {
                int a = l[(k + count - 1) % count];
                int b = l[k];
                int c = l[(k + 1) % count];
                double[] u = new double[3];
                double[] w = new double[3];
                for (int axis = 0; axis < 3; axis++) {
                    u[axis] = points.coordinate(a, axis) - points.coordinate(b, axis);
                    w[axis] = points.coordinate(c, axis) - points.coordinate(b, axis);
                }
                double cross = n[0] * (u[1] * w[2] - u[2] * w[1]) + n[1] * (u[2] * w[0] - u[0] * w[2]) + n[2] * (u[0] * w[1] - u[1] * w[0]);
                double dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
                double angle = Math.toDegrees(Math.atan2(Math.abs(cross), dot));
                if (angle < 180 - 1e-6) {
                    smallest = Math.min(smallest, angle);
                }
            }
            return smallest;
        }


        private static int root(int[] region, int c) {
            while (region[c] != c) {
                region[c] = region[region[c]];
                c = region[c];
            }
            return c;
        }

        /** The one boundary loop of cells joined, counter-clockwise; null if it is more than one loop, or not a loop. */
        private int[] boundary(List<Integer> cells) {
            Map<Long, Integer> edges = new HashMap<>();
            for (int c : cells) {
                int[] l = loop[c];
                for (int k = 0; k < l.length; k++) {
                    int a = l[k];
                    int b = l[(k + 1) % l.length];
                    if (edges.remove(directed(b, a)) == null) {
                        edges.put(directed(a, b), b);
                    }
                }
            }
            Map<Integer, Integer> next = new HashMap<>();
            for (Map.Entry<Long, Integer> e : edges.entrySet()) {
                if (next.put((int) (e.getKey() >>> 32), e.getValue()) != null) {
                    return null; // two boundary edges leave one vertex: not one simple loop
                }
            }
            if (next.isEmpty()) {
                return null;
            }
            int start = next.keySet().iterator().next();
            int[] out = new int[next.size()];
            int v = start;
            for (int k = 0; k < out.length; k++) {
                out[k] = v;
                v = next.get(v);
                if (v == start && k + 1 < out.length) {
                    return null; // more than one loop
                }
            }
            return v == start ? out : null;
        }

        private static long directed(int a, int b) {
            return ((long) a << 32) | (b & 0xffffffffL);
        }

        /**
         * The union of two convex loops that share one chain of edges (P runs a → … → b along
         * it, Q b → … → a): P from b round to a, then Q past a round to b. Null if they share
         * no edge, or more than one chain.
         */
        private static int[] union(int[] p, int[] q) {
            Map<Long, Integer> inQ = new HashMap<>();
            for (int k = 0; k < q.length; k++) {
                inQ.put(directed(q[k], q[(k + 1) % q.length]), k);
            }
            int n = p.length;
            boolean[] shared = new boolean[n];
            int sharedCount = 0;
            for (int k = 0; k < n; k++) {
                shared[k] = inQ.containsKey(directed(p[(k + 1) % n], p[k]));
                sharedCount += shared[k] ? 1 : 0;
            }
            if (sharedCount == 0 || sharedCount == n) {
                return null;
            }
            int first = -1;
            for (int k = 0; k < n; k++) {
                if (shared[k] && !shared[(k + n - 1) % n]) {
                    if (first >= 0) {
                        return null; // two chains: the union would have a hole
                    }
                    first = k;
                }
            }
            int a = p[first];
            int b = p[(first + sharedCount) % n];
            for (int k = 0; k < sharedCount; k++) {
                if (!shared[(first + k) % n]) {
                    return null;
                }
            }
            int[] out = new int[p.length + q.length - 2 * sharedCount];
            int m = 0;
            for (int k = (first + sharedCount) % n; ; k = (k + 1) % n) {
                out[m++] = p[k];
                if (p[k] == a) {
                    break;
                }
            }
            int qa = 0;
            while (q[qa] != a) {
                qa++;
            }
            // Q runs the chain b → … → a, then from a the long way round to b.
            for (int k = (qa + 1) % q.length; q[k] != b; k = (k + 1) % q.length) {
                if (m == out.length) {
                    return null;
                }
                out[m++] = q[k];
            }
            if (m != out.length) {
                return null;
            }
            for (int i = 0; i < m; i++) {
                for (int j = i + 1; j < m; j++) {
                    if (out[i] == out[j]) {
                        return null;
                    }
                }
            }
            return out;
        }

        /** Whether a loop turns left (or runs straight) at every corner, seen along the normal. */
        private boolean convex(int[] l, double[] n) {
            int count = l.length;
            for (int k = 0; k < count; k++) {
                if (turn(l[(k + count - 1) % count], l[k], l[(k + 1) % count], n) < -Tolerance.DEGENERATE_AREA) {
                    return false;
                }
            }
            return true;
        }

        /** How far the path a → b → c turns left at b, seen along n: the sine of the turn. */
        private double turn(int a, int b, int c, double[] n) {
            double[] u = new double[3];
            double[] w = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                u[axis] = points.coordinate(b, axis) - points.coordinate(a, axis);
                w[axis] = points.coordinate(c, axis) - points.coordinate(b, axis);
            }
            double cross = n[0] * (u[1] * w[2] - u[2] * w[1]) + n[1] * (u[2] * w[0] - u[0] * w[2]) + n[2] * (u[0] * w[1] - u[1] * w[0]);
            return cross / Math.sqrt((u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
        }

        private double[] normal(int[] l) {
            double[] n = new double[3];
            // Newell's normal: exact for a triangle, the area-weighted mean for any planar loop.
            for (int k = 0; k < l.length; k++) {
                int a = l[k];
                int b = l[(k + 1) % l.length];
                double ax = points.coordinate(a, 0);
                double ay = points.coordinate(a, 1);
                double az = points.coordinate(a, 2);
                double bx = points.coordinate(b, 0);
                double by = points.coordinate(b, 1);
                double bz = points.coordinate(b, 2);
                n[0] += (ay - by) * (az + bz);
                n[1] += (az - bz) * (ax + bx);
                n[2] += (ax - bx) * (ay + by);
            }
            double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            return new double[] {n[0] / length, n[1] / length, n[2] / length};
        }

        /** A piece's corners: its loop less the vertices in line with their neighbours (a refinement's midpoints, a cut edge's points). */
        int[] corners(int piece) {
            int[] l = loop[piece];
            double[] n = normal[piece];
            List<Integer> kept = new ArrayList<>();
            int count = l.length;
            for (int k = 0; k < count; k++) {
                if (turn(l[(k + count - 1) % count], l[k], l[(k + 1) % count], n) > Tolerance.DEGENERATE_AREA) {
                    kept.add(l[k]);
                }
            }
            return kept.stream().mapToInt(Integer::intValue).toArray();
        }
    }

    /** Whether each triangle of the mesh is alone on its host (a curved surface's are). */
    boolean[] alone() {
        int[] count = new int[hostCount()];
        for (int h : hostOf) {
            count[h]++;
        }
        boolean[] alone = new boolean[hostOf.length];
        for (int t = 0; t < alone.length; t++) {
            alone[t] = count[hostOf[t]] == 1;
        }
        return alone;
    }

    /**
     * Each host's frame: the frame of the first triangle of the path on it (a host of one
     * triangle keeps its triangle's frame), with the host's polygon for corners.
     */
    HostFrame[] frames(IndexedPolygons mesh, HostFrame[] triangleFrames) {
        HostFrame[] frames = new HostFrame[hostCount()];
        for (int t = 0; t < triangleFrames.length; t++) {
            int h = hostOf[t];
            if (frames[h] != null) {
                continue;
            }
            HostFrame f = triangleFrames[t];
            int[] corners = this.corners[h];
            if (corners.length == 3 && sameCorners(corners, mesh, t)) {
                frames[h] = f; // a host of one triangle: its frame and corners as the planner has them
                continue;
            }
            double[] xy = new double[2 * corners.length];
            for (int k = 0; k < corners.length; k++) {
                double[] p = Wrap.position(mesh, corners[k]);
                xy[2 * k] = f.localX(p);
                xy[2 * k + 1] = f.localY(p);
            }
            frames[h] = new HostFrame(f.origin(), f.ex(), f.ey(), f.normal(), xy);
        }
        return frames;
    }

    private static boolean sameCorners(int[] corners, IndexedPolygons mesh, int t) {
        for (int v : corners) {
            if (v != mesh.faceVertex(t, 0) && v != mesh.faceVertex(t, 1) && v != mesh.faceVertex(t, 2)) {
                return false;
            }
        }
        return true;
    }
}
