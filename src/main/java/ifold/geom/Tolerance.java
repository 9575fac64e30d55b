package ifold.geom;

/**
 * The numerical tolerances of the geometry core, in one place so that no algorithm invents its
 * own {@code 1e-9}. All are relative: a length is compared with the size of what it belongs to.
 */
public final class Tolerance {
    private Tolerance() {
    }

    /**
     * A triangle whose doubled area is at most this times its longest edge squared is treated as
     * having no area: its smallest angle is then below about 1e-12 radians, far below anything a
     * model means on purpose, and far above the rounding error of the cross product.
     */
    public static final double DEGENERATE_AREA = 1e-12;

    /**
     * Relative agreement asked of lengths and areas that should be equal after an exact
     * construction (refinement preserves area, folding preserves edge lengths).
     */
    public static final double RELATIVE_EQUALITY = 1e-9;

    /**
     * A point this close to a plane, relative to the size of the model, lies on it: fold lines
     * through existing vertices and along existing creases must find them, not cut beside them
     * and leave slivers. Rounding after a few hundred folds stays far below it.
     */
    public static final double ON_PLANE = 1e-9;

    /**
     * Two faces whose unit normals agree to this (1 - the cosine of the angle between them, an
     * angle of about 1.4e-6 radians) and whose corners lie within {@link #ON_PLANE} of each
     * other's plane are one plane: the wrap's hosts and the regions prepared before the
     * refinement are the same.
     */
    public static final double COPLANAR_COSINE = 1e-12;

    /**
     * What a FOLD file's numbers are good to, relative: other tools write them in single
     * precision or to seven digits, so points and directions of a crease pattern that agree to
     * this are the same, and a fold angle below this many degrees is no fold.
     */
    public static final double FILE_PRECISION = 1e-7;

    /**
     * The smallest and largest sizes iFold computes with, across a model, a triangle or a sheet:
     * a triangle's frame squares a cross product of edges, the fourth power of their length,
     * which underflows to zero below about 1e-77 and overflows above about 1e77 (every triangle
     * then seems to have no area, every fold the wrong way); a factor of 1e17 either way is left
     * for the areas and measures that follow. A crease pattern 1e85 across came out with its
     * valley a mountain.
     */
    public static final double SMALLEST_SIZE = 1e-60;

    /** See {@link #SMALLEST_SIZE}. */
    public static final double LARGEST_SIZE = 1e60;

    /** Whether a triangle with doubled area {@code twiceArea} and longest edge squared {@code longestSquared} has no area. */
    public static boolean isDegenerateTriangle(double twiceArea, double longestSquared) {
        return !(twiceArea > DEGENERATE_AREA * longestSquared);
    }

    /** Whether {@code a} and {@code b} agree to {@link #RELATIVE_EQUALITY} of the larger magnitude (or of 1 near zero). */
    public static boolean nearlyEqual(double a, double b) {
        double scale = Math.max(1.0, Math.max(Math.abs(a), Math.abs(b)));
        return Math.abs(a - b) <= RELATIVE_EQUALITY * scale;
    }
}
