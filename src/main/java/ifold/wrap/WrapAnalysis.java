package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.io.Workers;
import ifold.sheet.HostFrame;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Future;

/**
 * The measures of a wrap, taken from the folded sheets: layers counted exactly (the arrangement
 * of the faces on each triangle, cut into cells), coverage as the area of the surface under
 * paper, how far paper stands off the surface, how far any face strays from its paper shape,
 * and the seed's measures of nice origami (paper area, creases inside the model's faces rather
 * than along its edges, the most layers).
 *
 * @param maxLayers the most layers of paper over any point of the surface
 * @param stackLevels the levels in the deepest stack (its top level + 1): at least maxLayers
 * @param coverage the fraction of the surface's area under paper
 * @param surfaceArea the area of the surface
 * @param paperArea the area of all strips, Σ L·w
 * @param outsidePaper the largest distance of any paper vertex beyond the triangle it rests on
 * @param farthest the largest height of any paper above the surface
 * @param isometryError the largest difference between a face's distances in space and on the sheet, relative to its size (or the strip width),
 *     the paper as laid, before its creases creep at concave edges
 * @param stretch the largest difference between a face's distances in space and on the sheet
 *     over what rounding allows there: {@link Tolerance#RELATIVE_EQUALITY} of the face's size (as
 *     for {@code isometryError}), or, far along a long strip, the drift of the poses composed fold
 *     after fold ({@link Sheet#POSE_DRIFT} of u), the distance within which the sheet itself takes
 *     two points as one; over 1, the paper came out stretched
 * @param creep the farthest a paper vertex stands back from where the paper was laid, at a concave edge of the model ({@link ConcaveWalls})
 * @param creasesInside creases lying inside the model's faces: count
 * @param creaseLengthInside and their length
 * @param creasesOnEdges creases along the model's edges: count
 * @param creaseLengthOnEdges and their length
 * @param deepest where the layers are most, and where they come from; null without paper
 */
