package ifold.refine;

import ifold.geom.Triangles;
import ifold.geom.UnionFind;
import ifold.mesh.HalfedgeMesh;
import java.util.ArrayDeque;
import java.util.Arrays;

/**
 * A path through the model's own triangles, which the zig-zag may follow instead of the
 * Hamiltonian refinement's 5n - 2: Demaine, Demaine and Mitchell need only consecutive triangles
 * sharing an edge, and the refinement is there to make such a path exist on any mesh. Most of a
 * closed mesh's triangles can be passed whole, each once:
 * <ol>
 *   <li>the dual graph of a closed triangle mesh (triangles joined through shared edges) has three
 *       edges at every node and no bridge, so it has a perfect matching (Petersen); the edges not
 *       matched leave every triangle two neighbours, and so cover the triangles by disjoint cycles;</li>
 *   <li>two cycles that meet at a matched edge are spliced there, as the refinement joins across
 *       a tree edge: the triangles on both sides are cut from their incentres and the edge split
 *       at its midpoint, and the path goes from the one triangle into the other, round the whole of
 *       the other cycle, and back;</li>
 *   <li>a spanning tree of such splices makes one cycle of each connected component.</li>
 * </ol>
 * Each triangle has one matched edge, so it is cut for at most one splice: a component of n
 * triangles covered by k cycles becomes a path of n + 6(k - 1) triangles, and every triangle
 * not cut keeps its own angles rather than half of them. Where there is no perfect matching (a
 * surface with a boundary, whose triangles have fewer than three neighbours), there is no such
 * path, and the refinement is followed.
 *
 * <p>The result is a {@link HamiltonianRefinement.Result} whose {@link RefinedMesh} lists whole
 * triangles ({@code RefinedMesh.FACE}) among the pieces of the cut ones, its split edges in
 * place of the tree edges.
 */
public final class CycleCoverPath {
    private CycleCoverPath() {
    }

    /**
     * The path through {@code mesh}'s own triangles, a cycle for each connected component, or null
     * where it has none this way (a triangle with a side on a boundary; no perfect matching).
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    public static HamiltonianRefinement.Result of(HalfedgeMesh mesh) {
        int faces = mesh.faceCount();
        double[] xyz = mesh.positionArray();
        for (int f = 0; f < faces; f++) {
            int h = mesh.faceHalfedge(f);
            if (mesh.next(mesh.next(mesh.next(h))) != h) {
                throw new IllegalArgumentException("a path of triangles needs triangles, but face " + f + " has " + mesh.faceSize(f) + " sides");
            }
            if (Triangles.isDegenerate(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)))) {
                throw new IllegalArgumentException("face " + f + " has no area, so it has no incentre");
            }
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                if (mesh.face(HalfedgeMesh.twin(h)) < 0) {
                    return null; // a side on the boundary: fewer than three neighbours
                }
            }
        }
        if (faces == 0 || mesh.halfedgeCount() > (Integer.MAX_VALUE >>> 2)) {
            return null;
        }
        int[] matched = Matching.perfect(mesh);
        if (matched == null) {
            return null;
        }
        return new Splicer(mesh, matched).path();
    }

    /**
     * A perfect matching of the dual graph by Edmonds' blossoms, begun from a greedy one: each
     * triangle's matched halfedge (the side across which its partner lies), or null where the
     * graph has none.
     */
    static final class Matching {
        private final HalfedgeMesh mesh;
        private final int faces;
        /** The partner of each triangle, -1 while unmatched. */
        private final int[] mate;
        private final int[] parent;
        private final int[] base;
        private final boolean[] inQueue;
        private final boolean[] inBlossom;
        private final boolean[] onPath;
        private final int[] queue;

        private Matching(HalfedgeMesh mesh) {
            this.mesh = mesh;
            this.faces = mesh.faceCount();
            mate = new int[faces];
            parent = new int[faces];
            base = new int[faces];
            inQueue = new boolean[faces];
            inBlossom = new boolean[faces];
            onPath = new boolean[faces];
            queue = new int[faces];
        }

