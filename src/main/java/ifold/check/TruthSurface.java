package ifold.check;

import ifold.check.WrapTruths.Faces;
import java.util.Arrays;
import java.util.HashSet;

/**
 * Truth 5 of {@link WrapTruths}: every paper face lies flat on the model, between 0 and (stack +
 * 1)·T above it, over one triangle or over triangles of one plane whose parts under it add up to
 * its area; caps stay near the surface.
 */
final class TruthSurface {
    private final WrapTruths wrap;

    TruthSurface(WrapTruths wrap) {
        this.wrap = wrap;
    }

    void checkOnSurface(TruthReport report, TruthModel model, Faces geometry, double eps, double top) {
        Ints candidates = new Ints();
        double farthest = Double.NaN;
        for (int f : geometry.paper) {
            double[] box = geometry.box(f);
            double reach = top + eps;
            model.grid.query(box[0] - reach, box[1] - reach, box[2] - reach, box[3] + reach, box[4] + reach, box[5] + reach, candidates);
            double bestMiss = Double.POSITIVE_INFINITY;
            int bestTriangle = -1;
            int parallels = 0;
            boolean rests = false;
            for (int k = 0; k < candidates.size() && !rests; k++) {
                int t = candidates.get(k);
                if (!WrapTruths.parallel(geometry.normal(f), model.normal(t)) && !equallyHigh(f, model, t, eps)) {
                    continue;
                }
                parallels++;
                double miss = restingMiss(f, model, t, eps, top);
                if (miss == 0) {
                    rests = true;
                    double highest = Double.NEGATIVE_INFINITY;
                    for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                        highest = Math.max(highest, model.height(t, wrap.xyz, 3 * wrap.cornerV[c]));
                    }
                    farthest = Double.isNaN(farthest) ? highest : Math.max(farthest, highest);
                } else if (miss < bestMiss) {
                    bestMiss = miss;
                    bestTriangle = t;
                }
            }
            if (!rests) {
                double highest = restsOnPlane(f, model, candidates, eps, top);
                if (!Double.isNaN(highest)) {
                    rests = true;
                    farthest = Double.isNaN(farthest) ? highest : Math.max(farthest, highest);
                }
            }
            if (!rests) {
                report.add(WrapTruths.ON_SURFACE, wrap.face(f) + " rests on no model triangle, nor on triangles of one plane: "
                        + (parallels == 0 ? "none within reach is parallel to it"
                                : parallels + " parallel within reach, the nearest, triangle " + (bestTriangle + 1) + ", "
                                        + restingWhy(f, model, bestTriangle, eps, top)));
            }
        }
        wrap.farthestFromSurface = farthest;
        // Cap vertices: within two stacks of paper of the surface.
        double capReach = 2 * top + eps;
        HashSet<Integer> seen = new HashSet<>();
        for (int f = 0; f < wrap.faces(); f++) {
            if (!wrap.faceCap[f]) {
                continue;
            }
            for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                int v = wrap.cornerV[c];
                if (!seen.add(v)) {
                    continue;
                }
                double x = wrap.xyz[3 * v];
                double y = wrap.xyz[3 * v + 1];
                double z = wrap.xyz[3 * v + 2];
                model.grid.query(x - capReach, y - capReach, z - capReach, x + capReach, y + capReach, z + capReach, candidates);
                double nearest = Double.POSITIVE_INFINITY;
                for (int k = 0; k < candidates.size(); k++) {
                    nearest = Math.min(nearest, model.distanceTo(candidates.get(k), x, y, z));
                }
                if (!(nearest <= capReach)) {
                    report.add(WrapTruths.ON_SURFACE, "cap vertex " + (v + 1) + " " + WrapTruths.point(x, y, z) + " of " + wrap.face(f) + " is "
                            + (nearest == Double.POSITIVE_INFINITY ? "farther than " + capReach : nearest)
                            + " from the surface, more than 2 (maxStack + 1) * thickness = " + 2 * top);
                }
            }
        }
    }

    /**
     * How far paper face f is from resting on model triangle t (0: it rests): the worst of a
     * corner's height outside [-eps, top + eps] and its projection's distance outside t beyond eps
     * (the negative barycentric coordinate times t's longest edge).
     */
    double restingMiss(int f, TruthModel model, int t, double eps, double top) {
        double miss = 0;
        double[] bary = new double[3];
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            int v = wrap.cornerV[c];
            double height = model.height(t, wrap.xyz, 3 * v);
            miss = Math.max(miss, Math.max(-eps - height, height - top - eps));
            model.barycentric(t, wrap.xyz, 3 * v, bary);
            // Outside by more than eps, as every other length here: a billionth of the model, not
            // of the triangle (a tiny triangle's own billionth is below the rounding of its corners).
            double outside = -Math.min(bary[0], Math.min(bary[1], bary[2])) * model.longestEdge(t);
            if (outside > eps) {
                miss = Math.max(miss, outside);
            }
        }
        return miss;
    }

    /**
     * Whether paper face f lies over triangles of one plane that cover it: each corner within
     * [-eps, top + eps] of their plane, and the parts of f over each (its projection clipped to
     * the triangle) adding up to f's area, to eps times its perimeter. The highest corner's
     * height if so, else NaN.
     */
    double restsOnPlane(int f, TruthModel model, Ints candidates, double eps, double top) {
        double[] n = null;
        int plane = -1;
        for (int k = 0; k < candidates.size() && plane < 0; k++) {
            int t = candidates.get(k);
            if (!WrapTruths.parallel(geometryNormal(f), model.normal(t)) && !equallyHigh(f, model, t, eps)) {
                continue;
            }
            boolean within = true;
            for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1] && within; c++) {
                double height = model.height(t, wrap.xyz, 3 * wrap.cornerV[c]);
                within = height >= -eps && height <= top + eps;
            }
            if (within) {
                plane = t;
                n = model.normal(t);
            }
        }
        if (plane < 0) {
            return Double.NaN;
        }
        // A frame in the plane: e1 along the first triangle's first edge, e2 = n × e1.
        double[] e1 = {model.corners[9 * plane + 3] - model.corners[9 * plane], model.corners[9 * plane + 4] - model.corners[9 * plane + 1],
            model.corners[9 * plane + 5] - model.corners[9 * plane + 2]};
        double length = Math.sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        e1 = new double[] {e1[0] / length, e1[1] / length, e1[2] / length};
        double[] e2 = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
        int corners = wrap.faceStart[f + 1] - wrap.faceStart[f];
        double[] face = new double[2 * corners];
        double perimeter = 0;
        double highest = Double.NEGATIVE_INFINITY;
        for (int c = 0; c < corners; c++) {
            int v = wrap.cornerV[wrap.faceStart[f] + c];
            face[2 * c] = wrap.xyz[3 * v] * e1[0] + wrap.xyz[3 * v + 1] * e1[1] + wrap.xyz[3 * v + 2] * e1[2];
            face[2 * c + 1] = wrap.xyz[3 * v] * e2[0] + wrap.xyz[3 * v + 1] * e2[1] + wrap.xyz[3 * v + 2] * e2[2];
            perimeter += WrapTruths.distance(wrap.xyz, 3 * v, wrap.xyz, 3 * wrap.cornerV[wrap.faceStart[f] + (c + 1) % corners]);
            highest = Math.max(highest, model.height(plane, wrap.xyz, 3 * v));
        }
        double whole = Math.abs(twiceArea(face)) / 2;
        double covered = 0;
        for (int k = 0; k < candidates.size(); k++) {
            int t = candidates.get(k);
            if (!WrapTruths.parallel(n, model.normal(t)) || Math.abs(model.height(plane, model.corners, 9 * t)) > eps) {
                continue;
            }
            double[] triangle = new double[6];
            for (int c = 0; c < 3; c++) {
                int i = 9 * t + 3 * c;
                triangle[2 * c] = model.corners[i] * e1[0] + model.corners[i + 1] * e1[1] + model.corners[i + 2] * e1[2];
                triangle[2 * c + 1] = model.corners[i] * e2[0] + model.corners[i + 1] * e2[1] + model.corners[i + 2] * e2[2];
            }
            double[] part = face;
            double sign = Math.signum(twiceArea(triangle));
            for (int c = 0; c < 3 && part != null; c++) {
                double ax = triangle[2 * c];
                double ay = triangle[2 * c + 1];
                double bx = triangle[2 * ((c + 1) % 3)];
                double by = triangle[2 * ((c + 1) % 3) + 1];
                part = clipLeft(part, ax, ay, bx, by, sign);
            }
            if (part != null) {
                covered += Math.abs(twiceArea(part)) / 2;
            }
        }
        return whole - covered <= eps * perimeter ? highest : Double.NaN;
    }

    double[] geometryNormal(int f) {
        double[] n = new double[3];
        int corners = wrap.faceStart[f + 1] - wrap.faceStart[f];
        for (int c = 0; c < corners; c++) {
            int a = 3 * wrap.cornerV[wrap.faceStart[f] + c];
            int b = 3 * wrap.cornerV[wrap.faceStart[f] + (c + 1) % corners];
            n[0] += (wrap.xyz[a + 1] - wrap.xyz[b + 1]) * (wrap.xyz[a + 2] + wrap.xyz[b + 2]);
            n[1] += (wrap.xyz[a + 2] - wrap.xyz[b + 2]) * (wrap.xyz[a] + wrap.xyz[b]);
            n[2] += (wrap.xyz[a] - wrap.xyz[b]) * (wrap.xyz[a + 1] + wrap.xyz[b + 1]);
        }
        double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        return new double[] {n[0] / length, n[1] / length, n[2] / length};
    }

    static double twiceArea(double[] xy) {
        double twice = 0;
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            twice += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
        }
        return twice;
    }

    /** The part of polygon xy on the inner side of the line a → b (its left for sign +1, its right for -1); null if none. */
    static double[] clipLeft(double[] xy, double ax, double ay, double bx, double by, double sign) {
        int n = xy.length / 2;
        double[] out = new double[4 * n + 4];
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            double di = sign * ((bx - ax) * (xy[2 * i + 1] - ay) - (by - ay) * (xy[2 * i] - ax));
            double dj = sign * ((bx - ax) * (xy[2 * j + 1] - ay) - (by - ay) * (xy[2 * j] - ax));
            if (di >= 0) {
                out[2 * m] = xy[2 * i];
                out[2 * m + 1] = xy[2 * i + 1];
                m++;
            }
            if ((di > 0 && dj < 0) || (di < 0 && dj > 0)) {
                double t = di / (di - dj);
                out[2 * m] = xy[2 * i] + t * (xy[2 * j] - xy[2 * i]);
                out[2 * m + 1] = xy[2 * i + 1] + t * (xy[2 * j + 1] - xy[2 * i + 1]);
                m++;
            }
        }
        return m >= 3 ? Arrays.copyOf(out, 2 * m) : null;
    }

    /** restingMiss in words: the first corner that keeps f off t. */
    String restingWhy(int f, TruthModel model, int t, double eps, double top) {
        double[] bary = new double[3];
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            int v = wrap.cornerV[c];
            double height = model.height(t, wrap.xyz, 3 * v);
            if (height < -eps) {
                return "vertex " + (v + 1) + " is " + -height + " below it, inside the solid";
            }
            if (height > top + eps) {
                return "vertex " + (v + 1) + " is " + height + " above it, more than (maxStack + 1) * thickness = " + top;
            }
            model.barycentric(t, wrap.xyz, 3 * v, bary);
            if (-Math.min(bary[0], Math.min(bary[1], bary[2])) * model.longestEdge(t) > eps) {
                return "vertex " + (v + 1) + " lies outside it, at barycentric " + WrapTruths.point(bary);
            }
        }
        return "it rests";
    }

    /** Face f's signed area on the sheet (positive counter-clockwise in u, v). */
    double sheetArea(int f) {
        // From the first corner: far along a long strip, products of whole coordinates would lose
        // the area of a small face in their rounding.
        int first = wrap.cornerT[wrap.faceStart[f]];
        double u0 = wrap.uv[2 * first];
        double v0 = wrap.uv[2 * first + 1];
        double twice = 0;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            int a = wrap.cornerT[c];
            int b = wrap.cornerT[wrap.neighbours.nextCorner(f, c)];
            twice += (wrap.uv[2 * a] - u0) * (wrap.uv[2 * b + 1] - v0) - (wrap.uv[2 * b] - u0) * (wrap.uv[2 * a + 1] - v0);
        }
        return twice / 2;
    }

    /** Face f's size: its longest sheet edge. */
    double sheetSize(int f) {
        double size = 0;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            size = Math.max(size, wrap.neighbours.sheetDistance(c, wrap.neighbours.nextCorner(f, c)));
        }
        return size;
    }

    void sheetBox(int f, double grow, double[] box, int at) {
        box[at] = box[at + 1] = Double.POSITIVE_INFINITY;
        box[at + 3] = box[at + 4] = Double.NEGATIVE_INFINITY;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            int t = wrap.cornerT[c];
            box[at] = Math.min(box[at], wrap.uv[2 * t] - grow);
            box[at + 1] = Math.min(box[at + 1], wrap.uv[2 * t + 1] - grow);
            box[at + 3] = Math.max(box[at + 3], wrap.uv[2 * t] + grow);
            box[at + 4] = Math.max(box[at + 4], wrap.uv[2 * t + 1] + grow);
        }
        box[at + 2] = box[at + 5] = 0;
    }

    /** The least signed distance from (u, v) to face f's sheet edges: positive inside. f must be convex. */
    double sheetDepth(int f, double u, double v) {
        double sign = Math.signum(sheetArea(f));
        double depth = Double.POSITIVE_INFINITY;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            int a = wrap.cornerT[c];
            int b = wrap.cornerT[wrap.neighbours.nextCorner(f, c)];
            double eu = wrap.uv[2 * b] - wrap.uv[2 * a];
            double ev = wrap.uv[2 * b + 1] - wrap.uv[2 * a + 1];
            double length = Math.hypot(eu, ev);
            if (length > 0) {
                depth = Math.min(depth, sign * (eu * (v - wrap.uv[2 * a + 1]) - ev * (u - wrap.uv[2 * a])) / length);
            }
        }
        return depth;
    }

    /**
     * Whether face f is squashed in space to far less than its area on the sheet: crept to a
     * sliver at a concave edge (truth 2 holds such a face to its creep zone), its own normal
     * rounding.
     */
    boolean squashed(int f) {
        double[] n = new double[3];
        int o = 3 * wrap.cornerV[wrap.faceStart[f]];
        for (int c = wrap.faceStart[f] + 1; c + 1 < wrap.faceStart[f + 1]; c++) {
            int i = 3 * wrap.cornerV[c];
            int j = 3 * wrap.cornerV[c + 1];
            double[] e1 = {wrap.xyz[i] - wrap.xyz[o], wrap.xyz[i + 1] - wrap.xyz[o + 1], wrap.xyz[i + 2] - wrap.xyz[o + 2]};
            double[] e2 = {wrap.xyz[j] - wrap.xyz[o], wrap.xyz[j + 1] - wrap.xyz[o + 1], wrap.xyz[j + 2] - wrap.xyz[o + 2]};
            double[] x = TruthIsometry.crossed(e1, e2);
            for (int d = 0; d < 3; d++) {
                n[d] += x[d];
            }
        }
        return Math.sqrt(TruthIsometry.times(n, n)) / 2 < 1e-3 * Math.abs(sheetArea(f));
    }

    /**
     * Whether every corner of face f stands equally high above model triangle t's plane, to
     * {@code eps}: the face lies parallel to it as closely as lengths are measured, though its
     * own normal says otherwise. That normal is noise for a face squashed to a sliver (crept at a
     * concave edge) and for a speck: on fertility's wrap, triangles of paper 7·10⁻⁶ across (its
     * size about 150) leaned by more than the 10⁻⁷ radians of {@link WrapTruths#PARALLEL}, their
     * corners as high as each other to the lengths' tolerance: 5 faces "off the surface".
     */
    boolean equallyHigh(int f, TruthModel model, int t, double eps) {
        double low = Double.POSITIVE_INFINITY;
        double high = Double.NEGATIVE_INFINITY;
        for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
            double height = model.height(t, wrap.xyz, 3 * wrap.cornerV[c]);
            low = Math.min(low, height);
            high = Math.max(high, height);
        }
        return high - low <= eps;
    }
}
