package ifold.refine;

import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import java.util.Arrays;

/**
 * The Hamiltonian refinement of Arkin, Held, Mitchell and Skiena ("Hamiltonian triangulations
 * for fast rendering", 1996), as used by Demaine, Demaine and Mitchell to wrap polyhedra:
 * <ol>
 *   <li>a Steiner point at each triangle's incentre, joined to its three corners;</li>
 *   <li>a depth-first spanning tree of the dual graph (triangles joined through shared edges);</li>
 *   <li>each tree edge split at its midpoint, which is joined to the incentres on both sides;</li>
 *   <li>the path: walk around the tree, keeping it on one side, emitting each sub-triangle as
 *       it is passed.</li>
 * </ol>
 * A component of n triangles becomes 5n - 2 triangles (3 per triangle plus 2 per tree edge);
 * the path passes through each exactly once and consecutive ones share an edge. Every
 * sub-triangle keeps half of each of its parent's angles at the parent's corners, and the
 * angles at incentre and midpoint are no smaller, so the minimum angle is at least half the
 * input's. Works for any topology, open or closed; one path per connected component.
 *
 * <p>Both the tree search and the walk are iterative: a million faces in a long strip do not
 * overflow the stack. The walk needs no stack at all: at a halfedge of a tree edge it crosses
 * to the neighbour, otherwise it moves on around the face, and it stops when it comes back to
 * where it started.
 */
public final class HamiltonianRefinement {
    private HamiltonianRefinement() {
    }

    /**
     * What the refinement made.
     *
     * @param mesh the refined triangles in path order
     * @param componentStart the first triangle of each component's path, plus a last entry
     *     equal to the triangle count
     * @param treeEdge for each edge of the input mesh, whether it is in the spanning tree
     */
    public record Result(RefinedMesh mesh, int[] componentStart, boolean[] treeEdge) {
        public int componentCount() {
            return componentStart.length - 1;
        }

