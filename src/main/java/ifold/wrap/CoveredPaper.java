package ifold.wrap;

import ifold.sheet.HostFrame;
import ifold.sheet.Polygons2;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.BitSet;
import java.util.List;

/**
 * The faces and caps of a wrapped strip that higher paper on their own host covers whole, and
 * from which face laid on: from then on they cannot be seen from outside, so a picture of the
 * wrap at that moment or later need not draw them. A wrap of a million faces stacks several
 * layers over most points, and drawing only what is exposed is part of what lets a software
 * renderer play it at a frame rate ({@code render.GpuMesh}).
 *
 * <p>Read from the geometry in space alone: each face is projected onto its host's plane, and
 * its height above the plane is its layer. A face is covered when the faces of its host lying
 * higher by more than half a thickness cover its polygon (convex pieces subtracted one by one,
 * nothing of area left, in the order they were laid, so that the last of them says when it
 * was covered); a cap, when they cover its footprint on the plane above its top. Only
 * paper of the same host covers: what lies under a neighbour host's paper, past a concave
 * edge, is drawn. Where the subtraction would split a face into many pieces, the face is kept:
 * every face called covered is covered.
 *
 * <p>A solid hides its paper from below; an open surface does not (the zig-zag demo's lone
 * triangle, seen from below, shows the excess tucked under its strip). Where paper can be seen
 * from both sides of its host, a face is covered only where the paper lower than it covers it
 * too, from the moment the later of the two covers is laid.
 */
public final class CoveredPaper {
    /** More pieces left than this, the face is kept rather than followed further. */
    private static final int MOST_PIECES = 48;
    /** What area is left of a face, relative to the face, that counts as none (rounding along shared edges). */
    private static final double NO_AREA = 1e-9;

    private CoveredPaper() {
    }

    /**
     * What covers each face (by index in {@code paperFaces}) and cap (in {@code caps}): the last
     * of the faces that cover it, so that it is covered from the moment that face is laid on
     * (faces are laid in the order of their indices); -1 where it is seen. And, for what a
     * picture from far away shows instead of the faces, which faces show their underside
     * outward and each face's area.
     */
    public record Covered(int[] faceCover, int[] capCover, BitSet undersideOut, double[] areas) {
        public boolean face(int f) {
            return faceCover[f] >= 0;
        }

        public boolean cap(int c) {
            return capCover[c] >= 0;
        }
    }

    /**
     * The covered paper of {@code geometry}, whose faces rest on {@code frames} (by
     * {@code paperHosts}) in layers {@code thickness} apart, on a solid that hides what lies under
     * its paper.
     */
    public static Covered of(PaperInSpace geometry, HostFrame[] frames, double thickness) {
        return of(geometry, frames, thickness, false);
    }

