package ifold.geom;

/** Measures of polygons given as lists of vertex indices into an interleaved coordinate array. */
public final class Polygons {
    private Polygons() {
    }

    /**
     * Writes Newell's normal of the polygon to {@code dest}: twice the vector area, which is
     * robust for non-convex and slightly non-planar polygons.
     *
     * @return whether the polygon has area in the sense of {@link Tolerance#DEGENERATE_AREA}
     */
    public static boolean newellNormal(double[] xyz, int[] polygon, int size, double[] dest) {
        double nx = 0;
        double ny = 0;
        double nz = 0;
        double longest = 0;
        for (int i = 0; i < size; i++) {
            int a = polygon[i];
            int b = polygon[(i + 1) % size];
            int pa = 3 * a;
            int pb = 3 * b;
            nx += (xyz[pa + 1] - xyz[pb + 1]) * (xyz[pa + 2] + xyz[pb + 2]);
            ny += (xyz[pa + 2] - xyz[pb + 2]) * (xyz[pa] + xyz[pb]);
            nz += (xyz[pa] - xyz[pb]) * (xyz[pa + 1] + xyz[pb + 1]);
            longest = Math.max(longest, Triangles.distanceSquared(xyz, a, b));
        }
        dest[0] = nx;
        dest[1] = ny;
        dest[2] = nz;
        return !Tolerance.isDegenerateTriangle(Math.sqrt(nx * nx + ny * ny + nz * nz), longest);
    }

    /** Whether the polygon has area in the sense of {@link Tolerance#DEGENERATE_AREA}. */
    public static boolean hasArea(double[] xyz, int[] polygon, int size) {
        return newellNormal(xyz, polygon, size, new double[3]);
    }
}
