package ifold.refine;

import ifold.geom.Triangles;
import ifold.geom.UnionFind;
import ifold.mesh.HalfedgeMesh;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

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
 * not cut keeps its own angles rather than half of them.
 *
 * <p>On a surface with a boundary a triangle with a side on it has two neighbours, and keeps
 * both for its cycle; an ear (two sides on the boundary) is on no cycle; and the triangles with
 * three neighbours need not have a perfect matching among themselves ({@link #cover}). A
 * triangle on no cycle is cut from its incentre as the refinement cuts every triangle, and gone
 * round as the refinement goes round its spanning tree, a node of the tree of its own: the path
 * goes into it by one half of a side and out by the other half, round its incentre and every
 * node joined on across its other sides (three pieces and one more for each side split). One
 * joined by a single side, a leaf of the tree (an ear, mostly), may be halved instead
 * ({@link Leaf#HALVED}) by the line from its corner opposite that side to the side's midpoint:
 * two pieces, each at least half as wide as the triangle where those round its incentre are a
 * third as wide or less (the elephant with holes' widest strip 0.00107 -> 0.00151). So the path
 * is as long as the refinement's about the cut triangles and as the cycles' elsewhere: the shared
 * capsule's 10,000 triangles (a sphere split open along a seam, 200 ears at its poles) become a
 * path of 23,006 pieces round the incentres, 20,838 with its leaves halved, 2,698 triangles cut,
 * against the refinement's 49,998.
 *
 * <p>The result is a {@link HamiltonianRefinement.Result} whose {@link RefinedMesh} lists whole
 * triangles ({@code RefinedMesh.FACE}) among the pieces of the cut ones, its split edges in
 * place of the tree edges.
 */
public final class CycleCoverPath {
    private CycleCoverPath() {
    }

    /**
     * The path through {@code mesh}'s own triangles, a cycle for each connected component (a lone
     * triangle's three pieces round its incentre, as the refinement's), or null where the mesh is
     * too big for one array of pieces.
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    public static HamiltonianRefinement.Result of(HalfedgeMesh mesh) {
        return of(mesh, Way.PLAIN);
    }

    /**
     * How a cut triangle joined to the rest of the path by one side only, a leaf of the tree of
     * splices (an ear, mostly), is gone round. Halved, the strip may be wider, but on figure3 its
     * own path crossed itself from both starts (12 and 16 pairs) where round the incentres one
     * start is sound: only the seam's big models try both ({@code Seam.ownInstead}).
     */
    public enum Leaf {
        /** From its incentre, as the refinement goes round every triangle: four pieces. */
        ROUND_INCENTRE,
        /** Halved by the line from its corner opposite the side it is joined by to that side's midpoint: two pieces. */
        HALVED
    }

    /**
     * The choices a path through the own triangles leaves open, each of which may widen the
     * narrowest triangle of the path, which sets the widest strip, or narrow it.
     *
     * @param sliversFirst whether the matching begins with each sliver matched across its longest
     *     side, narrowest first ({@link #SLIVER}): a triangle matched there is passed by its two
     *     shorter sides, never left across the side it is narrowest over, but the cycles and
     *     splices change with it (igl_fertility.off's widest strip 0.2543 -> 0.4134; the cow's
     *     0.00389 -> 0.00134, set by a splice's pieces)
     * @param leaf how a cut triangle at a leaf of the splices' tree is gone round
     */
    public record Way(boolean sliversFirst, Leaf leaf) {
        /** The greedy matching in the triangles' order, every cut triangle round its incentre: the seam's short paths. */
        public static final Way PLAIN = new Way(false, Leaf.ROUND_INCENTRE);
    }

    /**
     * A sliver, for {@link Way#sliversFirst}: a triangle whose altitude onto its longest side is
     * under this fraction of the median such altitude of the mesh's triangles (none on a solid of
     * like triangles: the cube's, an icosphere's).
     */
    static final double SLIVER = 0.5;

    /**
     * {@link #of(HalfedgeMesh)} made {@code way}.
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    public static HamiltonianRefinement.Result of(HalfedgeMesh mesh, Way way) {
        return checked(mesh) ? new Splicer(mesh, cover(mesh, way.sliversFirst()), way.leaf() == Leaf.HALVED).path() : null;
    }

    /**
     * The paths of every {@link Way} that makes a path of its own (a closed mesh has no leaves to
     * halve; a mesh without slivers, no sliver to match first), the plain way's first; empty where
     * the mesh is too big for one array of pieces.
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    public static List<HamiltonianRefinement.Result> ways(HalfedgeMesh mesh) {
        List<HamiltonianRefinement.Result> paths = new ArrayList<>();
        if (!checked(mesh)) {
            return paths;
        }
        int[] slivers = slivers(mesh);
        for (int[] first : slivers.length == 0 ? List.of(new int[0]) : List.of(new int[0], slivers)) {
            Cover cover = coverMatching(mesh, first);
            for (Leaf leaf : Leaf.values()) {
                if (leaf == Leaf.HALVED && cover.cutCount() == 0) {
                    continue;
                }
                HamiltonianRefinement.Result path = new Splicer(mesh, cover, leaf == Leaf.HALVED).path();
                if (path != null) {
                    paths.add(path);
                }
            }
        }
        return paths;
    }

    /**
     * Whether {@code mesh} can have a path: not empty and not too big for one array of pieces.
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    private static boolean checked(HalfedgeMesh mesh) {
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
        }
        return faces > 0 && mesh.halfedgeCount() <= (Integer.MAX_VALUE >>> RefinedMesh.SHIFT);
    }

    /** The longest side of triangle {@code f} (the first of equals). */
    static int longestSide(HalfedgeMesh mesh, int f) {
        double[] xyz = mesh.positionArray();
        int h = mesh.faceHalfedge(f);
        int longest = h;
        double most = -1;
        for (int k = 0; k < 3; k++, h = mesh.next(h)) {
            double length = Triangles.distance(xyz, mesh.fromVertex(h), mesh.toVertex(h));
            if (length > most) {
                most = length;
                longest = h;
            }
        }
        return longest;
    }

    /** The slivers of {@code mesh} ({@link #SLIVER}), narrowest over its longest side first. */
    static int[] slivers(HalfedgeMesh mesh) {
        int faces = mesh.faceCount();
        double[] xyz = mesh.positionArray();
        double[] narrow = new double[faces];
        for (int f = 0; f < faces; f++) {
            int h = longestSide(mesh, f);
            narrow[f] = Triangles.twiceArea(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)))
                    / Triangles.distance(xyz, mesh.fromVertex(h), mesh.toVertex(h));
        }
        double[] sorted = narrow.clone();
        Arrays.sort(sorted);
        double sliver = faces == 0 ? 0 : SLIVER * sorted[faces / 2];
        return java.util.stream.IntStream.range(0, faces).filter(f -> narrow[f] < sliver).boxed()
                .sorted((a, b) -> Double.compare(narrow[a], narrow[b])).mapToInt(Integer::intValue).toArray();
    }

    /** How many neighbours triangle {@code f} has across its sides (three but on a boundary). */
    static int neighbours(HalfedgeMesh mesh, int f) {
        int count = 0;
        int h = mesh.faceHalfedge(f);
        for (int k = 0; k < 3; k++, h = mesh.next(h)) {
            count += mesh.face(HalfedgeMesh.twin(h)) >= 0 ? 1 : 0;
        }
        return count;
    }

    /**
     * Which triangles are cut (on no cycle, gone round from their incentres) and each other
     * triangle's side off its cycle: the side across which its partner lies, or, where a
     * neighbour is cut, the side facing it; -1 for a triangle with a side on the boundary, whose
     * two others are its cycle's.
     */
    record Cover(int[] offCycle, boolean[] cut) {
        int cutCount() {
            int count = 0;
            for (boolean c : cut) {
                count += c ? 1 : 0;
            }
            return count;
        }
    }

    /**
     * The cover of {@code mesh}'s triangles by cycles and cut triangles, as few cut as this finds.
     * A triangle on a cycle passes two of its sides to the cycle, so one with three neighbours
     * is matched to one of them, or faces a cut one, and one with two faces none. Ears (one
     * neighbour) are cut, and then every triangle left with fewer than two neighbours not cut;
     * the triangles left with three are matched, a maximum matching; a neighbour of one left
     * unmatched is cut, and the rest matched again, until every triangle left with three has a
     * partner. A closed mesh's matching is perfect at once. Which neighbour to cut is tried two
     * ways, and the cover with fewer cut kept: which is better depends on the mesh, by far (any
     * neighbour: the shared capsule 2,698 of 10,000 cut, the elephant with holes 3,197 of 4,463;
     * one with no partner to lose: 9,488 and 1,497).
     */
    static Cover cover(HalfedgeMesh mesh) {
        return cover(mesh, false);
    }

    /** {@link #cover(HalfedgeMesh)}, its matchings begun with the slivers where {@code sliversFirst} ({@link Way}). */
    static Cover cover(HalfedgeMesh mesh, boolean sliversFirst) {
        return coverMatching(mesh, sliversFirst ? slivers(mesh) : new int[0]);
    }

    /** {@link #cover(HalfedgeMesh)}, its matchings begun with the triangles {@code first}, each across its longest side. */
    private static Cover coverMatching(HalfedgeMesh mesh, int[] first) {
        Cover any = cover(mesh, false, first);
        if (any.cutCount() == 0) {
            return any; // none cut (a closed mesh, matched at once; an open tube): none fewer
        }
        Cover unmatched = cover(mesh, true, first);
        return unmatched.cutCount() < any.cutCount() ? unmatched : any;
    }

    /**
     * The cover as {@link #cover(HalfedgeMesh)} finds it, cutting for a triangle left unmatched
     * its first neighbour not cut, or where {@code unmatchedFirst}, one that is not matched
     * (with two neighbours left, or facing a cut one) where it has such; the matchings begun with
     * {@code slivers}, each across its longest side.
     */
    private static Cover cover(HalfedgeMesh mesh, boolean unmatchedFirst, int[] slivers) {
        int faces = mesh.faceCount();
        boolean[] cut = new boolean[faces];
        int[] live = new int[faces]; // neighbours not cut
        int[] queue = new int[faces];
        int tail = 0;
        for (int f = 0; f < faces; f++) {
            live[f] = neighbours(mesh, f);
            if (live[f] < 2) {
                cut[f] = true;
                queue[tail++] = f;
            }
        }
        Matching m = new Matching(mesh, slivers);
        while (true) {
            // A cut triangle leaves its neighbours one fewer: any with fewer than two is cut too.
            for (int head = 0; head < tail; head++) {
                int h = mesh.faceHalfedge(queue[head]);
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    int g = mesh.face(HalfedgeMesh.twin(h));
                    if (g >= 0 && !cut[g] && --live[g] < 2) {
                        cut[g] = true;
                        queue[tail++] = g;
                    }
                }
            }
            tail = 0;
            for (int f = 0; f < faces; f++) {
                m.node[f] = !cut[f] && live[f] == 3;
            }
            m.match();
            // A triangle left unmatched faces a neighbour cut for it, and needs no partner. Cut
            // itself, it would take its three neighbours' sides off their cycles, and their
            // partners would be left unmatched in turn (the shared capsule: 49,982 pieces
            // rather than 23,006).
            for (int f = 0; f < faces; f++) {
                if (m.node[f] && m.mate[f] < 0 && !cut[f]) {
                    int h = mesh.faceHalfedge(f);
                    int neighbour = f;
                    for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                        int g = mesh.face(HalfedgeMesh.twin(h));
                        if (g >= 0 && !cut[g] && (neighbour == f || unmatchedFirst && !m.node[g])) {
                            neighbour = g;
                        }
                    }
                    cut[neighbour] = true;
                    queue[tail++] = neighbour;
                }
            }
            if (tail == 0) {
                break;
            }
        }
        int[] offCycle = new int[faces];
        for (int f = 0; f < faces; f++) {
            offCycle[f] = -1;
            if (cut[f]) {
                continue;
            }
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                int g = mesh.face(HalfedgeMesh.twin(h));
                if (g >= 0 && (m.node[f] ? g == m.mate[f] : cut[g])) {
                    offCycle[f] = h;
                    break;
                }
            }
        }
        // Two triangles sharing two sides: one side matched on both, the same edge.
        for (int f = 0; f < faces; f++) {
            int g = m.node[f] ? m.mate[f] : -1;
            if (g >= 0 && HalfedgeMesh.twin(offCycle[f]) != offCycle[g]) {
                offCycle[g] = HalfedgeMesh.twin(offCycle[f]);
            }
        }
        return new Cover(offCycle, cut);
    }

    /**
     * A maximum matching of the dual graph's nodes (triangles; which, set by the caller) by
     * Edmonds' blossoms, begun from a greedy one (the triangles given first, each across its
     * longest side).
     */
    static final class Matching {
        private final HalfedgeMesh mesh;
        private final int faces;
        /** Whether each triangle is a node of the graph: the others are not matched. */
        final boolean[] node;
        /** The partner of each triangle, -1 while unmatched. */
        final int[] mate;
        private final int[] parent;
        private final int[] base;
        private final boolean[] inQueue;
        private final boolean[] inBlossom;
        private final boolean[] onPath;
        private final int[] queue;

        /** The triangles matched first, each across its longest side where its partner there is free. */
        private final int[] first;

        Matching(HalfedgeMesh mesh, int[] first) {
            this.mesh = mesh;
            this.first = first;
            this.faces = mesh.faceCount();
            mate = new int[faces];
            parent = new int[faces];
            base = new int[faces];
            inQueue = new boolean[faces];
            inBlossom = new boolean[faces];
            onPath = new boolean[faces];
            queue = new int[faces];
            node = new boolean[faces];
        }

        /** The triangle across halfedge {@code h} where it is a node of the graph, else -1. */
        private int across(int h) {
            int g = mesh.face(HalfedgeMesh.twin(h));
            return g >= 0 && node[g] ? g : -1;
        }

        /** Matches the nodes, from none matched: greedily, then along augmenting paths. */
        void match() {
            Arrays.fill(mate, -1);
            for (int f : first) {
                int g = node[f] && mate[f] < 0 ? across(longestSide(mesh, f)) : -1;
                if (g >= 0 && g != f && mate[g] < 0) {
                    mate[f] = g;
                    mate[g] = f;
                }
            }
            for (int f = 0; f < faces; f++) {
                if (node[f] && mate[f] < 0) {
                    int h = mesh.faceHalfedge(f);
                    for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                        int g = across(h);
                        if (g >= 0 && g != f && mate[g] < 0) {
                            mate[f] = g;
                            mate[g] = f;
                            break;
                        }
                    }
                }
            }
            for (int f = 0; f < faces; f++) {
                if (node[f] && mate[f] < 0) {
                    augment(f); // where no path augments from f now, none will later: f stays unmatched
                }
            }
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
                    int to = across(h);
                    if (to < 0 || to == v || base[v] == base[to] || mate[v] == to) {
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

    /**
     * The cycles of the edges not matched, spliced into one per component, and the triangles on
     * no such cycle gone round from their incentres as the refinement goes round its triangles;
     * emitted as pieces.
     */
    private static final class Splicer {
        private final HalfedgeMesh mesh;
        private final int[] matched;
        /** The node of the tree each triangle belongs to: its cycle, or itself where it is cut (on no cycle). */
        private final int[] nodeOf;
        /** Whether each triangle lies on a cycle (else it is cut from its incentre, every side a piece). */
        private final boolean[] onCycle;
        /** Whether each edge is split for a splice: the edges of the tree joining the nodes. */
        private final boolean[] split;
        /** Whether a cut triangle joined by one split side is halved about it rather than gone round from its incentre ({@link Leaf}). */
        private final boolean halveLeaves;
        private int[] path;
        private int emitted;

        Splicer(HalfedgeMesh mesh, Cover cover, boolean halveLeaves) {
            this.mesh = mesh;
            this.halveLeaves = halveLeaves;
            this.matched = cover.offCycle();
            this.nodeOf = new int[mesh.faceCount()];
            this.onCycle = new boolean[mesh.faceCount()];
            for (int f = 0; f < onCycle.length; f++) {
                onCycle[f] = !cover.cut()[f];
            }
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

        /** The halfedge of {@code f} other than {@code matched[f]}, {@code not} and a side on the boundary: the cycle's way on. */
        private int otherCycleSide(int f, int not) {
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                if (h != matched[f] && h != not && mesh.face(HalfedgeMesh.twin(h)) >= 0) {
                    return h;
                }
            }
            throw new IllegalStateException("triangle " + f + " has no side left for its cycle");
        }

        /** Whether the side of halfedge {@code h} joins two triangles on cycles and is off neither's cycle: a cycle's way on. */
        private boolean cycleSide(int h) {
            int g = mesh.face(HalfedgeMesh.twin(h));
            return g >= 0 && onCycle[mesh.face(h)] && onCycle[g] && h != matched[mesh.face(h)] && HalfedgeMesh.twin(h) != matched[g];
        }

        /**
         * Numbers the nodes of the tree: each cycle (the triangles not cut, joined by their cycle
         * sides, two each), and each cut triangle on its own. How many.
         */
        private int nodes() {
            int faces = mesh.faceCount();
            Arrays.fill(nodeOf, -1);
            int nodes = 0;
            int[] queue = new int[faces];
            for (int s = 0; s < faces; s++) {
                if (nodeOf[s] >= 0) {
                    continue;
                }
                nodeOf[s] = nodes;
                if (onCycle[s]) {
                    int head = 0;
                    int tail = 0;
                    queue[tail++] = s;
                    while (head < tail) {
                        int f = queue[head++];
                        int sides = 0;
                        int h = mesh.faceHalfedge(f);
                        for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                            if (cycleSide(h)) {
                                sides++;
                                int g = mesh.face(HalfedgeMesh.twin(h));
                                if (nodeOf[g] < 0) {
                                    nodeOf[g] = nodes;
                                    queue[tail++] = g;
                                }
                            }
                        }
                        if (sides != 2) {
                            throw new IllegalStateException("triangle " + f + " has " + sides + " sides on its cycle");
                        }
                    }
                }
                nodes++;
            }
            return nodes;
        }

        /** Whether the side of halfedge {@code h} may join its triangle's node to another's: any side of a cut triangle, a cycle's triangle's matched side. */
        private boolean joins(int h) {
            int f = mesh.face(h);
            return !onCycle[f] || matched[f] == h;
        }

        /** The path, or null where it would be longer than an array holds. */
        HamiltonianRefinement.Result path() {
            int faces = mesh.faceCount();
            int nodes = nodes();
            double[] incentres = new double[3 * faces];
            double[] xyz = mesh.positionArray();
            for (int f = 0; f < faces; f++) {
                int h = mesh.faceHalfedge(f);
                Triangles.incenter(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)), incentres, 3 * f);
            }
            // A spanning forest of splices, the widest first (Kruskal): a splice's pieces are
            // narrower than its triangles, and the narrowest triangle of the path sets the widest strip.
            int[] candidates = new int[mesh.halfedgeCount() / 2];
            int count = 0;
            for (int f = 0; f < faces; f++) {
                int h = mesh.faceHalfedge(f);
                for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                    int g = mesh.face(HalfedgeMesh.twin(h));
                    if (f < g && nodeOf[f] != nodeOf[g] && joins(h) && joins(HalfedgeMesh.twin(h))) {
                        candidates[count++] = h;
                    }
                }
            }
            double[] narrowest = new double[count];
            Integer[] order = new Integer[count];
            for (int i = 0; i < count; i++) {
                order[i] = i;
                narrowest[i] = Math.min(narrowestPiece(xyz, incentres, candidates[i]), narrowestPiece(xyz, incentres, HalfedgeMesh.twin(candidates[i])));
            }
            Arrays.sort(order, (x, y) -> Double.compare(narrowest[y], narrowest[x]));
            int[] joined = UnionFind.pieces(nodes);
            for (int i : order) {
                int h = candidates[i];
                int f = mesh.face(h);
                int g = mesh.face(HalfedgeMesh.twin(h));
                if (UnionFind.find(joined, nodeOf[f]) != UnionFind.find(joined, nodeOf[g])) {
                    UnionFind.union(joined, nodeOf[f], nodeOf[g]);
                    split[HalfedgeMesh.edge(h)] = true;
                }
            }
            // Each component's tour begins at its lowest triangle.
            boolean[] toured = new boolean[nodes];
            boolean[] first = new boolean[faces];
            for (int s = 0; s < faces; s++) {
                int root = UnionFind.find(joined, nodeOf[s]);
                first[s] = !toured[root];
                toured[root] = true;
            }
            // A triangle on a cycle is one piece, or four where it is spliced; a cut one two where
            // it is a leaf of the tree, entered by its one split side, and leaves are halved, else
            // three and one more for each split side.
            long pieces = 0;
            for (int f = 0; f < faces; f++) {
                int splits = splits(f);
                pieces += onCycle[f] ? (splits == 0 ? 1 : 4) : halveLeaves && splits == 1 && !first[f] ? 2 : 3 + splits;
            }
            if (pieces > Integer.MAX_VALUE - 8) {
                return null;
            }
            path = new int[(int) pieces];
            // One tour per component, from its lowest triangle: round its cycle, or round its pieces,
            // into each node joined on in its turn.
            int[] componentStart = new int[faces + 1];
            int components = 0;
            for (int s = 0; s < faces; s++) {
                if (first[s]) {
                    componentStart[components++] = emitted;
                    tour(s);
                }
            }
            componentStart[components] = emitted;
            if (emitted != path.length) {
                throw new IllegalStateException("splicing emitted " + emitted + " triangles, expected " + path.length);
            }
            return new HamiltonianRefinement.Result(new RefinedMesh(mesh, path, incentres, new EdgeSet(split), true),
                    Arrays.copyOf(componentStart, components + 1), split);
        }

        // What is left to emit, last first: a piece, or a node to go round, entered across a side at a corner.
        private static final int PIECE = 0;
        /** A cut triangle gone round from a side at a corner (side -1: the first triangle, gone round from its first side). */
        private static final int CUT = 1;
        /** A cycle's triangle entered across its matched side at a corner: its cycle gone round from it back to it. */
        private static final int CYCLE = 2;
        /** The next triangle round a cycle, entered across a side, the cycle ending at a triangle. */
        private static final int ROUND = 3;

        private int[] tasks = new int[64];
        private int top;

        private void push(int kind, int a, int b, int c) {
            if (top + 4 > tasks.length) {
                tasks = Arrays.copyOf(tasks, 2 * tasks.length);
            }
            tasks[top++] = kind;
            tasks[top++] = a;
            tasks[top++] = b;
            tasks[top++] = c;
        }

        /** Emits the component of triangle {@code start}, every node joined on gone round in its turn. */
        private void tour(int start) {
            top = 0;
            if (onCycle[start]) {
                int out = otherCycleSide(start, -1);
                round(start, otherCycleSide(start, out), start); // as if from the triangle before it round the cycle
            } else {
                goRound(start, -1, -1);
            }
            while (top > 0) {
                top -= 4;
                int kind = tasks[top];
                int a = tasks[top + 1];
                int b = tasks[top + 2];
                int c = tasks[top + 3];
                switch (kind) {
                    case PIECE -> path[emitted++] = a;
                    case CUT -> goRound(a, b, c);
                    case CYCLE -> enterCycle(a, b, c);
                    default -> {
                        if (a != c) {
                            round(a, b, c);
                        }
                    }
                }
            }
        }

        /** The half of side {@code h} at its end {@code v}, as a piece. */
        private int half(int h, int v) {
            return h << RefinedMesh.SHIFT | (mesh.fromVertex(h) == v ? RefinedMesh.FIRST_HALF : RefinedMesh.SECOND_HALF);
        }

        /** The half of the face of side {@code h} at its end {@code v}, cut from the corner opposite h to h's midpoint, as a piece. */
        private int faceHalf(int h, int v) {
            return h << RefinedMesh.SHIFT | (mesh.fromVertex(h) == v ? RefinedMesh.FACE_FIRST_HALF : RefinedMesh.FACE_SECOND_HALF);
        }

        /** How many of triangle {@code f}'s sides are split. */
        private int splits(int f) {
            int count = 0;
            int h = mesh.faceHalfedge(f);
            for (int k = 0; k < 3; k++, h = mesh.next(h)) {
                count += split[HalfedgeMesh.edge(h)] ? 1 : 0;
            }
            return count;
        }

        /**
         * Pushes, to be emitted in this order: the pieces of side {@code h} of a cut triangle or a
         * spliced one, gone along from its end {@code v}: its whole piece, or where it is split, its
         * half at {@code v}, the node across it gone round (entered at {@code v}), and its other half.
         * Pushed last first, as all pushes here.
         */
        private void pushSide(int h, int v) {
            if (!split[HalfedgeMesh.edge(h)]) {
                push(PIECE, h << RefinedMesh.SHIFT | RefinedMesh.WHOLE, 0, 0);
                return;
            }
            int across = HalfedgeMesh.twin(h);
            push(PIECE, half(h, otherEnd(h, v)), 0, 0);
            push(onCycle[mesh.face(across)] ? CYCLE : CUT, mesh.face(across), across, v);
            push(PIECE, half(h, v), 0, 0);
        }

        /**
         * Goes round cut triangle {@code t} from its incentre, entered across side {@code in} at
         * corner {@code v} (the half of {@code in} there first, its other half last), or, where
         * {@code in} is -1, from its first side on.
         */
        private void goRound(int t, int in, int v) {
            if (halveLeaves && in >= 0 && splits(t) == 1) {
                // A leaf of the tree (an ear, mostly): its two halves about the side it is joined
                // by, cut from the corner opposite, each at least half as wide as the triangle
                // where its pieces round the incentre are a third as wide or less.
                push(PIECE, faceHalf(in, otherEnd(in, v)), 0, 0);
                push(PIECE, faceHalf(in, v), 0, 0);
                return;
            }
            if (in < 0) {
                int h = mesh.faceHalfedge(t);
                int h1 = mesh.next(h);
                int h2 = mesh.next(h1);
                pushSide(h2, mesh.fromVertex(h2));
                pushSide(h1, mesh.fromVertex(h1));
                pushSide(h, mesh.fromVertex(h));
                return;
            }
            int first = sideAt(t, in, v);
            int w = otherEnd(first, v);
            int second = sideAt(t, first, w);
            push(PIECE, half(in, otherEnd(in, v)), 0, 0);
            pushSide(second, w);
            pushSide(first, v);
            push(PIECE, half(in, v), 0, 0);
        }

        /**
         * Goes round the cycle of triangle {@code g}, entered across its matched side {@code in}
         * at corner {@code v}: the half of {@code in} there, the piece on its side at {@code v},
         * round the cycle and back, the piece on its third side, the other half of {@code in}.
         */
        private void enterCycle(int g, int in, int v) {
            int leave = sideAt(g, in, v);
            int back = sideAt(g, in, otherEnd(in, v));
            push(PIECE, half(in, otherEnd(in, v)), 0, 0);
            push(PIECE, back << RefinedMesh.SHIFT | RefinedMesh.WHOLE, 0, 0);
            push(ROUND, mesh.face(HalfedgeMesh.twin(leave)), HalfedgeMesh.twin(leave), g);
            push(PIECE, leave << RefinedMesh.SHIFT | RefinedMesh.WHOLE, 0, 0);
            push(PIECE, half(in, v), 0, 0);
        }

        /**
         * Triangle {@code f} of a cycle, entered by its side {@code in}, left by the other side of
         * its cycle, and the cycle on to {@code stop}: whole, or, where its matched side is split
         * (a node joined on, other than the one the cycle was entered from, at {@code stop}), its
         * pieces round that node. The path goes A, E1 | (the node across), E2, B: A and B the
         * pieces on the sides entered and left by, E1 and E2 the halves of the matched side at the
         * corner it shares with A and with B.
         */
        private void round(int f, int in, int stop) {
            int out = otherCycleSide(f, in);
            push(ROUND, mesh.face(HalfedgeMesh.twin(out)), HalfedgeMesh.twin(out), stop);
            int e = matched[f];
            if (e < 0 || !split[HalfedgeMesh.edge(e)]) {
                push(PIECE, in << RefinedMesh.SHIFT | RefinedMesh.FACE, 0, 0);
                return;
            }
            push(PIECE, out << RefinedMesh.SHIFT | RefinedMesh.WHOLE, 0, 0);
            pushSide(e, sharedCorner(e, in));
            push(PIECE, in << RefinedMesh.SHIFT | RefinedMesh.WHOLE, 0, 0);
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
