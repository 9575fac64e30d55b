package ifold.wrap;

import static ifold.wrap.WrapAnalysis.counterClockwise;

import ifold.sheet.Polygons2;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * The arrangement of faces of paper over one triangle of a host, for the layers and the
 * coverage: the triangle cut into the convex cells the faces' edges make, each with the faces
 * over it counted, in a grid so that a face visits only the cells near it.
 */
final class FaceArrangement {
    private FaceArrangement() {
    }

    /**
     * Cuts the triangle into the cells of the faces' arrangement: {area, area under at least one
     * face, the most faces over any cell, then the centre and corners of the largest cell that
     * deep}. Every cell is convex: splitting a cell by a face gives the part inside the face and,
     * edge by edge, the parts outside it. The cells are kept in a grid over the triangle, so that
     * a face visits only the cells near it: a narrow strip lays thousands of faces on one
     * triangle, mostly side by side.
     */
    static double[] depths(double[] triangle, List<double[]> polygons, double tolerance) {
        return depths(triangle, polygons, null, tolerance, null);
    }

    /**
     * {@link #depths(double[], List, double)}, where only the most layers over the whole surface
     * and the cell that deep are wanted: {@code deepestElsewhere} holds the most found so far on
     * other triangles, and is raised to this one's. A bucket of the grid can have no more layers
     * than the levels of the faces whose boxes meet it ({@code levels}: each polygon's level in
     * its stack, where faces of one level never overlap; null: each face a level of its own); one
     * with fewer than the most found, here or elsewhere, is only covered, not counted (of the
     * 5,000-triangle torus's 312,000 buckets, 5,400 are counted; by the faces alone, not their
     * levels, 24,000 were). The area and the area covered are this triangle's still; the
     * most layers too where this triangle has the surface's most, and then the same cell, as
     * every bucket that could hold that many is counted; elsewhere, fewer than the most found.
     */
    static double[] depths(double[] triangle, List<double[]> polygons, int[] levels, double tolerance,
            AtomicInteger deepestElsewhere) {
        // Buckets of about four faces each: finer, the grid's own lines cut the faces into more
        // cells than it saves in looking (the 1,280-triangle icosphere: 2.3 million cells at
        // this size, 2.9 million at one face a bucket, 4.5 at a quarter). Shaped as the faces
        // are, on the whole: the passes run along x, and on a big triangle they are long and
        // thin, so that square buckets each held a piece of dozens of passes, which every pass
        // then looked through (a 10 x 10 face crossed by 12,000 passes: a minute).
        int buckets = Math.max(1, polygons.size() / 4);
        double[] box = Polygons2.bounds(triangle);
        double wide = 0;
        double tall = 0;
        for (double[] polygon : polygons) {
            double[] b = Polygons2.bounds(polygon);
            wide += b[2] - b[0];
            tall += b[3] - b[1];
        }
        // Across the triangle's box, as many buckets as faces side by side there, x to y.
        double across = wide > 0 && tall > 0 ? ((box[2] - box[0]) / wide) / ((box[3] - box[1]) / tall) : 1;
        int columns = (int) Math.max(1, Math.min(buckets, Math.round(Math.sqrt(buckets * across))));
        int rows = Math.max(1, buckets / columns);
        Cells cells = new Cells(triangle, columns, rows, tolerance);
        // The faces that cover something, each with its box, and for each bucket those whose
        // boxes meet it, in their order.
        int count = 0;
        double[][] faces = new double[polygons.size()][];
        double[][] faceBoxes = new double[polygons.size()][];
        int[] levelOf = new int[polygons.size()];
        int[] meeting = new int[columns * rows];
        for (int i = 0; i < polygons.size(); i++) {
            double[] p = counterClockwise(polygons.get(i));
            if (thinnerThan(p, tolerance)) {
                // No part of it is more than the tolerance across: it covers nothing. (Its edges,
                // all shorter than the tolerance, would cut no cell, and every cell its box met
                // was counted under it: a face of 1e-13 put a 21st layer on the cube at width 1e-3.)
                continue;
            }
            double[] b = Polygons2.bounds(p);
            levelOf[count] = levels == null ? count : levels[i];
            faces[count] = p;
            faceBoxes[count++] = b;
            for (int bx = cells.column(b[0]); bx <= cells.column(b[2]); bx++) {
                for (int by = cells.row(b[1]); by <= cells.row(b[3]); by++) {
                    meeting[by * columns + bx]++;
                }
            }
        }
        int[][] facesOf = new int[columns * rows][];
        for (int bucket = 0; bucket < facesOf.length; bucket++) {
            facesOf[bucket] = new int[meeting[bucket]];
            meeting[bucket] = 0;
        }
        // Each bucket's faces the largest first: where only covered, the first few cover it, and
        // the rest meet no cell left uncovered (counted, they go in their order, below).
        Integer[] largestFirst = new Integer[count];
        double[] areas = new double[count];
        for (int f = 0; f < count; f++) {
            largestFirst[f] = f;
            areas[f] = Math.abs(Polygons2.twiceArea(faces[f], faces[f].length / 2));
        }
        java.util.Arrays.sort(largestFirst, (a, b) -> Double.compare(areas[b], areas[a]));
        for (int f : largestFirst) {
            double[] b = faceBoxes[f];
            for (int bx = cells.column(b[0]); bx <= cells.column(b[2]); bx++) {
                for (int by = cells.row(b[1]); by <= cells.row(b[3]); by++) {
                    int bucket = by * columns + bx;
                    facesOf[bucket][meeting[bucket]++] = f;
                }
            }
        }
        // Every bucket covered, the largest faces first: the area and the area covered come from
        // these cells alone, the same whichever buckets are counted below (which depends on the
        // other triangles' threads: the reports stay the same to the byte).
        for (int bucket = 0; bucket < facesOf.length; bucket++) {
            for (int f : facesOf[bucket]) {
                cut(cells, bucket, faces[f], faceBoxes[f], false);
            }
        }
        // Counted, in buckets of their own: those that could be deepest first, so that the rest
        // can be passed over sooner.
        Cells counted = new Cells(cells);
        int[] levelsMeeting = new int[facesOf.length];
        int[] seen = new int[count == 0 ? 0 : java.util.Arrays.stream(levelOf, 0, count).max().getAsInt() + 1];
        Integer[] order = new Integer[facesOf.length];
        for (int bucket = 0; bucket < order.length; bucket++) {
            order[bucket] = bucket;
            for (int f : facesOf[bucket]) {
                if (seen[levelOf[f]] != bucket + 1) {
                    seen[levelOf[f]] = bucket + 1;
                    levelsMeeting[bucket]++;
                }
            }
        }
        java.util.Arrays.sort(order, (a, b) -> Integer.compare(levelsMeeting[b], levelsMeeting[a]));
        int most = 0;
        for (int bucket : order) {
            int floor = Math.max(most, deepestElsewhere == null ? 0 : deepestElsewhere.get());
            if (levelsMeeting[bucket] < floor) {
                break; // nor any after it
            }
            counted.open(bucket);
            // In their order: the cells, and so the deepest cell reported, are the same as a
            // face at a time over the whole triangle made.
            java.util.Arrays.sort(facesOf[bucket]);
            for (int f : facesOf[bucket]) {
                cut(counted, bucket, faces[f], faceBoxes[f], true);
            }
            most = Math.max(most, counted.deepestIn(bucket));
        }
        if (deepestElsewhere != null) {
            deepestElsewhere.accumulateAndGet(most, Math::max);
        }
        double[] covered = cells.totals();
        double[] deepest = counted.totals();
        deepest[0] = covered[0];
        deepest[1] = covered[1];
        return deepest;
    }

