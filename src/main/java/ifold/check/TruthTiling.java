package ifold.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * Truth 1 of {@link WrapTruths}: each strip's paper coordinates tile its L × w rectangle once,
 * and the strip is one piece in space.
 */
final class TruthTiling {
    private final WrapTruths wrap;

    TruthTiling(WrapTruths wrap) {
        this.wrap = wrap;
    }

    void checkStripsAreTiledOnce(TruthReport report, double eps) {
        // v and vt indices are separate spaces; each must stay within one strip.
        for (boolean positions : new boolean[] {true, false}) {
            int[] index = positions ? wrap.cornerV : wrap.cornerT;
            int[] owner = new int[positions ? wrap.xyz.length / 3 : wrap.uv.length / 2];
            Arrays.fill(owner, -1);
            for (int f = 0; f < wrap.faces(); f++) {
                for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                    int i = index[c];
                    if (owner[i] < 0) {
                        owner[i] = wrap.faceStrip[f];
                    } else if (owner[i] != wrap.faceStrip[f] && owner[i] != wrap.strips()) {
                        report.add(WrapTruths.TILED, (positions ? "vertex " : "paper coordinate ") + (i + 1) + " is used by "
                                + wrap.stripNames.get(owner[i]) + " and by " + wrap.face(f));
                        // Reported once.
                        owner[i] = wrap.strips();
                    }
                }
            }
        }
        int[] parent = new int[wrap.xyz.length / 3];
        for (int s = 0; s < wrap.strips(); s++) {
            checkTiling(report, s);
            checkOnePiece(report, s, parent, eps);
        }
    }

    void checkTiling(TruthReport report, int s) {
        String strip = wrap.stripNames.get(s);
        int[] paper = wrap.stripPaper.get(s);
        if (paper.length == 0) {
            report.add(WrapTruths.TILED, strip + " has no paper faces");
            return;
        }
        double length = wrap.stripL[s];
        double width = wrap.stripW[s];
        double tol = WrapTruths.RELATIVE * Math.hypot(length, width);
        if (Math.abs(wrap.stripMinU[s]) > tol || Math.abs(wrap.stripMinV[s]) > tol) {
            report.add(WrapTruths.TILED, strip + "'s sheet starts at " + WrapTruths.point(wrap.stripMinU[s], wrap.stripMinV[s]) + ", not at (0, 0)");
        }
        double area = 0;
        for (int f : paper) {
            double faceSize = wrap.surface.sheetSize(f);
            if (!(Math.abs(wrap.surface.sheetArea(f)) > WrapTruths.RELATIVE * faceSize * faceSize)) {
                report.add(WrapTruths.TILED, wrap.face(f) + " has no area on the sheet");
            } else if (!sheetConvex(f)) {
                report.add(WrapTruths.TILED, wrap.face(f) + " is not a convex polygon on the sheet");
            }
            area += Math.abs(wrap.surface.sheetArea(f));
        }
        if (!(Math.abs(area - length * width) <= WrapTruths.RELATIVE * length * width)) {
            report.add(WrapTruths.TILED, strip + "'s paper faces have area " + area + " on the sheet, not L * w = " + length + " * " + width
                    + " = " + length * width);
        }
        // A cap's corners lie on one crease of the sheet, each good to about 1e-16 of the strip's
        // length: a short cap far along a long strip has that much area across its length.
        double rounding = 1e-13 * Math.hypot(length, width);
        for (int f : wrap.stripCaps.get(s)) {
            double faceSize = wrap.surface.sheetSize(f);
            if (Math.abs(wrap.surface.sheetArea(f)) > WrapTruths.RELATIVE * Math.max(faceSize * faceSize, tol * tol) + rounding * faceSize) {
                report.add(WrapTruths.TILED, "cap " + wrap.face(f) + " has area " + Math.abs(wrap.surface.sheetArea(f)) + " on the sheet, not 0");
            }
        }
        double[] boxes = new double[6 * paper.length];
        for (int i = 0; i < paper.length; i++) {
            wrap.surface.sheetBox(paper[i], tol, boxes, 6 * i);
        }
        TruthGrid grid = new TruthGrid(boxes, paper.length, TruthGrid.cellFor(boxes, paper.length, tol));
        Ints candidates = new Ints();
        int gaps = 0;
        int overlaps = 0;
        String firstGap = "";
        String firstOverlap = "";
        for (int i = 0; i < WrapTruths.SAMPLES_U; i++) {
            double u = (i + WrapTruths.OFFSET_U) / WrapTruths.SAMPLES_U * length;
            for (int j = 0; j < WrapTruths.SAMPLES_V; j++) {
                double v = (j + WrapTruths.OFFSET_V) / WrapTruths.SAMPLES_V * width;
                grid.query(u, v, 0, u, v, 0, candidates);
                int touching = 0;
                int inside = 0;
                int first = -1;
                int second = -1;
                for (int k = 0; k < candidates.size(); k++) {
                    int f = paper[candidates.get(k)];
                    double depth = wrap.surface.sheetDepth(f, u, v);
                    if (depth >= -tol) {
                        touching++;
                    }
                    // Strictly inside by more than the tolerance: a point on a crease is in both faces.
                    if (depth > tol) {
                        inside++;
                        first = first < 0 ? f : first;
                        second = first != f ? f : second;
                    }
                }
                if (touching == 0 && gaps++ == 0) {
                    firstGap = WrapTruths.point(u, v);
                }
                if (inside > 1 && overlaps++ == 0) {
                    firstOverlap = WrapTruths.point(u, v) + " (in " + wrap.face(first) + " and " + wrap.face(second) + ")";
                }
            }
        }
        int samples = WrapTruths.SAMPLES_U * WrapTruths.SAMPLES_V;
        if (gaps > 0) {
            report.add(WrapTruths.TILED, gaps + " of " + samples + " sheet points of " + strip + " lie in no paper face, the first " + firstGap);
        }
        if (overlaps > 0) {
            report.add(WrapTruths.TILED, overlaps + " of " + samples + " sheet points of " + strip + " lie in two paper faces, the first "
                    + firstOverlap);
        }
    }

    /** Whether face f turns one way only, once round, on the sheet (collinear corners allowed). */
    boolean sheetConvex(int f) {
        int start = wrap.faceStart[f];
        int n = wrap.faceStart[f + 1] - start;
        double sign = Math.signum(wrap.surface.sheetArea(f));
        double turning = 0;
        double tol = WrapTruths.RELATIVE * wrap.surface.sheetSize(f);
        double rounding = 1e-15 * Math.hypot(wrap.stripL[wrap.faceStrip[f]], wrap.stripW[wrap.faceStrip[f]]);
        for (int k = 0; k < n; k++) {
            int a = wrap.cornerT[start + k];
            int b = wrap.cornerT[start + (k + 1) % n];
            int c = wrap.cornerT[start + (k + 2) % n];
            double e1u = wrap.uv[2 * b] - wrap.uv[2 * a];
            double e1v = wrap.uv[2 * b + 1] - wrap.uv[2 * a + 1];
            double e2u = wrap.uv[2 * c] - wrap.uv[2 * b];
            double e2v = wrap.uv[2 * c + 1] - wrap.uv[2 * b + 1];
            // A repeated corner turns nowhere.
            if (Math.hypot(e1u, e1v) <= tol || Math.hypot(e2u, e2v) <= tol) {
                continue;
            }
            double cross = e1u * e2v - e1v * e2u;
            double dot = e1u * e2u + e1v * e2v;
            // A corner good to about 1e-16 of the strip's length turns a short side by that much.
            if (sign * cross < -WrapTruths.RELATIVE * Math.hypot(e1u, e1v) * Math.hypot(e2u, e2v) - rounding * (Math.hypot(e1u, e1v) + Math.hypot(e2u, e2v))) {
                return false;
            }
            turning += Math.atan2(sign * cross, dot);
        }
        // One way round: 2 pi; a star polygon turns one way too but two or more times round.
        return Math.abs(turning - 2 * Math.PI) < WrapTruths.TURNING;
    }

    /** Strip s is one piece in space: its faces joined through shared vertices or vertices at one position. */
    void checkOnePiece(TruthReport report, int s, int[] parent, double eps) {
        Ints used = new Ints();
        boolean[] seen = new boolean[parent.length];
        for (int[] faces : List.of(wrap.stripPaper.get(s), wrap.stripCaps.get(s))) {
            for (int f : faces) {
                for (int c = wrap.faceStart[f]; c < wrap.faceStart[f + 1]; c++) {
                    int v = wrap.cornerV[c];
                    if (!seen[v]) {
                        seen[v] = true;
                        used.add(v);
                        parent[v] = v;
                    }
                }
                for (int c = wrap.faceStart[f] + 1; c < wrap.faceStart[f + 1]; c++) {
                    union(parent, wrap.cornerV[wrap.faceStart[f]], wrap.cornerV[c]);
                }
            }
        }
        if (used.size() == 0) {
            return;
        }
        int[] vertices = used.toArray();
        TruthGrid grid = pointGrid(vertices, eps);
        Ints near = new Ints();
        for (int v : vertices) {
            grid.query(wrap.xyz[3 * v] - eps, wrap.xyz[3 * v + 1] - eps, wrap.xyz[3 * v + 2] - eps,
                    wrap.xyz[3 * v] + eps, wrap.xyz[3 * v + 1] + eps, wrap.xyz[3 * v + 2] + eps, near);
            for (int k = 0; k < near.size(); k++) {
                int w = vertices[near.get(k)];
                if (WrapTruths.distance(wrap.xyz, 3 * v, wrap.xyz, 3 * w) <= eps) {
                    union(parent, v, w);
                }
            }
        }
        Map<Integer, Integer> pieces = new LinkedHashMap<>();
        for (int[] faces : List.of(wrap.stripPaper.get(s), wrap.stripCaps.get(s))) {
            for (int f : faces) {
                pieces.putIfAbsent(find(parent, wrap.cornerV[wrap.faceStart[f]]), f);
            }
        }
        if (pieces.size() > 1) {
            List<Integer> firsts = new ArrayList<>(pieces.values());
            report.add(WrapTruths.TILED, wrap.stripNames.get(s) + " falls apart into " + pieces.size() + " pieces in space: " + wrap.face(firsts.get(0))
                    + " and " + wrap.face(firsts.get(1)) + " are not joined");
        }
    }

    static int find(int[] parent, int v) {
        int root = v;
        while (parent[root] != root) {
            root = parent[root];
        }
        while (parent[v] != root) {
            int next = parent[v];
            parent[v] = root;
            v = next;
        }
        return root;
    }

    static void union(int[] parent, int a, int b) {
        int ra = find(parent, a);
        int rb = find(parent, b);
        if (ra != rb) {
            parent[ra] = rb;
        }
    }

    /** A grid of the given vertices' positions, for lookups within eps. */
    TruthGrid pointGrid(int[] vertices, double eps) {
        double[] boxes = new double[6 * vertices.length];
        for (int i = 0; i < vertices.length; i++) {
            for (int d = 0; d < 3; d++) {
                boxes[6 * i + d] = wrap.xyz[3 * vertices[i] + d];
                boxes[6 * i + 3 + d] = wrap.xyz[3 * vertices[i] + d];
            }
        }
        return new TruthGrid(boxes, vertices.length, 4 * eps);
    }
}
