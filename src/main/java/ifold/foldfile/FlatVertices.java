package ifold.foldfile;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Whether each vertex inside the paper of a crease pattern folded flat can fold flat on its own:
 * the mountains and valleys meeting there differ by two (Maekawa), and the angles between its
 * creases, taken alternately, sum to 180° each (Kawasaki). A pattern that fails at a vertex is
 * refused naming it, before anything is placed.
 */
final class FlatVertices {
    /**
     * How far, in radians, Kawasaki's sums may stray: the rounding of coordinates written to a
     * file, and designs that approximate curves (Lang's Rings8: 6.4e-4 at a vertex).
     */
    static final double ANGLE_TOLERANCE = 1e-3;

    private FlatVertices() {
    }

    /** Whether vertex v lies on a border edge that runs past it (a pattern whose border is not split where creases meet it). */
    private static boolean onBorderEdge(double[][] uv, int[][] edges, boolean[] hingeable, int v) {
        for (int e = 0; e < edges.length; e++) {
            if (hingeable[e] || edges[e][0] == v || edges[e][1] == v) {
                continue;
            }
            double[] a = uv[edges[e][0]];
            double[] b = uv[edges[e][1]];
            double dx = b[0] - a[0];
            double dy = b[1] - a[1];
            double length = Math.hypot(dx, dy);
            double along = ((uv[v][0] - a[0]) * dx + (uv[v][1] - a[1]) * dy) / (length * length);
            double across = Math.abs((uv[v][0] - a[0]) * dy - (uv[v][1] - a[1]) * dx) / length;
            if (along > 0 && along < 1 && across <= 1e-9 * length) {
                return true;
            }
        }
        return false;
    }

    /**
     * @param angles each edge's fold angle, radians (0, or ±π)
     * @param hingeable whether an edge joins faces (not the border, not a cut)
     */
    static void check(double[][] uv, int[][] edges, double[] angles, boolean[] hingeable) throws CreasePattern.Refused {
        int n = uv.length;
        boolean[] onBorder = new boolean[n];
        List<List<Integer>> creasesAt = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            creasesAt.add(new ArrayList<>());
        }
        for (int e = 0; e < edges.length; e++) {
            if (!hingeable[e]) {
                onBorder[edges[e][0]] = true;
                onBorder[edges[e][1]] = true;
            } else if (Math.abs(angles[e]) > 1) {
                creasesAt.get(edges[e][0]).add(e);
                creasesAt.get(edges[e][1]).add(e);
            }
        }
        for (int v = 0; v < n; v++) {
            List<Integer> creases = creasesAt.get(v);
            if (onBorder[v] || creases.isEmpty() || onBorderEdge(uv, edges, hingeable, v)) {
                continue;
            }
            if (creases.size() == 1) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "edge %d: the crease ends inside the paper at vertex %d (%s, %s),"
                        + " where no other crease meets it: a lone crease cannot fold flat (Maekawa's theorem)", creases.get(0), v,
                        CreasePattern.fmt(uv[v][0]), CreasePattern.fmt(uv[v][1])));
            }
            int mountains = 0;
            int valleys = 0;
            for (int e : creases) {
                if (angles[e] > 0) {
                    valleys++;
                } else {
                    mountains++;
                }
            }
            String where = String.format(Locale.ROOT, "vertex %d (%s, %s) cannot fold flat: ", v, CreasePattern.fmt(uv[v][0]),
                    CreasePattern.fmt(uv[v][1]));
            if (Math.abs(mountains - valleys) != 2) {
                throw new CreasePattern.Refused(where + String.format(Locale.ROOT, "%d %s and %d %s meet there, and Maekawa's theorem"
                        + " wants them to differ by 2", mountains, mountains == 1 ? "mountain" : "mountains", valleys,
                        valleys == 1 ? "valley" : "valleys"));
            }
            final int centre = v;
            double[] directions = creases.stream().mapToDouble(e -> {
                int other = edges[e][0] == centre ? edges[e][1] : edges[e][0];
                return Math.atan2(uv[other][1] - uv[centre][1], uv[other][0] - uv[centre][0]);
            }).sorted().toArray();
            double alternate = 0;
            for (int i = 0; i < directions.length; i++) {
                double next = i + 1 < directions.length ? directions[i + 1] : directions[0] + 2 * Math.PI;
                alternate += (i % 2 == 0 ? 1 : -1) * (next - directions[i]);
            }
            if (Math.abs(alternate) > ANGLE_TOLERANCE) {
                double odd = (2 * Math.PI + alternate) / 2;
                throw new CreasePattern.Refused(where + String.format(Locale.ROOT, "the angles between its creases, taken alternately,"
                        + " sum to %.4g° and %.4g°, and Kawasaki's theorem wants 180° each", Math.toDegrees(odd),
                        360 - Math.toDegrees(odd)));
            }
        }
    }
}
