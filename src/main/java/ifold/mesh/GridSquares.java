package ifold.mesh;

import ifold.geom.UnionFind;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * A grid polyhedron's surface as lattice squares: a surface whose every face is axis-aligned and
 * every corner on a cubic lattice (the surface of a polycube, a box), cut into the squares of
 * that lattice, each with its neighbour across each side. The lattice's spacing is found from
 * the corners: the largest that puts every one of them on it.
 *
 * <p>Squares are numbered in the order their faces come; square {@code q}'s corners are
 * counter-clockwise seen from outside, and its side {@code k} runs from corner {@code k} to
 * corner {@code k + 1}. On a closed surface every side is shared with exactly one other square,
 * which runs along it the other way.
 */
public final class GridSquares {
    /** The most squares a surface may be cut into: the lattice found from its corners may be much finer than its faces. */
    public static final int MOST_SQUARES = 4_000_000;

    /** How far a corner may lie off the lattice, or a normal off an axis, relative to the model's size: rounding, not design. */
    private static final double OFF_LATTICE = 1e-9;

    /** The most lattice steps across the surface along an axis, plus one: a corner's coordinate then fits in 20 bits. */
    private static final int LATTICE_STEPS = 1 << 20;

    /** The finest lattice tried, as the smallest gap between corners' coordinates over it. */
    private static final int FINEST_DIVISION = 64;

    /** The lattice's spacing, and the point of it all squares' corners count from. */
    private final double spacing;
    private final double[] origin;
    /** Per square: the axis of its normal (0 = x), the normal's sign (+1, -1), and its corners' lattice coordinates (4 × 3 ints). */
    private final int[] axis;
    private final int[] sign;
    private final int[] corners;
    /** Per square and side (4 q + k): the square across it, and that square's side along it. */
    private final int[] across;
    private final int[] acrossSide;
    /** Per square: its connected component, numbered from 0 in the order of their first squares. */
    private final int[] component;
    private final int components;

    private GridSquares(double spacing, double[] origin, int[] axis, int[] sign, int[] corners, int[] across, int[] acrossSide,
            int[] component, int components) {
        this.spacing = spacing;
        this.origin = origin;
        this.axis = axis;
        this.sign = sign;
        this.corners = corners;
        this.across = across;
        this.acrossSide = acrossSide;
        this.component = component;
        this.components = components;
    }

    /** Why a surface is not a closed grid polyhedron, in one line naming the face or edge that breaks it. */
    public static final class NotGrid extends Exception {
        private static final long serialVersionUID = 1L;

        NotGrid(String message) {
            super(message);
        }
    }

