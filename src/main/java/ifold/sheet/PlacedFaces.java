package ifold.sheet;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The sheet's faces as placed on their hosts, and the tests of one against another that folding
 * asks: whether two overlap, where, and whether one holds another (or all of where two
 * overlap). Each face's polygon and bounding box are kept until the face changes, and the
 * answers that a pile asks again at every fold landing on it are kept with the placements they
 * were found for.
 */
final class PlacedFaces {
    private final Sheet sheet;
    private final double tolerance;

    PlacedFaces(Sheet sheet, double tolerance) {
        this.sheet = sheet;
        this.tolerance = tolerance;
    }

    /** Per face h, whether it holds all of the face being placed: {@link #holdsStamp} where it does, one more where not. */
    private int[] holdsMark = new int[16];
    private int holdsStamp;

    int nextHoldsStamp() {
        if (holdsMark.length < sheet.faceCount()) {
            holdsMark = Arrays.copyOf(holdsMark, Math.max(sheet.faceCount(), 2 * holdsMark.length));
        }
        holdsStamp += 2;
        return holdsStamp;
    }

    /** Whether face h, as placed, holds all of face f: asked once a stamp (a face being placed), then remembered. */
    boolean holdsAll(int h, int f, int stamp) {
        if (holdsMark[h] == stamp || holdsMark[h] == stamp + 1) {
            return holdsMark[h] == stamp;
        }
        boolean holds = holdsBox(h, f) && contains(h, f);
        holdsMark[h] = holds ? stamp : stamp + 1;
        return holds;
    }

    /**
     * Whether face h, as placed, holds all of face g: the last answer for g is kept, with the
     * two placements it was found for, since a pile's layers are asked again at every fold
     * landing on it, and a face placed anew is a new placement.
     */
    boolean holdsFace(int h, int g) {
        double[] outer = polygon(h);
        double[] inner = polygon(g);
        if (heldOuter.length <= g) {
            int size = Math.max(g + 1, 2 * heldOuter.length);
            heldOuter = Arrays.copyOf(heldOuter, size);
            heldInner = Arrays.copyOf(heldInner, size);
            heldAnswer = Arrays.copyOf(heldAnswer, size);
        }
        if (heldOuter[g] != outer || heldInner[g] != inner) {
            heldOuter[g] = outer;
            heldInner[g] = inner;
            heldAnswer[g] = holdsBox(h, g) && containsPoints(outer, inner);
        }
        return heldAnswer[g];
    }

    /** {@link #holdsFace}'s last answer by face, and the placements it was for. */
    private double[][] heldOuter = new double[16][];
    private double[][] heldInner = new double[16][];
    private boolean[] heldAnswer = new boolean[16];

    /** Whether the bounding box of face h, as placed, holds that of face f: a quick test before {@link #contains}. */
    boolean holdsBox(int h, int f) {
        polygon(h);
        polygon(f);
        double[] boxH = boxes.get(h);
        double[] boxF = boxes.get(f);
        return boxF[0] >= boxH[0] - tolerance && boxF[1] >= boxH[1] - tolerance && boxF[2] <= boxH[2] + tolerance
                && boxF[3] <= boxH[3] + tolerance;
    }

    /** Whether face h, as placed, holds all of where faces f and g overlap. */
    boolean holdsOverlap(int h, int f, int g) {
        int corners = overlapInPlace(f, g);
        return corners > 0 && containsPoints(polygon(h), overlap, corners);
    }