    /**
     * Cuts the cells of one bucket by face p (counter-clockwise, its box {@code box}), each cell
     * inside it one deeper; where not {@code counted}, only the cells no face covers yet.
     */
    private static void cut(Cells cells, int bucket, double[] p, double[] box, boolean counted) {
        double tolerance = cells.tolerance;
        int found = cells.near(bucket, box, counted);
        for (int k = 0; k < found; k++) {
            int cell = cells.found(k);
            double[] rest = cells.polygon(cell);
            double[] boxes = cells.boxes();
            int at = 4 * cell;
            int d = cells.depth(cell);
            boolean cut = false;
            boolean outside = false;
            int n = p.length / 2;
            for (int e = 0; e < n && rest != null; e++) {
                double ax = p[2 * e];
                double ay = p[2 * e + 1];
                double bx = p[2 * ((e + 1) % n)];
                double by = p[2 * ((e + 1) % n) + 1];
                double length = Math.sqrt((bx - ax) * (bx - ax) + (by - ay) * (by - ay));
                if (!(length > tolerance)) {
                    continue;
                }
                // Left of a → b is inside: n_left · x >= n_left · a, with n_left = (-dy, dx).
                double nx = -(by - ay) / length;
                double ny = (bx - ax) / length;
                double c = nx * ax + ny * ay;
                // The cell's box first, while the cell is whole: a box more than the
                // tolerance inside the edge holds a cell that is too, a box more than it
                // outside one that is outside (the same answers as its corners give).
                if (!cut) {
                    double boxLeast = nx * boxes[nx > 0 ? at : at + 2] + ny * boxes[ny > 0 ? at + 1 : at + 3] - c;
                    if (boxLeast > tolerance) {
                        continue; // inside this edge
                    }
                    double boxMost = nx * boxes[nx > 0 ? at + 2 : at] + ny * boxes[ny > 0 ? at + 3 : at + 1] - c;
                    if (boxMost < -tolerance) {
                        outside = true; // the cell outside the face, whole
                        rest = null;
                        break;
                    }
                }
                // Most cells lie wholly on one side of most edges: those are not clipped.
                double least = Double.POSITIVE_INFINITY;
                double most = Double.NEGATIVE_INFINITY;
                for (int i = 0; i < rest.length; i += 2) {
                    double side = nx * rest[i] + ny * rest[i + 1] - c;
                    // Comparisons, not Math.min and max: their care for NaN and -0 costs in this loop.
                    if (side < least) {
                        least = side;
                    }
                    if (side > most) {
                        most = side;
                    }
                }
                if (least >= -tolerance && most > tolerance) {
                    continue; // inside this edge
                }
                if (most <= tolerance && least < -tolerance) {
                    if (cut) {
                        cells.add(rest, d, bucket); // the rest outside the face, whole
                    } else {
                        outside = true; // the cell outside the face, whole
                    }
                    rest = null;
                    break;
                }
                if (!cut) {
                    cells.remove(cell);
                    cut = true;
                }
                double[] out = Polygons2.clip(rest, rest.length / 2, nx, ny, c, tolerance);
                if (out != null) {
                    cells.add(out, d, bucket);
                }
                rest = Polygons2.clip(rest, rest.length / 2, -nx, -ny, -c, tolerance);
            }
            if (!cut && !outside) {
                cells.deepen(cell); // inside the face, whole
            } else if (cut && rest != null) {
                cells.add(rest, d + 1, bucket);
            }
        }
    }

