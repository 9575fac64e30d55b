package ifold.foldfile;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The faces of a crease pattern that gives only its edges: each bounded region of the plane the
 * edges cut, traced by turning at each vertex to the next edge clockwise from the one arrived
 * by. The faces come out counter-clockwise; the unbounded region (clockwise) is left out.
 */
final class PlanarFaceTracing {
    private PlanarFaceTracing() {
    }

    static int[][] faces(double[][] vertices, int[][] edges) throws CreasePattern.Refused {
        int n = vertices.length;
        List<List<Integer>> around = new ArrayList<>();
        for (int v = 0; v < n; v++) {
            around.add(new ArrayList<>());
        }
        for (int[] e : edges) {
            around.get(e[0]).add(e[1]);
            around.get(e[1]).add(e[0]);
        }
        // Each vertex's neighbours counter-clockwise by direction.
        int[][] sorted = new int[n][];
        for (int v = 0; v < n; v++) {
            final int centre = v;
            sorted[v] = around.get(v).stream().sorted((a, b) -> Double.compare(angle(vertices, centre, a), angle(vertices, centre, b)))
                    .mapToInt(Integer::intValue).toArray();
        }
        Map<Long, Boolean> used = new HashMap<>();
        List<int[]> faces = new ArrayList<>();
        for (int[] e : edges) {
            for (int side = 0; side < 2; side++) {
                int a = side == 0 ? e[0] : e[1];
                int b = side == 0 ? e[1] : e[0];
                if (used.containsKey(key(a, b))) {
                    continue;
                }
                List<Integer> loop = new ArrayList<>();
                int from = a;
                int to = b;
                while (!used.containsKey(key(from, to))) {
                    used.put(key(from, to), true);
                    loop.add(from);
                    if (loop.size() > 2 * edges.length + 2) {
                        throw new CreasePattern.Refused("the edges do not cut the paper into faces: give faces_vertices");
                    }
                    // At `to`, the edge next clockwise from the way back to `from`: the face on the left.
                    int[] next = sorted[to];
                    int back = Arrays.stream(next).boxed().toList().indexOf(from);
                    int turn = next[(back - 1 + next.length) % next.length];
                    from = to;
                    to = turn;
                }
                int[] face = loop.stream().mapToInt(Integer::intValue).toArray();
                if (face.length >= 3 && area(vertices, face) > 0) {
                    faces.add(face);
                }
            }
        }
        return faces.toArray(new int[0][]);
    }

    private static double angle(double[][] vertices, int from, int to) {
        return Math.atan2(vertices[to][1] - vertices[from][1], vertices[to][0] - vertices[from][0]);
    }

    private static long key(int a, int b) {
        return ((long) a << 32) | (b & 0xffffffffL);
    }

    /** Twice the signed area of the polygon (counter-clockwise positive). */
    static double area(double[][] vertices, int[] face) {
        double sum = 0;
        double[] o = vertices[face[0]];
        for (int i = 1; i + 1 < face.length; i++) {
            double[] p = vertices[face[i]];
            double[] q = vertices[face[i + 1]];
            sum += (p[0] - o[0]) * (q[1] - o[1]) - (q[0] - o[0]) * (p[1] - o[1]);
        }
        return sum;
    }
}
