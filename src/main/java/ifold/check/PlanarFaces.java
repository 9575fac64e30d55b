package ifold.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The faces of a folded state sorted onto the planes they lie in, each in its plane's 2D frame,
 * with the order the file gives to faces of one plane: what the layer-order rules read.
 *
 * <p>A face's plane is found from its own corners (Newell's normal); faces whose normals and
 * offsets agree within {@link #NORMAL} and {@link #OFFSET} of the model's size lie in one plane,
 * whichever way they face. Each plane has an up direction, its normal; a face's
 * {@link #sigma} says whether its own normal (its corners counter-clockwise) points up.
 */
final class PlanarFaces {
    /** Normals that agree to this lie in one plane, with offsets that agree to {@link #OFFSET} of the size. */
    static final double NORMAL = 1e-7;
    static final double OFFSET = 1e-7;
    /** Lengths below this fraction of the size are nothing: faces that overlap less only touch. */
    static final double TOUCH = 1e-9;

    final FoldedState state;
    /** The model's size: the diagonal of its vertices' box. */
    final double size;
    /** Lengths below this are nothing. */
    final double eps;
    /** Each face's plane, or -1 for a face of no area. */
    final int[] plane;
    /** Each face's place in its plane's {@link #facesOf}. */
    final int[] placeInPlane;
    /** +1 where a face's normal points to its plane's up side, -1 where it points down. */
    final byte[] sigma;
    /** Each face's corners in its plane's frame, counter-clockwise seen from up: x0 y0 x1 y1 ... */
    final double[][] polygon;
    /** Each face's box in its plane's frame: min x, min y, max x, max y. */
    final double[] box;
    /** Each face's centroid in space. */
    final double[] centroid;
    /** Each plane's up normal, then its frame's x and y axes: nine numbers. */
    final List<double[]> frames = new ArrayList<>();
    /** Each plane's faces. */
    final List<int[]> facesOf = new ArrayList<>();
    /** Orders of faces of one plane, by {@link #pair}: +1 where the lower-numbered face lies above the other. */
    private final LongIntTable relation;
    /** Pairs the file orders both ways. */
    final List<int[]> contradictions = new ArrayList<>();
    /** Each plane's grid, made when first asked for. */
    private final List<Grid> grids = new ArrayList<>();
    /** Per-face marks for one query, told apart by {@link #nextMark} rather than cleared. */
    final int[] marks;
    private int mark;

    PlanarFaces(FoldedState state) {
        this.state = state;
        this.size = diagonal(state);
        this.eps = TOUCH * size;
        int faces = state.faceCount;
        plane = new int[faces];
        placeInPlane = new int[faces];
        sigma = new byte[faces];
        polygon = new double[faces][];
        box = new double[4 * faces];
        centroid = new double[3 * faces];
        NearKeys planes = new NearKeys(1e-6, 1e-6, 1e-6, 1e-6 * size);
        double[] tolerances = {NORMAL, NORMAL, NORMAL, OFFSET * size};
        List<List<Integer>> members = new ArrayList<>();
        for (int f = 0; f < faces; f++) {
            double[] n = newellNormal(f);
            double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            int start = state.faceStart[f];
            int corners = state.faceStart[f + 1] - start;
            for (int i = 0; i < corners; i++) {
                int v = state.faceVertices[start + i];
                centroid[3 * f] += state.x(v) / corners;
                centroid[3 * f + 1] += state.y(v) / corners;
                centroid[3 * f + 2] += state.z(v) / corners;
            }
            // Twice the area under (size × eps): a face that thin has no direction to speak of.
            if (!(length > 2 * eps * size)) {
                plane[f] = -1;
                continue;
            }
            double[] key = {n[0] / length, n[1] / length, n[2] / length, 0};
            key[3] = key[0] * centroid[3 * f] + key[1] * centroid[3 * f + 1] + key[2] * centroid[3 * f + 2];
            int p = planes.find(key, tolerances);
            byte side = 1;
            if (p < 0) {
                double[] flipped = {-key[0], -key[1], -key[2], -key[3]};
                p = planes.find(flipped, tolerances);
                side = -1;
            }
            if (p < 0) {
                p = planes.add(key);
                side = 1;
                frames.add(frame(key));
                members.add(new ArrayList<>());
            }
            plane[f] = p;
            sigma[f] = side;
            members.get(p).add(f);
        }
        for (int p = 0; p < members.size(); p++) {
            facesOf.add(members.get(p).stream().mapToInt(Integer::intValue).toArray());
            double[] frame = frames.get(p);
            int place = 0;
            for (int f : facesOf.get(p)) {
                project(f, frame);
                placeInPlane[f] = place++;
            }
        }
        int[] orders = state.orders;
        relation = new LongIntTable(orders.length / 3 + 16);
        for (int i = 0; i < orders.length; i += 3) {
            int f = orders[i];
            int g = orders[i + 1];
            if (f == g || plane[f] < 0 || plane[f] != plane[g]) {
                continue; // between faces of different planes, or of no area: no rule reads it
            }
            // s = +1: f on the side g's normal points to; up is g's normal where sigma says so.
            boolean fAbove = orders[i + 2] * sigma[g] > 0;
            int value = (f < g) == fAbove ? 1 : -1;
            int before = relation.put(pair(f, g), value, 0);
            if (before != 0 && before != value) {
                contradictions.add(new int[] {Math.min(f, g), Math.max(f, g)});
            }
        }
        marks = new int[faces];
    }

    int nextMark() {
        return ++mark;
    }

    /** The grid of plane p's faces. */
    Grid grid(int p) {
        while (grids.size() <= p) {
            grids.add(null);
        }
        if (grids.get(p) == null) {
            grids.set(p, new Grid(facesOf.get(p)));
        }
        return grids.get(p);
    }

    static long pair(int f, int g) {
        return ((long) Math.min(f, g) << 32) | Math.max(f, g);
    }

    /** +1 where face p lies above face q in their plane, -1 where below, 0 where the file does not say. */
    int above(int p, int q) {
        int value = relation.get(pair(p, q), 0);
        return p < q ? value : -value;
    }

    /** Whether z lies strictly between a and b, as the file orders them (false where it does not say). */
    boolean between(int z, int a, int b) {
        int first = above(a, z);
        return first != 0 && first == above(z, b);
    }

    private double[] newellNormal(int f) {
        double nx = 0;
        double ny = 0;
        double nz = 0;
        int start = state.faceStart[f];
        int corners = state.faceStart[f + 1] - start;
        for (int i = 0; i < corners; i++) {
            int a = state.faceVertices[start + i];
            int b = state.faceVertices[start + (i + 1) % corners];
            nx += (state.y(a) - state.y(b)) * (state.z(a) + state.z(b));
            ny += (state.z(a) - state.z(b)) * (state.x(a) + state.x(b));
            nz += (state.x(a) - state.x(b)) * (state.y(a) + state.y(b));
        }
        return new double[] {nx, ny, nz};
    }

    /** A plane's up normal and two axes in it, x × y = up. */
    private static double[] frame(double[] n) {
        double ax = Math.abs(n[0]) < 0.6 ? 1 : 0;
        double ay = ax == 1 ? 0 : 1;
        // x = unit(a × n) for a helper axis a off the normal; y = n × x.
        double xx = ay * n[2];
        double xy = -ax * n[2];
        double xz = ax * n[1] - ay * n[0];
        double length = Math.sqrt(xx * xx + xy * xy + xz * xz);
        xx /= length;
        xy /= length;
        xz /= length;
        double yx = n[1] * xz - n[2] * xy;
        double yy = n[2] * xx - n[0] * xz;
        double yz = n[0] * xy - n[1] * xx;
        return new double[] {n[0], n[1], n[2], xx, xy, xz, yx, yy, yz};
    }

    private void project(int f, double[] frame) {
        int start = state.faceStart[f];
        int corners = state.faceStart[f + 1] - start;
        double[] points = new double[2 * corners];
        double area = 0;
        for (int i = 0; i < corners; i++) {
            int v = state.faceVertices[start + i];
            points[2 * i] = frame[3] * state.x(v) + frame[4] * state.y(v) + frame[5] * state.z(v);
            points[2 * i + 1] = frame[6] * state.x(v) + frame[7] * state.y(v) + frame[8] * state.z(v);
        }
        for (int i = 0; i < corners; i++) {
            int j = (i + 1) % corners;
            area += points[2 * i] * points[2 * j + 1] - points[2 * j] * points[2 * i + 1];
        }
        if (area < 0) {
            for (int i = 0, j = corners - 1; i < j; i++, j--) {
                double x = points[2 * i];
                double y = points[2 * i + 1];
                points[2 * i] = points[2 * j];
                points[2 * i + 1] = points[2 * j + 1];
                points[2 * j] = x;
                points[2 * j + 1] = y;
            }
        }
        polygon[f] = points;
        box[4 * f] = Double.POSITIVE_INFINITY;
        box[4 * f + 1] = Double.POSITIVE_INFINITY;
        box[4 * f + 2] = Double.NEGATIVE_INFINITY;
        box[4 * f + 3] = Double.NEGATIVE_INFINITY;
        for (int i = 0; i < corners; i++) {
            box[4 * f] = Math.min(box[4 * f], points[2 * i]);
            box[4 * f + 1] = Math.min(box[4 * f + 1], points[2 * i + 1]);
            box[4 * f + 2] = Math.max(box[4 * f + 2], points[2 * i]);
            box[4 * f + 3] = Math.max(box[4 * f + 3], points[2 * i + 1]);
        }
    }

    /** Whether two faces of one plane overlap in more than a touch: no axis of their edges separates them (convex faces). */
    boolean overlap(int f, int g) {
        if (box[4 * f] >= box[4 * g + 2] - eps || box[4 * g] >= box[4 * f + 2] - eps
                || box[4 * f + 1] >= box[4 * g + 3] - eps || box[4 * g + 1] >= box[4 * f + 3] - eps) {
            return false;
        }
        return !separates(polygon[f], polygon[g]) && !separates(polygon[g], polygon[f]);
    }

    /** Whether an edge of {@code a} has {@code b} wholly on its outer side, but for {@link #eps}. */
    private boolean separates(double[] a, double[] b) {
        int n = a.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = a[2 * j] - a[2 * i];
            double ey = a[2 * j + 1] - a[2 * i + 1];
            // Not hypot: a tenth of the cost, and lengths of a model's size neither overflow nor underflow.
            double length = Math.sqrt(ex * ex + ey * ey);
            if (!(length > 0)) {
                continue;
            }
            // Counter-clockwise: the inside is to the left, where the cross product is positive.
            double most = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < b.length; k += 2) {
                most = Math.max(most, (ex * (b[k + 1] - a[2 * i + 1]) - ey * (b[k] - a[2 * i])) / length);
            }
            if (most <= eps) {
                return true;
            }
        }
        return false;
    }

    /**
     * A uniform grid of one plane's faces, each entered in the cells its polygon meets (row by
     * row, not its box: a long pass at 45° lies in a few cells of a row, not in every cell of its
     * box). The cell is twice the median face's narrow width, grown while the entries would be
     * more than {@link #ENTRIES_PER_FACE} a face: the layers over a point then share a cell with
     * few faces beside them, where a cell of the faces' length held a whole host's passes and its
     * pairs grew with the square of the faces (a cube at width 0.001: 16 s for 49,000 faces).
     */
    final class Grid {
        /** Entries a face may have on average before the cell grows: a bound on memory and time. */
        private static final int ENTRIES_PER_FACE = 24;

        final double x0;
        final double y0;
        final double cell;
        /** Each occupied cell's faces: a count, then the faces in ascending order. */
        final Map<Long, int[]> cells = new HashMap<>();

        Grid(int[] faces) {
            double minX = Double.POSITIVE_INFINITY;
            double minY = Double.POSITIVE_INFINITY;
            double maxX = Double.NEGATIVE_INFINITY;
            double maxY = Double.NEGATIVE_INFINITY;
            double[] narrow = new double[faces.length];
            double area = 0;
            double perimeter = 0;
            for (int i = 0; i < faces.length; i++) {
                int f = faces[i];
                minX = Math.min(minX, box[4 * f]);
                minY = Math.min(minY, box[4 * f + 1]);
                maxX = Math.max(maxX, box[4 * f + 2]);
                maxY = Math.max(maxY, box[4 * f + 3]);
                double[] shape = areaAndPerimeter(polygon[f]);
                area += shape[0];
                perimeter += shape[1];
                narrow[i] = shape[1] > 0 ? 2 * shape[0] / shape[1] : 0;
            }
            Arrays.sort(narrow);
            double median = faces.length == 0 ? 1 : narrow[faces.length / 2];
            double span = Math.max(maxX - minX, maxY - minY);
            double c = Math.max(Math.max(4 * median, span / (1 << 20)), Double.MIN_NORMAL);
            // The cells a face meets: about its area, a share of its outline, and one.
            while (area / (c * c) + perimeter / c + faces.length > ENTRIES_PER_FACE * (double) faces.length && c < span) {
                c *= 1.5;
            }
            cell = c;
            x0 = minX;
            y0 = minY;
            for (int f : faces) {
                forPolygon(polygon[f], key -> {
                    int[] list = cells.computeIfAbsent(key, k -> new int[] {0, 0, 0, 0, 0});
                    if (list[0] + 1 == list.length) {
                        list = Arrays.copyOf(list, 2 * list.length);
                        cells.put(key, list);
                    }
                    list[++list[0]] = f;
                });
            }
        }

        long key(int ix, int iy) {
            return ((long) ix << 32) ^ (iy & 0xffffffffL);
        }

        int ix(double x) {
            return (int) Math.floor((x - x0) / cell);
        }

        int iy(double y) {
            return (int) Math.floor((y - y0) / cell);
        }

        /**
         * The cells a polygon (x0 y0 x1 y1 …; two points make a segment) meets, but for
         * {@link #eps}: in each row of cells, those between the least and most x of its edges
         * within the row — the row's part of a convex polygon.
         */
        void forPolygon(double[] points, java.util.function.LongConsumer action) {
            int n = points.length / 2;
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < n; i++) {
                low = Math.min(low, points[2 * i + 1]);
                high = Math.max(high, points[2 * i + 1]);
            }
            int first = iy(low - eps);
            int last = iy(high + eps);
            for (int row = first; row <= last; row++) {
                double bottom = row == first ? Double.NEGATIVE_INFINITY : y0 + row * cell - eps;
                double top = row == last ? Double.POSITIVE_INFINITY : y0 + (row + 1) * cell + eps;
                double least = Double.POSITIVE_INFINITY;
                double most = Double.NEGATIVE_INFINITY;
                for (int i = 0; i < n; i++) {
                    int j = (i + 1) % n;
                    double ax = points[2 * i];
                    double ay = points[2 * i + 1];
                    double bx = points[2 * j];
                    double by = points[2 * j + 1];
                    if (Math.max(ay, by) < bottom || Math.min(ay, by) > top) {
                        continue;
                    }
                    // The edge's part within the row: its x at the row's lines where it crosses them.
                    double fromX = ax;
                    double toX = bx;
                    if (ay != by) {
                        double t0 = Math.max(0, Math.min(1, (bottom - ay) / (by - ay)));
                        double t1 = Math.max(0, Math.min(1, (top - ay) / (by - ay)));
                        fromX = ax + (bx - ax) * t0;
                        toX = ax + (bx - ax) * t1;
                    }
                    least = Math.min(least, Math.min(fromX, toX));
                    most = Math.max(most, Math.max(fromX, toX));
                }
                if (least > most) {
                    continue;
                }
                for (int column = ix(least - eps); column <= ix(most + eps); column++) {
                    action.accept(key(column, row));
                }
            }
        }
    }

    /** A polygon's area and perimeter (x0 y0 x1 y1 …, counter-clockwise). */
    private static double[] areaAndPerimeter(double[] points) {
        int n = points.length / 2;
        double twice = 0;
        double perimeter = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            twice += points[2 * i] * points[2 * j + 1] - points[2 * j] * points[2 * i + 1];
            perimeter += Math.hypot(points[2 * j] - points[2 * i], points[2 * j + 1] - points[2 * i + 1]);
        }
        return new double[] {Math.abs(twice) / 2, perimeter};
    }

    private static double diagonal(FoldedState state) {
        double[] low = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] high = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < state.vertexCount; v++) {
            for (int axis = 0; axis < 3; axis++) {
                low[axis] = Math.min(low[axis], state.coords[3 * v + axis]);
                high[axis] = Math.max(high[axis], state.coords[3 * v + axis]);
            }
        }
        double d = Math.sqrt(Math.pow(high[0] - low[0], 2) + Math.pow(high[1] - low[1], 2) + Math.pow(high[2] - low[2], 2));
        return d > 0 && Double.isFinite(d) ? d : 1;
    }
}
