package ifold.geom;

/** Whether two convex polygons in the plane overlap with some area: the separating-axis test. */
public final class ConvexOverlap {
    private ConvexOverlap() {
    }

    /**
     * Whether convex polygons {@code a} and {@code b} (x, y interleaved, either orientation)
     * overlap by more than {@code margin} across every edge direction of both: polygons that only
     * touch along an edge or at a corner do not.
     */
    public static boolean overlaps(double[] a, double[] b, double margin) {
        return !separatedByAnEdgeOf(a, b, margin) && !separatedByAnEdgeOf(b, a, margin);
    }

    private static boolean separatedByAnEdgeOf(double[] edges, double[] other, double margin) {
        int n = edges.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double nx = edges[2 * j + 1] - edges[2 * i + 1];
            double ny = edges[2 * i] - edges[2 * j];
            double length = Math.hypot(nx, ny);
            if (length == 0) {
                continue;
            }
            nx /= length;
            ny /= length;
            double minA = Double.POSITIVE_INFINITY;
            double maxA = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < edges.length; k += 2) {
                double p = nx * edges[k] + ny * edges[k + 1];
                minA = Math.min(minA, p);
                maxA = Math.max(maxA, p);
            }
            double minB = Double.POSITIVE_INFINITY;
            double maxB = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < other.length; k += 2) {
                double p = nx * other[k] + ny * other[k + 1];
                minB = Math.min(minB, p);
                maxB = Math.max(maxB, p);
            }
            if (maxA <= minB + margin || maxB <= minA + margin) {
                return true;
            }
        }
        return false;
    }
}
