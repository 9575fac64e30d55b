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
        // On corners taken relative to the first and scaled to order 1 (halved first, so that
        // coordinates near 1e308 do not overflow): the normal's direction and the area test are
        // the same for a polygon of side 1e-100 or 1e154 as for one of side 1.
        int first = 3 * polygon[0];
        double scale = 0;
        for (int i = 0; i < size; i++) {
            for (int axis = 0; axis < 3; axis++) {
                scale = Math.max(scale, Math.abs(xyz[3 * polygon[i] + axis] * 0.5 - xyz[first + axis] * 0.5));
            }
        }
        if (!(scale > 0) || !Double.isFinite(scale)) {
            dest[0] = 0;
            dest[1] = 0;
            dest[2] = 0;
            return false;
        }
        double nx = 0;
        double ny = 0;
        double nz = 0;
        double longest = 0;
        for (int i = 0; i < size; i++) {
            int pa = 3 * polygon[i];
            int pb = 3 * polygon[(i + 1) % size];
            double px = (xyz[pa] * 0.5 - xyz[first] * 0.5) / scale;
            double py = (xyz[pa + 1] * 0.5 - xyz[first + 1] * 0.5) / scale;
            double pz = (xyz[pa + 2] * 0.5 - xyz[first + 2] * 0.5) / scale;
            double qx = (xyz[pb] * 0.5 - xyz[first] * 0.5) / scale;
            double qy = (xyz[pb + 1] * 0.5 - xyz[first + 1] * 0.5) / scale;
            double qz = (xyz[pb + 2] * 0.5 - xyz[first + 2] * 0.5) / scale;
            nx += (py - qy) * (pz + qz);
            ny += (pz - qz) * (px + qx);
            nz += (px - qx) * (py + qy);
            longest = Math.max(longest, (px - qx) * (px - qx) + (py - qy) * (py - qy) + (pz - qz) * (pz - qz));
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