    /**
     * As {@link #of(PaperInSpace, HostFrame[], double)}, the paper seen from below its hosts too
     * where {@code bothSides} (an open surface's).
     */
    public static Covered of(PaperInSpace geometry, HostFrame[] frames, double thickness, boolean bothSides) {
        Projected paper = new Projected(geometry, frames);
        int[] faces = new int[geometry.paperFaces().size()];
        int[] caps = new int[geometry.caps().size()];
        Arrays.fill(faces, -1);
        Arrays.fill(caps, -1);
        Covered covered = new Covered(faces, caps, paper.undersideOut, paper.areas);
        if (!(thickness > 0)) {
            return covered; // no layers apart: nothing lies above anything
        }
        double margin = thickness / 2;
        int faceCount = geometry.paperFaces().size();
        // The faces of each host together, and the caps with the host of the face they follow.
        int hostCount = frames.length;
        int[] start = new int[hostCount + 1];
        for (int f = 0; f < faceCount; f++) {
            start[geometry.paperHosts()[f] + 1]++;
        }
        for (int h = 0; h < hostCount; h++) {
            start[h + 1] += start[h];
        }
        int[] byHost = new int[faceCount];
        int[] fill = Arrays.copyOf(start, hostCount);
        for (int f = 0; f < faceCount; f++) {
            byHost[fill[geometry.paperHosts()[f]]++] = f;
        }
        int capCount = geometry.caps().size();
        int[] capStart = new int[hostCount + 1];
        for (int c = 0; c < capCount; c++) {
            capStart[geometry.paperHosts()[geometry.capAfter()[c]] + 1]++;
        }
        for (int h = 0; h < hostCount; h++) {
            capStart[h + 1] += capStart[h];
        }
        int[] capsByHost = new int[capCount];
        fill = Arrays.copyOf(capStart, hostCount);
        for (int c = 0; c < capCount; c++) {
            capsByHost[fill[geometry.paperHosts()[geometry.capAfter()[c]]]++] = c;
        }
        int[] stamp = new int[faceCount];
        int[] round = {0};
        for (int h = 0; h < hostCount; h++) {
            int n = start[h + 1] - start[h];
            if (n < 2) {
                continue; // one face alone is seen, and covers no cap that is not its own
            }
            HostGrid grid = new HostGrid(paper, byHost, start[h], start[h + 1]);
            for (int i = start[h]; i < start[h + 1]; i++) {
                int f = byHost[i];
                faces[f] = cover(paper.polygon(f), paper.height(f) + margin, true, paper.box(f), grid, paper, stamp, round);
                if (bothSides && faces[f] >= 0) {
                    faces[f] = later(faces[f], cover(paper.polygon(f), paper.height(f) - margin, false, paper.box(f), grid, paper, stamp, round));
                }
            }
            for (int i = capStart[h]; i < capStart[h + 1]; i++) {
                int c = capsByHost[i];
                int[] cap = geometry.caps().get(c);
                HostFrame frame = frames[h];
                double[] footprint = new double[2 * cap.length];
                double top = Double.NEGATIVE_INFINITY;
                double bottom = Double.POSITIVE_INFINITY;
                double[] p = new double[3];
                for (int k = 0; k < cap.length; k++) {
                    System.arraycopy(geometry.xyz(), 3 * cap[k], p, 0, 3);
                    footprint[2 * k] = frame.localX(p);
                    footprint[2 * k + 1] = frame.localY(p);
                    top = Math.max(top, frame.height(p));
                    bottom = Math.min(bottom, frame.height(p));
                }
                footprint = convexHull(footprint);
                if (footprint == null) {
                    continue; // on edge, seen from the plane: a cap over the host's edge, or none
                }
                double[] box = Polygons2.bounds(footprint);
                caps[c] = cover(footprint, top + margin, true, box, grid, paper, stamp, round);
                if (bothSides && caps[c] >= 0) {
                    caps[c] = later(caps[c], cover(footprint, bottom - margin, false, box, grid, paper, stamp, round));
                }
            }
        }
        return covered;
    }

    /** Covered from above by {@code above} and from below by {@code below} (faces, or -1): covered once both are laid. */
    private static int later(int above, int below) {
        return below < 0 ? -1 : Math.max(above, below);
    }

    /**
     * The last of the faces of {@code grid} beyond height {@code beyond} (higher where {@code up},
     * else lower) that together cover convex {@code polygon} (counter-clockwise), taken in the
     * order they were laid; -1 where they do not.
     */
    private static int cover(double[] polygon, double beyond, boolean up, double[] box, HostGrid grid, Projected paper, int[] stamp,
            int[] round) {
        double area = twiceArea(polygon);
        if (!(area > 0)) {
            return -1;
        }
        List<Integer> over = grid.beyond(box, beyond, up, paper, stamp, ++round[0]);
        if (over.isEmpty()) {
            return -1;
        }
        // Most faces that are seen are seen at their middle: say so before any subtraction (this
        // only spares work; the subtraction decides).
        double cx = 0;
        double cy = 0;
        int n = polygon.length / 2;
        for (int k = 0; k < n; k++) {
            cx += polygon[2 * k];
            cy += polygon[2 * k + 1];
        }
        cx /= n;
        cy /= n;
        boolean middle = false;
        for (int g : over) {
            if (inside(paper.polygon(g), cx, cy)) {
                middle = true;
                break;
            }
        }
        if (!middle) {
            return -1;
        }
        // In the order they were laid: the first that cover it are those it lies under first.
        over.sort(null);
        double none = NO_AREA * area;
        List<double[]> pieces = new ArrayList<>();
        pieces.add(polygon);
        for (int g : over) {
            pieces = subtract(pieces, paper.polygon(g), none);
            if (pieces == null) {
                return -1;
            }
            if (pieces.isEmpty()) {
                return g;
            }
        }
        return -1;
    }