public record WrapAnalysis(int maxLayers, int stackLevels, double coverage, double surfaceArea, double paperArea,
        double outsidePaper, double farthest, double isometryError, double stretch, double creep, int creasesInside, double creaseLengthInside,
        int creasesOnEdges, double creaseLengthOnEdges, Deepest deepest) {

    /**
     * The layers over the point of the surface where they are most, by where each came from: a
     * face that a tuck moved is a tuck's (a flap cut off and folded under); any other is the
     * paper of the fold of the tail it was laid after: a pass (after a zig-zag turn, or the
     * strip's start), a turn gadget's, or a strip come over an edge (up to its first fold on
     * the triangle).
     *
     * @param strip the strip (from 0)
     * @param triangle the path triangle (from 0)
     * @param point the point, in space on the surface
     */
    public record Deepest(int strip, int triangle, double[] point, int layers, int passes, int turnGadgets, int edgeCrossings,
            int tucks) {
    }

    /** The measures of {@code result}, whose strips' paper is placed in space as {@code geometries}. */
    public static WrapAnalysis of(Wrap.Result result, List<PaperInSpace> geometries) {
        return start(result).finish(geometries);
    }

    /**
     * The measures of a wrap begun: each host's arrangement of faces on the workers' threads,
     * while the caller places the paper in space ({@link PlacedWrap}), which needs none of them.
     */
    static Started start(Wrap.Result result) {
        List<List<Future<HostCells>>> pending = new ArrayList<>();
        List<Map<Integer, List<Integer>>> hostsOfStrips = new ArrayList<>();
        java.util.concurrent.atomic.AtomicInteger deepestSoFar = new java.util.concurrent.atomic.AtomicInteger();
        for (Wrap.Strip strip : result.strips()) {
            // Every stack's levels found here, on this thread, before any worker reads them:
            // the sheet keeps them once found, and placing the paper reads them too.
            strip.sheet().levels();
            // Host by host (the strip's faces rest on hosts), triangle by triangle of each: a
            // host's arrangement of faces, passes of many triangles crossing, would cost far more.
            Map<Integer, List<Integer>> trianglesOn = new java.util.LinkedHashMap<>();
            for (int triangle = strip.firstTriangle(); triangle < strip.firstTriangle() + strip.triangles(); triangle++) {
                trianglesOn.computeIfAbsent(result.hostOf()[triangle], h -> new ArrayList<>()).add(triangle);
            }
            // Hosts one by one on the workers' threads (their arrangements are independent), the
            // figures then taken in order: the same as one by one on one thread. (Begun on the
            // other core as the strip left each host, they slowed the folding as much as they
            // saved after it: the 5,000-triangle torus folded in 20 s rather than 16, and was
            // measured in 15 rather than 19.)
            HostCells.Context context = HostCells.Context.of(result.mesh(), result.frames(), strip.firstTriangle(), strip.triangles(),
                    strip.sheet(), deepestSoFar);
            // The hosts of the tallest stacks first: the most layers found on them early, the
            // triangles of lower stacks are only covered, not counted (HostCells.Context). The
            // figures do not depend on the order.
            List<Map.Entry<Integer, List<Integer>>> entries = new ArrayList<>(trianglesOn.entrySet());
            Integer[] tallestFirst = new Integer[entries.size()];
            int[] levels = new int[entries.size()];
            for (int i = 0; i < tallestFirst.length; i++) {
                tallestFirst[i] = i;
                levels[i] = strip.sheet().topLevel(entries.get(i).getKey());
            }
            java.util.Arrays.sort(tallestFirst, (a, b) -> Integer.compare(levels[b], levels[a]));
            List<Future<HostCells>> hosts = new ArrayList<>(java.util.Collections.nCopies(entries.size(), null));
            for (int i : tallestFirst) {
                int host = entries.get(i).getKey();
                List<Integer> triangles = entries.get(i).getValue();
                hosts.set(i, Workers.pool().submit(() -> HostCells.of(context, host, HostCells.Paper.of(strip.sheet(), host), triangles)));
            }
            pending.add(hosts);
            hostsOfStrips.add(trianglesOn);
        }
        return new Started(result, pending, hostsOfStrips);
    }

    /** A wrap's measures being taken: {@link #finish} waits for them. */
    static final class Started {
        private final Wrap.Result result;
        private final List<List<Future<HostCells>>> pending;
        private final List<Map<Integer, List<Integer>>> hostsOfStrips;

        private Started(Wrap.Result result, List<List<Future<HostCells>>> pending, List<Map<Integer, List<Integer>>> hostsOfStrips) {
            this.result = result;
            this.pending = pending;
            this.hostsOfStrips = hostsOfStrips;
        }

        /** Stops the hosts' arrangements not yet begun (the caller failed or was stopped). */
        void cancel() {
            for (List<Future<HostCells>> hosts : pending) {
                for (Future<HostCells> host : hosts) {
                    host.cancel(false);
                }
            }
        }

        /** The measures, once every host's are taken, with the isometry of the paper as {@code geometries} place it. */
        WrapAnalysis finish(List<PaperInSpace> geometries) {
            HostFrame[] frames = result.frames();
            int maxLayers = 0;
            int stackLevels = 0;
            double covered = 0;
            double surface = 0;
            double paper = 0;
            double outside = 0;
            double farthest = 0;
            int inside = 0;
            double insideLength = 0;
            int onEdges = 0;
            double onEdgesLength = 0;
            // Where the layers are most: strip, triangle, and a point inside the deepest cell.
            int deepestStrip = -1;
            int deepestTriangle = -1;
            double[] deepestPoint = null;
            double[] deepestCell = null;
            List<Future<double[]>> isometryParts = new ArrayList<>();
            double isometry = 0;
            double stretch = 0;
            double creep = 0;
            try {
                // The creases first, from the sheets alone, while the workers finish the hosts'
                // arrangements; the paper's isometry in parts on the workers after them, one part here.
                for (Wrap.Strip strip : result.strips()) {
                    Sheet sheet = strip.sheet();
                    for (int f = 0; f < sheet.faceCount(); f++) {
                        int n = sheet.loopLength(f); // read in place: a copy a face was a million arrays
                        for (int i = 0; i < n; i++) {
                            int a = sheet.loopVertex(f, i);
                            int b = sheet.loopVertex(f, (i + 1) % n);
                            if (a > b && sheet.faceAcross(a, b) >= 0) {
                                continue; // each crease once, from the face holding its lower-to-higher side
                            }
                            if (sheet.crease(a, b) == null) {
                                continue;
                            }
                            double length = Math.hypot(sheet.u(b) - sheet.u(a), sheet.v(b) - sheet.v(a));
                            if (onModelEdge(sheet, f, a, b, frames)) {
                                onEdges++;
                                onEdgesLength += length;
                            } else {
                                inside++;
                                insideLength += length;
                            }
                        }
                    }
                }
                int parts = Workers.threads() + 1;
                for (PaperInSpace geometry : geometries) {
                    int faces = geometry.paperFaces().size();
                    for (int part = 1; part < parts; part++) {
                        int from = (int) ((long) faces * part / parts);
                        int to = (int) ((long) faces * (part + 1) / parts);
                        isometryParts.add(Workers.pool().submit(() -> isometryErrors(geometry, result.width(), from, to)));
                    }
                }
                for (int k = 0; k < result.strips().size(); k++) {
                    Sheet sheet = result.strips().get(k).sheet();
                    paper += sheet.length() * sheet.width();
                    stackLevels = Math.max(stackLevels, sheet.stackLevels());
                    int p = 0;
                    for (Map.Entry<Integer, List<Integer>> entry : hostsOfStrips.get(k).entrySet()) {
                        HostCells cells = Workers.result(pending.get(k).get(p++));
                        outside = Math.max(outside, cells.outside());
                        farthest = Math.max(farthest, cells.farthest());
                        List<Integer> triangles = entry.getValue();
                        for (int i = 0; i < triangles.size(); i++) {
                            double[] figures = cells.triangles()[i];
                            surface += figures[0];
                            covered += figures[1];
                            if ((int) figures[2] > maxLayers) {
                                deepestStrip = k;
                                deepestTriangle = triangles.get(i);
                                deepestPoint = new double[] {figures[3], figures[4]};
                                deepestCell = java.util.Arrays.copyOfRange(figures, 5, figures.length);
                            }
                            maxLayers = Math.max(maxLayers, (int) figures[2]);
                        }
                    }
                }
                for (PaperInSpace geometry : geometries) {
                    int faces = geometry.paperFaces().size();
                    double[] errors = isometryErrors(geometry, result.width(), 0, (int) ((long) faces / parts));
                    isometry = Math.max(isometry, errors[0]);
                    stretch = Math.max(stretch, errors[1]);
                    creep = Math.max(creep, geometry.creep().most(geometry));
                }
                for (Future<double[]> part : isometryParts) {
                    double[] errors = Workers.result(part);
                    isometry = Math.max(isometry, errors[0]);
                    stretch = Math.max(stretch, errors[1]);
                }
            } finally {
                cancel(); // none left running where one failed
                for (Future<double[]> part : isometryParts) {
                    part.cancel(false);
                }
            }
            Deepest deepest = deepestStrip < 0 ? null
                    : deepest(result.strips().get(deepestStrip).sheet(), deepestStrip, deepestTriangle, deepestPoint, deepestCell,
                            result.hostOf()[deepestTriangle], frames[result.hostOf()[deepestTriangle]]);
            return new WrapAnalysis(maxLayers, stackLevels, surface > 0 ? covered / surface : 0, surface, paper, outside, farthest,
                    isometry, stretch, creep, inside, insideLength, onEdges, onEdgesLength, deepest);
        }
    }

    /**
     * Whether a convex counter-clockwise face holds a cell of the arrangement as {@link
     * FaceArrangement} decides it: a face it does not leave out as too thin, every corner of the
     * cell within {@code tolerance} inside each edge of the face longer than that.
     */
    private static boolean holds(double[] face, double[] cell, double tolerance) {
        if (FaceArrangement.thinnerThan(face, tolerance)) {
            return false; // the arrangement leaves it out: it covers nothing
        }
        int n = face.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double dx = face[2 * j] - face[2 * i];
            double dy = face[2 * j + 1] - face[2 * i + 1];
            double length = Math.sqrt(dx * dx + dy * dy);
            if (!(length > tolerance)) {
                continue;
            }
            for (int k = 0; k + 1 < cell.length; k += 2) {
                if ((dx * (cell[k + 1] - face[2 * i + 1]) - dy * (cell[k] - face[2 * i])) / length < -tolerance) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * The faces of a sheet over the deepest cell of one triangle's arrangement (its corners x y
     * each, its centre xy), counted by where they came from: the faces that hold the cell as the
     * arrangement decided, every corner within the tolerance inside each of their edges (the
     * centre alone, strictly inside, missed a face along whose edge a thin deepest cell lay).
     */
    private static Deepest deepest(Sheet sheet, int strip, int triangle, double[] xy, double[] cell, int host, HostFrame frame) {
        int layers = 0;
        int passes = 0;
        int gadgets = 0;
        int crossings = 0;
        int tucks = 0;
        for (int f : sheet.facesOn(host)) {
            if (!holds(counterClockwise(sheet.placed(f)), cell, sheet.tolerance())) {
                continue;
            }
            layers++;
            Sheet.Crease after = sheet.laidAfter(f);
            if (sheet.tucked(f)) {
                tucks++;
            } else if (after == Sheet.Crease.GADGET) {
                gadgets++;
            } else if (after == Sheet.Crease.CROSSING) {
                crossings++;
            } else {
                passes++;
            }
        }
        double[] point = new double[3];
        frame.toSpace(xy[0], xy[1], 0, point, 0);
        return new Deepest(strip, triangle, point, layers, passes, gadgets, crossings, tucks);
    }

    /**
     * The most layers of paper over any point of any of the first {@code hosts} hosts of a
     * sheet, counted exactly on the arrangement of each host's faces (for paper that rests on
     * planes rather than on triangles: the faces are cut into cells inside a triangle around
     * them all).
     */
    public static int maxLayers(Sheet sheet, int hosts) {
        int most = 0;
        for (int h = 0; h < hosts; h++) {
            int[] faces = sheet.facesOn(h);
            if (faces.length == 0) {
                continue;
            }
            List<double[]> polygons = new ArrayList<>();
            double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int f : faces) {
                double[] xy = sheet.placed(f);
                polygons.add(xy);
                double[] b = Polygons2.bounds(xy);
                box[0] = Math.min(box[0], b[0]);
                box[1] = Math.min(box[1], b[1]);
                box[2] = Math.max(box[2], b[2]);
                box[3] = Math.max(box[3], b[3]);
            }
            double margin = Math.max(box[2] - box[0], box[3] - box[1]) * 0.1 + sheet.width();
            double x0 = box[0] - margin;
            double y0 = box[1] - margin;
            double legX = 2 * (box[2] - box[0] + 2 * margin);
            double legY = 2 * (box[3] - box[1] + 2 * margin);
            double[] around = {x0, y0, x0 + legX, y0, x0, y0 + legY};
            most = Math.max(most, (int) FaceArrangement.depths(around, polygons, sheet.tolerance())[2]);
        }
        return most;
    }

    /**
     * The area of paper whose shadow on its host falls outside it: each face less its part
     * inside the host's polygon. After the tucks, nothing (up to rounding).
     */
    public static double outsideArea(Wrap.Result result) {
        double outside = 0;
        for (Wrap.Strip strip : result.strips()) {
            Sheet sheet = strip.sheet();
            for (int f = 0; f < sheet.faceCount(); f++) {
                double[] c = result.frames()[sheet.host(f)].corners();
                double[] xy = sheet.placed(f);
                double whole = Math.abs(Polygons2.twiceArea(xy, xy.length / 2)) / 2;
                double[] inside = xy;
                int n = c.length / 2;
                for (int e = 0; e < n && inside != null; e++) {
                    double ax = c[2 * e];
                    double ay = c[2 * e + 1];
                    double dx = c[2 * ((e + 1) % n)] - ax;
                    double dy = c[2 * ((e + 1) % n) + 1] - ay;
                    // Inside is left of each edge: dy·x - dx·y <= dy·ax - dx·ay.
                    inside = Polygons2.clip(inside, inside.length / 2, dy, -dx, dy * ax - dx * ay, 0);
                }
                double kept = inside == null ? 0 : Math.abs(Polygons2.twiceArea(inside, inside.length / 2)) / 2;
                outside += Math.max(0, whole - kept);
            }
        }
        return outside;
    }

    /**
     * Whether crease (a, b) of face f lies along an edge of the model: a side of its host, the
     * convex piece of the model's plane it rests on (the refinement's spokes lie inside).
     */
    private static boolean onModelEdge(Sheet sheet, int f, int a, int b, HostFrame[] frames) {
        double[] c = frames[sheet.host(f)].corners();
        int n = c.length / 2;
        for (int e = 0; e < n; e++) {
            int next = (e + 1) % n;
            if (onLine(sheet, f, a, b, c[2 * e], c[2 * e + 1], c[2 * next], c[2 * next + 1])) {
                return true;
            }
        }
        return false;
    }

    /** Whether paper vertices a and b of face f lie on the line through (fx, fy) and (tx, ty) of its triangle's frame. */
    private static boolean onLine(Sheet sheet, int f, int a, int b, double fx, double fy, double tx, double ty) {
        double dx = tx - fx;
        double dy = ty - fy;
        double length = Math.hypot(dx, dy);
        var pose = sheet.pose(f);
        for (int p : new int[] {a, b}) {
            double x = pose.x(sheet.u(p), sheet.v(p)) - fx;
            double y = pose.y(sheet.u(p), sheet.v(p)) - fy;
            if (Math.abs(x * dy - y * dx) / length > 10 * sheet.tolerance()) {
                return false;
            }
        }
        return true;
    }

    static double[] counterClockwise(double[] polygon) {
        int n = polygon.length / 2;
        if (Polygons2.twiceArea(polygon, n) >= 0) {
            return polygon;
        }
        double[] reversed = new double[polygon.length];
        for (int i = 0; i < n; i++) {
            reversed[2 * i] = polygon[2 * (n - 1 - i)];
            reversed[2 * i + 1] = polygon[2 * (n - 1 - i) + 1];
        }
        return reversed;
    }

    /**
     * The largest difference between a paper face's distances in space and on the sheet,
     * relative to the face's size, or to the strip's width for faces smaller than it, the paper
     * as laid (before its creases creep at concave edges, {@link PaperInSpace.Creep}): a paper
     * coordinate u on a strip of length L is a double good to about 1e-16 L, so a sliver far
     * along a long strip cannot be exact to 1e-9 of its own size.
     */
    public static double isometryError(PaperInSpace geometry, double width) {
        return isometryErrors(geometry, width, 0, geometry.paperFaces().size())[0];
    }

    /**
     * Over paper faces {@code from} to {@code to} - 1: the {@link #isometryError(PaperInSpace,
     * double)} and the {@code stretch} (see the record): the most of parts is the whole's, to the
     * bit, whatever the parts.
     *
     * <p>Why the stretch allows for u: each fold composes the tail's pose once more, and the
     * rounding of the poses grows with u ({@link Sheet#toleranceAt}). A scan's strip is narrow
     * and long: the 5,558-triangle elephant of CGAL at width 0.00106, 1.1 million faces on, had
     * slivers 2e-6 long at u = 75 to 787 whose corners, placed by poses of neighbouring faces,
     * were 1e-12 to 1.3e-11 off: 1.2e-8 of the width, refused as stretched after 98 s, where the
     * sheet takes points 7.9e-10 apart there as one.
     */
    static double[] isometryErrors(PaperInSpace geometry, double width, int from, int to) {
        double worst = 0;
        double stretch = 0;
        // The paper as laid, before its creases creep at concave edges (a creep is measured on its
        // own): a crept vertex is taken where it was, looked up among the few that crept, once
        // for each corner of a face, and each distance on the sheet found once for each pair.
        PaperInSpace.Creep creep = geometry.creep();
        double[] uv = geometry.uv();
        double[] laid = new double[3 * 8];
        double[] onSheet = new double[8 * 8];
        double[] point = new double[3];
        List<int[]> faces = geometry.paperFaces();
        for (int k = from; k < to; k++) {
            int[] face = faces.get(k);
            int n = face.length;
            if (laid.length < 3 * n) {
                laid = new double[3 * n];
                onSheet = new double[n * n];
            }
            double farthest = 0;
            for (int i = 0; i < n; i++) {
                creep.laid(geometry, face[i], point);
                System.arraycopy(point, 0, laid, 3 * i, 3);
                farthest = Math.max(farthest, Math.abs(uv[2 * face[i]]));
            }
            double size = width;
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    double sheet = Math.hypot(uv[2 * face[i]] - uv[2 * face[j]], uv[2 * face[i] + 1] - uv[2 * face[j] + 1]);
                    onSheet[n * i + j] = sheet;
                    size = Math.max(size, sheet);
                }
            }
            double allowed = Math.max(Tolerance.RELATIVE_EQUALITY * size, Sheet.POSE_DRIFT * farthest);
            for (int i = 0; i < n; i++) {
                for (int j = i + 1; j < n; j++) {
                    double space = Math.sqrt(Math.pow(laid[3 * i] - laid[3 * j], 2) + Math.pow(laid[3 * i + 1] - laid[3 * j + 1], 2)
                            + Math.pow(laid[3 * i + 2] - laid[3 * j + 2], 2));
                    double difference = Math.abs(space - onSheet[n * i + j]);
                    worst = Math.max(worst, difference / size);
                    stretch = Math.max(stretch, difference / allowed);
                }
            }
        }
        return new double[] {worst, stretch};
    }
}
