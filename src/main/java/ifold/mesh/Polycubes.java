package ifold.mesh;

import ifold.geom.UnionFind;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.SplittableRandom;

/**
 * Solids made of unit cubes on the integer grid (polycubes), the grid polyhedra a hinge strip
 * wraps: boxes, the L, T and plus shapes, a staircase, and random ones grown cube by cube. Their
 * surface is the unit squares between a cube and an empty cell, each facing out.
 */
public final class Polycubes {
    /** The most cubes a polycube is made of: a million is six million squares at most. */
    public static final int MOST_CUBES = 1_000_000;

    /** The six directions from a cube to its neighbours. */
    private static final int[][] DIRECTIONS = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};

    private Polycubes() {
    }

    /** The a × b × c box of unit cubes. */
    public static List<int[]> box(int a, int b, int c) {
        if (a < 1 || b < 1 || c < 1 || (long) a * b * c > MOST_CUBES) {
            throw new IllegalArgumentException("a box of 1 to " + MOST_CUBES + " cubes, each side at least 1, got " + a + "x" + b + "x" + c);
        }
        List<int[]> cubes = new ArrayList<>();
        for (int x = 0; x < a; x++) {
            for (int y = 0; y < b; y++) {
                for (int z = 0; z < c; z++) {
                    cubes.add(new int[] {x, y, z});
                }
            }
        }
        return cubes;
    }

    /** Four cubes: a row of three and one on the end of it. */
    public static List<int[]> l() {
        return List.of(new int[] {0, 0, 0}, new int[] {1, 0, 0}, new int[] {2, 0, 0}, new int[] {0, 1, 0});
    }

    /** Four cubes: a row of three and one on its middle. */
    public static List<int[]> t() {
        return List.of(new int[] {0, 0, 0}, new int[] {1, 0, 0}, new int[] {2, 0, 0}, new int[] {1, 1, 0});
    }

    /** Five cubes: a middle one and its four neighbours in a plane. */
    public static List<int[]> plus() {
        return List.of(new int[] {1, 0, 0}, new int[] {0, 1, 0}, new int[] {1, 1, 0}, new int[] {2, 1, 0}, new int[] {1, 2, 0});
    }

    /** Six cubes: three steps, each a row one shorter on the one below. */
    public static List<int[]> staircase() {
        return List.of(new int[] {0, 0, 0}, new int[] {1, 0, 0}, new int[] {2, 0, 0}, new int[] {1, 0, 1}, new int[] {2, 0, 1},
                new int[] {2, 0, 2});
    }

    /**
     * {@code count} cubes grown from one at random ({@code seed}): each new cube against a face of
     * one already there, kept only where the surface stays one sphere (a manifold of Euler
     * characteristic 2: no cubes meeting along an edge or at a corner alone, no hole through,
     * no cavity inside). The same seed grows the same polycube.
     */
    public static List<int[]> random(int count, long seed) {
        if (count < 1 || count > MOST_CUBES) {
            throw new IllegalArgumentException("from 1 to " + MOST_CUBES + " cubes, got " + count);
        }
        SplittableRandom random = new SplittableRandom(seed);
        Set<Long> cells = new LinkedHashSet<>();
        List<int[]> cubes = new ArrayList<>();
        cells.add(key(0, 0, 0));
        cubes.add(new int[] {0, 0, 0});
        while (cubes.size() < count) {
            int[] from = cubes.get(random.nextInt(cubes.size()));
            int[] d = DIRECTIONS[random.nextInt(6)];
            int[] cell = {from[0] + d[0], from[1] + d[1], from[2] + d[2]};
            if (cells.contains(key(cell[0], cell[1], cell[2])) || !keepsASphere(cells, cell)) {
                continue;
            }
            cells.add(key(cell[0], cell[1], cell[2]));
            cubes.add(cell);
        }
        return cubes;
    }

    /**
     * Whether adding {@code cell} keeps the surface of the cubes one sphere: each edge of its
     * squares shared by two (no cubes meeting along an edge alone), the squares round each corner
     * one fan (none meeting at a corner alone), one piece, and Euler's V - E + F = 2 (no hole
     * through, no cavity). Measured on the whole surface: growing n cubes costs n² squares.
     */
    static boolean keepsASphere(Set<Long> cells, int[] cell) {
        List<int[]> cubes = new ArrayList<>();
        for (long k : cells) {
            cubes.add(unkey(k));
        }
        cubes.add(cell);
        return isSphere(surface(cubes));
    }

    /** Whether a surface of squares (as {@link #surface} makes) is one closed manifold sphere. */
    static boolean isSphere(PolygonSoup soup) {
        int faces = soup.faceCount();
        Map<Long, int[]> edges = new HashMap<>();
        Map<Integer, List<Integer>> facesAt = new HashMap<>();
        for (int f = 0; f < faces; f++) {
            int[] loop = loop(soup, f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                long edge = ((long) Math.min(a, b) << 32) | Math.max(a, b);
                int[] use = edges.computeIfAbsent(edge, e -> new int[] {0, -1, -1});
                if (use[0] >= 2) {
                    return false; // three squares or more on one edge
                }
                use[1 + use[0]++] = f;
                facesAt.computeIfAbsent(a, v -> new ArrayList<>()).add(f);
            }
        }
        int[] piece = UnionFind.pieces(faces);
        for (int[] use : edges.values()) {
            if (use[0] != 2) {
                return false; // an open edge
            }
            UnionFind.union(piece, use[1], use[2]);
        }
        for (int f = 1; f < faces; f++) {
            if (UnionFind.find(piece, f) != UnionFind.find(piece, 0)) {
                return false;
            }
        }
        // Each corner's squares one fan: joined through the edges at the corner.
        for (Map.Entry<Integer, List<Integer>> corner : facesAt.entrySet()) {
            List<Integer> around = corner.getValue();
            Map<Integer, Integer> local = new HashMap<>();
            int[] fan = UnionFind.pieces(around.size());
            for (int i = 0; i < around.size(); i++) {
                local.put(around.get(i), i);
            }
            int v = corner.getKey();
            for (int f : around) {
                int[] loop = loop(soup, f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    if (a == v || b == v) {
                        int[] use = edges.get(((long) Math.min(a, b) << 32) | Math.max(a, b));
                        UnionFind.union(fan, local.get(use[1]), local.get(use[2]));
                    }
                }
            }
            for (int i = 1; i < fan.length; i++) {
                if (UnionFind.find(fan, i) != UnionFind.find(fan, 0)) {
                    return false;
                }
            }
        }
        return soup.vertexCount() - edges.size() + faces == 2;
    }

    private static int[] loop(PolygonSoup soup, int f) {
        int[] loop = new int[soup.faceSize(f)];
        for (int k = 0; k < loop.length; k++) {
            loop[k] = soup.faceVertex(f, k);
        }
        return loop;
    }

    /** The surface of the cubes: a unit square for each face of a cube against an empty cell, counter-clockwise seen from outside. */
    public static PolygonSoup surface(List<int[]> cubes) {
        Set<Long> cells = new java.util.HashSet<>();
        for (int[] c : cubes) {
            cells.add(key(c[0], c[1], c[2]));
        }
        PolygonSoup soup = new PolygonSoup();
        Map<Long, Integer> vertexAt = new HashMap<>();
        for (int[] c : cubes) {
            for (int[] d : DIRECTIONS) {
                if (cells.contains(key(c[0] + d[0], c[1] + d[1], c[2] + d[2]))) {
                    continue;
                }
                int[] square = new int[4];
                int[][] corners = corners(c, d);
                for (int k = 0; k < 4; k++) {
                    int[] p = corners[k];
                    square[k] = vertexAt.computeIfAbsent(key(p[0], p[1], p[2]), q -> soup.addVertex(p[0], p[1], p[2]));
                }
                soup.addFace(square, 4, 0);
            }
        }
        return soup;
    }

    /** The corners of cube c's face towards direction d, counter-clockwise seen from outside (along d). */
    private static int[][] corners(int[] c, int[] d) {
        int axis = d[0] != 0 ? 0 : d[1] != 0 ? 1 : 2;
        int u = (axis + 1) % 3;
        int v = (axis + 2) % 3;
        int plane = d[axis] > 0 ? 1 : 0;
        int[][] square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        int[][] corners = new int[4][];
        for (int k = 0; k < 4; k++) {
            // u, v, axis is right-handed: counter-clockwise in (u, v) faces +axis; reversed for -axis.
            int[] uv = square[d[axis] > 0 ? k : 3 - k];
            int[] p = c.clone();
            p[axis] += plane;
            p[u] += uv[0];
            p[v] += uv[1];
            corners[k] = p;
        }
        return corners;
    }

    private static long key(int x, int y, int z) {
        return ((long) (x + (1 << 20)) << 42) | ((long) (y + (1 << 20)) << 21) | (z + (1 << 20));
    }

    private static int[] unkey(long key) {
        int mask = (1 << 21) - 1;
        return new int[] {(int) (key >>> 42) - (1 << 20), (int) ((key >>> 21) & mask) - (1 << 20), (int) (key & mask) - (1 << 20)};
    }
}
