package ifold.geom;

/**
 * Pieces joined pair by pair (union–find) over the indices of a parent array, each index its own
 * parent to begin with: which creases run on as one, which squares make one surface.
 */
public final class UnionFind {
    private UnionFind() {
    }

    /** A parent array of n indices, each its own piece. */
    public static int[] pieces(int n) {
        int[] parent = new int[n];
        for (int i = 0; i < n; i++) {
            parent[i] = i;
        }
        return parent;
    }

    /** The index that stands for i's piece (halving the path to it on the way). */
    public static int find(int[] parent, int i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    }

    /** Joins the pieces of i and j. */
    public static void union(int[] parent, int i, int j) {
        parent[find(parent, i)] = find(parent, j);
    }
}
