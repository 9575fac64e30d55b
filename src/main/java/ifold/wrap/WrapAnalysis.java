package ifold.wrap;

import ifold.io.Workers;
import ifold.mesh.IndexedPolygons;
import ifold.sheet.FaceGrid;
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
 * @param creep the farthest a paper vertex stands back from where the paper was laid, at a concave edge of the model ({@link ConcaveWalls})
 * @param creasesInside creases lying inside the model's faces: count
 * @param creaseLengthInside and their length
 * @param creasesOnEdges creases along the model's edges: count
 * @param creaseLengthOnEdges and their length
 * @param deepest where the layers are most, and where they come from; null without paper
 */
public record WrapAnalysis(int maxLayers, int stackLevels, double coverage, double surfaceArea, double paperArea,
        double outsidePaper, double farthest, double isometryError, double creep, int creasesInside, double creaseLengthInside,
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
        for (Wrap.Strip strip : result.strips()) {
            // Every stack's levels found here, on this thread, before any worker reads them:
            // the sheet keeps them once found, and placing the paper reads them too.
            int[] levels = strip.sheet().levels();
            // Host by host (the strip's faces rest on hosts), triangle by triangle of each: a
            // host's arrangement of faces, passes of many triangles crossing, would cost far more.
            Map<Integer, List<Integer>> trianglesOn = new java.util.LinkedHashMap<>();
            for (int triangle = strip.firstTriangle(); triangle < strip.firstTriangle() + strip.triangles(); triangle++) {
                trianglesOn.computeIfAbsent(result.hostOf()[triangle], h -> new ArrayList<>()).add(triangle);
            }
            // Hosts one by one on the workers' threads (their arrangements are independent), the
            // figures then taken in order: the same as one by one on one thread.
            List<Future<HostCells>> hosts = new ArrayList<>();
            for (Map.Entry<Integer, List<Integer>> entry : trianglesOn.entrySet()) {
                int host = entry.getKey();
                List<Integer> triangles = entry.getValue();
                hosts.add(Workers.pool().submit(() -> hostCells(result, strip, levels, host, triangles)));
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
            try {
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
                    // Creases: along an edge of the model when they lie on one.
                    for (int f = 0; f < sheet.faceCount(); f++) {
                        int[] loop = sheet.loop(f);
                        for (int i = 0; i < loop.length; i++) {
                            int a = loop[i];
                            int b = loop[(i + 1) % loop.length];
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
            } finally {
                cancel(); // none left running where one failed
            }
            double isometry = 0;
            double creep = 0;
            for (PaperInSpace geometry : geometries) {
                isometry = Math.max(isometry, isometryError(geometry, result.width()));
                creep = Math.max(creep, geometry.creep().most(geometry));
            }
            Deepest deepest = deepestStrip < 0 ? null
                    : deepest(result.strips().get(deepestStrip).sheet(), deepestStrip, deepestTriangle, deepestPoint, deepestCell,
                            result.hostOf()[deepestTriangle], frames[result.hostOf()[deepestTriangle]]);
            return new WrapAnalysis(maxLayers, stackLevels, surface > 0 ? covered / surface : 0, surface, paper, outside, farthest,
                    isometry, creep, inside, insideLength, onEdges, onEdgesLength, deepest);
        }
    }

    /**
     * One host's figures: how far its paper goes beyond it and above it, and for each of its
     * {@code triangles} {area, area covered, most layers, x and y of a point there in the host's
     * frame}.
     */
    private record HostCells(double outside, double farthest, double[][] triangles) {
    }

    private static HostCells hostCells(Wrap.Result result, Wrap.Strip strip, int[] levels, int host, List<Integer> triangles) {
        Sheet sheet = strip.sheet();
        HostFrame frame = result.frames()[host];
        double[] c = frame.corners();
        int[] faces = sheet.facesOn(host);
        double[][] placed = new double[faces.length][];
        double[][] boxes = new double[faces.length][];
        double outside = 0;
        double farthest = 0;
        // A host of many triangles holds their faces all: each triangle looks only at
        // those of the grid's cells it meets.
        for (int i = 0; i < faces.length; i++) {
            double[] xy = sheet.placed(faces[i]);
            placed[i] = xy;
            boxes[i] = Polygons2.bounds(xy);
            outside = Math.max(outside, beyond(c, xy));
            farthest = Math.max(farthest, (levels[faces[i]] + 1) * sheet.thickness());
        }
        FaceGrid grid = null;
        if (triangles.size() > 1) {
            grid = new FaceGrid(FaceGrid.cellFor(placed, faces.length, 2 * sheet.width()));
            for (int i = 0; i < faces.length; i++) {
                grid.add(i, placed[i]);
            }
        }
        double[][] figures = new double[triangles.size()][];
        for (int t = 0; t < triangles.size(); t++) {
            int triangle = triangles.get(t);
            double[] corners = cornersIn(result.mesh(), triangle, frame);
            double[] box = Polygons2.bounds(corners);
            // Turned so that the triangle's passes run along x, as they run along its
            // exit edge: their boxes are then thin, and each meets only the cells near it.
            // Each face clipped to the triangle first: only its part there makes cells.
            // The faces in their order, whichever way they were found: the cells, and so
            // the deepest point reported, do not depend on the grid.
            double[] along = passDirection(result.mesh(), strip, triangle, frame);
            int[] near = grid == null ? null : grid.near(corners); // null: look at all
            List<double[]> polygons = new ArrayList<>();
            for (int m = 0; m < (near == null ? faces.length : near.length); m++) {
                int i = near == null ? m : near[m];
                double[] b = boxes[i];
                if (!(b[0] < box[2] && box[0] < b[2] && b[1] < box[3] && box[1] < b[3])) {
                    continue;
                }
                double[] part = clipToTriangle(counterClockwise(placed[i]), corners, sheet.tolerance());
                if (part != null) {
                    polygons.add(turned(part, along));
                }
            }
            double[] cells = FaceArrangement.depths(counterClockwise(turned(corners, along)), polygons, sheet.tolerance());
            // The point and the deepest cell's corners back in the host's frame.
            figures[t] = new double[cells.length];
            System.arraycopy(cells, 0, figures[t], 0, 3);
            for (int k = 3; k + 1 < cells.length; k += 2) {
                figures[t][k] = along[0] * cells[k] - along[1] * cells[k + 1];
                figures[t][k + 1] = along[1] * cells[k] + along[0] * cells[k + 1];
            }
        }
        return new HostCells(outside, farthest, figures);
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
     * The unit direction, in the host's frame, of the edge path triangle t leaves by (shared with
     * the next triangle of its strip; for the last, with the one before): its passes run along it.
     */
    private static double[] passDirection(IndexedPolygons mesh, Wrap.Strip strip, int t, HostFrame frame) {
        int other = t + 1 < strip.firstTriangle() + strip.triangles() ? t + 1 : t - 1;
        int[] shared = new int[2];
        int n = 0;
        for (int a = 0; a < 3 && other >= strip.firstTriangle(); a++) {
            for (int b = 0; b < 3; b++) {
                if (mesh.faceVertex(t, a) == mesh.faceVertex(other, b) && n < 2) {
                    shared[n++] = mesh.faceVertex(t, a);
                }
            }
        }
        if (n < 2) {
            shared = new int[] {mesh.faceVertex(t, 0), mesh.faceVertex(t, 1)};
        }
        double[] p = {mesh.coordinate(shared[0], 0), mesh.coordinate(shared[0], 1), mesh.coordinate(shared[0], 2)};
        double[] q = {mesh.coordinate(shared[1], 0), mesh.coordinate(shared[1], 1), mesh.coordinate(shared[1], 2)};
        double dx = frame.localX(q) - frame.localX(p);
        double dy = frame.localY(q) - frame.localY(p);
        double length = Math.hypot(dx, dy);
        return length > 0 ? new double[] {dx / length, dy / length} : new double[] {1, 0};
    }

    /** The part of convex polygon xy inside triangle c (both counter-clockwise), or null. */
    private static double[] clipToTriangle(double[] xy, double[] c, double tolerance) {
        double[] inside = xy;
        for (int e = 0; e < 3 && inside != null; e++) {
            double ax = c[2 * e];
            double ay = c[2 * e + 1];
            double dx = c[2 * ((e + 1) % 3)] - ax;
            double dy = c[2 * ((e + 1) % 3) + 1] - ay;
            // Inside is left of each edge: dy·x - dx·y <= dy·ax - dx·ay.
            inside = Polygons2.clip(inside, inside.length / 2, dy, -dx, dy * ax - dx * ay, 0);
        }
        return inside;
    }

    /** A polygon turned by the rotation that takes {@code along} to the x axis. */
    private static double[] turned(double[] xy, double[] along) {
        double[] out = new double[xy.length];
        for (int k = 0; k < xy.length; k += 2) {
            out[k] = along[0] * xy[k] + along[1] * xy[k + 1];
            out[k + 1] = -along[1] * xy[k] + along[0] * xy[k + 1];
        }
        return out;
    }

    /** Triangle t of the mesh in a host's frame, x0 y0 x1 y1 x2 y2, counter-clockwise. */
    private static double[] cornersIn(IndexedPolygons mesh, int t, HostFrame frame) {
        double[] xy = new double[6];
        for (int k = 0; k < 3; k++) {
            int v = mesh.faceVertex(t, k);
            double[] p = {mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2)};
            xy[2 * k] = frame.localX(p);
            xy[2 * k + 1] = frame.localY(p);
        }
        return counterClockwise(xy);
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

    /** How far the polygon reaches beyond the triangle (corners counter-clockwise), 0 if not at all. */
    private static double beyond(double[] c, double[] xy) {
        double worst = 0;
        int n = c.length / 2;
        for (int e = 0; e < n; e++) {
            double ax = c[2 * e];
            double ay = c[2 * e + 1];
            double dx = c[2 * ((e + 1) % n)] - ax;
            double dy = c[2 * ((e + 1) % n) + 1] - ay;
            double length = Math.hypot(dx, dy);
            for (int k = 0; k < xy.length; k += 2) {
                worst = Math.max(worst, ((xy[k] - ax) * dy - (xy[k + 1] - ay) * dx) / length);
            }
        }
        return worst;
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
        double worst = 0;
        // The paper as laid, before its creases creep at concave edges (a creep is measured on its
        // own): a crept vertex is taken where it was, looked up among the few that crept.
        PaperInSpace.Creep creep = geometry.creep();
        double[] uv = geometry.uv();
        double[] pa = new double[3];
        double[] pb = new double[3];
        for (int[] face : geometry.paperFaces()) {
            double size = width;
            for (int i = 0; i < face.length; i++) {
                for (int j = i + 1; j < face.length; j++) {
                    size = Math.max(size, Math.hypot(uv[2 * face[i]] - uv[2 * face[j]], uv[2 * face[i] + 1] - uv[2 * face[j] + 1]));
                }
            }
            for (int i = 0; i < face.length; i++) {
                for (int j = i + 1; j < face.length; j++) {
                    int a = face[i];
                    int b = face[j];
                    creep.laid(geometry, a, pa);
                    creep.laid(geometry, b, pb);
                    double space = Math.sqrt(Math.pow(pa[0] - pb[0], 2) + Math.pow(pa[1] - pb[1], 2) + Math.pow(pa[2] - pb[2], 2));
                    double sheet = Math.hypot(uv[2 * a] - uv[2 * b], uv[2 * a + 1] - uv[2 * b + 1]);
                    worst = Math.max(worst, Math.abs(space - sheet) / size);
                }
            }
        }
        return worst;
    }
}
