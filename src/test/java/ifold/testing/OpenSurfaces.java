package ifold.testing;

import ifold.mesh.PolygonSoup;

/** Surfaces with a boundary, made for the tests: a tube open at both ends, a flat grid. */
public final class OpenSurfaces {
    private OpenSurfaces() {
    }

    /**
     * A tube of radius 1 open at both ends: {@code around} squares round it in each of
     * {@code along} rings, each cut into two triangles on the same diagonal, so every triangle of
     * an end ring has one side on the boundary.
     */
    public static PolygonSoup tube(int around, int along) {
        PolygonSoup soup = new PolygonSoup();
        for (int j = 0; j <= along; j++) {
            for (int i = 0; i < around; i++) {
                double a = 2 * Math.PI * i / around;
                soup.addVertex(Math.cos(a), Math.sin(a), 0.25 * j);
            }
        }
        for (int j = 0; j < along; j++) {
            for (int i = 0; i < around; i++) {
                int a = j * around + i;
                int b = j * around + (i + 1) % around;
                int c = b + around;
                int d = a + around;
                soup.addTriangle(a, b, c);
                soup.addTriangle(a, c, d);
            }
        }
        return soup;
    }

    /**
     * A flat n × n grid of unit squares, each cut into two triangles on the same diagonal: the
     * triangle at two of its corners has two sides on the boundary (an ear).
     */
    public static PolygonSoup grid(int n) {
        PolygonSoup soup = new PolygonSoup();
        for (int j = 0; j <= n; j++) {
            for (int i = 0; i <= n; i++) {
                soup.addVertex(i, j, 0);
            }
        }
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) {
                int a = j * (n + 1) + i;
                int b = a + 1;
                int c = b + n + 1;
                int d = a + n + 1;
                soup.addTriangle(a, b, c);
                soup.addTriangle(a, c, d);
            }
        }
        return soup;
    }
}