    /**
     * Where faces f and g, as placed, overlap (a convex polygon): the number of its corners (0
     * where they do not, beyond the tolerance), which are the first numbers of {@link #overlap}
     * until the next call. Not copied out: a tuck asks it of most pairs of faces that overlap,
     * and a copy each was a tenth of what it allocated.
     */
    int overlapInPlace(int f, int g) {
        polygonTests++;
        double[] common = polygon(f);
        int corners = common.length / 2;
        double[] other = polygon(g);
        int n = other.length / 2;
        double orientation = Math.signum(Polygons2.twiceArea(other, n));
        // The steps between in two arrays kept for it, the answer alone made anew.
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = other[2 * j] - other[2 * i];
            double ey = other[2 * j + 1] - other[2 * i + 1];
            double length = Math.sqrt(ex * ex + ey * ey);
            // Inside g: orientation × (e × (p - corner i)) >= 0, as n·p <= c with n of unit length.
            double nx = orientation * ey / length;
            double ny = -orientation * ex / length;
            double c = nx * other[2 * i] + ny * other[2 * i + 1];
            int m = Polygons2.clippedCorners(common, corners, nx, ny, c, tolerance);
            if (m == 0) {
                return 0;
            }
            double[] into = common == clipped[0] ? clipped[1] : clipped[0];
            if (into.length < 2 * m) {
                into = new double[4 * m];
                clipped[common == clipped[0] ? 1 : 0] = into;
            }
            Polygons2.clipInto(common, corners, nx, ny, c, into);
            common = into;
            corners = m;
        }
        overlap = common;
        return corners;
    }

    /** Where {@link #overlapInPlace} clips, step by step. */
    private final double[][] clipped = {new double[32], new double[32]};
    /** Where the last two faces {@link #overlapInPlace} asked of overlap: one of {@link #clipped}, or a face's own polygon. */
    double[] overlap;

    /** Whether face g, as placed, lies wholly inside face h (convex, either way round). */
    boolean contains(int h, int g) {
        return containsPoints(polygon(h), polygon(g));
    }

    /** Whether the points {@code inner} (x y x y ...) lie inside the convex polygon {@code outer}, either way round. */
    boolean containsPoints(double[] outer, double[] inner) {
        return containsPoints(outer, inner, inner.length / 2);
    }

    /** {@link #containsPoints(double[], double[])} for the first {@code points} points of {@code inner}. */
    boolean containsPoints(double[] outer, double[] inner, int points) {
        polygonTests++;
        int n = outer.length / 2;
        double orientation = Math.signum(Polygons2.twiceArea(outer, n));
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double ex = outer[2 * j] - outer[2 * i];
            double ey = outer[2 * j + 1] - outer[2 * i + 1];
            double length = Math.sqrt(ex * ex + ey * ey);
            for (int k = 0; k < 2 * points; k += 2) {
                double cross = ex * (inner[k + 1] - outer[2 * i + 1]) - ey * (inner[k] - outer[2 * i]);
                if (orientation * cross < -tolerance * length) {
                    return false;
                }
            }
        }
        return true;
    }

    /** How many polygon tests (overlap, where two overlap, containment) the sheet has made. */
    private long polygonTests;

    /** How many polygon tests it has made ({@link Sheet#polygonTests}). */
    long polygonTests() {
        return polygonTests;
    }

    boolean overlap(int f, int g) {
        polygonTests++;
        double[] a = polygon(f);
        double[] b = polygon(g);
        // Bounding boxes first: most faces of a triangle lie apart, and this is four comparisons.
        double[] boxA = boxes.get(f);
        double[] boxB = boxes.get(g);
        if (boxA[0] >= boxB[2] - tolerance || boxB[0] >= boxA[2] - tolerance || boxA[1] >= boxB[3] - tolerance
                || boxB[1] >= boxA[3] - tolerance) {
            return false;
        }
        return Polygons2.overlap(a, a.length / 2, extentsOf(f, a), b, b.length / 2, extentsOf(g, b), tolerance);
    }

    /**
     * Face f's own extents ({@link Polygons2#ownExtents}) for its polygon {@code polygon}, found
     * at its first overlap test and kept with the polygon: three in four tests on a wrap are of
     * faces that overlap, for which every axis is projected, and a face is tested against every
     * face near it as it lands and again as others land on it (the 5,000-triangle torus: 8
     * million tests; keeping the last two polygons' extents, a fifth of the tests' time went to
     * finding them again).
     */
    private double[] extentsOf(int f, double[] polygon) {
        double[] own = extents.get(f);
        if (own == null) {
            own = new double[polygon.length];
            Polygons2.ownExtents(polygon, polygon.length / 2, own);
            extents.set(f, own);
        }
        return own;
    }

    /** Each face's corners in its host's frame, its bounding box and its extents (once tested), kept until the face changes. */
    private final List<double[]> placements = new ArrayList<>();
    private final List<double[]> boxes = new ArrayList<>();
    private final List<double[]> extents = new ArrayList<>();

    double[] polygon(int f) {
        while (placements.size() <= f) {
            placements.add(null);
            boxes.add(null);
            extents.add(null);
        }
        double[] xy = placements.get(f);
        if (xy == null) {
            xy = sheet.placed(f);
            placements.set(f, xy);
            boxes.set(f, Polygons2.bounds(xy));
            extents.set(f, null);
        }
        return xy;
    }

    /** Forgets face f's polygon and box: the face changed (moved, cut, turned over). */
    void forget(int f) {
        if (f < placements.size()) {
            placements.set(f, null);
            extents.set(f, null);
        }
    }

    /**
     * Forgets face f's polygon and box for good, and {@link #holdsFace}'s answer for it, the
     * memory they took too: its host is finished (the answers pair faces of one host, so once
     * all of a host's faces are released none keeps a polygon of theirs).
     */
    void release(int f) {
        if (f < placements.size()) {
            placements.set(f, null);
            boxes.set(f, null);
            extents.set(f, null);
        }
        if (f < heldOuter.length) {
            heldOuter[f] = null;
            heldInner[f] = null;
        }
    }
}