    /** What is left of {@code pieces} outside convex {@code cut} (counter-clockwise); null past {@link #MOST_PIECES}. */
    private static List<double[]> subtract(List<double[]> pieces, double[] cut, double none) {
        List<double[]> left = new ArrayList<>();
        int m = cut.length / 2;
        for (double[] piece : pieces) {
            double[] rest = piece;
            for (int k = 0; k < m && rest != null; k++) {
                double ax = cut[2 * k];
                double ay = cut[2 * k + 1];
                double bx = cut[2 * ((k + 1) % m)];
                double by = cut[2 * ((k + 1) % m) + 1];
                // Left of a → b is inside the cut (n · p <= n · a, n = (b - a) turned clockwise);
                // right of it, outside.
                double nx = by - ay;
                double ny = ax - bx;
                double c = nx * ax + ny * ay;
                double[] outside = Polygons2.clip(rest, rest.length / 2, -nx, -ny, -c, 0);
                if (outside != null && twiceArea(outside) > 2 * none) {
                    left.add(outside);
                }
                rest = Polygons2.clip(rest, rest.length / 2, nx, ny, c, 0);
            }
            if (left.size() > MOST_PIECES) {
                return null;
            }
        }
        return left;
    }

    /** Whether (x, y) lies inside convex counter-clockwise {@code xy} or on its border (two faces meeting there both hold it). */
    private static boolean inside(double[] xy, double x, double y) {
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double cross = (xy[2 * j] - xy[2 * i]) * (y - xy[2 * i + 1]) - (xy[2 * j + 1] - xy[2 * i + 1]) * (x - xy[2 * i]);
            if (cross < 0) {
                return false;
            }
        }
        return true;
    }

    static double twiceArea(double[] xy) {
        return Polygons2.twiceArea(xy, xy.length / 2);
    }

    /**
     * The convex hull of the points, counter-clockwise (a cap's two facets seen from above make
     * one convex footprint); null where it has no area beyond rounding.
     */
    static double[] convexHull(double[] points) {
        int n = points.length / 2;
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (a, b) -> points[2 * a] != points[2 * b] ? Double.compare(points[2 * a], points[2 * b])
                : Double.compare(points[2 * a + 1], points[2 * b + 1]));
        int[] hull = new int[2 * n + 1];
        int k = 0;
        for (int pass = 0; pass < 2; pass++) {
            int floor = k;
            for (int s = 0; s < n; s++) {
                int i = pass == 0 ? order[s] : order[n - 1 - s];
                while (k >= floor + 2 && turn(points, hull[k - 2], hull[k - 1], i) <= 0) {
                    k--;
                }
                hull[k++] = i;
            }
            k--; // the last point starts the other chain
        }
        if (k < 3) {
            return null;
        }
        double[] xy = new double[2 * k];
        double span = 0;
        for (int i = 0; i < k; i++) {
            xy[2 * i] = points[2 * hull[i]];
            xy[2 * i + 1] = points[2 * hull[i] + 1];
        }
        for (int i = 0; i < k; i++) {
            int j = (i + 1) % k;
            span = Math.max(span, Math.hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]));
        }
        return twiceArea(xy) > NO_AREA * span * span ? xy : null;
    }

    private static double turn(double[] p, int a, int b, int c) {
        return (p[2 * b] - p[2 * a]) * (p[2 * c + 1] - p[2 * a + 1]) - (p[2 * b + 1] - p[2 * a + 1]) * (p[2 * c] - p[2 * a]);
    }

    /** Every face projected on its host's plane, counter-clockwise there, with its height and box. */
    private static final class Projected {
        private final double[][] polygons;
        private final double[] heights;
        private final double[] boxes;
        final BitSet undersideOut = new BitSet();
        final double[] areas;

        Projected(PaperInSpace geometry, HostFrame[] frames) {
            int n = geometry.paperFaces().size();
            areas = new double[n];
            polygons = new double[n][];
            heights = new double[n];
            boxes = new double[4 * n];
            double[] p = new double[3];
            for (int f = 0; f < n; f++) {
                int[] loop = geometry.paperFaces().get(f);
                HostFrame frame = frames[geometry.paperHosts()[f]];
                double[] xy = new double[2 * loop.length];
                double height = 0;
                for (int k = 0; k < loop.length; k++) {
                    System.arraycopy(geometry.xyz(), 3 * loop[k], p, 0, 3);
                    xy[2 * k] = frame.localX(p);
                    xy[2 * k + 1] = frame.localY(p);
                    height += frame.height(p);
                }
                double twice = twiceArea(xy);
                areas[f] = Math.abs(twice) / 2;
                if (twice < 0) { // the paper's underside out: its loop runs clockwise on the plane
                    undersideOut.set(f);
                    xy = WrapAnalysis.counterClockwise(xy);
                }
                polygons[f] = xy;
                heights[f] = height / loop.length;
                System.arraycopy(Polygons2.bounds(xy), 0, boxes, 4 * f, 4);
            }
        }

        double[] polygon(int f) {
            return polygons[f];
        }

        double height(int f) {
            return heights[f];
        }

        double[] box(int f) {
            return Arrays.copyOfRange(boxes, 4 * f, 4 * f + 4);
        }

        boolean boxesMeet(int f, double[] box) {
            return boxes[4 * f] < box[2] && box[0] < boxes[4 * f + 2] && boxes[4 * f + 1] < box[3] && box[1] < boxes[4 * f + 3];
        }
    }

    /** The faces of one host in a grid of cells about the size of a face, entered by their boxes. */
    private static final class HostGrid {
        private final double x0;
        private final double y0;
        private final double cell;
        private final int columns;
        private final int rows;
        private final int[] cellStart;
        private final int[] entries;

        HostGrid(Projected paper, int[] byHost, int from, int to) {
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int i = from; i < to; i++) {
                double[] b = paper.box(byHost[i]);
                box[0] = Math.min(box[0], b[0]);
                box[1] = Math.min(box[1], b[1]);
                box[2] = Math.max(box[2], b[2]);
                box[3] = Math.max(box[3], b[3]);
            }
            int n = to - from;
            double w = Math.max(box[2] - box[0], 1e-300);
            double h = Math.max(box[3] - box[1], 1e-300);
            // About two faces a cell, in at most 2n cells.
            double size = Math.sqrt(w * h / Math.max(1, n / 2.0));
            size = Math.max(size, Math.max(w, h) / (2.0 * n));
            x0 = box[0];
            y0 = box[1];
            cell = size;
            columns = Math.max(1, (int) Math.min(2L * n, (long) Math.ceil(w / size)));
            rows = Math.max(1, (int) Math.min(2L * n, (long) Math.ceil(h / size)));
            cellStart = new int[columns * rows + 1];
            for (int i = from; i < to; i++) {
                double[] b = paper.box(byHost[i]);
                for (int r = row(b[1]); r <= row(b[3]); r++) {
                    for (int c = column(b[0]); c <= column(b[2]); c++) {
                        cellStart[r * columns + c + 1]++;
                    }
                }
            }
            for (int k = 0; k < columns * rows; k++) {
                cellStart[k + 1] += cellStart[k];
            }
            entries = new int[cellStart[columns * rows]];
            int[] fill = Arrays.copyOf(cellStart, columns * rows);
            for (int i = from; i < to; i++) {
                int f = byHost[i];
                double[] b = paper.box(f);
                for (int r = row(b[1]); r <= row(b[3]); r++) {
                    for (int c = column(b[0]); c <= column(b[2]); c++) {
                        entries[fill[r * columns + c]++] = f;
                    }
                }
            }
        }

        private int column(double x) {
            return Math.max(0, Math.min(columns - 1, (int) ((x - x0) / cell)));
        }

        private int row(double y) {
            return Math.max(0, Math.min(rows - 1, (int) ((y - y0) / cell)));
        }

        /** The faces higher than {@code beyond} where {@code up}, else lower, whose boxes meet {@code box}, each once. */
        List<Integer> beyond(double[] box, double beyond, boolean up, Projected paper, int[] stamp, int round) {
            List<Integer> found = new ArrayList<>();
            for (int r = row(box[1]); r <= row(box[3]); r++) {
                for (int c = column(box[0]); c <= column(box[2]); c++) {
                    for (int k = cellStart[r * columns + c]; k < cellStart[r * columns + c + 1]; k++) {
                        int g = entries[k];
                        if (stamp[g] == round) {
                            continue;
                        }
                        stamp[g] = round;
                        if ((up ? paper.height(g) > beyond : paper.height(g) < beyond) && paper.boxesMeet(g, box)) {
                            found.add(g);
                        }
                    }
                }
            }
            return found;
        }
    }
}
