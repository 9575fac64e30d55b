package ifold.job;

import ifold.mesh.HalfedgeMesh;

/**
 * Moves a model far from the origin to about its own centre before it is wrapped. A double
 * near 1e15 is good to 0.125: a cube of side 1 there cannot hold paper a thousandth thick, and
 * every fold computed at those coordinates rounds by as much (the paper came out torn into
 * thousands of pieces, stretched 13 times). About its centre the same cube is the cube at the
 * origin, and wraps as it does.
 */
public final class NearOrigin {
    private NearOrigin() {
    }

    /**
     * Moves {@code mesh}, in place, by the offset returned: along each axis on which the model
     * lies farther from the origin than 16 times its size, the point nearest its centre on a
     * grid of a power of two at least 4 times its size; elsewhere 0, so that a model near the
     * origin is not moved at all. The move is exact: every coordinate then lies within a
     * factor of two of the offset, where a difference of doubles rounds nothing (Sterbenz), so
     * the moved model is the same shape to the last bit.
     *
     * @return the offset subtracted from every vertex, x, y, z (all 0 where nothing moved)
     */
    public static double[] move(HalfedgeMesh mesh) {
        int n = mesh.vertexCount();
        double[] offset = new double[3];
        if (n == 0) {
            return offset;
        }
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (int v = 0; v < n; v++) {
            for (int axis = 0; axis < 3; axis++) {
                min[axis] = Math.min(min[axis], mesh.coordinate(v, axis));
                max[axis] = Math.max(max[axis], mesh.coordinate(v, axis));
            }
        }
        double size = 0;
        for (int axis = 0; axis < 3; axis++) {
            size = Math.max(size, max[axis] - min[axis]);
        }
        if (!(size > 0) || !Double.isFinite(size)) {
            return offset; // nothing to wrap, or nothing a move could help; the wrap says why
        }
        // The smallest power of two at least 4 times the size: x - offset is then within the grid
        // step of the offset, and the offset (a whole number of steps) at least 16 steps out.
        double grid = Math.scalb(1.0, Math.getExponent(size) + 3);
        boolean moved = false;
        for (int axis = 0; axis < 3; axis++) {
            double centre = min[axis] / 2 + max[axis] / 2;
            if (Math.abs(centre) >= 16 * grid) {
                offset[axis] = Math.rint(centre / grid) * grid;
                moved = true;
            }
        }
        if (moved) {
            for (int v = 0; v < n; v++) {
                mesh.setPosition(v, mesh.x(v) - offset[0], mesh.y(v) - offset[1], mesh.z(v) - offset[2]);
            }
        }
        return offset;
    }

    /** Whether {@link #move} moved the model. */
    public static boolean moved(double[] offset) {
        return offset[0] != 0 || offset[1] != 0 || offset[2] != 0;
    }
}