    /**
     * Whether a convex polygon is nowhere wider than {@code tolerance}: twice its area at most the
     * tolerance times its perimeter, or no edge longer than the tolerance. The second, because the
     * area of a polygon far smaller than its coordinates is rounding (a speck 1e-10 across at 0.9
     * from the origin had 7e-18, more than the first test allows), and every edge of it is too
     * short to cut a cell: each cell its box met was counted under it, a layer the torus did not have.
     */
    static boolean thinnerThan(double[] p, double tolerance) {
        int n = p.length / 2;
        boolean edgeLonger = false;
        for (int i = 0; i < n && !edgeLonger; i++) {
            int j = (i + 1) % n;
            edgeLonger = Polygons2.length(p[2 * j] - p[2 * i], p[2 * j + 1] - p[2 * i + 1]) > tolerance;
        }
        return !edgeLonger || !(Math.abs(Polygons2.twiceArea(p, n)) > tolerance * Polygons2.perimeter(p, n));
    }

    /**
     * The convex cells of an arrangement, with their depth, each in one bucket of a grid over
     * the triangle: the triangle is first cut along the grid, and a cell's parts stay in its
     * bucket, so that no cell is ever big and a face meets only the cells of the buckets it covers.
     * Kept in plain arrays: a wrap makes millions of cells, and boxed lists of them cost more
     * than the clipping.
     */
    private static final class Cells {
        private double[][] polygons = new double[64][];
        /** Per cell: min x, min y, max x, max y. */
        private double[] boxes = new double[4 * 64];
        /** Per cell: its depth, or -1 once it is cut up. */
        private int[] depths = new int[64];
        private int count;
        /** Per bucket: its cell count, then the cells (the dead ones too, skipped by near()). */
        private final int[][] buckets;
        /** Per bucket: the triangle's part in it, or null. */
        private final double[][] pieces;
        private final double minX;
        private final double minY;
        private final double cellWidth;
        private final double cellHeight;
        private final int columns;
        private final int rows;
        final double tolerance;
        private int[] found = new int[16];

