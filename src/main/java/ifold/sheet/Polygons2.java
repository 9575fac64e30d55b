package ifold.sheet;

import java.util.Arrays;

/** Small convex-polygon helpers in a plane, as flat arrays x0 y0 x1 y1 ...; no allocation beyond the results. */
public final class Polygons2 {
    private Polygons2() {
    }

    /** Twice the signed area: positive for a counter-clockwise polygon. */
    public static double twiceArea(double[] xy, int n) {
        double sum = 0;
        for (int i = 0, j = n - 1; i < n; j = i++) {
            sum += xy[2 * j] * xy[2 * i + 1] - xy[2 * i] * xy[2 * j + 1];
        }
        return sum;
    }

    /**
     * Whether two convex polygons share more than a boundary: no separating axis among their
     * edge normals leaves a gap or an overlap thinner than {@code tolerance}.
     */
    public static boolean overlap(double[] a, int na, double[] b, int nb, double tolerance) {
        double[] extentsA = new double[2 * na];
        double[] extentsB = new double[2 * nb];
        ownExtents(a, na, extentsA);
        ownExtents(b, nb, extentsB);
        return overlap(a, na, extentsA, b, nb, extentsB, tolerance);
    }

    /**
     * {@link #overlap(double[], int, double[], int, double)} with each polygon's own extents along
     * its edges' normals found before ({@link #ownExtents}): a face tested against every face
     * near it projects itself once, not once a test (the same answers to the bit).
     */
    public static boolean overlap(double[] a, int na, double[] extentsA, double[] b, int nb, double[] extentsB, double tolerance) {
        return !separated(a, na, extentsA, b, nb, tolerance) && !separated(b, nb, extentsB, a, na, tolerance);
    }

    /**
     * A convex polygon's least and most projection on each of its edges' normals (not made unit),
     * edge by edge as {@link #overlap} takes them, into {@code out} (at least 2n long).
     */
    public static void ownExtents(double[] a, int na, double[] out) {
        for (int i = 0, j = na - 1; i < na; j = i++) {
            double nx = a[2 * i + 1] - a[2 * j + 1];
            double ny = a[2 * j] - a[2 * i];
            double minA = Double.POSITIVE_INFINITY;
            double maxA = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < na; k++) {
                double p = a[2 * k] * nx + a[2 * k + 1] * ny;
                if (p < minA) {
                    minA = p;
                }
                if (p > maxA) {
                    maxA = p;
                }
            }
            out[2 * i] = minA;
            out[2 * i + 1] = maxA;
        }
    }

    private static boolean separated(double[] a, int na, double[] extentsA, double[] b, int nb, double tolerance) {
        // The hottest loop of a wrap (tucks test each flap's faces against the paper near them):
        // the normals are not made unit, the overlap is measured against the tolerance times
        // their length, squared; and comparisons, not Math.min and max, whose care for NaN and
        // -0 costs here and which neither comes up in.
        double tolerance2 = tolerance * tolerance;
        for (int i = 0, j = na - 1; i < na; j = i++) {
            double nx = a[2 * i + 1] - a[2 * j + 1];
            double ny = a[2 * j] - a[2 * i];
            double length2 = nx * nx + ny * ny;
            if (!(length2 > 0)) {
                continue;
            }
            double minA = extentsA[2 * i];
            double maxA = extentsA[2 * i + 1];
            double minB = Double.POSITIVE_INFINITY;
            double maxB = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < nb; k++) {
                double p = b[2 * k] * nx + b[2 * k + 1] * ny;
                if (p < minB) {
                    minB = p;
                }
                if (p > maxB) {
                    maxB = p;
                }
            }
            double overlap = (maxA < maxB ? maxA : maxB) - (minA > minB ? minA : minB);
            if (overlap <= 0 || overlap * overlap <= tolerance2 * length2) {
                return true;
            }
        }
        return false;
    }

    /**
     * The part of convex polygon {@code xy} (n corners) where {@code nx·x + ny·y <= c}, or null
     * when none of it, beyond {@code tolerance}, is there.
     */
    public static double[] clip(double[] xy, int n, double nx, double ny, double c, double tolerance) {
        // Corners counted first, the array then made to size: a wrap clips hundreds of millions
        // of times, and an array with room to spare and then its copy to size were a tenth of
        // all it allocated (the 5,000-triangle torus: 1.9 of 16 GB).
        int m = clippedCorners(xy, n, nx, ny, c, tolerance);
        if (m == 0) {
            return null;
        }
        double[] out = new double[2 * m];
        clipInto(xy, n, nx, ny, c, out);
        return out;
    }

    /**
     * How many corners {@link #clip} gives: 0 where none of the polygon, beyond the tolerance, is
     * there. A convex polygon cut by a line has at most n + 1 corners, but rounding on a nearly
     * flat one can make a point hop across the line and back: at most 2n.
     */
    public static int clippedCorners(double[] xy, int n, double nx, double ny, double c, double tolerance) {
        int m = 0;
        boolean any = false;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double di = xy[2 * i] * nx + xy[2 * i + 1] * ny - c;
            double dj = xy[2 * j] * nx + xy[2 * j + 1] * ny - c;
            if (di <= 0) {
                m++;
                any |= di < -tolerance;
            }
            if ((di < 0 && dj > 0) || (di > 0 && dj < 0)) {
                m++;
            }
        }
        return !any || m < 3 ? 0 : m;
    }

    /**
     * {@link #clip} into {@code out} (x y pairs from 0), where {@link #clippedCorners} has found
     * some, and {@code out} holds twice as many: for a chain of clips whose steps between are not
     * kept.
     */
    public static void clipInto(double[] xy, int n, double nx, double ny, double c, double[] out) {
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double di = xy[2 * i] * nx + xy[2 * i + 1] * ny - c;
            double dj = xy[2 * j] * nx + xy[2 * j + 1] * ny - c;
            if (di <= 0) {
                out[2 * m] = xy[2 * i];
                out[2 * m + 1] = xy[2 * i + 1];
                m++;
            }
            if ((di < 0 && dj > 0) || (di > 0 && dj < 0)) {
                double t = di / (di - dj);
                out[2 * m] = xy[2 * i] + t * (xy[2 * j] - xy[2 * i]);
                out[2 * m + 1] = xy[2 * i + 1] + t * (xy[2 * j + 1] - xy[2 * i + 1]);
                m++;
            }
        }
    }

    /**
     * The length of the vector (dx, dy): lengths within one host or sheet, where Math.hypot's
     * guard against overflow buys nothing and costs (a wrap's geometry measures millions).
     */
    public static double length(double dx, double dy) {
        return Math.sqrt(dx * dx + dy * dy);
    }

    /** The length around a polygon of {@code n} corners. */
    public static double perimeter(double[] xy, int n) {
        double around = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            around += Math.hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]);
        }
        return around;
    }

    /** The bounding box of a polygon: min x, min y, max x, max y. */
    public static double[] bounds(double[] xy) {
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int k = 0; k < xy.length; k += 2) {
            box[0] = Math.min(box[0], xy[k]);
            box[1] = Math.min(box[1], xy[k + 1]);
            box[2] = Math.max(box[2], xy[k]);
            box[3] = Math.max(box[3], xy[k + 1]);
        }
        return box;
    }
}
