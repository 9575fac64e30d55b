package ifold.mesh;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Small models the project makes itself, as polygon soups oriented outward: the Platonic solids
 * used in tests and in {@code models/}, a torus, a single triangle and the twelve-triangle sheet
 * of the seed's Figure 3.
 */
public final class Solids {
    private Solids() {
    }

    public static PolygonSoup tetrahedron() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(1, 1, 1);
        soup.addVertex(1, -1, -1);
        soup.addVertex(-1, 1, -1);
        soup.addVertex(-1, -1, 1);
        soup.addTriangle(0, 1, 2);
        soup.addTriangle(0, 3, 1);
        soup.addTriangle(0, 2, 3);
        soup.addTriangle(1, 3, 2);
        return soup;
    }

    /** The unit cube [0,1]^3 with square faces. */
    public static PolygonSoup cube() {
        return box(1, 1, 1);
    }

    /** A box of six quads, {@code a} × {@code b} × {@code c}, one corner at the origin: {@code box(1, 1, 1)} is the cube. */
    public static PolygonSoup box(double a, double b, double c) {
        PolygonSoup soup = new PolygonSoup();
        for (int i = 0; i < 8; i++) {
            soup.addVertex((i & 1) * a, ((i >> 1) & 1) * b, ((i >> 2) & 1) * c);
        }
        int[][] quads = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (int[] quad : quads) {
            soup.addFace(quad, 4, 0);
        }
        return soup;
    }

    public static PolygonSoup octahedron() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(1, 0, 0);
        soup.addVertex(-1, 0, 0);
        soup.addVertex(0, 1, 0);
        soup.addVertex(0, -1, 0);
        soup.addVertex(0, 0, 1);
        soup.addVertex(0, 0, -1);
        int[][] triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4}, {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
        for (int[] t : triangles) {
            soup.addTriangle(t[0], t[1], t[2]);
        }
        return soup;
    }

    public static PolygonSoup icosahedron() {
        PolygonSoup soup = new PolygonSoup();
        double p = (1 + Math.sqrt(5)) / 2;
        double[][] vertices = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
            {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
        for (double[] v : vertices) {
            soup.addVertex(v[0], v[1], v[2]);
        }
        int[][] triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
            {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
            {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
        for (int[] t : triangles) {
            soup.addTriangle(t[0], t[1], t[2]);
        }
        return soup;
    }

    /**
     * The icosahedron with each triangle cut into 4^{@code subdivisions} and every vertex pushed
     * out onto its circumscribed sphere: 20 · 4^subdivisions triangles, all nearly equilateral.
     */
    public static PolygonSoup icosphere(int subdivisions) {
        if (subdivisions < 0 || subdivisions > 8) {
            throw new IllegalArgumentException("an icosphere has 0 to 8 subdivisions, got " + subdivisions);
        }
        PolygonSoup ico = icosahedron();
        List<double[]> vertices = new ArrayList<>();
        for (int v = 0; v < ico.vertexCount(); v++) {
            vertices.add(new double[] {ico.coordinate(v, 0), ico.coordinate(v, 1), ico.coordinate(v, 2)});
        }
        double radius = Math.sqrt(1 + (1 + Math.sqrt(5)) * (1 + Math.sqrt(5)) / 4);
        List<int[]> triangles = new ArrayList<>();
        for (int f = 0; f < ico.faceCount(); f++) {
            triangles.add(new int[] {ico.faceVertex(f, 0), ico.faceVertex(f, 1), ico.faceVertex(f, 2)});
        }
        for (int level = 0; level < subdivisions; level++) {
            Map<Long, Integer> midpoints = new HashMap<>();
            List<int[]> finer = new ArrayList<>();
            for (int[] t : triangles) {
                int ab = midpoint(t[0], t[1], vertices, midpoints, radius);
                int bc = midpoint(t[1], t[2], vertices, midpoints, radius);
                int ca = midpoint(t[2], t[0], vertices, midpoints, radius);
                finer.add(new int[] {t[0], ab, ca});
                finer.add(new int[] {ab, t[1], bc});
                finer.add(new int[] {ca, bc, t[2]});
                finer.add(new int[] {ab, bc, ca});
            }
            triangles = finer;
        }
        PolygonSoup soup = new PolygonSoup();
        for (double[] v : vertices) {
            soup.addVertex(v[0], v[1], v[2]);
        }
        for (int[] t : triangles) {
            soup.addTriangle(t[0], t[1], t[2]);
        }
        return soup;
    }

    private static int midpoint(int a, int b, List<double[]> vertices, Map<Long, Integer> midpoints, double radius) {
        long key = ((long) Math.min(a, b) << 32) | Math.max(a, b);
        Integer known = midpoints.get(key);
        if (known != null) {
            return known;
        }
        double[] p = vertices.get(a);
        double[] q = vertices.get(b);
        double x = (p[0] + q[0]) / 2;
        double y = (p[1] + q[1]) / 2;
        double z = (p[2] + q[2]) / 2;
        double scale = radius / Math.sqrt(x * x + y * y + z * z);
        vertices.add(new double[] {x * scale, y * scale, z * scale});
        midpoints.put(key, vertices.size() - 1);
        return vertices.size() - 1;
    }

    /**
     * A torus around the z axis, {@code around} segments along the ring and {@code across}
     * around the tube, each quad split into two triangles: 2 · around · across triangles.
     */
    public static PolygonSoup torus(double ringRadius, double tubeRadius, int around, int across) {
        if (around < 3 || across < 3) {
            throw new IllegalArgumentException("a torus needs at least 3 segments each way");
        }
        PolygonSoup soup = new PolygonSoup();
        for (int i = 0; i < around; i++) {
            double u = 2 * Math.PI * i / around;
            for (int j = 0; j < across; j++) {
                double w = 2 * Math.PI * j / across;
                double r = ringRadius + tubeRadius * Math.cos(w);
                soup.addVertex(r * Math.cos(u), r * Math.sin(u), tubeRadius * Math.sin(w));
            }
        }
        for (int i = 0; i < around; i++) {
            for (int j = 0; j < across; j++) {
                int a = i * across + j;
                int b = ((i + 1) % around) * across + j;
                int c = ((i + 1) % around) * across + (j + 1) % across;
                int d = i * across + (j + 1) % across;
                soup.addTriangle(a, b, c);
                soup.addTriangle(a, c, d);
            }
        }
        return soup;
    }

    /** One acute scalene triangle in the plane z = 0. */
    public static PolygonSoup triangle() {
        PolygonSoup soup = new PolygonSoup();
        soup.addVertex(0, 0, 0);
        soup.addVertex(4, 0, 0);
        soup.addVertex(1.5, 3, 0);
        soup.addTriangle(0, 1, 2);
        return soup;
    }

    /**
     * The twelve-triangle flat sheet of the seed's Figure 3: a slightly irregular 3 by 2 grid of
     * quadrilaterals, each cut along alternating diagonals, so that the dual graph has vertices
     * of degree one, two and three.
     */
    public static PolygonSoup figure3() {
        PolygonSoup soup = new PolygonSoup();
        double[][] jitter = {{0, 0}, {0.1, -0.15}, {-0.1, 0.1}, {0, 0}, {0.15, 0.1}, {-0.2, 0.05},
            {0.1, 0.15}, {0.05, -0.1}, {0, 0.2}, {-0.1, 0}, {0.1, -0.1}, {0, 0}};
        for (int j = 0; j <= 2; j++) {
            for (int i = 0; i <= 3; i++) {
                double[] d = jitter[j * 4 + i];
                soup.addVertex(i + d[0], j + d[1], 0);
            }
        }
        for (int j = 0; j < 2; j++) {
            for (int i = 0; i < 3; i++) {
                int a = j * 4 + i;
                int b = a + 1;
                int c = a + 5;
                int d = a + 4;
                if ((i + j) % 2 == 0) {
                    soup.addTriangle(a, b, c);
                    soup.addTriangle(a, c, d);
                } else {
                    soup.addTriangle(a, b, d);
                    soup.addTriangle(b, c, d);
                }
            }
        }
        return soup;
    }
}
