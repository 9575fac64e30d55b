package ifold.check;

import java.util.Arrays;

/**
 * One thread's share of the pairs: the cells of a {@link BoxGrid} it is given, each swept along
 * the axis its boxes are thinnest on (sorted by their low ends there, a member is paired only
 * with those that start before it ends), each pair tested where it belongs (the cell of its
 * overlap's lowest corner), and only then by {@link TriangleContact}. What it finds it keeps in
 * arrays: the pair, the answer, the depth and the segment. Not thread-safe: one per thread.
 */
final class CellSweep {
    /** The low bits of the sort keys that hold a member's place in its cell. */
    private static final long INDEX_MASK = (1L << 24) - 1;

    private final BoxGrid grid;
    private final TriangleSet set;
    private final double[] boxes;
    private final double thickness;
    private final TriangleContact contact = new TriangleContact();
    /**
     * The cell being tested, its members sorted along the sweep axis: each one's
     * triangle, its box (low and high along the three axes, the sweep axis first), and
     * whether its lowest cell is this one along each axis.
     */
    private int[] members = new int[64];
    private long[] order = new long[64];
    private double[] lo0 = new double[64];
    private double[] lo1 = new double[64];
    private double[] lo2 = new double[64];
    private double[] hi0 = new double[64];
    private double[] hi1 = new double[64];
    private double[] hi2 = new double[64];
    /** Bit a set: the member's lowest cell along axis a is this cell's. */
    private int[] lowHere = new int[64];
    /** The loaded cell's coordinates, and its members' summed extents along each axis. */
    private final long[] here = new long[3];
    private final double[] extent = new double[3];
    /** Each finding's two triangles (the paper one, or the one of the lower face, first), what the test answered. */
    private final Ints foundA = new Ints();
    private final Ints foundB = new Ints();
    private final Ints foundAnswer = new Ints();
    /** Each finding's depth in T (0 when coplanar) and segment (6 numbers). */
    private final PaperObj.Doubles foundDepth = new PaperObj.Doubles();
    private final PaperObj.Doubles foundSegment = new PaperObj.Doubles();

    /**
     * @param thickness the paper's thickness: depths are recorded in it
     */
    CellSweep(BoxGrid grid, TriangleSet set, double thickness) {
        this.grid = grid;
        this.set = set;
        this.boxes = set.boxes;
        this.thickness = thickness;
    }

    /** Tests the pairs of the cells whose runs make up entries [from, to). */
    void cells(int from, int to) {
        long[] entries = grid.entries;
        for (int start = from; start < to; ) {
            int end = grid.runEnd(start);
            load(entries, start, end);
            sweep(end - start);
            start = end;
        }
    }

    /**
     * Loads the cell of entries [start, end): the axis along which its boxes are
     * thinnest on the whole is swept; the members are sorted by their low end on it.
     */
    private void load(long[] entries, int start, int end) {
        int k = end - start;
        if (k > INDEX_MASK) {
            throw new IllegalStateException(k + " triangles in one cell of the grid: more than it can sort");
        }
        if (k > members.length) {
            int size = Math.max(k, 2 * members.length);
            members = new int[size];
            order = new long[size];
            lo0 = new double[size];
            lo1 = new double[size];
            lo2 = new double[size];
            hi0 = new double[size];
            hi1 = new double[size];
            hi2 = new double[size];
            lowHere = new int[size];
        }
        double[] extent = this.extent;
        Arrays.fill(extent, 0);
        for (int e = 0; e < k; e++) {
            int b = 6 * grid.box(entries[start + e]);
            for (int axis = 0; axis < 3; axis++) {
                extent[axis] += boxes[b + 3 + axis] - boxes[b + axis];
            }
        }
        int sweep = extent[0] <= extent[1] && extent[0] <= extent[2] ? 0 : extent[1] <= extent[2] ? 1 : 2;
        long cellIndex = grid.cellOf(entries[start]);
        // Sorted by the low end's bits above the index's: non-negative doubles order as their bits do.
        double floor = Double.POSITIVE_INFINITY;
        for (int e = 0; e < k; e++) {
            floor = Math.min(floor, boxes[6 * grid.box(entries[start + e]) + sweep]);
        }
        for (int e = 0; e < k; e++) {
            long bits = Double.doubleToRawLongBits(boxes[6 * grid.box(entries[start + e]) + sweep] - floor);
            order[e] = (bits & ~INDEX_MASK) | e;
        }
        Arrays.sort(order, 0, k);
        int second = sweep == 0 ? 1 : 0;
        int third = sweep == 2 ? 1 : 2;
        long[] here = this.here;
        for (int axis = 0; axis < 3; axis++) {
            here[axis] = grid.coordinateOf(cellIndex, axis);
        }
        for (int s = 0; s < k; s++) {
            int i = grid.box(entries[start + (int) (order[s] & INDEX_MASK)]);
            int b = 6 * i;
            members[s] = i;
            lo0[s] = boxes[b + sweep] - floor;
            hi0[s] = boxes[b + 3 + sweep] - floor;
            lo1[s] = boxes[b + second];
            hi1[s] = boxes[b + 3 + second];
            lo2[s] = boxes[b + third];
            hi2[s] = boxes[b + 3 + third];
            int low = 0;
            for (int axis = 0; axis < 3; axis++) {
                low |= grid.coordinate(axis, boxes[b + axis]) == here[axis] ? 1 << axis : 0;
            }
            lowHere[s] = low;
        }
    }

