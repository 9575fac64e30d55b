package ifold.fold;

import ifold.geom.Tolerance;
import ifold.geom.ConvexOverlap;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Set;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Presses folded paper flat, as a folder's thumb does: a rigid fold keeps the moving layers'
 * heights relative to each other, so tucking a stack that holds gaps (a turn's two layers beside
 * paper tucked before) carries the gaps along, and the stack grows deeper than its layers. The
 * press moves every piece of paper (faces joined by shared vertices) straight towards a base
 * height, keeping the order of every two pieces that overlap: pieces at or above the base come
 * down until they rest on the base or one thickness above a piece under them, pieces below it
 * come up until they lie one thickness under the base or under a piece over them. Nothing turns,
 * so the paper stays isometric, and no two overlapping layers change order or come closer than a
 * thickness. The caps follow: each is stretched between the new heights of the layers it joins,
 * its bulge scaled with their gap.
 *
 * <p>Only a flat folded paper (every paper face parallel to the sheet) is pressed; any other
 * comes back as it is.
 */
public final class Press {
    private Press() {
    }

    /**
     * The paper before and after pressing; {@link #at} slides the pieces between the two.
     *
     * @param before the paper as folded
     * @param after the paper pressed
     * @param moved how far the farthest piece moved
     */
    public record Pressed(Paper before, Paper after, double moved) implements PaperMotion {
        @Override
        public Paper at(double fraction) {
            if (fraction <= 0) {
                return before;
            }
            if (fraction >= 1) {
                return after;
            }
            double[] xyz = before.positionsCopy();
            for (int i = 0; i < xyz.length; i++) {
                xyz[i] += fraction * (after.positions[i] - xyz[i]);
            }
            return new Paper(xyz, before.paperCoordinates, before.faces, before.cap, before.thickness, before.normal,
                    before.creases);
        }
    }

    /** Presses {@code paper} towards {@code base}, a height along the sheet's normal. */
    public static Pressed press(Paper paper, double base) {
        int faceCount = paper.faceCount();
        int vertexCount = paper.vertexCount();
        Vector3dc n = paper.normal;
        double t = paper.thickness;
        double tolerance = Tolerance.ON_PLANE * paper.size(); // relative to the sheet, whatever its scale
        // Pieces: paper faces joined through shared vertices (union-find over vertices).
        int[] parent = new int[vertexCount];
        Arrays.setAll(parent, i -> i);
        boolean[] onPaper = new boolean[vertexCount];
        for (int f = 0; f < faceCount; f++) {
            if (paper.cap[f]) {
                continue;
            }
            int[] face = paper.faces.get(f);
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            for (int v : face) {
                onPaper[v] = true;
                union(parent, face[0], v);
                low = Math.min(low, paper.height(v));
                high = Math.max(high, paper.height(v));
            }
            if (high - low > 10 * tolerance) {
                return new Pressed(paper, paper, 0); // not folded flat: nothing to press
            }
        }
        int[] pieceOfVertex = new int[vertexCount];
        int pieces = 0;
        int[] pieceOfRoot = new int[vertexCount];
        Arrays.fill(pieceOfRoot, -1);
        for (int v = 0; v < vertexCount; v++) {
            if (onPaper[v]) {
                int root = find(parent, v);
                if (pieceOfRoot[root] < 0) {
                    pieceOfRoot[root] = pieces++;
                }
                pieceOfVertex[v] = pieceOfRoot[root];
            } else {
                pieceOfVertex[v] = -1;
            }
        }
        double[] height = new double[pieces];
        for (int v = 0; v < vertexCount; v++) {
            if (onPaper[v]) {
                height[pieceOfVertex[v]] = paper.height(v);
            }
        }
        List<Set<Integer>> below = overlapsBelow(paper, pieceOfVertex, pieces, height, tolerance);
        // The two sides of a fold stay stacked, even where they barely overlap: a cap joins them.
        for (java.util.Set<Integer> joined : capJoins(paper, onPaper).values()) {
            java.util.Set<Integer> joinedPieces = new java.util.TreeSet<>();
            for (int v : joined) {
                joinedPieces.add(pieceOfVertex[v]);
            }
            for (int pa : joinedPieces) {
                for (int pb : joinedPieces) {
                    if (height[pa] < height[pb] - tolerance) {
                        below.get(pb).add(pa);
                    }
                }
            }
        }
        List<List<Integer>> above = new ArrayList<>();
        for (int p = 0; p < pieces; p++) {
            above.add(new ArrayList<>());
        }
        for (int p = 0; p < pieces; p++) {
            for (int q : below.get(p)) {
                above.get(q).add(p);
            }
        }
        Integer[] order = new Integer[pieces];
        Arrays.setAll(order, i -> i);
        Arrays.sort(order, (a, b) -> Double.compare(height[a], height[b]));
        double[] pressed = new double[pieces];
        // Upwards from the base: each piece rests on the base or on the highest piece under it.
        for (int p : order) {
            if (height[p] >= base - tolerance) {
                double rest = base;
                for (int q : below.get(p)) {
                    if (height[q] >= base - tolerance) { // pieces under the base stay under it anyway
                        rest = Math.max(rest, pressed[q] + t);
                    }
                }
                pressed[p] = Math.min(height[p], rest);
            }
        }
        // Downwards from the base: each piece hangs under the base or under the lowest piece over it.
        for (int i = pieces - 1; i >= 0; i--) {
            int p = order[i];
            if (height[p] < base - tolerance) {
                double hang = base - t;
                for (int q : above.get(p)) {
                    hang = Math.min(hang, pressed[q] - t);
                }
                pressed[p] = Math.max(height[p], hang);
            }
        }
        double[] xyz = paper.positionsCopy();
        double moved = 0;
        for (int v = 0; v < vertexCount; v++) {
            if (onPaper[v]) {
                double shift = pressed[pieceOfVertex[v]] - height[pieceOfVertex[v]];
                moved = Math.max(moved, Math.abs(shift));
                xyz[3 * v] += shift * n.x();
                xyz[3 * v + 1] += shift * n.y();
                xyz[3 * v + 2] += shift * n.z();
            }
        }
        if (moved <= tolerance) {
            return new Pressed(paper, paper, 0);
        }
        followCaps(paper, onPaper, xyz);
        Paper after = new Paper(xyz, paper.paperCoordinates, paper.faces, paper.cap, t, n, paper.creases);
        return new Pressed(paper, after, moved);
    }