        Cells(double[] triangle, int columns, int rows, double tolerance) {
            double[] box = Polygons2.bounds(triangle);
            this.columns = columns;
            this.rows = rows;
            this.minX = box[0];
            this.minY = box[1];
            this.cellWidth = Math.max(box[2] - box[0], tolerance) / columns;
            this.cellHeight = Math.max(box[3] - box[1], tolerance) / rows;
            this.tolerance = tolerance;
            this.buckets = new int[columns * rows][];
            this.pieces = new double[columns * rows][];
            for (int by = 0; by < rows; by++) {
                for (int bx = 0; bx < columns; bx++) {
                    buckets[by * columns + bx] = new int[5];
                    double[] piece = triangle.clone();
                    double x0 = minX + bx * cellWidth;
                    double y0 = minY + by * cellHeight;
                    // The grid's outer lines lie beyond the triangle, so that rounding loses none of it.
                    double left = bx == 0 ? Double.NEGATIVE_INFINITY : x0;
                    double right = bx == columns - 1 ? Double.POSITIVE_INFINITY : x0 + cellWidth;
                    double bottom = by == 0 ? Double.NEGATIVE_INFINITY : y0;
                    double top = by == rows - 1 ? Double.POSITIVE_INFINITY : y0 + cellHeight;
                    piece = clipTo(piece, -1, 0, -left);
                    piece = clipTo(piece, 1, 0, right);
                    piece = clipTo(piece, 0, -1, -bottom);
                    piece = clipTo(piece, 0, 1, top);
                    pieces[by * columns + bx] = piece;
                    if (piece != null) {
                        add(piece, 0, by * columns + bx);
                    }
                }
            }
        }

        /** Cells on the same grid over the same triangle, with no bucket opened yet ({@link #open}). */
        Cells(Cells grid) {
            this.columns = grid.columns;
            this.rows = grid.rows;
            this.minX = grid.minX;
            this.minY = grid.minY;
            this.cellWidth = grid.cellWidth;
            this.cellHeight = grid.cellHeight;
            this.tolerance = grid.tolerance;
            this.pieces = grid.pieces;
            this.buckets = new int[columns * rows][];
        }

        /** Puts the triangle's piece in the bucket as its one cell, of no depth. */
        void open(int bucket) {
            buckets[bucket] = new int[5];
            if (pieces[bucket] != null) {
                add(pieces[bucket], 0, bucket);
            }
        }

        private double[] clipTo(double[] polygon, double nx, double ny, double c) {
            if (polygon == null || Double.isInfinite(c)) {
                return polygon;
            }
            return Polygons2.clip(polygon, polygon.length / 2, nx, ny, c, tolerance);
        }

        void add(double[] polygon, int depth, int bucket) {
            if (count == depths.length) {
                int more = 2 * count;
                polygons = java.util.Arrays.copyOf(polygons, more);
                boxes = java.util.Arrays.copyOf(boxes, 4 * more);
                depths = java.util.Arrays.copyOf(depths, more);
            }
            int id = count++;
            polygons[id] = polygon;
            double x0 = Double.POSITIVE_INFINITY;
            double y0 = Double.POSITIVE_INFINITY;
            double x1 = Double.NEGATIVE_INFINITY;
            double y1 = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < polygon.length; k += 2) {
                x0 = Math.min(x0, polygon[k]);
                x1 = Math.max(x1, polygon[k]);
                y0 = Math.min(y0, polygon[k + 1]);
                y1 = Math.max(y1, polygon[k + 1]);
            }
            boxes[4 * id] = x0;
            boxes[4 * id + 1] = y0;
            boxes[4 * id + 2] = x1;
            boxes[4 * id + 3] = y1;
            depths[id] = depth;
            int[] cells = buckets[bucket];
            if (cells[0] + 1 == cells.length) {
                cells = java.util.Arrays.copyOf(cells, 2 * cells.length);
                buckets[bucket] = cells;
            }
            cells[++cells[0]] = id;
        }

