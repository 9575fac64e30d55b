package ifold.fold;

import ifold.geom.ConvexOverlap;
import java.util.List;
import org.joml.Vector3d;
import org.joml.Vector3dc;

/**
 * Where a fold lays its moving layers. Folded flat, the moving paper lands mirrored across the
 * fold line; every layer that stays and lies (with some area) under or over where a moving layer
 * lands must end up below it (valley) or above it (mountain), one thickness apart. The layers at
 * the fold line alone do not settle this: a flap folded over a stack that is thicker away from
 * the line, or a tuck under paper tucked before, would pass through it.
 *
 * <p>Only flat faces (parallel to the sheet) take part: after a partial fold there is no landing
 * to speak of, and the fold line's layers decide as before.
 */
final class Landing {
    private Landing() {
    }

    /**
     * The faces of a cut paper as they stand before the fold turns.
     *
     * @param xyz vertex positions
     * @param faces the faces
     * @param caps whether each face is a cap facet
     * @param moving whether each face moves
     * @param tolerance lengths below this are rounding
     */
    record Faces(double[] xyz, List<int[]> faces, List<Boolean> caps, boolean[] moving, double tolerance) {
    }

    /**
     * The axis height (along {@code n}) that lands the moving flat faces just clear of the staying
     * flat faces they overlap, or {@code atLine} (from the layers at the fold line) if they
     * overlap none.
     *
     * @param linePoint a point of the fold line
     * @param side the unit direction across the line, in the sheet's plane, towards the moving side
     */
    static double axisHeight(Faces faces, Vector3dc linePoint, Vector3dc side, Vector3dc n, boolean valley, double thickness,
            double atLine) {
        Vector3d along = new Vector3d(n).cross(side).normalize();
        int count = faces.faces().size();
        double[][] shadows = new double[count][];
        double[] heights = new double[count];
        double[] boxes = new double[4 * count];
        double flatness = 10 * faces.tolerance();
        for (int f = 0; f < count; f++) {
            if (faces.caps().get(f)) {
                continue;
            }
            int[] face = faces.faces().get(f);
            double[] shadow = new double[2 * face.length];
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            double minS = Double.POSITIVE_INFINITY;
            double maxS = Double.NEGATIVE_INFINITY;
            double minL = Double.POSITIVE_INFINITY;
            double maxL = Double.NEGATIVE_INFINITY;
            for (int i = 0; i < face.length; i++) {
                int v = face[i];
                double dx = faces.xyz()[3 * v] - linePoint.x();
                double dy = faces.xyz()[3 * v + 1] - linePoint.y();
                double dz = faces.xyz()[3 * v + 2] - linePoint.z();
                double h = dx * n.x() + dy * n.y() + dz * n.z();
                double s = dx * side.x() + dy * side.y() + dz * side.z();
                double l = dx * along.x + dy * along.y + dz * along.z;
                if (faces.moving()[f]) {
                    s = -s; // where it lands: mirrored across the fold line
                }
                shadow[2 * i] = s;
                shadow[2 * i + 1] = l;
                low = Math.min(low, h);
                high = Math.max(high, h);
                minS = Math.min(minS, s);
                maxS = Math.max(maxS, s);
                minL = Math.min(minL, l);
                maxL = Math.max(maxL, l);
            }
            if (high - low > flatness) {
                continue; // not lying flat: it lands nowhere in particular
            }
            shadows[f] = shadow;
            heights[f] = (low + high) / 2 + linePoint.dot(n);
            boxes[4 * f] = minS;
            boxes[4 * f + 1] = maxS;
            boxes[4 * f + 2] = minL;
            boxes[4 * f + 3] = maxL;
        }
        // Overlaps thinner than this are faces that only touch, sharing an edge or a crease.
        double overlap = faces.tolerance();
        // Where landing layers overlap layers that stay, they decide alone: the layers at the line
        // may include paper that only touches it at a corner and lies beside the landing, not under it.
        double height = valley ? Double.NEGATIVE_INFINITY : Double.POSITIVE_INFINITY;
        // Only the highest overlapping pair matters for a valley fold (the lowest for a mountain
        // fold): visit the faces from the top down (bottom up), and stop as soon as no pair left
        // could beat the best found. A stack folded through all layers then costs a few tests a
        // face, not one for every pair.
        double sign = valley ? 1 : -1;
        List<Integer> movingFaces = new java.util.ArrayList<>();
        List<Integer> fixedFaces = new java.util.ArrayList<>();
        for (int f = 0; f < count; f++) {
            if (shadows[f] != null) {
                (faces.moving()[f] ? movingFaces : fixedFaces).add(f);
            }
        }
        java.util.Comparator<Integer> topFirst = (a, b) -> Double.compare(sign * heights[b], sign * heights[a]);
        movingFaces.sort(topFirst);
        fixedFaces.sort(topFirst);
        double best = Double.NEGATIVE_INFINITY; // sign * (hm + hf), the larger the better
        for (int m : movingFaces) {
            if (fixedFaces.isEmpty() || sign * (heights[m] + heights[fixedFaces.get(0)]) <= best) {
                break;
            }
            for (int f : fixedFaces) {
                if (sign * (heights[m] + heights[f]) <= best) {
                    break;
                }
                if (boxes[4 * m] > boxes[4 * f + 1] - overlap || boxes[4 * f] > boxes[4 * m + 1] - overlap
                        || boxes[4 * m + 2] > boxes[4 * f + 3] - overlap || boxes[4 * f + 2] > boxes[4 * m + 3] - overlap) {
                    continue;
                }
                if (ConvexOverlap.overlaps(shadows[m], shadows[f], overlap)) {
                    best = sign * (heights[m] + heights[f]);
                    break;
                }
            }
        }
        if (best > Double.NEGATIVE_INFINITY) {
            height = valley ? (best + thickness) / 2 : (-best - thickness) / 2;
        }
        return Double.isInfinite(height) ? atLine : height;
    }
}