    /** For each piece, the pieces lower than it whose paper overlaps its paper (seen along the normal). */
    private static List<Set<Integer>> overlapsBelow(Paper paper, int[] pieceOfVertex, int pieces, double[] height,
            double tolerance) {
        Vector3dc n = paper.normal;
        Vector3d e1 = new Vector3d(Math.abs(n.x()) < 0.9 ? new Vector3d(1, 0, 0) : new Vector3d(0, 1, 0)).cross(n).normalize();
        Vector3d e2 = new Vector3d(n).cross(e1).normalize();
        List<double[]> shadows = new ArrayList<>();
        List<Integer> owners = new ArrayList<>();
        List<double[]> boxes = new ArrayList<>();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.cap[f]) {
                continue;
            }
            int[] face = paper.faces.get(f);
            double[] shadow = new double[2 * face.length];
            double[] box = {Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY};
            for (int i = 0; i < face.length; i++) {
                int v = face[i];
                double s = e1.x * paper.x(v) + e1.y * paper.y(v) + e1.z * paper.z(v);
                double r = e2.x * paper.x(v) + e2.y * paper.y(v) + e2.z * paper.z(v);
                shadow[2 * i] = s;
                shadow[2 * i + 1] = r;
                box[0] = Math.min(box[0], s);
                box[1] = Math.max(box[1], s);
                box[2] = Math.min(box[2], r);
                box[3] = Math.max(box[3], r);
            }
            shadows.add(shadow);
            owners.add(pieceOfVertex[face[0]]);
            boxes.add(box);
        }
        // Sweep along the first axis so that only faces whose boxes meet are compared.
        Integer[] order = new Integer[shadows.size()];
        Arrays.setAll(order, i -> i);
        Arrays.sort(order, (a, b) -> Double.compare(boxes.get(a)[0], boxes.get(b)[0]));
        double margin = tolerance;
        List<Set<Integer>> below = new ArrayList<>();
        for (int p = 0; p < pieces; p++) {
            below.add(new java.util.LinkedHashSet<>());
        }
        for (int i = 0; i < order.length; i++) {
            int a = order[i];
            double[] boxA = boxes.get(a);
            for (int j = i + 1; j < order.length; j++) {
                int b = order[j];
                double[] boxB = boxes.get(b);
                if (boxB[0] > boxA[1] - margin) {
                    break;
                }
                int pa = owners.get(a);
                int pb = owners.get(b);
                if (pa == pb || boxB[2] > boxA[3] - margin || boxA[2] > boxB[3] - margin) {
                    continue;
                }
                if (ConvexOverlap.overlaps(shadows.get(a), shadows.get(b), margin)) {
                    if (height[pa] < height[pb]) {
                        below.get(pb).add(pa);
                    } else {
                        below.get(pa).add(pb);
                    }
                }
            }
        }
        return below;
    }

    /**
     * Moves the cap vertices after the layers they join: each group of caps joined by shared cap
     * vertices bridges paper at two heights; its vertices keep their place between those heights
     * in proportion, and their distance from the crease scales with the gap.
     */
    private static void followCaps(Paper paper, boolean[] onPaper, double[] xyz) {
        int vertexCount = paper.vertexCount();
        int[] parent = capGroups(paper, onPaper);
        java.util.Map<Integer, java.util.Set<Integer>> touched = capJoins(paper, onPaper);
        Vector3dc n = paper.normal;
        for (int v = 0; v < vertexCount; v++) {
            if (onPaper[v] || !touched.containsKey(find(parent, v))) {
                continue;
            }
            java.util.Set<Integer> joins = touched.get(find(parent, v));
            double oldLow = Double.POSITIVE_INFINITY;
            double oldHigh = Double.NEGATIVE_INFINITY;
            double newLow = Double.POSITIVE_INFINITY;
            double newHigh = Double.NEGATIVE_INFINITY;
            int nearest = -1;
            double nearestDistance = Double.POSITIVE_INFINITY;
            Vector3d p = new Vector3d(paper.x(v), paper.y(v), paper.z(v));
            for (int w : joins) {
                double before = paper.height(w);
                double after = xyz[3 * w] * n.x() + xyz[3 * w + 1] * n.y() + xyz[3 * w + 2] * n.z();
                if (before < oldLow) {
                    oldLow = before;
                    newLow = after;
                }
                if (before > oldHigh) {
                    oldHigh = before;
                    newHigh = after;
                }
                Vector3d q = new Vector3d(paper.x(w), paper.y(w), paper.z(w));
                Vector3d across = new Vector3d(p).sub(q);
                across.fma(-across.dot(n), n);
                if (across.length() < nearestDistance) {
                    nearestDistance = across.length();
                    nearest = w;
                }
            }
            double gapBefore = oldHigh - oldLow;
            double gapAfter = newHigh - newLow;
            double h = paper.height(v);
            double newHeight = gapBefore > 0 ? newLow + (h - oldLow) / gapBefore * gapAfter : h + (newLow - oldLow);
            double scale = gapBefore > 0 ? gapAfter / gapBefore : 1;
            // The bulge: the offset across the normal from the nearest joined paper vertex, scaled with the gap.
            Vector3d anchor = new Vector3d(xyz[3 * nearest], xyz[3 * nearest + 1], xyz[3 * nearest + 2]);
            Vector3d oldAnchor = new Vector3d(paper.x(nearest), paper.y(nearest), paper.z(nearest));
            Vector3d across = new Vector3d(p).sub(oldAnchor);
            across.fma(-across.dot(n), n).mul(scale);
            Vector3d moved = new Vector3d(anchor).fma(-anchor.dot(n), n).add(across).fma(newHeight, n);
            xyz[3 * v] = moved.x;
            xyz[3 * v + 1] = moved.y;
            xyz[3 * v + 2] = moved.z;
        }
    }

    /** Union-find over the cap vertices (those on no paper face): caps joined by shared cap vertices are one group. */
    private static int[] capGroups(Paper paper, boolean[] onPaper) {
        int[] parent = new int[paper.vertexCount()];
        Arrays.setAll(parent, i -> i);
        for (int f = 0; f < paper.faceCount(); f++) {
            if (paper.cap[f]) {
                int first = -1;
                for (int v : paper.faces.get(f)) {
                    if (!onPaper[v]) {
                        if (first < 0) {
                            first = v;
                        } else {
                            union(parent, first, v);
                        }
                    }
                }
            }
        }
        return parent;
    }

    /** For each group of caps (by the root of {@link #capGroups}), the paper vertices it joins. */
    private static java.util.Map<Integer, java.util.Set<Integer>> capJoins(Paper paper, boolean[] onPaper) {
        int[] parent = capGroups(paper, onPaper);
        java.util.Map<Integer, java.util.Set<Integer>> touched = new java.util.HashMap<>();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.cap[f]) {
                continue;
            }
            int[] face = paper.faces.get(f);
            int root = -1;
            for (int v : face) {
                if (!onPaper[v]) {
                    root = find(parent, v);
                }
            }
            if (root < 0) {
                continue;
            }
            for (int v : face) {
                if (onPaper[v]) {
                    touched.computeIfAbsent(root, k -> new java.util.LinkedHashSet<>()).add(v);
                }
            }
        }
        return touched;
    }

    private static int find(int[] parent, int v) {
        while (parent[v] != v) {
            parent[v] = parent[parent[v]];
            v = parent[v];
        }
        return v;
    }

    private static void union(int[] parent, int a, int b) {
        int ra = find(parent, a);
        int rb = find(parent, b);
        if (ra != rb) {
            parent[ra] = rb;
        }
    }
}