    /**
     * The lattice squares of {@code mesh}, a valid surface of triangles (or other flat polygons)
     * at {@code spacing} (NaN: the largest lattice every corner lies on). A given spacing must
     * divide the found one.
     *
     * @throws NotGrid naming the first face that is not axis-aligned, the corner off the lattice,
     *     the edge with one square or more than two, or a surface cut into too many squares
     */
    public static GridSquares of(IndexedPolygons mesh, double spacing) throws NotGrid {
        int vertices = mesh.vertexCount();
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < vertices; v++) {
            for (int a = 0; a < 3; a++) {
                min[a] = Math.min(min[a], mesh.coordinate(v, a));
                max[a] = Math.max(max[a], mesh.coordinate(v, a));
            }
        }
        double size = Math.max(max[0] - min[0], Math.max(max[1] - min[1], max[2] - min[2]));
        if (!(size > 0) || !Double.isFinite(size)) {
            throw new NotGrid("the surface has no extent");
        }
        double tolerance = OFF_LATTICE * size;
        int[] normalAxis = new int[mesh.faceCount()];
        int[] normalSign = new int[mesh.faceCount()];
        for (int f = 0; f < mesh.faceCount(); f++) {
            double[] n = normal(mesh, f);
            double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            int a = Math.abs(n[0]) >= Math.abs(n[1]) && Math.abs(n[0]) >= Math.abs(n[2]) ? 0 : Math.abs(n[1]) >= Math.abs(n[2]) ? 1 : 2;
            if (!(length > 0) || Math.abs(n[(a + 1) % 3]) > OFF_LATTICE * length || Math.abs(n[(a + 2) % 3]) > OFF_LATTICE * length) {
                throw new NotGrid(String.format(Locale.ROOT, "the face through %s is not square to the axes, as every face of "
                        + "a grid polyhedron (a polycube, a box) is: the hinge strip wraps those only", corners(mesh, f)));
            }
            normalAxis[f] = a;
            normalSign[f] = n[a] > 0 ? 1 : -1;
        }
        double found = spacing(mesh, min, tolerance);
        if (Double.isNaN(found)) {
            // Name the corner farthest off the lattice of the smallest gap, and by how much: a model
            // written with few decimals (0.333333 for a third) is off by its rounding.
            double gap = smallestGap(mesh, min, tolerance);
            int worst = -1;
            double off = 0;
            for (int v = 0; v < mesh.vertexCount(); v++) {
                for (int a = 0; a < 3; a++) {
                    double steps = (mesh.coordinate(v, a) - min[a]) / gap;
                    double by = Math.abs(steps - Math.rint(steps)) * gap;
                    if (by > off) {
                        off = by;
                        worst = v;
                    }
                }
            }
            throw new NotGrid(String.format(Locale.ROOT, "the corners lie on no lattice of cubes to a billionth of the model's size: "
                    + "corner %s is %.3g off the lattice of the smallest gap between corners, %.6g, and off every lattice as fine as "
                    + "a %dth of it", point(mesh, worst), off, gap, FINEST_DIVISION));
        }
        double s = Double.isNaN(spacing) ? found : spacing;
        if (!Double.isNaN(spacing)) {
            double ratio = found / spacing;
            if (!(Math.abs(ratio - Math.rint(ratio)) <= 1e-9 * ratio) || Math.rint(ratio) < 1) {
                throw new NotGrid(String.format(Locale.ROOT, "the squares' side %s must divide the lattice's %s (the side by a whole "
                        + "number)", spacing, found));
            }
        }
        double steps = 0;
        for (int a = 0; a < 3; a++) {
            steps = Math.max(steps, (max[a] - min[a]) / s);
        }
        if (steps >= LATTICE_STEPS) {
            throw new NotGrid(String.format(Locale.ROOT, "the surface is %.0f squares of side %s across, more than %d", steps, s,
                    LATTICE_STEPS - 1));
        }
        return new Cutting(mesh, s, min, normalAxis, normalSign, tolerance).cut();
    }

    /** A face's normal by Newell's sum: its area twice, along the normal. */
    private static double[] normal(IndexedPolygons mesh, int f) {
        double[] n = new double[3];
        int size = mesh.faceSize(f);
        for (int k = 0; k < size; k++) {
            int a = mesh.faceVertex(f, k);
            int b = mesh.faceVertex(f, (k + 1) % size);
            for (int axis = 0; axis < 3; axis++) {
                int y = (axis + 1) % 3;
                int z = (axis + 2) % 3;
                n[axis] += (mesh.coordinate(a, y) - mesh.coordinate(b, y)) * (mesh.coordinate(a, z) + mesh.coordinate(b, z));
            }
        }
        return n;
    }

    /** The smallest gap between two distinct corner coordinates along any axis. */
    private static double smallestGap(IndexedPolygons mesh, double[] min, double tolerance) {
        double gap = Double.POSITIVE_INFINITY;
        for (int a = 0; a < 3; a++) {
            double[] values = new double[mesh.vertexCount()];
            for (int v = 0; v < values.length; v++) {
                values[v] = mesh.coordinate(v, a) - min[a];
            }
            Arrays.sort(values);
            for (int i = 1; i < values.length; i++) {
                if (values[i] - values[i - 1] > tolerance) {
                    gap = Math.min(gap, values[i] - values[i - 1]);
                }
            }
        }
        return gap;
    }

    /**
     * The largest spacing that puts every corner on the lattice from {@code min}: the smallest gap
     * between corners' coordinates over 1, 2, … {@link #FINEST_DIVISION}; NaN where none does.
     */
    private static double spacing(IndexedPolygons mesh, double[] min, double tolerance) {
        double gap = smallestGap(mesh, min, tolerance);
        if (!Double.isFinite(gap)) {
            return Double.NaN;
        }
        for (int n = 1; n <= FINEST_DIVISION; n++) {
            if (offLattice(mesh, min, gap / n, tolerance) < 0) {
                return gap / n;
            }
        }
        return Double.NaN;
    }

    /** The first corner off the lattice of spacing s from min, or -1. */
    private static int offLattice(IndexedPolygons mesh, double[] min, double s, double tolerance) {
        for (int v = 0; v < mesh.vertexCount(); v++) {
            for (int a = 0; a < 3; a++) {
                double steps = (mesh.coordinate(v, a) - min[a]) / s;
                if (Math.abs(steps - Math.rint(steps)) * s > tolerance) {
                    return v;
                }
            }
        }
        return -1;
    }

    /** The cutting of the faces into squares and the pairing of their sides. */
    private static final class Cutting {
        private final IndexedPolygons mesh;
        private final double s;
        private final double[] min;
        private final int[] normalAxis;
        private final int[] normalSign;
        private final double tolerance;

        Cutting(IndexedPolygons mesh, double s, double[] min, int[] normalAxis, int[] normalSign, double tolerance) {
            this.mesh = mesh;
            this.s = s;
            this.min = min;
            this.normalAxis = normalAxis;
            this.normalSign = normalSign;
            this.tolerance = tolerance;
        }

        GridSquares cut() throws NotGrid {
            java.util.stream.IntStream.Builder axis = java.util.stream.IntStream.builder();
            java.util.stream.IntStream.Builder sign = java.util.stream.IntStream.builder();
            java.util.stream.IntStream.Builder corners = java.util.stream.IntStream.builder();
            int made = 0;
            Map<Long, Integer> squareAt = new HashMap<>();
            // Per plane (as the key of its cell 0, 0): its faces' area, its squares, its first face.
            Map<Long, double[]> byPlane = new java.util.LinkedHashMap<>();
            for (int f = 0; f < mesh.faceCount(); f++) {
                int a = normalAxis[f];
                int u = (a + 1) % 3;
                int v = (a + 2) % 3;
                int size = mesh.faceSize(f);
                double[] pu = new double[size];
                double[] pv = new double[size];
                double level = 0;
                for (int k = 0; k < size; k++) {
                    int vertex = mesh.faceVertex(f, k);
                    pu[k] = (mesh.coordinate(vertex, u) - min[u]) / s;
                    pv[k] = (mesh.coordinate(vertex, v) - min[v]) / s;
                    level += (mesh.coordinate(vertex, a) - min[a]) / s / size;
                }
                int plane = (int) Math.rint(level);
                int lowU = (int) Math.floor(Arrays.stream(pu).min().getAsDouble() + 1e-6);
                int highU = (int) Math.ceil(Arrays.stream(pu).max().getAsDouble() - 1e-6);
                int lowV = (int) Math.floor(Arrays.stream(pv).min().getAsDouble() + 1e-6);
                int highV = (int) Math.ceil(Arrays.stream(pv).max().getAsDouble() - 1e-6);
                double area = 0;
                for (int k = 0; k < size; k++) {
                    area += pu[k] * pv[(k + 1) % size] - pu[(k + 1) % size] * pv[k];
                }
                area = Math.abs(area) / 2;
                int count = 0;
                for (int i = lowU; i < highU; i++) {
                    for (int j = lowV; j < highV; j++) {
                        // A point near the square's centre but on no line a lattice polygon's edge can take.
                        if (!inside(pu, pv, i + 0.5 + 1.234e-4, j + 0.5 + 2.345e-5)) {
                            continue;
                        }
                        count++;
                        long key = key(a, normalSign[f], plane, i, j);
                        if (squareAt.containsKey(key)) {
                            throw new NotGrid(String.format(Locale.ROOT, "the face through %s lies over another face", GridSquares.corners(mesh, f)));
                        }
                        squareAt.put(key, made++);
                        if (made > MOST_SQUARES) {
                            throw new NotGrid(String.format(Locale.ROOT, "the surface makes more than %d squares of side %s", MOST_SQUARES, s));
                        }
                        axis.add(a);
                        sign.add(normalSign[f]);
                        int[][] uv = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                        for (int k = 0; k < 4; k++) {
                            // u, v, axis is right-handed: counter-clockwise in (u, v) is seen from +axis.
                            int[] c = uv[normalSign[f] > 0 ? k : 3 - k];
                            int[] p = new int[3];
                            p[a] = plane;
                            p[u] = c[0];
                            p[v] = c[1];
                            corners.add(p[0]);
                            corners.add(p[1]);
                            corners.add(p[2]);
                        }
                    }
                }
                long plane1 = key(a, normalSign[f], plane, 0, 0);
                int face = f;
                double[] tally = byPlane.computeIfAbsent(plane1, k -> new double[] {0, 0, face});
                tally[0] += area;
                tally[1] += count;
            }
            // The faces of one plane cover whole squares, exactly as many as their area; a part of one is off the grid.
            for (double[] tally : byPlane.values()) {
                if (Math.abs(tally[1] - tally[0]) > 1e-6 * Math.max(1, tally[0])) {
                    int f = (int) tally[2];
                    throw new NotGrid(String.format(Locale.ROOT, "the face through %s and those in its plane do not cover whole "
                            + "squares of side %s (%.4g squares' area): the hinge strip wraps closed surfaces of squares",
                            GridSquares.corners(mesh, f), s, tally[0]));
                }
            }
            return pair(axis.build().toArray(), sign.build().toArray(), corners.build().toArray());
        }

        private GridSquares pair(int[] axis, int[] sign, int[] corners) throws NotGrid {
            int n = axis.length;
            int[] across = new int[4 * n];
            int[] acrossSide = new int[4 * n];
            Arrays.fill(across, -1);
            Map<Long, Integer> sideAt = new HashMap<>();
            Map<Long, Integer> squaresOn = new HashMap<>();
            for (int q = 0; q < n; q++) {
                for (int k = 0; k < 4; k++) {
                    int from = 12 * q + 3 * k;
                    int to = 12 * q + 3 * ((k + 1) % 4);
                    long key = sideKey(corners, from, to);
                    if (squaresOn.merge(key, 1, Integer::sum) > 2) {
                        // Cubes meeting along an edge alone: the squares on it pair any way, and paper
                        // wrapping both would pass through itself there.
                        throw new NotGrid("an edge of the surface at " + side(corners, from, to) + " has more than two squares on it "
                                + "(solids meeting along an edge alone)");
                    }
                    Integer other = sideAt.remove(key);
                    if (other == null) {
                        sideAt.put(key, 4 * q + k);
                        continue;
                    }
                    int p = other / 4;
                    int j = other % 4;
                    if (across[4 * p + j] >= 0) {
                        throw new NotGrid("an edge of the surface at " + side(corners, from, to) + " has more than two squares on it");
                    }
                    // The same side twice the same way round: the two squares face each other, or the surface is not oriented.
                    if (corners[12 * p + 3 * j] != corners[to] || corners[12 * p + 3 * j + 1] != corners[to + 1]
                            || corners[12 * p + 3 * j + 2] != corners[to + 2]) {
                        throw new NotGrid("the squares at " + side(corners, from, to) + " are not oriented alike");
                    }
                    across[4 * q + k] = p;
                    acrossSide[4 * q + k] = j;
                    across[4 * p + j] = q;
                    acrossSide[4 * p + j] = k;
                }
            }
            for (Map.Entry<Long, Integer> open : sideAt.entrySet()) {
                int q = open.getValue() / 4;
                int k = open.getValue() % 4;
                throw new NotGrid("the surface is open at " + side(corners, 12 * q + 3 * k, 12 * q + 3 * ((k + 1) % 4))
                        + ": the hinge strip wraps closed surfaces, where two squares meet at every edge");
            }
            // Round each corner the squares make one fan, side to side: solids meeting at a corner
            // alone make two, and paper wrapping both would pass through itself there.
            Map<Long, Integer> atCorner = new HashMap<>();
            for (int q = 0; q < n; q++) {
                for (int k = 0; k < 4; k++) {
                    atCorner.merge(pointKey(corners, 12 * q + 3 * k), 1, Integer::sum);
                }
            }
            java.util.Set<Long> walked = new java.util.HashSet<>();
            for (int q = 0; q < n; q++) {
                for (int k = 0; k < 4; k++) {
                    long key = pointKey(corners, 12 * q + 3 * k);
                    if (!walked.add(key)) {
                        continue;
                    }
                    int fan = 0;
                    int p = q;
                    int c = k;
                    do {
                        fan++;
                        int next = across[4 * p + c];
                        c = (acrossSide[4 * p + c] + 1) % 4;
                        p = next;
                    } while (!(p == q && c == k) && fan <= 4 * n);
                    if (fan != atCorner.get(key)) {
                        throw new NotGrid("the squares round the corner (" + point(corners, 12 * q + 3 * k) + ") make more than one fan "
                                + "(solids meeting at a corner alone)");
                    }
                }
            }
            int[] parent = UnionFind.pieces(n);
            for (int q = 0; q < n; q++) {
                for (int k = 0; k < 4; k++) {
                    UnionFind.union(parent, q, across[4 * q + k]);
                }
            }
            int[] component = new int[n];
            int[] number = new int[n];
            Arrays.fill(number, -1);
            int components = 0;
            for (int q = 0; q < n; q++) {
                int root = UnionFind.find(parent, q);
                if (number[root] < 0) {
                    number[root] = components++;
                }
                component[q] = number[root];
            }
            return new GridSquares(s, min.clone(), axis, sign, corners, across, acrossSide, component, components);
        }

        private String side(int[] corners, int from, int to) {
            return "(" + point(corners, from) + ")\u2013(" + point(corners, to) + ")";
        }

        private String point(int[] corners, int at) {
            return String.format(Locale.ROOT, "%.6g %.6g %.6g", min[0] + corners[at] * s, min[1] + corners[at + 1] * s,
                    min[2] + corners[at + 2] * s);
        }

        /** Whether (x, y) lies inside the polygon (pu, pv), by crossings. */
        private static boolean inside(double[] pu, double[] pv, double x, double y) {
            boolean in = false;
            int n = pu.length;
            for (int k = 0, j = n - 1; k < n; j = k++) {
                if ((pv[k] > y) != (pv[j] > y) && x < (pu[j] - pu[k]) * (y - pv[k]) / (pv[j] - pv[k]) + pu[k]) {
                    in = !in;
                }
            }
            return in;
        }
    }

    /** A square by its plane (axis, side it faces, place) and its cell in that plane: 3 + 3 × 20 bits. */
    private static long key(int axis, int sign, int plane, int i, int j) {
        return ((((long) axis * 2 + (sign > 0 ? 1 : 0)) << 20 | plane) << 20 | i) << 20 | j;
    }

    /** An undirected side: its lower corner (three coordinates of 20 bits) and the axis it runs along. */
    private static long sideKey(int[] corners, int from, int to) {
        long a = pointKey(corners, from);
        long b = pointKey(corners, to);
        // A side is one lattice step along one axis: the lower corner and the axis name it.
        long low = Math.min(a, b);
        int along = corners[from] != corners[to] ? 0 : corners[from + 1] != corners[to + 1] ? 1 : 2;
        return low * 3 + along;
    }

    private static long pointKey(int[] corners, int at) {
        return ((long) corners[at] << 40) | ((long) corners[at + 1] << 20) | corners[at + 2];
    }

    private static String corners(IndexedPolygons mesh, int f) {
        StringBuilder text = new StringBuilder();
        for (int k = 0; k < mesh.faceSize(f); k++) {
            text.append(k == 0 ? "" : ", ").append('(').append(point(mesh, mesh.faceVertex(f, k))).append(')');
        }
        return text.toString();
    }

    private static String point(IndexedPolygons mesh, int v) {
        return String.format(Locale.ROOT, "%.6g %.6g %.6g", mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2));
    }

    /** How many squares. */
    public int count() {
        return axis.length;
    }

    /** The lattice's spacing: every square's side. */
    public double spacing() {
        return spacing;
    }

    /** The axis of square q's outward normal (0 = x, 1 = y, 2 = z). */
    public int axis(int q) {
        return axis[q];
    }

    /** The sign of square q's outward normal along its axis: +1 or -1. */
    public int sign(int q) {
        return sign[q];
    }

    /** Coordinate {@code a} of corner {@code k} (0 to 3, counter-clockwise from outside) of square q. */
    public double corner(int q, int k, int a) {
        return origin[a] + corners[12 * q + 3 * k + a] * spacing;
    }

    /** Corner k of square q as lattice coordinates (in spacings from the lattice's origin): a key for shared corners. */
    public int latticeCorner(int q, int k, int a) {
        return corners[12 * q + 3 * k + a];
    }

    /** The square across side k of square q. */
    public int across(int q, int k) {
        return across[4 * q + k];
    }

    /** That square's side along side k of square q. */
    public int acrossSide(int q, int k) {
        return acrossSide[4 * q + k];
    }

    /** Square q's connected component, numbered from 0 in the order of their first squares. */
    public int component(int q) {
        return component[q];
    }

    public int components() {
        return components;
    }

    /** Whether the squares across side k of q lie in one plane with q (the strip crosses it flat). */
    public boolean flatAcross(int q, int k) {
        int p = across(q, k);
        return axis[p] == axis[q] && sign[p] == sign[q];
    }
}
