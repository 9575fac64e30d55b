package ifold.wrap;

import ifold.mesh.HalfedgeMesh;
import ifold.refine.RefinedMesh;
import ifold.sheet.HostFrame;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import java.util.ArrayList;
import java.util.List;

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
 * @param isometryError the largest difference between a face's distances in space and on the sheet, relative to its size (or the strip width)
 * @param creasesInside creases lying inside the model's faces: count
 * @param creaseLengthInside and their length
 * @param creasesOnEdges creases along the model's edges: count
 * @param creaseLengthOnEdges and their length
 */
public record WrapAnalysis(int maxLayers, int stackLevels, double coverage, double surfaceArea, double paperArea,
        double outsidePaper, double farthest, double isometryError, int creasesInside, double creaseLengthInside,
        int creasesOnEdges, double creaseLengthOnEdges) {

    public static WrapAnalysis of(Wrap.Result result, List<WrapGeometry> geometries) {
        RefinedMesh mesh = result.mesh();
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
        for (Wrap.Strip strip : result.strips()) {
            Sheet sheet = strip.sheet();
            paper += sheet.length() * sheet.width();
            stackLevels = Math.max(stackLevels, sheet.stackLevels());
            int[] levels = sheet.levels();
            for (int t = strip.firstTriangle(); t < strip.firstTriangle() + strip.triangles(); t++) {
                double[] c = frames[t].corners();
                int[] faces = sheet.facesOn(t);
                List<double[]> polygons = new ArrayList<>();
                for (int f : faces) {
                    double[] xy = sheet.placed(f);
                    polygons.add(xy);
                    outside = Math.max(outside, beyond(c, xy));
                    farthest = Math.max(farthest, (levels[f] + 1) * sheet.thickness());
                }
                double[] cells = depths(c, polygons, sheet.tolerance());
                surface += cells[0];
                covered += cells[1];
                maxLayers = Math.max(maxLayers, (int) cells[2]);
            }
            // Creases: along an edge of the model when they lie on the original edge the triangle stands on.
            HalfedgeMesh original = mesh.original();
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
                    if (onOriginalEdge(sheet, f, a, b, original, mesh, frames)) {
                        onEdges++;
                        onEdgesLength += length;
                    } else {
                        inside++;
                        insideLength += length;
                    }
                }
            }
        }
        double isometry = 0;
        for (WrapGeometry geometry : geometries) {
            isometry = Math.max(isometry, isometryError(geometry, result.width()));
        }
        return new WrapAnalysis(maxLayers, stackLevels, surface > 0 ? covered / surface : 0, surface, paper, outside, farthest,
                isometry, inside, insideLength, onEdges, onEdgesLength);
    }

    private static boolean onOriginalEdge(Sheet sheet, int f, int a, int b, HalfedgeMesh original, RefinedMesh mesh,
            HostFrame[] frames) {
        int h = mesh.parentHalfedge(sheet.host(f));
        HostFrame frame = frames[sheet.host(f)];
        double[] from = point(original, original.fromVertex(h));
        double[] to = point(original, original.toVertex(h));
        double fx = frame.localX(from);
        double fy = frame.localY(from);
        double dx = frame.localX(to) - fx;
        double dy = frame.localY(to) - fy;
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

    private static double[] point(HalfedgeMesh mesh, int v) {
        return new double[] {mesh.x(v), mesh.y(v), mesh.z(v)};
    }

    /** How far the polygon reaches beyond the triangle (corners counter-clockwise), 0 if not at all. */
    private static double beyond(double[] c, double[] xy) {
        double worst = 0;
        for (int e = 0; e < 3; e++) {
            double ax = c[2 * e];
            double ay = c[2 * e + 1];
            double dx = c[2 * ((e + 1) % 3)] - ax;
            double dy = c[2 * ((e + 1) % 3) + 1] - ay;
            double length = Math.hypot(dx, dy);
            for (int k = 0; k < xy.length; k += 2) {
                worst = Math.max(worst, ((xy[k] - ax) * dy - (xy[k + 1] - ay) * dx) / length);
            }
        }
        return worst;
    }

    /**
     * Cuts the triangle into the cells of the faces' arrangement: {area, area under at least one
     * face, the most faces over any cell}. Every cell is convex: splitting a cell by a face
     * gives the part inside the face and, edge by edge, the parts outside it.
     */
    static double[] depths(double[] triangle, List<double[]> polygons, double tolerance) {
        List<double[]> cells = new ArrayList<>();
        List<Integer> depth = new ArrayList<>();
        cells.add(triangle.clone());
        depth.add(0);
        for (double[] polygon : polygons) {
            double[] p = counterClockwise(polygon);
            double[] box = Polygons2.bounds(p);
            List<double[]> nextCells = new ArrayList<>();
            List<Integer> nextDepth = new ArrayList<>();
            for (int i = 0; i < cells.size(); i++) {
                double[] cell = cells.get(i);
                int d = depth.get(i);
                double[] cellBox = Polygons2.bounds(cell);
                if (cellBox[0] >= box[2] - tolerance || box[0] >= cellBox[2] - tolerance
                        || cellBox[1] >= box[3] - tolerance || box[1] >= cellBox[3] - tolerance) {
                    nextCells.add(cell);
                    nextDepth.add(d);
                    continue;
                }
                double[] rest = cell;
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
                    double[] out = Polygons2.clip(rest, rest.length / 2, nx, ny, c, tolerance);
                    if (out != null) {
                        nextCells.add(out);
                        nextDepth.add(d);
                    }
                    rest = Polygons2.clip(rest, rest.length / 2, -nx, -ny, -c, tolerance);
                }
                if (rest != null) {
                    nextCells.add(rest);
                    nextDepth.add(d + 1);
                }
            }
            cells = nextCells;
            depth = nextDepth;
        }
        double area = 0;
        double covered = 0;
        int most = 0;
        for (int i = 0; i < cells.size(); i++) {
            double[] cell = cells.get(i);
            double a = Math.abs(Polygons2.twiceArea(cell, cell.length / 2)) / 2;
            area += a;
            if (depth.get(i) > 0) {
                covered += a;
            }
            most = Math.max(most, depth.get(i));
        }
        return new double[] {area, covered, most};
    }

    private static double[] counterClockwise(double[] polygon) {
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
     * relative to the face's size, or to the strip's width for faces smaller than it: a paper
     * coordinate u on a strip of length L is a double good to about 1e-16 L, so a sliver far
     * along a long strip cannot be exact to 1e-9 of its own size.
     */
    static double isometryError(WrapGeometry geometry, double width) {
        double worst = 0;
        double[] xyz = geometry.xyz();
        double[] uv = geometry.uv();
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
                    double space = Math.sqrt(Math.pow(xyz[3 * a] - xyz[3 * b], 2) + Math.pow(xyz[3 * a + 1] - xyz[3 * b + 1], 2)
                            + Math.pow(xyz[3 * a + 2] - xyz[3 * b + 2], 2));
                    double sheet = Math.hypot(uv[2 * a] - uv[2 * b], uv[2 * a + 1] - uv[2 * b + 1]);
                    worst = Math.max(worst, Math.abs(space - sheet) / size);
                }
            }
        }
        return worst;
    }
}
