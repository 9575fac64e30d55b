package ifold.wrap;

import static ifold.wrap.PathPlan.narrowestFitting;
import static ifold.wrap.PathPlan.passes;

import ifold.mesh.IndexedPolygons;
import java.util.List;
import java.util.Locale;
import java.util.function.DoubleToLongFunction;

/**
 * The tucks at the hosts' sharp corners, known before any fold. The naïve tuck-under bounces
 * a flap between the edges of a corner of θ degrees about 180/θ times, each bounce a tuck
 * (181, 601 and 1,801 tucks on the triangles with a corner of 1°, 0.3° and 0.1°, whatever the
 * width), and every one of them cut at least 2 faces; the first few cut through every pass's
 * turns along the host's edges, about 5 faces a pass of the host more in all (5.1 at 1°, 6.1 at
 * 0.3°). The passes' own floor ({@link PathPlan#faces}) leaves them out: a triangle with a
 * corner of 0.001° has a floor of 486,192 faces for its 243,096 passes, under the limit, and
 * ran 22 s and 1.25 GiB into the limit in its second tuck. Counted here, it is refused at once.
 */
final class CornerTucks {
    /**
     * Corners sharper than this, in degrees, are counted: there the bounces (180 and more)
     * outnumber a host's other tucks (7 to 19 on a path triangle at corners of 90° to 10°).
     */
    static final double SHARP_DEGREES = 1;
    /** The fewest faces a tuck at a sharp corner was seen to make. */
    static final int FEWEST_FACES_A_TUCK = 2;
    /** The faces the first tucks at a sharp corner likely make, a pass of the host's triangles. */
    static final int LIKELY_FACES_A_PASS = 5;

    /** Per host: its smallest corner's angle in degrees. */
    private final double[] smallest;
    /** Per host: the vertex of the path at its smallest corner. */
    private final int[] cornerVertex;
    /** The host of each triangle of the path. */
    private final int[] hostOf;

    private CornerTucks(double[] smallest, int[] cornerVertex, int[] hostOf) {
        this.smallest = smallest;
        this.cornerVertex = cornerVertex;
        this.hostOf = hostOf;
    }

    /** The hosts' smallest corners, from the path's vertices. */
    static CornerTucks of(IndexedPolygons mesh, HostPieces pieces) {
        int hosts = pieces.hostCount();
        double[] smallest = new double[hosts];
        int[] cornerVertex = new int[hosts];
        for (int h = 0; h < hosts; h++) {
            int[] corners = pieces.corners[h];
            int n = corners.length;
            smallest[h] = 180;
            cornerVertex[h] = corners[0];
            for (int k = 0; k < n; k++) {
                double degrees = angle(mesh, corners[(k + n - 1) % n], corners[k], corners[(k + 1) % n]);
                if (degrees < smallest[h]) {
                    smallest[h] = degrees;
                    cornerVertex[h] = corners[k];
                }
            }
        }
        return new CornerTucks(smallest, cornerVertex, pieces.hostOf);
    }