        /**
         * Whether component c's path is a cycle: its last triangle shares an edge with its first
         * (the walk round the tree ends where it began), so that a strip may begin anywhere on it.
         */
        public boolean cyclic(int c) {
            int first = componentStart[c];
            int last = componentStart[c + 1] - 1;
            if (last - first < 2) {
                return false;
            }
            int shared = 0;
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    shared += mesh.faceVertex(first, i) == mesh.faceVertex(last, j) ? 1 : 0;
                }
            }
            return shared == 2;
        }

        /**
         * The same refinement with each cyclic component's path begun {@code along} of the way
         * round it (0 to 1: the nearest triangle), its other components as they are.
         */
        public Result begunAt(double along) {
            if (!(along >= 0 && along < 1)) {
                throw new IllegalArgumentException("a path is begun from 0 to 1 of the way round it, not " + along);
            }
            int[] shift = new int[componentCount()];
            for (int c = 0; c < shift.length; c++) {
                int length = componentStart[c + 1] - componentStart[c];
                shift[c] = cyclic(c) ? (int) (Math.round(along * length) % length) : 0;
            }
            return new Result(mesh.rotated(componentStart, shift), componentStart, treeEdge);
        }

        /**
         * The same pieces with each component's path run the other way: each triangle is then
         * left across the side it was entered by, and its passes, parallel to that side, are
         * as many as its altitude over it takes (one way may be narrower or take fewer passes).
         */
        public Result reversed() {
            return new Result(mesh.reversed(componentStart), componentStart, treeEdge);
        }
    }

    /**
     * Refines {@code mesh}, which must be a valid triangle mesh.
     *
     * @throws IllegalArgumentException if a face is not a triangle or has no area
     */
    public static Result refine(HalfedgeMesh mesh) {
        int vertices = mesh.vertexCount();
        int faces = mesh.faceCount();
        double[] xyz = mesh.positionArray();
        for (int f = 0; f < faces; f++) {
            int h = mesh.faceHalfedge(f);
            if (mesh.next(mesh.next(mesh.next(h))) != h) {
                throw new IllegalArgumentException("refinement needs triangles, but face " + f + " has "
                        + mesh.faceSize(f) + " sides: triangulate the mesh first");
            }
            if (Triangles.isDegenerate(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)))) {
                throw new IllegalArgumentException("face " + f + " has no area, so it has no incentre");
            }
        }

        boolean[] treeEdge = new boolean[mesh.edgeCount()];
        int[] roots = spanningForest(mesh, treeEdge);
        int components = roots.length;

        // Steiner points: the incentres are stored; midpoints are computed when asked.
        double[] incentres = new double[3 * faces];
        for (int f = 0; f < faces; f++) {
            int h = mesh.faceHalfedge(f);
            Triangles.incenter(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h)), incentres, 3 * f);
        }

        if (mesh.halfedgeCount() > (Integer.MAX_VALUE >>> RefinedMesh.SHIFT)) {
            throw new IllegalArgumentException("too many halfedges to refine: " + mesh.halfedgeCount());
        }
        int triangleCount = 5 * faces - 2 * components;
        int[] path = new int[triangleCount];
        int[] componentStart = new int[components + 1];
        int t = 0;
        for (int c = 0; c < components; c++) {
            componentStart[c] = t;
            int start = mesh.faceHalfedge(roots[c]);
            int h = start;
            do {
                if (treeEdge[HalfedgeMesh.edge(h)]) {
                    // First half on this side, then cross into the neighbour's second half and
                    // go on around the neighbour.
                    int across = HalfedgeMesh.twin(h);
                    path[t++] = h << RefinedMesh.SHIFT | RefinedMesh.FIRST_HALF;
                    path[t++] = across << RefinedMesh.SHIFT | RefinedMesh.SECOND_HALF;
                    h = mesh.next(across);
                } else {
                    path[t++] = h << RefinedMesh.SHIFT | RefinedMesh.WHOLE;
                    h = mesh.next(h);
                }
            } while (h != start);
        }
        componentStart[components] = t;
        if (t != triangleCount) {
            throw new IllegalStateException("walk emitted " + t + " triangles, expected " + triangleCount);
        }
        return new Result(new RefinedMesh(mesh, path, incentres, new EdgeSet(treeEdge), false), componentStart, treeEdge);
    }

    /**
     * Marks the edges of a depth-first spanning forest of the dual graph in {@code treeEdge}
     * and returns the root face of each tree, one per component. Depth-first trees are long and
     * thin, so the path they give wanders far before it turns back.
     */
    static int[] spanningForest(HalfedgeMesh mesh, boolean[] treeEdge) {
        int faces = mesh.faceCount();
        boolean[] visited = new boolean[faces];
        // The stack of the search: for each face on it, the next of its halfedges to look
        // across and how many of them are left.
        int[] stackHalfedge = new int[faces];
        int[] remaining = new int[faces];
        int[] roots = new int[16];
        int rootCount = 0;
        for (int seed = 0; seed < faces; seed++) {
            if (visited[seed]) {
                continue;
            }
            if (rootCount == roots.length) {
                roots = Arrays.copyOf(roots, 2 * rootCount);
            }
            roots[rootCount++] = seed;
            visited[seed] = true;
            int top = 0;
            stackHalfedge[0] = mesh.faceHalfedge(seed);
            remaining[0] = 3;
            while (top >= 0) {
                if (remaining[top] == 0) {
                    top--;
                    continue;
                }
                int h = stackHalfedge[top];
                stackHalfedge[top] = mesh.next(h);
                remaining[top]--;
                int g = mesh.face(HalfedgeMesh.twin(h));
                if (g >= 0 && !visited[g]) {
                    visited[g] = true;
                    treeEdge[HalfedgeMesh.edge(h)] = true;
                    top++;
                    // Start the child's search just past the edge it was entered by.
                    stackHalfedge[top] = mesh.next(HalfedgeMesh.twin(h));
                    remaining[top] = 2;
                }
            }
        }
        return Arrays.copyOf(roots, rootCount);
    }
}
