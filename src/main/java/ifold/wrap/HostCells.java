package ifold.wrap;

import static ifold.wrap.WrapAnalysis.counterClockwise;

import ifold.mesh.IndexedPolygons;
import ifold.sheet.FaceGrid;
import ifold.sheet.HostFrame;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * One host's figures for a wrap's measures ({@link WrapAnalysis}), from the arrangement of the
 * faces of paper on each of its triangles: how far its paper goes beyond it and above it, and for
 * each of its {@code triangles} {area, area covered, most layers, x and y of a point there in the
 * host's frame, then the corners of the deepest cell, x y each}.
 */
record HostCells(double outside, double farthest, double[][] triangles) {

    /**
     * What the figures read besides a host's paper: the refined mesh and the hosts' frames, the
     * strip's first path triangle and how many it wraps (a triangle's passes run along the edge
     * it shares with the next), the sheet's thickness, width and tolerance, and the most layers
     * found so far on any host of the wrap, which all its hosts' figures share: a triangle that
     * cannot have as many is not counted to its most (its figure is then fewer than the wrap's
     * most, the same answer for the wrap's most and where it is).
     */
    record Context(IndexedPolygons mesh, HostFrame[] frames, int firstTriangle, int triangles, double thickness, double width,
            double tolerance, AtomicInteger deepestSoFar) {
        static Context of(IndexedPolygons mesh, HostFrame[] frames, int firstTriangle, int triangles, Sheet sheet,
                AtomicInteger deepestSoFar) {
            return new Context(mesh, frames, firstTriangle, triangles, sheet.thickness(), sheet.width(), sheet.tolerance(),
                    deepestSoFar);
        }
    }

    /**
     * A host's paper as the figures read it: its faces' corners in the host's frame, in the order
     * of its stack, their levels, and its top level (-1: no paper).
     */
    record Paper(double[][] placed, int[] levels, int topLevel) {
        static Paper of(Sheet sheet, int host) {
            int[] faces = sheet.facesOn(host);
            double[][] placed = new double[faces.length][];
            for (int i = 0; i < faces.length; i++) {
                placed[i] = sheet.placed(faces[i]);
            }
            return new Paper(placed, sheet.levelsOn(host), sheet.topLevel(host));
        }
    }

    /** The figures of {@code host}'s {@code paper} over its {@code triangles} (path triangles, in the order of the path). */
    static HostCells of(Context context, int host, Paper paper, List<Integer> triangles) {
        HostFrame frame = context.frames()[host];
        double[] c = frame.corners();
        double[][] placed = paper.placed();
        int faces = placed.length;
        double[][] boxes = new double[faces][];
        double outside = 0;
        for (int i = 0; i < faces; i++) {
            boxes[i] = Polygons2.bounds(placed[i]);
            outside = Math.max(outside, beyond(c, placed[i]));
        }
        // The highest paper's top: its level's mid-surface and half a thickness.
        double farthest = faces == 0 ? 0 : (paper.topLevel() + 1) * context.thickness();
        // A host of many triangles holds their faces all: each triangle looks only at
        // those of the grid's cells it meets.
        FaceGrid grid = null;
        if (triangles.size() > 1) {
            grid = new FaceGrid(FaceGrid.cellFor(placed, faces, 2 * context.width()));
            for (int i = 0; i < faces; i++) {
                grid.add(i, placed[i]);
            }
        }
        double[][] figures = new double[triangles.size()][];
        double[][] scratch = {new double[32], new double[32]};
        for (int t = 0; t < triangles.size(); t++) {
            int triangle = triangles.get(t);
            double[] corners = cornersIn(context.mesh(), triangle, frame);
            double[] box = Polygons2.bounds(corners);
            // Turned so that the triangle's passes run along x, as they run along its
            // exit edge: their boxes are then thin, and each meets only the cells near it.
            // Each face clipped to the triangle first: only its part there makes cells.
            // The faces in their order, whichever way they were found: the cells, and so
            // the deepest point reported, do not depend on the grid.
            double[] along = passDirection(context, triangle, frame);
            int[] near = grid == null ? null : grid.near(corners); // null: look at all
            List<double[]> polygons = new ArrayList<>();
            int[] levels = new int[near == null ? faces : near.length];
            for (int m = 0; m < (near == null ? faces : near.length); m++) {
                int i = near == null ? m : near[m];
                double[] b = boxes[i];
                if (!(b[0] < box[2] && box[0] < b[2] && b[1] < box[3] && box[1] < b[3])) {
                    continue;
                }
                double[] part = clipToTriangle(counterClockwise(placed[i]), corners, scratch);
                if (part != null) {
                    levels[polygons.size()] = paper.levels()[i];
                    polygons.add(turned(part, along));
                }
            }
            double[] cells = FaceArrangement.depths(counterClockwise(turned(corners, along)), polygons, levels, context.tolerance(),
                    context.deepestSoFar());
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
     * The unit direction, in the host's frame, of the edge path triangle t leaves by (shared with
     * the next triangle of its strip; for the last, with the one before): its passes run along it.
     */
    private static double[] passDirection(Context context, int t, HostFrame frame) {
        IndexedPolygons mesh = context.mesh();
        int other = t + 1 < context.firstTriangle() + context.triangles() ? t + 1 : t - 1;
        int[] shared = new int[2];
        int n = 0;
        for (int a = 0; a < 3 && other >= context.firstTriangle(); a++) {
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

    /**
     * The part of convex polygon xy inside triangle c (both counter-clockwise), or null; the
     * steps between in {@code scratch}'s two arrays (grown there as needed), the answer alone
     * made anew.
     */
    private static double[] clipToTriangle(double[] xy, double[] c, double[][] scratch) {
        double[] inside = xy;
        int corners = xy.length / 2;
        for (int e = 0; e < 3; e++) {
            double ax = c[2 * e];
            double ay = c[2 * e + 1];
            double dx = c[2 * ((e + 1) % 3)] - ax;
            double dy = c[2 * ((e + 1) % 3) + 1] - ay;
            // Inside is left of each edge: dy·x - dx·y <= dy·ax - dx·ay.
            int m = Polygons2.clippedCorners(inside, corners, dy, -dx, dy * ax - dx * ay, 0);
            if (m == 0) {
                return null;
            }
            int slot = inside == scratch[0] ? 1 : 0;
            if (scratch[slot].length < 2 * m) {
                scratch[slot] = new double[4 * m];
            }
            Polygons2.clipInto(inside, corners, dy, -dx, dy * ax - dx * ay, scratch[slot]);
            inside = scratch[slot];
            corners = m;
        }
        return java.util.Arrays.copyOf(inside, 2 * corners);
    }

    /** xy turned so that {@code along} (a unit vector) becomes the x axis. */
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

    /** How far the polygon reaches beyond the host's polygon c (corners counter-clockwise), 0 if not at all. */
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
}