    /** The angle at vertex v between its neighbours a and b, in degrees: atan2 of the cross and dot products, exact for needles. */
    private static double angle(IndexedPolygons mesh, int a, int v, int b) {
        double[] p = Wrap.position(mesh, v);
        double[] u = Wrap.position(mesh, a);
        double[] w = Wrap.position(mesh, b);
        for (int axis = 0; axis < 3; axis++) {
            u[axis] -= p[axis];
            w[axis] -= p[axis];
        }
        double cx = u[1] * w[2] - u[2] * w[1];
        double cy = u[2] * w[0] - u[0] * w[2];
        double cz = u[0] * w[1] - u[1] * w[0];
        double dot = u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
        return Math.toDegrees(Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), dot));
    }

    /**
     * The tucks a corner of {@code degrees} likely takes: a flap's bounces, 180/θ. Where only
     * the turn into a last pass reaches round the corner ({@code StripFolding.stopShort}), the
     * 135° of paper there take 3/4 of them (a needle's 0.9°, 0.5° and 0.3° corners about 150,
     * 270 and 450 tucks), each cutting more than 2 faces: the faces counted stay under those made
     * (begun at its own start, 2,111 against a floor of 962 at 0.9°).
     */
    static long tucks(double degrees) {
        return (long) Math.ceil(180 / degrees);
    }

    /** Whether host h has a corner sharper than {@link #SHARP_DEGREES}. */
    boolean sharp(int h) {
        return smallest[h] < SHARP_DEGREES;
    }

    /** The fewest faces the tucks at the sharp corners make: 2 a bounce. */
    long fewestFaces() {
        long faces = 0;
        for (int h = 0; h < smallest.length; h++) {
            faces += sharp(h) ? FEWEST_FACES_A_TUCK * tucks(smallest[h]) : 0;
        }
        return faces;
    }

    /** The faces the tucks at the sharp corners likely make at {@code width}: 2 a bounce, and 5 a pass of each sharp host's triangles. */
    long likelyFaces(List<PathPlan> plans, double width) {
        long faces = fewestFaces();
        for (PathPlan plan : plans) {
            for (int i = 0; i < plan.m; i++) {
                faces += sharp(hostOf[plan.first + i]) ? (long) LIKELY_FACES_A_PASS * passes(plan.frames[i].altitude(), width) : 0;
            }
        }
        return faces;
    }

    /** The tucks the sharp corners likely take, all together. */
    long tucks() {
        long tucks = 0;
        for (int h = 0; h < smallest.length; h++) {
            tucks += sharp(h) ? tucks(smallest[h]) : 0;
        }
        return tucks;
    }

    /** The host with the sharpest corner, or -1 where no corner is sharp. */
    int sharpest() {
        int sharpest = -1;
        for (int h = 0; h < smallest.length; h++) {
            if (sharp(h) && (sharpest < 0 || smallest[h] < smallest[sharpest])) {
                sharpest = h;
            }
        }
        return sharpest;
    }

    /**
     * Why a wrap whose passes fit is refused for its sharp corners' tucks, in one line: the
     * sharpest corner and its angle, the tucks and the faces they make with the passes, and
     * the narrowest strip likely to fit, or that none does.
     */
    String refusal(IndexedPolygons mesh, List<PathPlan> plans, boolean[] alone, double width, double widest, long passes,
            long passesFewest, int limit) {
        int h = sharpest();
        DoubleToLongFunction likely = w -> PathPlan.faces(plans, w, alone, true) + likelyFaces(plans, w);
        double fits = narrowestFitting(likely, width, widest, limit);
        double[] p = Wrap.position(mesh, cornerVertex[h]);
        int sharpCorners = 0;
        for (int g = 0; g < smallest.length; g++) {
            sharpCorners += sharp(g) ? 1 : 0;
        }
        return String.format(Locale.ROOT, "a strip %.4g wide would need %,d passes, and the corner of %.2g degrees at (%.6g %.6g %.6g)%s"
                + " about %,d tucks (a flap tucked there bounces between its edges about 180/angle times): at least %,d faces of paper"
                + " (%,d for the passes, %d a tuck; likely about %,d), more than the limit of %,d faces; %s", width, passes, smallest[h],
                p[0], p[1], p[2], sharpCorners > 1 ? String.format(Locale.ROOT, " with %d other host%s corners under %.0f degree", sharpCorners - 1,
                sharpCorners > 2 ? "s'" : "'s", SHARP_DEGREES) : "", tucks(), passesFewest + fewestFaces(), passesFewest, FEWEST_FACES_A_TUCK,
                likely.applyAsLong(width), limit, !Double.isNaN(fits)
                ? String.format(Locale.ROOT, "the narrowest strip that fits is about %.4g wide", fits)
                : fewestFaces() > limit ? "no strip fits: the tucks alone make more; widen the corner"
                : String.format(Locale.ROOT, "no strip the path takes fits: the widest, %.4g, would make about %,d; widen the corner",
                widest, likely.applyAsLong(widest)));
    }

    /** Host h's smallest corner in degrees. */
    double degrees(int h) {
        return smallest[h];
    }

    /** The vertex of the path at host h's smallest corner. */
    int cornerVertex(int h) {
        return cornerVertex[h];
    }
}