        /**
         * Finds the living cells of one bucket whose box overlaps {@code box} by more than the
         * tolerance (where not {@code counted}, only those no face covers yet) and returns how
         * many: {@link #found} gives them, until the next call.
         */
        int near(int bucket, double[] box, boolean counted) {
            int n = 0;
            int[] cells = buckets[bucket];
            int kept = 0; // the dead dropped from the bucket as it is read: a cell cut up leaves it for good
            for (int k = 1; k <= cells[0]; k++) {
                int id = cells[k];
                if (depths[id] < 0) {
                    continue;
                }
                cells[++kept] = id;
                if (!counted && depths[id] > 0) {
                    continue;
                }
                if (boxes[4 * id] < box[2] - tolerance && box[0] < boxes[4 * id + 2] - tolerance
                        && boxes[4 * id + 1] < box[3] - tolerance && box[1] < boxes[4 * id + 3] - tolerance) {
                    if (n == found.length) {
                        found = java.util.Arrays.copyOf(found, 2 * n);
                    }
                    found[n++] = id;
                }
            }
            cells[0] = kept;
            return n;
        }

        /** The most faces over a living cell of the bucket. */
        int deepestIn(int bucket) {
            int most = 0;
            int[] cells = buckets[bucket];
            for (int k = 1; k <= cells[0]; k++) {
                most = Math.max(most, depths[cells[k]]);
            }
            return most;
        }

        int found(int k) {
            return found[k];
        }

        double[] polygon(int id) {
            return polygons[id];
        }

        /** The cells' bounding boxes, min x, min y, max x, max y from 4 × a cell's id (the array as it is: adding cells may replace it). */
        double[] boxes() {
            return boxes;
        }

        int depth(int id) {
            return depths[id];
        }

        void deepen(int id) {
            depths[id]++;
        }

        void remove(int id) {
            depths[id] = -1; // its bucket forgets it lazily: near() drops the dead
            polygons[id] = null;
        }

        int column(double x) {
            return Math.max(0, Math.min(columns - 1, (int) Math.floor((x - minX) / cellWidth)));
        }

        int row(double y) {
            return Math.max(0, Math.min(rows - 1, (int) Math.floor((y - minY) / cellHeight)));
        }

        /** The area, the area covered, the most depth, the centre of the largest cell of that depth, and its corners (x y each). */
        double[] totals() {
            double area = 0;
            double covered = 0;
            int most = 0;
            double largest = -1;
            double cx = Double.NaN;
            double cy = Double.NaN;
            double[] deepest = new double[0];
            for (int id = 0; id < count; id++) {
                if (depths[id] < 0) {
                    continue;
                }
                double[] cell = polygons[id];
                double a = Math.abs(Polygons2.twiceArea(cell, cell.length / 2)) / 2;
                area += a;
                if (depths[id] > 0) {
                    covered += a;
                }
                if (depths[id] > most || depths[id] == most && a > largest) {
                    most = depths[id];
                    largest = a;
                    deepest = cell;
                    // The mean of a convex cell's corners lies inside it.
                    cx = 0;
                    cy = 0;
                    for (int i = 0; i < cell.length; i += 2) {
                        cx += cell[i] / (cell.length / 2);
                        cy += cell[i + 1] / (cell.length / 2);
                    }
                }
            }
            double[] totals = java.util.Arrays.copyOf(new double[] {area, covered, most, cx, cy}, 5 + deepest.length);
            System.arraycopy(deepest, 0, totals, 5, deepest.length);
            return totals;
        }
    }
}
