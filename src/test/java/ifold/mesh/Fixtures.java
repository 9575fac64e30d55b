package ifold.mesh;

/** Small meshes written inline, grouped by kind, for the tests of the mesh packages. */
public final class Fixtures {
    private Fixtures() {
    }

    /** A soup from vertex coordinates (x, y, z triples) and faces given as index arrays. */
    public static PolygonSoup soup(double[] xyz, int[]... faces) {
        PolygonSoup soup = new PolygonSoup();
        for (int i = 0; i < xyz.length; i += 3) {
            soup.addVertex(xyz[i], xyz[i + 1], xyz[i + 2]);
        }
        for (int[] face : faces) {
            soup.addFace(face, face.length, 0);
        }
        return soup;
    }

    /** The unit square as two triangles: open, one boundary loop. */
    public static PolygonSoup square() {
        return soup(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}, new int[] {0, 1, 2}, new int[] {0, 2, 3});
    }

    /** Six triangles around a centre vertex: an interior vertex of valence 6. */
    public static PolygonSoup oneRing() {
        double[] xyz = new double[3 * 7];
        for (int i = 0; i < 6; i++) {
            xyz[3 * (i + 1)] = Math.cos(Math.PI * i / 3);
            xyz[3 * (i + 1) + 1] = Math.sin(Math.PI * i / 3);
        }
        int[][] faces = new int[6][];
        for (int i = 0; i < 6; i++) {
            faces[i] = new int[] {0, 1 + i, 1 + (i + 1) % 6};
        }
        return soup(xyz, faces);
    }

    /** An L-shaped hexagon: one non-convex polygon. */
    public static PolygonSoup lShape() {
        return soup(new double[] {0, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 1, 2, 0, 0, 2, 0}, new int[] {0, 1, 2, 3, 4, 5});
    }

    /** An open cone: a fan of five triangles around an apex, not closed at the base. */
    public static PolygonSoup openCone() {
        double[] xyz = new double[3 * 6];
        xyz[2] = 1;
        for (int i = 0; i < 5; i++) {
            xyz[3 * (i + 1)] = Math.cos(2 * Math.PI * i / 5);
            xyz[3 * (i + 1) + 1] = Math.sin(2 * Math.PI * i / 5);
        }
        int[][] faces = new int[5][];
        for (int i = 0; i < 5; i++) {
            faces[i] = new int[] {0, 1 + i, 1 + (i + 1) % 5};
        }
        return soup(xyz, faces);
    }

    /** Two triangles that touch only at vertex 0: a pinch (non-manifold vertex). */
    public static PolygonSoup bowtie() {
        return soup(new double[] {0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0},
                new int[] {0, 1, 2}, new int[] {0, 3, 4});
    }

    /** Three triangles sharing edge 0-1: a non-manifold edge. */
    public static PolygonSoup book() {
        return soup(new double[] {0, 0, 0, 0, 0, 1, 1, 0, 0, -1, 0, 0, 0, 1, 0},
                new int[] {0, 1, 2}, new int[] {1, 0, 3}, new int[] {1, 0, 4});
    }

    /** A Moebius band of five quads: no orientation exists. */
    public static PolygonSoup moebius() {
        int n = 5;
        double[] xyz = new double[3 * 2 * n];
        for (int i = 0; i < n; i++) {
            double u = 2 * Math.PI * i / n;
            double twist = u / 2;
            for (int s = 0; s < 2; s++) {
                double w = s == 0 ? -0.3 : 0.3;
                double r = 1 + w * Math.cos(twist);
                xyz[3 * (2 * i + s)] = r * Math.cos(u);
                xyz[3 * (2 * i + s) + 1] = r * Math.sin(u);
                xyz[3 * (2 * i + s) + 2] = w * Math.sin(twist);
            }
        }
        int[][] faces = new int[n][];
        for (int i = 0; i < n; i++) {
            int a = 2 * i;
            int b = 2 * i + 1;
            // After a full turn the band comes back upside down: bottom meets top.
            int c = i + 1 < n ? 2 * (i + 1) + 1 : 0;
            int d = i + 1 < n ? 2 * (i + 1) : 1;
            faces[i] = new int[] {a, d, c, b};
        }
        return soup(xyz, faces);
    }

    public static HalfedgeMesh build(PolygonSoup soup) {
        try {
            return MeshBuilder.build(soup).mesh();
        } catch (InvalidMeshException e) {
            throw new AssertionError(e);
        }
    }
}