        static int[] perfect(HalfedgeMesh mesh) {
            Matching m = new Matching(mesh);
            Arrays.fill(m.mate, -1);
            // Greedy first, the triangle with fewest free neighbours taking one: few are left to augment.
            for (int f = 0; f < m.faces; f++) {
                if (m.mate[f] < 0) {
                    int h = mesh.faceHalfedge(f);
                    for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                        int g = mesh.face(HalfedgeMesh.twin(h));
                        if (g != f && m.mate[g] < 0) {
                            m.mate[f] = g;
                            m.mate[g] = f;
                            break;
                        }
                    }
                }
            }
            for (int f = 0; f < m.faces; f++) {
                if (m.mate[f] < 0 && !m.augment(f)) {
                    return null;
                }
            }
            int[] matchedHalfedge = new int[m.faces];
            for (int f = 0; f < m.faces; f++) {
                matchedHalfedge[f] = -1;
                int h = mesh.faceHalfedge(f);
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    if (mesh.face(HalfedgeMesh.twin(h)) == m.mate[f]) {
                        matchedHalfedge[f] = h;
                        break;
                    }
                }
            }
            // Two triangles sharing two sides: one side matched on both, the same edge.
            for (int f = 0; f < m.faces; f++) {
                int g = m.mate[f];
                if (HalfedgeMesh.twin(matchedHalfedge[f]) != matchedHalfedge[g]) {
                    matchedHalfedge[g] = HalfedgeMesh.twin(matchedHalfedge[f]);
                }
            }
            return matchedHalfedge;
        }

        /** Edmonds' search from the free triangle {@code root}: whether it found a path to augment along. */
        private boolean augment(int root) {
            Arrays.fill(parent, -1);
            Arrays.fill(inQueue, false);
            for (int i = 0; i < faces; i++) {
                base[i] = i;
            }
            int head = 0;
            int tail = 0;
            queue[tail++] = root;
            inQueue[root] = true;
            while (head < tail) {
                int v = queue[head++];
                int h = mesh.faceHalfedge(v);
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    int to = mesh.face(HalfedgeMesh.twin(h));
                    if (to == v || base[v] == base[to] || mate[v] == to) {
                        continue;
                    }
                    if (to == root || mate[to] >= 0 && parent[mate[to]] >= 0) {
                        int b = commonBase(v, to);
                        Arrays.fill(inBlossom, false);
                        markBlossom(v, b, to);
                        markBlossom(to, b, v);
                        for (int i = 0; i < faces; i++) {
                            if (inBlossom[base[i]]) {
                                base[i] = b;
                                if (!inQueue[i]) {
                                    inQueue[i] = true;
                                    queue[tail++] = i;
                                }
                            }
                        }
                    } else if (parent[to] < 0) {
                        parent[to] = v;
                        if (mate[to] < 0) {
                            for (int u = to; u >= 0; ) { // flip the path's edges
                                int p = parent[u];
                                int next = mate[p];
                                mate[u] = p;
                                mate[p] = u;
                                u = next;
                            }
                            return true;
                        }
                        inQueue[mate[to]] = true;
                        queue[tail++] = mate[to];
                    }
                }
            }
            return false;
        }

        private int commonBase(int a, int b) {
            Arrays.fill(onPath, false);
            while (true) {
                a = base[a];
                onPath[a] = true;
                if (mate[a] < 0) {
                    break;
                }
                a = parent[mate[a]];
            }
            while (true) {
                b = base[b];
                if (onPath[b]) {
                    return b;
                }
                b = parent[mate[b]];
            }
        }

        private void markBlossom(int v, int b, int child) {
            while (base[v] != b) {
                inBlossom[base[v]] = true;
                inBlossom[base[mate[v]]] = true;
                parent[v] = child;
                child = mate[v];
                v = parent[mate[v]];
            }
        }
    }

    /** The cycles of the unmatched edges, spliced into one per component, emitted as pieces. */
    private static final class Splicer {
        private final HalfedgeMesh mesh;
        private final int[] matched;
        /** The cycle each triangle lies on. */
        private final int[] cycleOf;
        /** Whether each edge is split for a splice. */
        private final boolean[] split;
        private int[] path;
        private int emitted;

        Splicer(HalfedgeMesh mesh, int[] matched) {
            this.mesh = mesh;
            this.matched = matched;
            this.cycleOf = new int[mesh.faceCount()];
            this.split = new boolean[mesh.edgeCount()];
        }

        /**
         * The smallest altitude of the pieces a splice across {@code h} cuts its triangle into:
         * the triangle cut from its incentre, the side of {@code h} split at its midpoint.
         */
        private double narrowestPiece(double[] xyz, double[] incentres, int h) {
            int f = mesh.face(h);
            double[] p = new double[12]; // incentre, the side's ends, its midpoint; then the third corner
            int from = mesh.fromVertex(h);
            int to = mesh.toVertex(h);
            int third = mesh.toVertex(mesh.next(h));
            for (int axis = 0; axis < 3; axis++) {
                p[axis] = incentres[3 * f + axis];
                p[3 + axis] = xyz[3 * from + axis];
                p[6 + axis] = xyz[3 * to + axis];
                p[9 + axis] = 0.5 * (xyz[3 * from + axis] + xyz[3 * to + axis]);
            }
            double[] q = {p[0], p[1], p[2], p[3], p[4], p[5], p[6], p[7], p[8], xyz[3 * third], xyz[3 * third + 1], xyz[3 * third + 2]};
            return Math.min(Math.min(altitude(p, 0, 1, 3), altitude(p, 0, 3, 2)), Math.min(altitude(q, 0, 2, 3), altitude(q, 0, 3, 1)));
        }

        /** The smallest altitude of triangle a, b, c of {@code xyz}: twice its area over its longest side. */
        private static double altitude(double[] xyz, int a, int b, int c) {
            double longest = Math.max(Triangles.distance(xyz, a, b), Math.max(Triangles.distance(xyz, b, c), Triangles.distance(xyz, c, a)));
            return Triangles.twiceArea(xyz, a, b, c) / longest;
        }

        /** The halfedge of {@code f} other than {@code matched[f]} and {@code not}: the cycle's way on. */
        private int otherCycleSide(int f, int not) {
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                if (h != matched[f] && h != not) {
                    return h;
                }
            }
            throw new IllegalStateException("triangle " + f + " has no side left for its cycle");
        }

        HamiltonianRefinement.Result path() {
            int faces = mesh.faceCount();
            // The cycles.
            Arrays.fill(cycleOf, -1);
            int cycles = 0;
            for (int s = 0; s < faces; s++) {
                if (cycleOf[s] >= 0) {
                    continue;
                }
                int f = s;
                int out = otherCycleSide(s, -1);
                while (cycleOf[f] < 0) {
                    cycleOf[f] = cycles;
                    int in = HalfedgeMesh.twin(out);
                    f = mesh.face(in);
                    out = otherCycleSide(f, in);
                }
                cycles++;
            }
            double[] incentres = new double[3 * faces];
            double[] xyz = mesh.positionArray();
            for (int f = 0; f < faces; f++) {
                int h = mesh.faceHalfedge(f);
                Triangles.incenter(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)), incentres, 3 * f);
            }
            // A spanning forest of splices, the widest first (Kruskal): a splice's pieces are
            // narrower than its triangles, and the narrowest triangle of the path sets the widest strip.
            int[] candidates = new int[faces];
            int count = 0;
            for (int f = 0; f < faces; f++) {
                int g = mesh.face(HalfedgeMesh.twin(matched[f]));
                if (f < g && cycleOf[f] != cycleOf[g]) {
                    candidates[count++] = matched[f];
                }
            }
            double[] narrowest = new double[count];
            Integer[] order = new Integer[count];
            for (int i = 0; i < count; i++) {
                order[i] = i;
                narrowest[i] = Math.min(narrowestPiece(xyz, incentres, candidates[i]), narrowestPiece(xyz, incentres, HalfedgeMesh.twin(candidates[i])));
            }
            Arrays.sort(order, (x, y) -> Double.compare(narrowest[y], narrowest[x]));
            int[] joined = UnionFind.pieces(cycles);
            for (int i : order) {
                int h = candidates[i];
                int f = mesh.face(h);
                int g = mesh.face(HalfedgeMesh.twin(h));
                if (UnionFind.find(joined, cycleOf[f]) != UnionFind.find(joined, cycleOf[g])) {
                    UnionFind.union(joined, cycleOf[f], cycleOf[g]);
                    split[HalfedgeMesh.edge(h)] = true;
                }
            }
            int splices = 0;
            for (boolean s : split) {
                splices += s ? 1 : 0;
            }
            path = new int[faces + 6 * splices];
            // One walk per component, from its lowest triangle: round its cycle, into each cycle spliced on.
            boolean[] walked = new boolean[cycles];
            int[] componentStart = new int[cycles + 1];
            int components = 0;
            for (int s = 0; s < faces; s++) {
                if (!walked[cycleOf[s]]) {
                    componentStart[components++] = emitted;
                    walk(s, walked);
                }
            }
            componentStart[components] = emitted;
            if (emitted != path.length) {
                throw new IllegalStateException("splicing emitted " + emitted + " triangles, expected " + path.length);
            }
            return new HamiltonianRefinement.Result(new RefinedMesh(mesh, path, incentres, new EdgeSet(split), true),
                    Arrays.copyOf(componentStart, components + 1), split);
        }

        /**
         * A cycle being walked: it began at the spliced triangle {@code stop}, and when the walk
         * comes back to it, the pieces {@code closing} are emitted and the walk goes on round the
         * cycle it was spliced from, by the side {@code outAfter}.
         */
        private record Round(int stop, int[] closing, int outAfter) {
        }

        /** Emits the component of {@code start}'s cycle, every cycle spliced on walked in its turn. */
        private void walk(int start, boolean[] walked) {
            walked[cycleOf[start]] = true;
            ArrayDeque<Round> rounds = new ArrayDeque<>();
            rounds.push(new Round(start, null, -1)); // the walk ends back at its start
            int f = start;
            int out = otherCycleSide(start, -1);
            int in = otherCycleSide(start, out); // as if from the triangle before it round the cycle
            while (true) {
                int next = emitTriangle(f, in, out, walked, rounds);
                int g = mesh.face(HalfedgeMesh.twin(next));
                while (g == rounds.peek().stop) {
                    Round done = rounds.pop();
                    if (done.closing == null) {
                        return;
                    }
                    for (int code : done.closing) {
                        path[emitted++] = code;
                    }
                    next = done.outAfter;
                    g = mesh.face(HalfedgeMesh.twin(next));
                }
                in = HalfedgeMesh.twin(next);
                f = g;
                out = otherCycleSide(f, in);
            }
        }

        /**
         * Emits triangle {@code f}, entered by its side {@code in} and left by {@code out}, and
         * returns the side the walk leaves by: whole, leaving by {@code out}; or, where its matched
         * edge splices on a cycle not yet walked, its pieces up to that cycle, which is pushed on
         * {@code rounds} with the pieces that close it, leaving by the spliced triangle's side.
         * The path goes A, E1 | F1, C, (round the cycle spliced on), D, F2 | E2, B: A and B the
         * pieces on the sides entered and left by, E1 and E2 the halves of the matched edge at the
         * corner it shares with A and with B, F1 and F2 the halves on the far side, C and D the
         * pieces there beside them.
         */
        private int emitTriangle(int f, int in, int out, boolean[] walked, ArrayDeque<Round> rounds) {
            int e = matched[f];
            int g = mesh.face(HalfedgeMesh.twin(e));
            if (!split[HalfedgeMesh.edge(e)] || walked[cycleOf[g]]) {
                path[emitted++] = in << 2 | RefinedMesh.FACE;
                return out;
            }
            walked[cycleOf[g]] = true;
            int v1 = sharedCorner(e, in);
            int across = HalfedgeMesh.twin(e);
            int nearHalf = mesh.fromVertex(e) == v1 ? RefinedMesh.FIRST_HALF : RefinedMesh.SECOND_HALF;
            int farHalf = RefinedMesh.FIRST_HALF + RefinedMesh.SECOND_HALF - nearHalf; // across runs the other way
            int leave = sideAt(g, across, v1);
            int back = sideAt(g, across, otherEnd(e, v1));
            path[emitted++] = in << 2 | RefinedMesh.WHOLE;
            path[emitted++] = e << 2 | nearHalf;
            path[emitted++] = across << 2 | farHalf;
            path[emitted++] = leave << 2 | RefinedMesh.WHOLE;
            int[] closing = {
                back << 2 | RefinedMesh.WHOLE,
                across << 2 | nearHalf,
                e << 2 | farHalf,
                out << 2 | RefinedMesh.WHOLE,
            };
            rounds.push(new Round(g, closing, out));
            return leave;
        }

        /** The corner that halfedges {@code a} and {@code b} of one triangle share. */
        private int sharedCorner(int a, int b) {
            int a0 = mesh.fromVertex(a);
            int a1 = mesh.toVertex(a);
            return a0 == mesh.fromVertex(b) || a0 == mesh.toVertex(b) ? a0 : a1;
        }

        private int otherEnd(int h, int v) {
            return mesh.fromVertex(h) == v ? mesh.toVertex(h) : mesh.fromVertex(h);
        }

        /** The side of triangle {@code f} other than {@code not} that ends at {@code v}. */
        private int sideAt(int f, int not, int v) {
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                if (h != not && (mesh.fromVertex(h) == v || mesh.toVertex(h) == v)) {
                    return h;
                }
            }
            throw new IllegalStateException("triangle " + f + " has no side at " + v);
        }
    }
}