    /** Tests the loaded cell's k members pair by pair, along the sweep axis. */
    private void sweep(int k) {
        int[] faceOf = set.paper.triFace;
        int paperTriangles = set.paperTriangles;
        double[] xyz = set.xyz;
        int[] tri = set.tri;
        double touch = set.touch;
        for (int p = 0; p < k; p++) {
            int i = members[p];
            boolean iModel = i >= paperTriangles;
            double high = hi0[p];
            // The members after p are in order of their keys; past high's key, they start beyond it.
            long highKey = Double.doubleToRawLongBits(high) & ~INDEX_MASK;
            double low1 = lo1[p];
            double high1 = hi1[p];
            double low2 = lo2[p];
            double high2 = hi2[p];
            int lowP = lowHere[p];
            for (int q = p + 1; q < k && (order[q] & ~INDEX_MASK) <= highKey; q++) {
                // The pair belongs to this cell when, along each axis, one of them starts in it.
                if (lo0[q] > high || lo1[q] > high1 || low1 > hi1[q] || lo2[q] > high2 || low2 > hi2[q] || (lowP | lowHere[q]) != 7) {
                    continue;
                }
                int j = members[q];
                boolean jModel = j >= paperTriangles;
                if (iModel && jModel || !iModel && !jModel && faceOf[i] == faceOf[j]
                        || TriangleContact.apart(xyz, set.normals, tri, i, j, touch)) {
                    continue;
                }
                int answer = contact.test(xyz, tri[3 * i], tri[3 * i + 1], tri[3 * i + 2], tri[3 * j], tri[3 * j + 1], tri[3 * j + 2], touch);
                if (answer != TriangleContact.APART) {
                    record(i, j, answer);
                }
            }
        }
    }

    private void record(int i, int j, int answer) {
        if (set.isModel(i) || !set.isModel(j) && set.paper.triFace[j] < set.paper.triFace[i]) {
            int swap = i;
            i = j;
            j = swap;
        }
        foundA.add(i);
        foundB.add(j);
        foundAnswer.add(answer);
        foundDepth.add(answer == TriangleContact.COPLANAR ? 0 : contact.depth / thickness);
        for (int c = 0; c < 6; c++) {
            foundSegment.add(contact.segment[c]);
        }
    }

    int size() {
        return foundA.size();
    }

    int paperTriangle(int f) {
        return foundA.get(f);
    }

    int otherTriangle(int f) {
        return foundB.get(f);
    }

    double depth(int f) {
        return foundDepth.get(f);
    }

    boolean coplanar(int f) {
        return foundAnswer.get(f) == TriangleContact.COPLANAR;
    }

    /** Finding f's segment: coordinate c (x0 y0 z0 x1 y1 z1) of its ends. */
    double segment(int f, int c) {
        return foundSegment.get(6 * f + c);
    }
}
