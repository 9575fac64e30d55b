package ifold.wrap;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.SplittableRandom;

/**
 * An independent check of the OBJ that {@code ifold wrap} writes: it reads the file's text itself
 * and knows nothing of how the wrap was computed, only what a wrapped strip must be.
 *
 * <p>The file holds strips ({@code o strip-K}); each has vertices ({@code v x y z}) with paper
 * coordinates ({@code vt u v}, where the vertex lies on the unfolded strip) and faces in two
 * groups: {@code g paper} (convex polygons of the sheet) and {@code g cap} (the bent paper at a
 * fold, zero area on the sheet). A strip's sheet is the rectangle [0, L] x [0, w] with L and w the
 * largest u and v of its paper faces. {@link #check} tests the five truths of a wrap:
 * <ol>
 * <li>{@link #TILED}: each strip's paper faces tile its rectangle once, and the strip is one piece
 * in space;</li>
 * <li>{@link #ISOMETRIC}: each paper face is planar and congruent to its sheet polygon; but thick
 * paper at a concave edge of the model (where the surface across rises towards the paper) may
 * stand back from it, as real layers must there: a corner within the creep zone of such an edge
 * (at most (maxStack + 1)·T·(tan(φ/2) + 1) in from its line, φ the edge's turn) is held to its
 * sheet distances only to within that much, and it must lie no nearer the edge than its mitre,
 * its height times tan(φ/2) in from it (the plane halving the wedge of air above the edge,
 * which the layers of the face across keep to from the other side);</li>
 * <li>{@link #NOT_TORN}: faces that are neighbours on the sheet are neighbours in space (or
 * joined by a cap across at most a few thicknesses);</li>
 * <li>{@link #COVERED}: random points of the model lie under paper (but within the creep zone
 * of a concave edge, truth 2, where thick paper stands back from the edge);</li>
 * <li>{@link #ON_SURFACE}: every paper face lies flat on the model, outside the solid and at most
 * (maxStack + 1) thicknesses above it: on one model triangle, or over triangles of one plane that
 * cover all of it (the strip lies flat across the edges between coplanar triangles); every cap
 * vertex is near the surface.</li>
 * </ol>
 * Tolerances scale with the model (its bounding-box diagonal, "size"), with the sheet, or with the
 * face, as each truth says. An instance is not thread-safe: {@link #check} records its summary.
 */
public final class WrapTruths {
    public static final String TILED = "1 tiled";
    public static final String ISOMETRIC = "2 isometric";
    public static final String NOT_TORN = "3 not torn";
    public static final String COVERED = "4 covered";
    public static final String ON_SURFACE = "5 on surface";

    /** A broken truth: which one (one of the constants of this class) and where (face, strip, point). */
    public record Violation(String truth, String message) {
    }

    // The tolerances, all in one place. Lengths are relative to the model, sheet or face.
    /** Relative length tolerance (of the model size, the sheet diagonal or the face size). */
    static final double RELATIVE = 1e-9;
    /** Largest angle between normals that still counts as parallel, radians. */
    static final double PARALLEL = 1e-7;
    /** The grid of sheet points per strip for the tiling check. */
    static final int SAMPLES_U = 200;
    static final int SAMPLES_V = 20;
    /** Irrational offsets within a grid cell, so that sample points avoid creases at round fractions. */
    private static final double OFFSET_U = 0.3819660112501051;
    private static final double OFFSET_V = 0.41421356237309515;
    /** A broken file can break a truth thousands of times; past this many, only the count is kept. */
    static final int LISTED_PER_TRUTH = 50;
    /** How far a convex face's total turning may be from 2 pi, radians (far below the 2 pi of a second turn). */
    private static final double TURNING = 1e-6;
    /** The smallest grid cell, relative to the model size: only for degenerate (zero-extent) inputs. */
    private static final double LEAST_CELL = 1e-6;

    // The file, as read. Indices are 0-based; faces keep their file order.
    /** Vertex positions, x y z interleaved. */
    private final double[] xyz;
    /** Paper coordinates, u v interleaved. */
    private final double[] uv;
    /** Face f's corners are cornerV/cornerT[faceStart[f] .. faceStart[f + 1]). */
    private final int[] faceStart;
    /** The vertex (v) index of each corner. */
    private final int[] cornerV;
    /** The paper coordinate (vt) index of each corner. */
    private final int[] cornerT;
    /** The strip each face belongs to. */
    private final int[] faceStrip;
    /** Whether each face is a cap (else paper). */
    private final boolean[] faceCap;
    /** The file line each face is on, for messages. */
    private final int[] faceLine;
    /** Each strip's name (what follows {@code o}). */
    private final List<String> stripNames;
    /** Each strip's paper faces and cap faces. */
    private final List<int[]> stripPaper;
    private final List<int[]> stripCaps;
    /** Each strip's sheet: the least and largest u and v of its paper faces. */
    private final double[] stripMinU;
    private final double[] stripMinV;
    private final double[] stripL;
    private final double[] stripW;
    private final int paperCount;
    private final double worstIsometry;
    /** Set by the last check; NaN before one. */
    private double farthestFromSurface = Double.NaN;

    private WrapTruths(double[] xyz, double[] uv, Ints faceStart, Ints cornerV, Ints cornerT, Ints faceStrip,
            List<Boolean> faceCap, Ints faceLine, List<String> stripNames) {
        this.xyz = xyz;
        this.uv = uv;
        this.faceStart = faceStart.toArray();
        this.cornerV = cornerV.toArray();
        this.cornerT = cornerT.toArray();
        this.faceStrip = faceStrip.toArray();
        this.faceLine = faceLine.toArray();
        this.faceCap = new boolean[faceCap.size()];
        for (int f = 0; f < faceCap.size(); f++) {
            this.faceCap[f] = faceCap.get(f);
        }
        this.stripNames = List.copyOf(stripNames);
        int strips = stripNames.size();
        List<Ints> paper = new ArrayList<>();
        List<Ints> caps = new ArrayList<>();
        for (int s = 0; s < strips; s++) {
            paper.add(new Ints());
            caps.add(new Ints());
        }
        stripMinU = new double[strips];
        stripMinV = new double[strips];
        stripL = new double[strips];
        stripW = new double[strips];
        Arrays.fill(stripMinU, Double.POSITIVE_INFINITY);
        Arrays.fill(stripMinV, Double.POSITIVE_INFINITY);
        int papers = 0;
        double worst = 0;
        for (int f = 0; f < faces(); f++) {
            int s = this.faceStrip[f];
            if (this.faceCap[f]) {
                caps.get(s).add(f);
                continue;
            }
            papers++;
            paper.get(s).add(f);
            for (int c = this.faceStart[f]; c < this.faceStart[f + 1]; c++) {
                int t = this.cornerT[c];
                stripMinU[s] = Math.min(stripMinU[s], uv[2 * t]);
                stripMinV[s] = Math.min(stripMinV[s], uv[2 * t + 1]);
                stripL[s] = Math.max(stripL[s], uv[2 * t]);
                stripW[s] = Math.max(stripW[s], uv[2 * t + 1]);
            }
        }
        for (int f = 0; f < faces(); f++) {
            if (!this.faceCap[f]) {
                worst = Math.max(worst, isometryError(f, null));
            }
        }
        paperCount = papers;
        worstIsometry = worst;
        stripPaper = paper.stream().map(Ints::toArray).toList();
        stripCaps = caps.stream().map(Ints::toArray).toList();
    }

    /**
     * Reads the OBJ text of a wrap.
     *
     * @throws IllegalArgumentException with the line, for a line that is not the format: a face
     *     outside a strip or outside the groups {@code paper} and {@code cap}, with fewer than 3
     *     corners, or naming a vertex or paper coordinate the file does not have; a number that
     *     does not parse
     */
    public static WrapTruths read(String objText) {
        List<Double> xyz = new ArrayList<>();
        List<Double> uv = new ArrayList<>();
        Ints faceStart = new Ints();
        Ints cornerV = new Ints();
        Ints cornerT = new Ints();
        Ints faceStrip = new Ints();
        Ints faceLine = new Ints();
        List<Boolean> faceCap = new ArrayList<>();
        List<String> stripNames = new ArrayList<>();
        String group = null;
        String[] lines = objText.split("\r\n|\r|\n", -1);
        faceStart.add(0);
        for (int i = 0; i < lines.length; i++) {
            int lineNo = i + 1;
            String line = lines[i].strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String[] tok = line.split("\\s+");
            try {
                switch (tok[0]) {
                    case "o" -> stripNames.add(line.substring(1).strip());
                    case "v" -> {
                        require(tok.length >= 4, lineNo, "a vertex needs x y z");
                        for (int k = 1; k <= 3; k++) {
                            xyz.add(Double.parseDouble(tok[k]));
                        }
                    }
                    case "vt" -> {
                        require(tok.length >= 3, lineNo, "a paper coordinate needs u v");
                        uv.add(Double.parseDouble(tok[1]));
                        uv.add(Double.parseDouble(tok[2]));
                    }
                    case "g" -> {
                        group = tok.length > 1 ? tok[1] : "";
                        require(group.equals("paper") || group.equals("cap"), lineNo,
                                "the groups are paper and cap, not '" + group + "'");
                    }
                    case "f" -> {
                        require(!stripNames.isEmpty(), lineNo, "a face before any 'o' strip");
                        require(group != null, lineNo, "a face before any 'g paper' or 'g cap'");
                        require(tok.length >= 4, lineNo, "a face needs 3 or more corners");
                        for (int k = 1; k < tok.length; k++) {
                            String[] parts = tok[k].split("/", -1);
                            int v = index(parts[0], xyz.size() / 3, lineNo, "vertex");
                            int t = parts.length > 1 && !parts[1].isEmpty() ? index(parts[1], uv.size() / 2, lineNo, "paper coordinate") : v;
                            require(t < uv.size() / 2, lineNo, "corner " + tok[k] + " has no paper coordinate");
                            cornerV.add(v);
                            cornerT.add(t);
                        }
                        faceStart.add(cornerV.size());
                        faceStrip.add(stripNames.size() - 1);
                        faceCap.add(group.equals("cap"));
                        faceLine.add(lineNo);
                    }
                    // Normals, smoothing groups, materials: not part of what is checked.
                    default -> {
                    }
                }
            } catch (NumberFormatException e) {
                throw new IllegalArgumentException("line " + lineNo + ": not a number in '" + line + "'", e);
            }
        }
        return new WrapTruths(unbox(xyz), unbox(uv), faceStart, cornerV, cornerT, faceStrip, faceCap, faceLine, stripNames);
    }

    private static void require(boolean condition, int lineNo, String message) {
        if (!condition) {
            throw new IllegalArgumentException("line " + lineNo + ": " + message);
        }
    }

    /** A 1-based (or negative, relative) OBJ index made 0-based; only elements already read count, as OBJ says. */
    private static int index(String token, int count, int lineNo, String what) {
        int k = Integer.parseInt(token);
        int i = k > 0 ? k - 1 : count + k;
        require(k != 0 && i >= 0 && i < count, lineNo, what + " " + k + " is not among the " + count + " read so far");
        return i;
    }

    private static double[] unbox(List<Double> list) {
        double[] a = new double[list.size()];
        for (int i = 0; i < a.length; i++) {
            a[i] = list.get(i);
        }
        return a;
    }

    /** The number of strips ({@code o} lines). */
    public int strips() {
        return stripNames.size();
    }

    /** Strip s's name (0-based, in file order), as its {@code o} line gives it. */
    public String stripName(int strip) {
        return stripNames.get(strip);
    }

    /** Strip s's sheet length L: the largest u of its paper faces (0 when it has none). */
    public double length(int strip) {
        return stripL[strip];
    }

    /** Strip s's sheet width w: the largest v of its paper faces (0 when it has none). */
    public double width(int strip) {
        return stripW[strip];
    }

    public int paperFaces() {
        return paperCount;
    }

    public int capFaces() {
        return faces() - paperCount;
    }

    /**
     * The worst departure of a paper face from its sheet polygon, relative to the face's size (its
     * largest sheet edge): over all faces, the largest difference of a 3D and a sheet distance
     * between two of its vertices, or of a vertex from the face's plane. Truth 2 holds when this
     * is at most {@link #RELATIVE}.
     */
    public double worstIsometry() {
        return worstIsometry;
    }

    /**
     * The largest height of a paper vertex above the model triangle its face rests on, as the
     * last {@link #check} found it (faces resting on none left out); NaN before any check.
     */
    public double farthestFromSurface() {
        return farthestFromSurface;
    }

    private int faces() {
        return faceStrip.length;
    }

    /** "face 3 (line 17, strip-1)": the 1-based face number in file order, for messages. */
    private String face(int f) {
        return "face " + (f + 1) + " (line " + faceLine[f] + ", " + stripNames.get(faceStrip[f]) + ")";
    }

    private static String point(double... p) {
        StringBuilder sb = new StringBuilder("(");
        for (int i = 0; i < p.length; i++) {
            sb.append(i == 0 ? "" : ", ").append(p[i]);
        }
        return sb.append(')').toString();
    }

    /**
     * Checks the five truths of a wrap of the model.
     *
     * @param modelTriangles the model's triangles, each x1 y1 z1 x2 y2 z2 x3 y3 z3, counter-clockwise
     *     seen from outside
     * @param thickness the paper's thickness, 0 or more
     * @param maxStack the deepest stack of layers the wrap reports: paper lies at most
     *     (maxStack + 1) thicknesses above the surface
     * @param coverageSamples how many random model points truth 4 tries (0: none)
     * @param seed the seed of those points
     * @return the violations, in truth order; each truth lists at most {@link #LISTED_PER_TRUTH},
     *     then one more that counts the rest
     * @throws IllegalArgumentException for no model, a triangle that is not 9 finite numbers, a
     *     model of zero size or area, a negative thickness, stack or sample count
     */
    public List<Violation> check(List<double[]> modelTriangles, double thickness, int maxStack, int coverageSamples, long seed) {
        if (!(thickness >= 0) || Double.isInfinite(thickness) || maxStack < 0 || coverageSamples < 0) {
            throw new IllegalArgumentException("thickness " + thickness + ", stack " + maxStack + " and samples "
                    + coverageSamples + " must be finite and not negative");
        }
        Model model = new Model(modelTriangles);
        Report report = new Report();
        double eps = RELATIVE * model.size;
        double top = (maxStack + 1) * thickness;
        Faces geometry = new Faces(eps, model.size);
        checkStripsAreTiledOnce(report, eps);
        List<ConcaveSide> concave = concaveSides(model, eps);
        boolean[] crept = new boolean[faces()];
        checkIsometry(report, concave, thickness, maxStack, eps, crept);
        checkNotTorn(report, eps, 2 * top);
        checkCovered(report, model, geometry, eps, top, coverageSamples, seed, thickness > 0 ? concave : List.of(), crept);
        checkOnSurface(report, model, geometry, eps, top);
        return report.finish();
    }

    // ---- Truth 1 ----

    private void checkStripsAreTiledOnce(Report report, double eps) {
        // v and vt indices are separate spaces; each must stay within one strip.
        for (boolean positions : new boolean[] {true, false}) {
            int[] index = positions ? cornerV : cornerT;
            int[] owner = new int[positions ? xyz.length / 3 : uv.length / 2];
            Arrays.fill(owner, -1);
            for (int f = 0; f < faces(); f++) {
                for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                    int i = index[c];
                    if (owner[i] < 0) {
                        owner[i] = faceStrip[f];
                    } else if (owner[i] != faceStrip[f] && owner[i] != strips()) {
                        report.add(TILED, (positions ? "vertex " : "paper coordinate ") + (i + 1) + " is used by "
                                + stripNames.get(owner[i]) + " and by " + face(f));
                        // Reported once.
                        owner[i] = strips();
                    }
                }
            }
        }
        int[] parent = new int[xyz.length / 3];
        for (int s = 0; s < strips(); s++) {
            checkTiling(report, s);
            checkOnePiece(report, s, parent, eps);
        }
    }

    private void checkTiling(Report report, int s) {
        String strip = stripNames.get(s);
        int[] paper = stripPaper.get(s);
        if (paper.length == 0) {
            report.add(TILED, strip + " has no paper faces");
            return;
        }
        double length = stripL[s];
        double width = stripW[s];
        double tol = RELATIVE * Math.hypot(length, width);
        if (Math.abs(stripMinU[s]) > tol || Math.abs(stripMinV[s]) > tol) {
            report.add(TILED, strip + "'s sheet starts at " + point(stripMinU[s], stripMinV[s]) + ", not at (0, 0)");
        }
        double area = 0;
        for (int f : paper) {
            double faceSize = sheetSize(f);
            if (!(Math.abs(sheetArea(f)) > RELATIVE * faceSize * faceSize)) {
                report.add(TILED, face(f) + " has no area on the sheet");
            } else if (!sheetConvex(f)) {
                report.add(TILED, face(f) + " is not a convex polygon on the sheet");
            }
            area += Math.abs(sheetArea(f));
        }
        if (!(Math.abs(area - length * width) <= RELATIVE * length * width)) {
            report.add(TILED, strip + "'s paper faces have area " + area + " on the sheet, not L * w = " + length + " * " + width
                    + " = " + length * width);
        }
        for (int f : stripCaps.get(s)) {
            double faceSize = sheetSize(f);
            if (Math.abs(sheetArea(f)) > RELATIVE * Math.max(faceSize * faceSize, tol * tol)) {
                report.add(TILED, "cap " + face(f) + " has area " + Math.abs(sheetArea(f)) + " on the sheet, not 0");
            }
        }
        double[] boxes = new double[6 * paper.length];
        for (int i = 0; i < paper.length; i++) {
            sheetBox(paper[i], tol, boxes, 6 * i);
        }
        Grid grid = new Grid(boxes, paper.length, Grid.cellFor(boxes, paper.length, tol));
        Ints candidates = new Ints();
        int gaps = 0;
        int overlaps = 0;
        String firstGap = "";
        String firstOverlap = "";
        for (int i = 0; i < SAMPLES_U; i++) {
            double u = (i + OFFSET_U) / SAMPLES_U * length;
            for (int j = 0; j < SAMPLES_V; j++) {
                double v = (j + OFFSET_V) / SAMPLES_V * width;
                grid.query(u, v, 0, u, v, 0, candidates);
                int touching = 0;
                int inside = 0;
                int first = -1;
                int second = -1;
                for (int k = 0; k < candidates.size(); k++) {
                    int f = paper[candidates.get(k)];
                    double depth = sheetDepth(f, u, v);
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
                    firstGap = point(u, v);
                }
                if (inside > 1 && overlaps++ == 0) {
                    firstOverlap = point(u, v) + " (in " + face(first) + " and " + face(second) + ")";
                }
            }
        }
        int samples = SAMPLES_U * SAMPLES_V;
        if (gaps > 0) {
            report.add(TILED, gaps + " of " + samples + " sheet points of " + strip + " lie in no paper face, the first " + firstGap);
        }
        if (overlaps > 0) {
            report.add(TILED, overlaps + " of " + samples + " sheet points of " + strip + " lie in two paper faces, the first "
                    + firstOverlap);
        }
    }

    /** Whether face f turns one way only, once round, on the sheet (collinear corners allowed). */
    private boolean sheetConvex(int f) {
        int start = faceStart[f];
        int n = faceStart[f + 1] - start;
        double sign = Math.signum(sheetArea(f));
        double turning = 0;
        double tol = RELATIVE * sheetSize(f);
        for (int k = 0; k < n; k++) {
            int a = cornerT[start + k];
            int b = cornerT[start + (k + 1) % n];
            int c = cornerT[start + (k + 2) % n];
            double e1u = uv[2 * b] - uv[2 * a];
            double e1v = uv[2 * b + 1] - uv[2 * a + 1];
            double e2u = uv[2 * c] - uv[2 * b];
            double e2v = uv[2 * c + 1] - uv[2 * b + 1];
            // A repeated corner turns nowhere.
            if (Math.hypot(e1u, e1v) <= tol || Math.hypot(e2u, e2v) <= tol) {
                continue;
            }
            double cross = e1u * e2v - e1v * e2u;
            double dot = e1u * e2u + e1v * e2v;
            if (sign * cross < -RELATIVE * Math.hypot(e1u, e1v) * Math.hypot(e2u, e2v)) {
                return false;
            }
            turning += Math.atan2(sign * cross, dot);
        }
        // One way round: 2 pi; a star polygon turns one way too but two or more times round.
        return Math.abs(turning - 2 * Math.PI) < TURNING;
    }

    /** Strip s is one piece in space: its faces joined through shared vertices or vertices at one position. */
    private void checkOnePiece(Report report, int s, int[] parent, double eps) {
        Ints used = new Ints();
        boolean[] seen = new boolean[parent.length];
        for (int[] faces : List.of(stripPaper.get(s), stripCaps.get(s))) {
            for (int f : faces) {
                for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                    int v = cornerV[c];
                    if (!seen[v]) {
                        seen[v] = true;
                        used.add(v);
                        parent[v] = v;
                    }
                }
                for (int c = faceStart[f] + 1; c < faceStart[f + 1]; c++) {
                    union(parent, cornerV[faceStart[f]], cornerV[c]);
                }
            }
        }
        if (used.size() == 0) {
            return;
        }
        int[] vertices = used.toArray();
        Grid grid = pointGrid(vertices, eps);
        Ints near = new Ints();
        for (int v : vertices) {
            grid.query(xyz[3 * v] - eps, xyz[3 * v + 1] - eps, xyz[3 * v + 2] - eps,
                    xyz[3 * v] + eps, xyz[3 * v + 1] + eps, xyz[3 * v + 2] + eps, near);
            for (int k = 0; k < near.size(); k++) {
                int w = vertices[near.get(k)];
                if (distance(xyz, 3 * v, xyz, 3 * w) <= eps) {
                    union(parent, v, w);
                }
            }
        }
        Map<Integer, Integer> pieces = new LinkedHashMap<>();
        for (int[] faces : List.of(stripPaper.get(s), stripCaps.get(s))) {
            for (int f : faces) {
                pieces.putIfAbsent(find(parent, cornerV[faceStart[f]]), f);
            }
        }
        if (pieces.size() > 1) {
            List<Integer> firsts = new ArrayList<>(pieces.values());
            report.add(TILED, stripNames.get(s) + " falls apart into " + pieces.size() + " pieces in space: " + face(firsts.get(0))
                    + " and " + face(firsts.get(1)) + " are not joined");
        }
    }

    private static int find(int[] parent, int v) {
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

    private static void union(int[] parent, int a, int b) {
        int ra = find(parent, a);
        int rb = find(parent, b);
        if (ra != rb) {
            parent[ra] = rb;
        }
    }

    /** A grid of the given vertices' positions, for lookups within eps. */
    private Grid pointGrid(int[] vertices, double eps) {
        double[] boxes = new double[6 * vertices.length];
        for (int i = 0; i < vertices.length; i++) {
            for (int d = 0; d < 3; d++) {
                boxes[6 * i + d] = xyz[3 * vertices[i] + d];
                boxes[6 * i + 3 + d] = xyz[3 * vertices[i] + d];
            }
        }
        return new Grid(boxes, vertices.length, 4 * eps);
    }

    // ---- Truth 2 ----

    /**
     * One side of a concave edge of the model: the edge from a to b on a triangle of outward unit
     * {@code normal}, whose neighbour across rises above its plane, turning by φ; {@code mitre}
     * is tan(φ/2).
     */
    private record ConcaveSide(double[] normal, double[] a, double[] b, double mitre) {
    }

    /** Every side of every concave edge of the model: edges are matched by their corners' coordinates. */
    private static List<ConcaveSide> concaveSides(Model model, double eps) {
        int n = model.corners.length / 9;
        Map<String, int[]> sides = new HashMap<>();
        List<ConcaveSide> concave = new ArrayList<>();
        for (int t = 0; t < n; t++) {
            for (int k = 0; k < 3; k++) {
                double[] a = Arrays.copyOfRange(model.corners, 9 * t + 3 * k, 9 * t + 3 * k + 3);
                double[] b = Arrays.copyOfRange(model.corners, 9 * t + 3 * ((k + 1) % 3), 9 * t + 3 * ((k + 1) % 3) + 3);
                String ab = Arrays.toString(a) + Arrays.toString(b);
                String ba = Arrays.toString(b) + Arrays.toString(a);
                int[] other = sides.remove(ba);
                if (other == null) {
                    sides.put(ab, new int[] {t, k});
                    continue;
                }
                for (int[] side : List.of(new int[] {t, k}, other)) {
                    int near = side[0];
                    int far = side == other ? t : other[0];
                    double rise = 0;
                    for (int c = 0; c < 3; c++) {
                        rise = Math.max(rise, model.height(near, model.corners, 9 * far + 3 * c));
                    }
                    if (rise > eps) {
                        double[] m = model.normal(near);
                        double[] o = model.normal(far);
                        double cos = Math.max(-1, Math.min(1, m[0] * o[0] + m[1] * o[1] + m[2] * o[2]));
                        double[] p = Arrays.copyOfRange(model.corners, 9 * near + 3 * side[1], 9 * near + 3 * side[1] + 3);
                        double[] q = Arrays.copyOfRange(model.corners, 9 * near + 3 * ((side[1] + 1) % 3), 9 * near + 3 * ((side[1] + 1) % 3) + 3);
                        concave.add(new ConcaveSide(m, p, q, Math.sqrt((1 - cos) / Math.max(1 + cos, 1e-12))));
                    }
                }
            }
        }
        return concave;
    }

    /** Truth 2; {@code crept} gets the faces let stand back from a concave edge. */
    private void checkIsometry(Report report, List<ConcaveSide> concave, double thickness, int maxStack, double eps, boolean[] crept) {
        StringBuilder why = new StringBuilder();
        for (int f = 0; f < faces(); f++) {
            if (!faceCap[f]) {
                why.setLength(0);
                double error = isometryError(f, why);
                Zones zones = thickness > 0 && !concave.isEmpty() ? zones(f, concave, thickness, maxStack, eps) : null;
                if (zones != null && zones.nearer() != null) {
                    report.add(ISOMETRIC, face(f) + ": " + zones.nearer());
                }
                if (!(error <= RELATIVE)) {
                    crept[f] = zones != null && creptOnly(f, zones);
                    if (!crept[f]) {
                        report.add(ISOMETRIC, face(f) + " is stretched: " + why + (zones == null || zones.widest() == 0 ? ""
                                : " (more than twice the " + zones.widest() + " its corners by a concave edge may creep)"));
                    }
                }
            }
        }
    }

    /**
     * Where face f lies by the concave edges of the model: which corners lie in a creep zone
     * ({@code inZone}), the widest such zone, and the first corner nearer a concave edge than
     * its mitre on every plane of a concave side the face lies on (null if none). The face lies
     * on the plane of a side when all its corners stand equally high above it (a face squashed
     * to a sliver may lie on both sides' planes, and must keep to its mitre on one).
     */
    private record Zones(boolean[] inZone, double widest, String nearer) {
    }

    private Zones zones(int f, List<ConcaveSide> concave, double thickness, int maxStack, double eps) {
        int start = faceStart[f];
        int end = faceStart[f + 1];
        double size = Math.max(sheetSize(f), stripW[faceStrip[f]]);
        double top = (maxStack + 1) * thickness;
        boolean[] inZone = new boolean[end - start];
        double widest = 0;
        // A face on a plane keeps to the mitre of every concave side of that plane (a room's floor
        // of both its walls); a squashed face may lie on two planes, and must keep to one's.
        List<ConcaveSide> planes = new ArrayList<>();
        List<String> nearerOn = new ArrayList<>();
        for (ConcaveSide side : concave) {
            double[] m = side.normal();
            double width = top * (side.mitre() + 1);
            double[] along = minus(side.b(), side.a());
            double length = Math.sqrt(times(along, along));
            for (int d = 0; d < 3; d++) {
                along[d] /= length;
            }
            double[] in = crossed(m, along); // in the plane, from the edge into the triangle
            double low = Double.POSITIVE_INFINITY;
            double high = Double.NEGATIVE_INFINITY;
            boolean near = false;
            for (int c = start; c < end; c++) {
                double[] p = minus(new double[] {xyz[3 * cornerV[c]], xyz[3 * cornerV[c] + 1], xyz[3 * cornerV[c] + 2]}, side.a());
                double height = times(p, m);
                low = Math.min(low, height);
                high = Math.max(high, height);
                double s = times(p, along);
                double inside = times(p, in);
                near |= s >= -width && s <= length + width && inside <= width && inside >= -width;
            }
            if (!near || high - low > RELATIVE * size + eps || low < -eps || high > top + eps) {
                continue; // not on this side's plane (so not planar there), or not near its edge
            }
            String here = null;
            for (int c = start; c < end; c++) {
                int v = cornerV[c];
                double[] p = minus(new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}, side.a());
                double s = times(p, along);
                double inside = times(p, in);
                if (s < -width || s > length + width || inside > width || inside < -width) {
                    continue;
                }
                inZone[c - start] = true;
                widest = Math.max(widest, width);
                double height = times(p, m);
                // The mitre stands beside the edge: round its ends the paper across turns away.
                if (here == null && s >= 0 && s <= length && inside < height * side.mitre() - eps - 1e-6 * thickness) {
                    here = "vertex " + (v + 1) + " is " + inside + " in from a concave edge of the model, nearer than its mitre ("
                            + height + " high: " + height * side.mitre() + " in), running into the layers across";
                }
            }
            int plane = -1;
            for (int i = 0; i < planes.size() && plane < 0; i++) {
                double[] n = planes.get(i).normal();
                if (times(n, m) > 1 - 1e-9 && Math.abs(times(n, minus(side.a(), planes.get(i).a()))) <= eps) {
                    plane = i;
                }
            }
            if (plane < 0) {
                planes.add(side);
                nearerOn.add(here);
            } else if (nearerOn.get(plane) == null) {
                nearerOn.set(plane, here);
            }
        }
        String nearer = null;
        for (String onPlane : nearerOn) {
            if (onPlane == null) {
                return new Zones(inZone, widest, null);
            }
            nearer = nearer == null ? onPlane : nearer;
        }
        return new Zones(inZone, widest, nearer);
    }

    /**
     * Whether face f, not congruent to its sheet polygon, is so only by corners standing back from
     * a concave edge: planar (its corners stand equally high above a concave side's plane, see
     * {@link #zones}, which holds for a face squashed to a sliver too, whose own normal is
     * rounding), its corners outside every creep zone congruent among themselves, and each pair
     * with a corner in a zone off its sheet distance by no more than twice the widest zone.
     */
    private boolean creptOnly(int f, Zones zones) {
        if (zones.widest() == 0) {
            return false;
        }
        int start = faceStart[f];
        int end = faceStart[f + 1];
        double size = Math.max(sheetSize(f), stripW[faceStrip[f]]);
        for (int a = start; a < end; a++) {
            for (int b = a + 1; b < end; b++) {
                double inSpace = distance(xyz, 3 * cornerV[a], xyz, 3 * cornerV[b]);
                double onSheet = Math.hypot(uv[2 * cornerT[a]] - uv[2 * cornerT[b]], uv[2 * cornerT[a] + 1] - uv[2 * cornerT[b] + 1]);
                boolean zone = zones.inZone()[a - start] || zones.inZone()[b - start];
                if (!(Math.abs(inSpace - onSheet) <= (zone ? 2 * zones.widest() + RELATIVE * size : RELATIVE * size))) {
                    return false;
                }
            }
        }
        return true;
    }

    /**
     * Face f's worst departure from its sheet polygon, relative to its size (at least the strip's width): of a 3D distance from
     * the sheet distance between two corners, or of a corner from the face's plane. When why is
     * given, it gets the worst one in words.
     */
    private double isometryError(int f, StringBuilder why) {
        int start = faceStart[f];
        int end = faceStart[f + 1];
        // A paper coordinate u on a strip of length L is a double good to about 1e-16 L: a sliver
        // far along a long strip cannot be exact to 1e-9 of its own size, only of the strip's width.
        double size = Math.max(sheetSize(f), stripW[faceStrip[f]]);
        double worst = 0;
        for (int a = start; a < end; a++) {
            for (int b = a + 1; b < end; b++) {
                double inSpace = distance(xyz, 3 * cornerV[a], xyz, 3 * cornerV[b]);
                double onSheet = Math.hypot(uv[2 * cornerT[a]] - uv[2 * cornerT[b]], uv[2 * cornerT[a] + 1] - uv[2 * cornerT[b] + 1]);
                double error = Math.abs(inSpace - onSheet) / size;
                if (!(error <= worst)) {
                    worst = error;
                    if (why != null) {
                        why.setLength(0);
                        why.append("vertices ").append(cornerV[a] + 1).append(" and ").append(cornerV[b] + 1).append(" are ")
                                .append(inSpace).append(" apart in space but ").append(onSheet).append(" on the sheet");
                    }
                }
            }
        }
        double[] normal = newellNormal(f);
        double[] centre = centroid(f);
        for (int c = start; c < end; c++) {
            int v = cornerV[c];
            double off = Math.abs(normal[0] * (xyz[3 * v] - centre[0]) + normal[1] * (xyz[3 * v + 1] - centre[1])
                    + normal[2] * (xyz[3 * v + 2] - centre[2]));
            double error = off / size;
            if (!(error <= worst)) {
                worst = error;
                if (why != null) {
                    why.setLength(0);
                    why.append("vertex ").append(v + 1).append(" is ").append(off).append(" off the face's plane");
                }
            }
        }
        return worst;
    }

    private static double[] minus(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    private static double times(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    private static double[] crossed(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    // ---- Truth 3 ----

    private void checkNotTorn(Report report, double eps, double capReach) {
        double[] a = new double[3];
        double[] b = new double[3];
        for (int s = 0; s < strips(); s++) {
            int[] paper = stripPaper.get(s);
            // Paper coordinates are good to about 1e-16 of the strip's length; edges closer than a
            // billionth of its width are the same line. (A billionth of a long strip's length would
            // take the edge of a sliver near the border for the border itself.)
            double tol = RELATIVE * stripW[s] + 1e-13 * stripL[s];
            Ints edgeCorner = new Ints();
            Ints edgeFace = new Ints();
            for (int f : paper) {
                for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                    edgeCorner.add(c);
                    edgeFace.add(f);
                }
            }
            int edges = edgeCorner.size();
            if (edges == 0) {
                continue;
            }
            double[] boxes = new double[6 * edges];
            for (int e = 0; e < edges; e++) {
                int ta = cornerT[edgeCorner.get(e)];
                int tb = cornerT[nextCorner(edgeFace.get(e), edgeCorner.get(e))];
                boxes[6 * e] = Math.min(uv[2 * ta], uv[2 * tb]) - tol;
                boxes[6 * e + 1] = Math.min(uv[2 * ta + 1], uv[2 * tb + 1]) - tol;
                boxes[6 * e + 3] = Math.max(uv[2 * ta], uv[2 * tb]) + tol;
                boxes[6 * e + 4] = Math.max(uv[2 * ta + 1], uv[2 * tb + 1]) + tol;
            }
            Grid grid = new Grid(boxes, edges, Grid.cellFor(boxes, edges, tol));
            int[] caps = capVertices(s);
            Grid capGrid = pointGrid(caps, eps);
            Ints candidates = new Ints();
            Ints near = new Ints();
            HashSet<Long> reported = new HashSet<>();
            double[] shared = new double[4];
            for (int e = 0; e < edges; e++) {
                grid.query(boxes[6 * e], boxes[6 * e + 1], 0, boxes[6 * e + 3], boxes[6 * e + 4], 0, candidates);
                int f = edgeFace.get(e);
                for (int k = 0; k < candidates.size(); k++) {
                    int g = candidates.get(k);
                    int h = edgeFace.get(g);
                    if (g <= e || h == f || !sharedSegment(f, edgeCorner.get(e), h, edgeCorner.get(g), tol, shared)) {
                        continue;
                    }
                    for (int end = 0; end < 2; end++) {
                        double u = shared[2 * end];
                        double v = shared[2 * end + 1];
                        toSpace(f, u, v, a);
                        toSpace(h, u, v, b);
                        double apart = distance(a, 0, b, 0);
                        if (apart <= eps) {
                            continue;
                        }
                        boolean capped = apart <= capReach && nearAny(capGrid, caps, a, eps, near) && nearAny(capGrid, caps, b, eps, near);
                        if (!capped && reported.add(((long) Math.min(f, h) << 32) | Math.max(f, h))) {
                            report.add(NOT_TORN, face(f) + " and " + face(h) + " meet on the sheet along "
                                    + point(shared[0], shared[1]) + " - " + point(shared[2], shared[3]) + " but at " + point(u, v)
                                    + " they are " + apart + " apart in space, at " + point(a) + " and " + point(b)
                                    + (apart > capReach ? ", more than a cap can bridge (" + capReach + ")" : ", with no cap there"));
                        }
                    }
                }
            }
        }
    }

    private int nextCorner(int f, int c) {
        return c + 1 < faceStart[f + 1] ? c + 1 : faceStart[f];
    }

    /**
     * Whether the sheet edge of face f from corner cf and that of face g from corner cg lie on one
     * line and overlap over more than tol; if so, shared gets the overlap's ends u0 v0 u1 v1.
     */
    private boolean sharedSegment(int f, int cf, int g, int cg, double tol, double[] shared) {
        int p0 = cornerT[cf];
        int p1 = cornerT[nextCorner(f, cf)];
        int q0 = cornerT[cg];
        int q1 = cornerT[nextCorner(g, cg)];
        double lp = Math.hypot(uv[2 * p1] - uv[2 * p0], uv[2 * p1 + 1] - uv[2 * p0 + 1]);
        double lq = Math.hypot(uv[2 * q1] - uv[2 * q0], uv[2 * q1 + 1] - uv[2 * q0 + 1]);
        // Measure along the longer edge: its direction is the better known.
        if (lq > lp) {
            int t = p0;
            p0 = q0;
            q0 = t;
            t = p1;
            p1 = q1;
            q1 = t;
            lp = lq;
        }
        if (!(lp > tol)) {
            return false;
        }
        double du = (uv[2 * p1] - uv[2 * p0]) / lp;
        double dv = (uv[2 * p1 + 1] - uv[2 * p0 + 1]) / lp;
        double s0 = 0;
        double s1 = 0;
        for (int k = 0; k < 2; k++) {
            int q = k == 0 ? q0 : q1;
            double ru = uv[2 * q] - uv[2 * p0];
            double rv = uv[2 * q + 1] - uv[2 * p0 + 1];
            if (Math.abs(du * rv - dv * ru) > tol) {
                return false;
            }
            if (k == 0) {
                s0 = du * ru + dv * rv;
            } else {
                s1 = du * ru + dv * rv;
            }
        }
        double lo = Math.max(0, Math.min(s0, s1));
        double hi = Math.min(lp, Math.max(s0, s1));
        if (!(hi - lo > tol)) {
            return false;
        }
        // The overlap ends at corners: take their own coordinates, not ones recomputed along the line.
        int from = lo == 0 ? p0 : s0 < s1 ? q0 : q1;
        int to = hi == lp ? p1 : s0 < s1 ? q1 : q0;
        // Lexicographic order, so that messages name a shared segment one way.
        if (uv[2 * to] < uv[2 * from] || uv[2 * to] == uv[2 * from] && uv[2 * to + 1] < uv[2 * from + 1]) {
            int t = from;
            from = to;
            to = t;
        }
        shared[0] = uv[2 * from];
        shared[1] = uv[2 * from + 1];
        shared[2] = uv[2 * to];
        shared[3] = uv[2 * to + 1];
        return true;
    }

    /** Where sheet point (u, v) of paper face f lies in space, through the face's affine map from vt to v. */
    private void toSpace(int f, double u, double v, double[] out) {
        int start = faceStart[f];
        int end = faceStart[f + 1];
        // A corner is where the face puts it: a face whose corners stand back from a concave edge
        // (truth 2) is not the rigid image of its sheet polygon, and the map below, through three
        // corners, would move the others.
        double near = RELATIVE * Math.max(sheetSize(f), stripW[faceStrip[f]]);
        for (int c = start; c < end; c++) {
            if (Math.hypot(uv[2 * cornerT[c]] - u, uv[2 * cornerT[c] + 1] - v) <= near) {
                System.arraycopy(xyz, 3 * cornerV[c], out, 0, 3);
                return;
            }
        }
        // The best-shaped corner triangle: the corner farthest from the first, then the one farthest from their line.
        int c0 = start;
        int c1 = start + 1;
        for (int c = start + 1; c < end; c++) {
            if (sheetDistance(c0, c) > sheetDistance(c0, c1)) {
                c1 = c;
            }
        }
        int c2 = -1;
        double best = -1;
        for (int c = start; c < end; c++) {
            double cross = Math.abs(sheetCross(c0, c1, c));
            if (cross > best) {
                best = cross;
                c2 = c;
            }
        }
        int t0 = cornerT[c0];
        double e1u = uv[2 * cornerT[c1]] - uv[2 * t0];
        double e1v = uv[2 * cornerT[c1] + 1] - uv[2 * t0 + 1];
        double e2u = uv[2 * cornerT[c2]] - uv[2 * t0];
        double e2v = uv[2 * cornerT[c2] + 1] - uv[2 * t0 + 1];
        double det = e1u * e2v - e1v * e2u;
        double du = u - uv[2 * t0];
        double dv = v - uv[2 * t0 + 1];
        double alpha = (du * e2v - dv * e2u) / det;
        double beta = (e1u * dv - e1v * du) / det;
        int v0 = cornerV[c0];
        int v1 = cornerV[c1];
        int v2 = cornerV[c2];
        for (int d = 0; d < 3; d++) {
            out[d] = xyz[3 * v0 + d] + alpha * (xyz[3 * v1 + d] - xyz[3 * v0 + d]) + beta * (xyz[3 * v2 + d] - xyz[3 * v0 + d]);
        }
    }

    private double sheetDistance(int ca, int cb) {
        int a = cornerT[ca];
        int b = cornerT[cb];
        return Math.hypot(uv[2 * b] - uv[2 * a], uv[2 * b + 1] - uv[2 * a + 1]);
    }

    private double sheetCross(int ca, int cb, int cc) {
        int a = cornerT[ca];
        int b = cornerT[cb];
        int c = cornerT[cc];
        return (uv[2 * b] - uv[2 * a]) * (uv[2 * c + 1] - uv[2 * a + 1]) - (uv[2 * b + 1] - uv[2 * a + 1]) * (uv[2 * c] - uv[2 * a]);
    }

    /** The vertices of strip s's cap faces, each once. */
    private int[] capVertices(int s) {
        Ints out = new Ints();
        HashSet<Integer> seen = new HashSet<>();
        for (int f : stripCaps.get(s)) {
            for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                if (seen.add(cornerV[c])) {
                    out.add(cornerV[c]);
                }
            }
        }
        return out.toArray();
    }

    private boolean nearAny(Grid grid, int[] vertices, double[] p, double eps, Ints near) {
        grid.query(p[0] - eps, p[1] - eps, p[2] - eps, p[0] + eps, p[1] + eps, p[2] + eps, near);
        for (int k = 0; k < near.size(); k++) {
            if (distance(xyz, 3 * vertices[near.get(k)], p, 0) <= eps) {
                return true;
            }
        }
        return false;
    }

    // ---- Truth 4 ----

    /**
     * Whether model point p, on a triangle of outward normal n, lies within the creep zone of a
     * concave edge: thick layers stand back from such an edge (truth 2), and the surface next to
     * it lies under the paper across, not under paper on its own plane.
     */
    private static boolean inCreepZone(double[] p, double[] n, List<ConcaveSide> concave, double top, double eps) {
        for (ConcaveSide side : concave) {
            double[] m = side.normal();
            if (times(m, n) < 1 - 1e-9) {
                continue;
            }
            double width = top * (side.mitre() + 1);
            double[] along = minus(side.b(), side.a());
            double length = Math.sqrt(times(along, along));
            for (int d = 0; d < 3; d++) {
                along[d] /= length;
            }
            double[] q = minus(p, side.a());
            double s = times(q, along);
            double inside = times(q, crossed(m, along));
            if (Math.abs(times(q, m)) <= eps && s >= -width && s <= length + width && inside >= -eps && inside <= width) {
                return true;
            }
        }
        return false;
    }

    /**
     * Whether model point p, on a triangle of outward normal n, lies within the widest creep zone
     * of the model's concave edges of a crept face on its plane (one truth 2 let stand back from
     * a concave edge): where layers joined at a crease creep by different amounts, the crease
     * opens a sliver no wider than that, which can run from the edge along the crease; a gap
     * any wider, or beside paper that did not creep, is a hole.
     */
    private static boolean nearPaper(double[] p, double[] n, Faces geometry, List<ConcaveSide> concave, double top, double eps,
            Ints candidates, boolean[] crept) {
        double widest = 0;
        for (ConcaveSide side : concave) {
            widest = Math.max(widest, top * (side.mitre() + 1));
        }
        if (widest == 0) {
            return false;
        }
        double reach = top + eps;
        double around = widest + eps;
        geometry.grid.query(Math.min(p[0], p[0] + reach * n[0]) - around, Math.min(p[1], p[1] + reach * n[1]) - around,
                Math.min(p[2], p[2] + reach * n[2]) - around, Math.max(p[0], p[0] + reach * n[0]) + around,
                Math.max(p[1], p[1] + reach * n[1]) + around, Math.max(p[2], p[2] + reach * n[2]) + around, candidates);
        for (int k = 0; k < candidates.size(); k++) {
            int f = geometry.paper[candidates.get(k)];
            if (crept[f] && depthOver(geometry, f, p, n, top, eps) >= -widest - eps) {
                return true;
            }
        }
        return false;
    }

    /**
     * How deep model point p, on a triangle of outward normal n, lies under paper face f, seen
     * along n (positive inside it, negative beyond its edges); minus infinity where f is not
     * parallel to the triangle, or not between 0 and {@code top} above it.
     */
    private static double depthOver(Faces geometry, int f, double[] p, double[] n, double top, double eps) {
        if (!parallel(geometry.normal(f), n)) {
            return Double.NEGATIVE_INFINITY;
        }
        double[] centre = geometry.centre(f);
        double height = n[0] * (centre[0] - p[0]) + n[1] * (centre[1] - p[1]) + n[2] * (centre[2] - p[2]);
        if (height < -eps || height > top + eps) {
            return Double.NEGATIVE_INFINITY;
        }
        return geometry.spaceDepth(f, new double[] {p[0] + height * n[0], p[1] + height * n[1], p[2] + height * n[2]});
    }

    private void checkCovered(Report report, Model model, Faces geometry, double eps, double top, int samples, long seed,
            List<ConcaveSide> concave, boolean[] crept) {
        SplittableRandom random = new SplittableRandom(seed);
        double[] p = new double[3];
        Ints candidates = new Ints();
        int uncovered = 0;
        for (int i = 0; i < samples; i++) {
            int t = model.pick(random.nextDouble());
            double r1 = Math.sqrt(random.nextDouble());
            double r2 = random.nextDouble();
            double[] n = model.normal(t);
            for (int d = 0; d < 3; d++) {
                p[d] = (1 - r1) * model.corners[9 * t + d] + r1 * (1 - r2) * model.corners[9 * t + 3 + d]
                        + r1 * r2 * model.corners[9 * t + 6 + d];
            }
            // Paper over p meets the segment from p up to the highest paper may lie.
            double reach = top + eps;
            geometry.grid.query(Math.min(p[0], p[0] + reach * n[0]) - eps, Math.min(p[1], p[1] + reach * n[1]) - eps,
                    Math.min(p[2], p[2] + reach * n[2]) - eps, Math.max(p[0], p[0] + reach * n[0]) + eps,
                    Math.max(p[1], p[1] + reach * n[1]) + eps, Math.max(p[2], p[2] + reach * n[2]) + eps, candidates);
            boolean covered = false;
            for (int k = 0; k < candidates.size() && !covered; k++) {
                covered = depthOver(geometry, geometry.paper[candidates.get(k)], p, n, top, eps) >= -eps;
            }
            if (!covered && !inCreepZone(p, n, concave, top, eps) && !nearPaper(p, n, geometry, concave, top, eps, candidates, crept)) {
                uncovered++;
                report.add(COVERED, "model point " + point(p) + " of triangle " + (t + 1) + " lies under no paper face");
            }
        }
        if (uncovered > 0) {
            report.add(COVERED, uncovered + " of " + samples + " model points lie under no paper");
        }
    }

    // ---- Truth 5 ----

    private void checkOnSurface(Report report, Model model, Faces geometry, double eps, double top) {
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
                if (!parallel(geometry.normal(f), model.normal(t)) && !(squashed(f) && equallyHigh(f, model, t, eps))) {
                    continue;
                }
                parallels++;
                double miss = restingMiss(f, model, t, eps, top);
                if (miss == 0) {
                    rests = true;
                    double highest = Double.NEGATIVE_INFINITY;
                    for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                        highest = Math.max(highest, model.height(t, xyz, 3 * cornerV[c]));
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
                report.add(ON_SURFACE, face(f) + " rests on no model triangle, nor on triangles of one plane: "
                        + (parallels == 0 ? "none within reach is parallel to it"
                                : parallels + " parallel within reach, the nearest, triangle " + (bestTriangle + 1) + ", "
                                        + restingWhy(f, model, bestTriangle, eps, top)));
            }
        }
        farthestFromSurface = farthest;
        // Cap vertices: within two stacks of paper of the surface.
        double capReach = 2 * top + eps;
        HashSet<Integer> seen = new HashSet<>();
        for (int f = 0; f < faces(); f++) {
            if (!faceCap[f]) {
                continue;
            }
            for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                int v = cornerV[c];
                if (!seen.add(v)) {
                    continue;
                }
                double x = xyz[3 * v];
                double y = xyz[3 * v + 1];
                double z = xyz[3 * v + 2];
                model.grid.query(x - capReach, y - capReach, z - capReach, x + capReach, y + capReach, z + capReach, candidates);
                double nearest = Double.POSITIVE_INFINITY;
                for (int k = 0; k < candidates.size(); k++) {
                    nearest = Math.min(nearest, model.distanceTo(candidates.get(k), x, y, z));
                }
                if (!(nearest <= capReach)) {
                    report.add(ON_SURFACE, "cap vertex " + (v + 1) + " " + point(x, y, z) + " of " + face(f) + " is "
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
    private double restingMiss(int f, Model model, int t, double eps, double top) {
        double miss = 0;
        double[] bary = new double[3];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int v = cornerV[c];
            double height = model.height(t, xyz, 3 * v);
            miss = Math.max(miss, Math.max(-eps - height, height - top - eps));
            model.barycentric(t, xyz, 3 * v, bary);
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
    private double restsOnPlane(int f, Model model, Ints candidates, double eps, double top) {
        double[] n = null;
        int plane = -1;
        for (int k = 0; k < candidates.size() && plane < 0; k++) {
            int t = candidates.get(k);
            if (!parallel(geometryNormal(f), model.normal(t)) && !(squashed(f) && equallyHigh(f, model, t, eps))) {
                continue;
            }
            boolean within = true;
            for (int c = faceStart[f]; c < faceStart[f + 1] && within; c++) {
                double height = model.height(t, xyz, 3 * cornerV[c]);
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
        int corners = faceStart[f + 1] - faceStart[f];
        double[] face = new double[2 * corners];
        double perimeter = 0;
        double highest = Double.NEGATIVE_INFINITY;
        for (int c = 0; c < corners; c++) {
            int v = cornerV[faceStart[f] + c];
            face[2 * c] = xyz[3 * v] * e1[0] + xyz[3 * v + 1] * e1[1] + xyz[3 * v + 2] * e1[2];
            face[2 * c + 1] = xyz[3 * v] * e2[0] + xyz[3 * v + 1] * e2[1] + xyz[3 * v + 2] * e2[2];
            perimeter += distance(xyz, 3 * v, xyz, 3 * cornerV[faceStart[f] + (c + 1) % corners]);
            highest = Math.max(highest, model.height(plane, xyz, 3 * v));
        }
        double whole = Math.abs(twiceArea(face)) / 2;
        double covered = 0;
        for (int k = 0; k < candidates.size(); k++) {
            int t = candidates.get(k);
            if (!parallel(n, model.normal(t)) || Math.abs(model.height(plane, model.corners, 9 * t)) > eps) {
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

    private double[] geometryNormal(int f) {
        double[] n = new double[3];
        int corners = faceStart[f + 1] - faceStart[f];
        for (int c = 0; c < corners; c++) {
            int a = 3 * cornerV[faceStart[f] + c];
            int b = 3 * cornerV[faceStart[f] + (c + 1) % corners];
            n[0] += (xyz[a + 1] - xyz[b + 1]) * (xyz[a + 2] + xyz[b + 2]);
            n[1] += (xyz[a + 2] - xyz[b + 2]) * (xyz[a] + xyz[b]);
            n[2] += (xyz[a] - xyz[b]) * (xyz[a + 1] + xyz[b + 1]);
        }
        double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        return new double[] {n[0] / length, n[1] / length, n[2] / length};
    }

    private static double twiceArea(double[] xy) {
        double twice = 0;
        int n = xy.length / 2;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            twice += xy[2 * i] * xy[2 * j + 1] - xy[2 * j] * xy[2 * i + 1];
        }
        return twice;
    }

    /** The part of polygon xy on the inner side of the line a → b (its left for sign +1, its right for -1); null if none. */
    private static double[] clipLeft(double[] xy, double ax, double ay, double bx, double by, double sign) {
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
    private String restingWhy(int f, Model model, int t, double eps, double top) {
        double[] bary = new double[3];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int v = cornerV[c];
            double height = model.height(t, xyz, 3 * v);
            if (height < -eps) {
                return "vertex " + (v + 1) + " is " + -height + " below it, inside the solid";
            }
            if (height > top + eps) {
                return "vertex " + (v + 1) + " is " + height + " above it, more than (maxStack + 1) * thickness = " + top;
            }
            model.barycentric(t, xyz, 3 * v, bary);
            if (-Math.min(bary[0], Math.min(bary[1], bary[2])) * model.longestEdge(t) > eps) {
                return "vertex " + (v + 1) + " lies outside it, at barycentric " + point(bary);
            }
        }
        return "it rests";
    }

    // ---- Geometry of the file's faces ----

    /** Face f's signed area on the sheet (positive counter-clockwise in u, v). */
    private double sheetArea(int f) {
        double twice = 0;
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int a = cornerT[c];
            int b = cornerT[nextCorner(f, c)];
            twice += uv[2 * a] * uv[2 * b + 1] - uv[2 * b] * uv[2 * a + 1];
        }
        return twice / 2;
    }

    /** Face f's size: its longest sheet edge. */
    private double sheetSize(int f) {
        double size = 0;
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            size = Math.max(size, sheetDistance(c, nextCorner(f, c)));
        }
        return size;
    }

    private void sheetBox(int f, double grow, double[] box, int at) {
        box[at] = box[at + 1] = Double.POSITIVE_INFINITY;
        box[at + 3] = box[at + 4] = Double.NEGATIVE_INFINITY;
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int t = cornerT[c];
            box[at] = Math.min(box[at], uv[2 * t] - grow);
            box[at + 1] = Math.min(box[at + 1], uv[2 * t + 1] - grow);
            box[at + 3] = Math.max(box[at + 3], uv[2 * t] + grow);
            box[at + 4] = Math.max(box[at + 4], uv[2 * t + 1] + grow);
        }
        box[at + 2] = box[at + 5] = 0;
    }

    /** The least signed distance from (u, v) to face f's sheet edges: positive inside. f must be convex. */
    private double sheetDepth(int f, double u, double v) {
        double sign = Math.signum(sheetArea(f));
        double depth = Double.POSITIVE_INFINITY;
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int a = cornerT[c];
            int b = cornerT[nextCorner(f, c)];
            double eu = uv[2 * b] - uv[2 * a];
            double ev = uv[2 * b + 1] - uv[2 * a + 1];
            double length = Math.hypot(eu, ev);
            if (length > 0) {
                depth = Math.min(depth, sign * (eu * (v - uv[2 * a + 1]) - ev * (u - uv[2 * a])) / length);
            }
        }
        return depth;
    }

    /** Face f's unit normal in space by the right-hand rule of its corners (Newell's sum, for any planar polygon). */
    /**
     * Whether face f is squashed in space to far less than its area on the sheet: crept to a
     * sliver at a concave edge (truth 2 holds such a face to its creep zone), its own normal
     * rounding.
     */
    private boolean squashed(int f) {
        double[] n = new double[3];
        int o = 3 * cornerV[faceStart[f]];
        for (int c = faceStart[f] + 1; c + 1 < faceStart[f + 1]; c++) {
            int i = 3 * cornerV[c];
            int j = 3 * cornerV[c + 1];
            double[] e1 = {xyz[i] - xyz[o], xyz[i + 1] - xyz[o + 1], xyz[i + 2] - xyz[o + 2]};
            double[] e2 = {xyz[j] - xyz[o], xyz[j + 1] - xyz[o + 1], xyz[j + 2] - xyz[o + 2]};
            double[] x = crossed(e1, e2);
            for (int d = 0; d < 3; d++) {
                n[d] += x[d];
            }
        }
        return Math.sqrt(times(n, n)) / 2 < 1e-3 * Math.abs(sheetArea(f));
    }

    /** Whether every corner of face f stands equally high above model triangle t's plane. */
    private boolean equallyHigh(int f, Model model, int t, double eps) {
        double low = Double.POSITIVE_INFINITY;
        double high = Double.NEGATIVE_INFINITY;
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            double height = model.height(t, xyz, 3 * cornerV[c]);
            low = Math.min(low, height);
            high = Math.max(high, height);
        }
        return high - low <= eps;
    }

    private double[] newellNormal(int f) {
        double[] n = new double[3];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int i = 3 * cornerV[c];
            int j = 3 * cornerV[nextCorner(f, c)];
            n[0] += (xyz[i + 1] - xyz[j + 1]) * (xyz[i + 2] + xyz[j + 2]);
            n[1] += (xyz[i + 2] - xyz[j + 2]) * (xyz[i] + xyz[j]);
            n[2] += (xyz[i] - xyz[j]) * (xyz[i + 1] + xyz[j + 1]);
        }
        double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int d = 0; d < 3; d++) {
            n[d] /= length;
        }
        return n;
    }

    private double[] centroid(int f) {
        double[] centre = new double[3];
        int n = faceStart[f + 1] - faceStart[f];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            for (int d = 0; d < 3; d++) {
                centre[d] += xyz[3 * cornerV[c] + d] / n;
            }
        }
        return centre;
    }

    private static double distance(double[] a, int i, double[] b, int j) {
        double dx = a[i] - b[j];
        double dy = a[i + 1] - b[j + 1];
        double dz = a[i + 2] - b[j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Whether unit normals a and b are parallel within PARALLEL radians, either way round. */
    private static boolean parallel(double[] a, double[] b) {
        double cx = a[1] * b[2] - a[2] * b[1];
        double cy = a[2] * b[0] - a[0] * b[2];
        double cz = a[0] * b[1] - a[1] * b[0];
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        // NaN (a degenerate face) is parallel to nothing.
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), Math.abs(dot)) <= PARALLEL;
    }

    /** The paper faces' normals, centres and boxes in space, and a grid of them. */
    private final class Faces {
        /** All paper faces, in file order; grid objects index this. */
        final int[] paper;
        /** Per paper face (by face index): unit normal, centroid, box, with NaN for caps. */
        private final double[] normals;
        private final double[] centres;
        private final double[] boxes;
        final Grid grid;

        Faces(double eps, double size) {
            Ints list = new Ints();
            normals = new double[3 * faces()];
            centres = new double[3 * faces()];
            boxes = new double[6 * faces()];
            Arrays.fill(normals, Double.NaN);
            for (int f = 0; f < faces(); f++) {
                if (faceCap[f]) {
                    continue;
                }
                list.add(f);
                System.arraycopy(newellNormal(f), 0, normals, 3 * f, 3);
                System.arraycopy(centroid(f), 0, centres, 3 * f, 3);
                for (int d = 0; d < 3; d++) {
                    boxes[6 * f + d] = Double.POSITIVE_INFINITY;
                    boxes[6 * f + 3 + d] = Double.NEGATIVE_INFINITY;
                }
                for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                    for (int d = 0; d < 3; d++) {
                        boxes[6 * f + d] = Math.min(boxes[6 * f + d], xyz[3 * cornerV[c] + d]);
                        boxes[6 * f + 3 + d] = Math.max(boxes[6 * f + 3 + d], xyz[3 * cornerV[c] + d]);
                    }
                }
            }
            paper = list.toArray();
            double[] paperBoxes = new double[6 * paper.length];
            for (int i = 0; i < paper.length; i++) {
                System.arraycopy(boxes, 6 * paper[i], paperBoxes, 6 * i, 6);
            }
            grid = new Grid(paperBoxes, paper.length, Grid.cellFor(paperBoxes, paper.length, LEAST_CELL * size + eps));
        }

        double[] normal(int f) {
            return Arrays.copyOfRange(normals, 3 * f, 3 * f + 3);
        }

        double[] centre(int f) {
            return Arrays.copyOfRange(centres, 3 * f, 3 * f + 3);
        }

        double[] box(int f) {
            return Arrays.copyOfRange(boxes, 6 * f, 6 * f + 6);
        }

        /** The least signed distance from p (in f's plane) to f's edges, measured in the plane: positive inside. */
        double spaceDepth(int f, double[] p) {
            double depth = Double.POSITIVE_INFINITY;
            double nx = normals[3 * f];
            double ny = normals[3 * f + 1];
            double nz = normals[3 * f + 2];
            for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
                int a = 3 * cornerV[c];
                int b = 3 * cornerV[nextCorner(f, c)];
                double ex = xyz[b] - xyz[a];
                double ey = xyz[b + 1] - xyz[a + 1];
                double ez = xyz[b + 2] - xyz[a + 2];
                double length = Math.sqrt(ex * ex + ey * ey + ez * ez);
                if (length == 0) {
                    continue;
                }
                double rx = p[0] - xyz[a];
                double ry = p[1] - xyz[a + 1];
                double rz = p[2] - xyz[a + 2];
                // (e x r) . n: positive when p is on the inner (left) side of the edge.
                double side = (ey * rz - ez * ry) * nx + (ez * rx - ex * rz) * ny + (ex * ry - ey * rx) * nz;
                depth = Math.min(depth, side / length);
            }
            return depth;
        }
    }

    /** The model: its triangles, their unit outward normals, areas, a grid of them and its size. */
    private static final class Model {
        /** x y z of the three corners of each triangle, 9 per triangle. */
        final double[] corners;
        /** Unit outward normals, 3 per triangle (NaN for a degenerate triangle). */
        private final double[] normals;
        /** Running sum of the areas, to pick triangles by area. */
        private final double[] cumulativeArea;
        /** The bounding-box diagonal. */
        final double size;
        final Grid grid;

        Model(List<double[]> triangles) {
            int n = triangles.size();
            if (n == 0) {
                throw new IllegalArgumentException("no model triangles");
            }
            corners = new double[9 * n];
            normals = new double[3 * n];
            cumulativeArea = new double[n];
            double[] boxes = new double[6 * n];
            double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
            double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
            double area = 0;
            for (int t = 0; t < n; t++) {
                double[] tri = triangles.get(t);
                if (tri.length != 9 || !Arrays.stream(tri).allMatch(Double::isFinite)) {
                    throw new IllegalArgumentException("model triangle " + (t + 1) + " is not 9 finite numbers");
                }
                System.arraycopy(tri, 0, corners, 9 * t, 9);
                double[] e1 = {tri[3] - tri[0], tri[4] - tri[1], tri[5] - tri[2]};
                double[] e2 = {tri[6] - tri[0], tri[7] - tri[1], tri[8] - tri[2]};
                double nx = e1[1] * e2[2] - e1[2] * e2[1];
                double ny = e1[2] * e2[0] - e1[0] * e2[2];
                double nz = e1[0] * e2[1] - e1[1] * e2[0];
                double twice = Math.sqrt(nx * nx + ny * ny + nz * nz);
                normals[3 * t] = nx / twice;
                normals[3 * t + 1] = ny / twice;
                normals[3 * t + 2] = nz / twice;
                area += twice / 2;
                cumulativeArea[t] = area;
                for (int d = 0; d < 3; d++) {
                    boxes[6 * t + d] = Math.min(tri[d], Math.min(tri[3 + d], tri[6 + d]));
                    boxes[6 * t + 3 + d] = Math.max(tri[d], Math.max(tri[3 + d], tri[6 + d]));
                    min[d] = Math.min(min[d], boxes[6 * t + d]);
                    max[d] = Math.max(max[d], boxes[6 * t + 3 + d]);
                }
            }
            size = Math.sqrt((max[0] - min[0]) * (max[0] - min[0]) + (max[1] - min[1]) * (max[1] - min[1])
                    + (max[2] - min[2]) * (max[2] - min[2]));
            if (!(size > 0) || !(area > 0)) {
                throw new IllegalArgumentException("the model has no size or no area");
            }
            grid = new Grid(boxes, n, Grid.cellFor(boxes, n, LEAST_CELL * size));
        }

        double[] normal(int t) {
            return Arrays.copyOfRange(normals, 3 * t, 3 * t + 3);
        }

        /** The triangle whose share of the total area holds r in [0, 1). */
        int pick(double r) {
            double target = r * cumulativeArea[cumulativeArea.length - 1];
            int i = Arrays.binarySearch(cumulativeArea, target);
            i = i >= 0 ? i + 1 : -i - 1;
            return Math.min(i, cumulativeArea.length - 1);
        }

        /** The height of point p[i..i+2] above triangle t's plane, along its outward normal. */
        double height(int t, double[] p, int i) {
            return normals[3 * t] * (p[i] - corners[9 * t]) + normals[3 * t + 1] * (p[i + 1] - corners[9 * t + 1])
                    + normals[3 * t + 2] * (p[i + 2] - corners[9 * t + 2]);
        }

        /** The barycentric coordinates, in t, of p[i..i+2] projected onto t's plane. */
        void barycentric(int t, double[] p, int i, double[] out) {
            double[] n = normal(t);
            for (int k = 0; k < 3; k++) {
                int a = 9 * t + 3 * ((k + 1) % 3);
                int b = 9 * t + 3 * ((k + 2) % 3);
                // Twice the area of (p, a, b) over twice the triangle's area, both along n.
                double ex = corners[b] - corners[a];
                double ey = corners[b + 1] - corners[a + 1];
                double ez = corners[b + 2] - corners[a + 2];
                double rx = p[i] - corners[a];
                double ry = p[i + 1] - corners[a + 1];
                double rz = p[i + 2] - corners[a + 2];
                out[k] = (ey * rz - ez * ry) * n[0] + (ez * rx - ex * rz) * n[1] + (ex * ry - ey * rx) * n[2];
            }
            double total = out[0] + out[1] + out[2];
            for (int k = 0; k < 3; k++) {
                out[k] /= total;
            }
        }

        double longestEdge(int t) {
            double longest = 0;
            for (int k = 0; k < 3; k++) {
                longest = Math.max(longest, distance(corners, 9 * t + 3 * k, corners, 9 * t + 3 * ((k + 1) % 3)));
            }
            return longest;
        }

        /** The distance from (x, y, z) to triangle t (Ericson, Real-Time Collision Detection, 5.1.5). */
        double distanceTo(int t, double x, double y, double z) {
            int i = 9 * t;
            double[] a = {corners[i], corners[i + 1], corners[i + 2]};
            double[] b = {corners[i + 3], corners[i + 4], corners[i + 5]};
            double[] c = {corners[i + 6], corners[i + 7], corners[i + 8]};
            double[] p = {x, y, z};
            double[] ab = minus(b, a);
            double[] ac = minus(c, a);
            double[] ap = minus(p, a);
            double d1 = dot(ab, ap);
            double d2 = dot(ac, ap);
            if (d1 <= 0 && d2 <= 0) {
                return length(ap);
            }
            double[] bp = minus(p, b);
            double d3 = dot(ab, bp);
            double d4 = dot(ac, bp);
            if (d3 >= 0 && d4 <= d3) {
                return length(bp);
            }
            double vc = d1 * d4 - d3 * d2;
            if (vc <= 0 && d1 >= 0 && d3 <= 0) {
                return length(minus(ap, scale(ab, d1 / (d1 - d3))));
            }
            double[] cp = minus(p, c);
            double d5 = dot(ab, cp);
            double d6 = dot(ac, cp);
            if (d6 >= 0 && d5 <= d6) {
                return length(cp);
            }
            double vb = d5 * d2 - d1 * d6;
            if (vb <= 0 && d2 >= 0 && d6 <= 0) {
                return length(minus(ap, scale(ac, d2 / (d2 - d6))));
            }
            double va = d3 * d6 - d5 * d4;
            if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
                return length(minus(bp, scale(minus(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6)))));
            }
            double denominator = 1 / (va + vb + vc);
            double v = vb * denominator;
            double w = vc * denominator;
            return length(minus(ap, plus(scale(ab, v), scale(ac, w))));
        }

        private static double[] minus(double[] a, double[] b) {
            return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
        }

        private static double[] plus(double[] a, double[] b) {
            return new double[] {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
        }

        private static double[] scale(double[] a, double s) {
            return new double[] {a[0] * s, a[1] * s, a[2] * s};
        }

        private static double dot(double[] a, double[] b) {
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        }

        private static double length(double[] a) {
            return Math.sqrt(dot(a, a));
        }
    }

    /**
     * A sparse uniform grid of boxes in space (a sheet is the plane z = 0), for candidate lookups:
     * a query returns every object whose box meets the query box, each once, and perhaps a few
     * more (cells are hashed, and two cells may share a key); callers test candidates exactly.
     */
    static final class Grid {
        private final double cell;
        private final HashMap<Long, int[]> cells = new HashMap<>();
        /** The query each object was last returned by, so that it is returned once. */
        private final int[] stamp;
        private int query;

        /** boxes: min x y z, max x y z of each of the n objects. */
        Grid(double[] boxes, int n, double cell) {
            this.cell = cell;
            stamp = new int[n];
            HashMap<Long, Ints> lists = new HashMap<>();
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                for (long x = floor(boxes[o]); x <= floor(boxes[o + 3]); x++) {
                    for (long y = floor(boxes[o + 1]); y <= floor(boxes[o + 4]); y++) {
                        for (long z = floor(boxes[o + 2]); z <= floor(boxes[o + 5]); z++) {
                            lists.computeIfAbsent(key(x, y, z), k -> new Ints()).add(i);
                        }
                    }
                }
            }
            lists.forEach((k, list) -> cells.put(k, list.toArray()));
        }

        /**
         * A cell size for these boxes: the median of their largest extents (so that the rare big
         * box spans many cells but the many small ones few), at least least, grown until the
         * cells the boxes span stay few.
         */
        static double cellFor(double[] boxes, int n, double least) {
            double[] extents = new double[n];
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                extents[i] = Math.max(boxes[o + 3] - boxes[o], Math.max(boxes[o + 4] - boxes[o + 1], boxes[o + 5] - boxes[o + 2]));
            }
            Arrays.sort(extents);
            double cell = Math.max(n == 0 ? least : extents[n / 2], least);
            while (spans(boxes, n, cell) > 16.0 * n + 100_000) {
                cell *= 2;
            }
            return cell;
        }

        private static double spans(double[] boxes, int n, double cell) {
            double total = 0;
            for (int i = 0; i < n; i++) {
                int o = 6 * i;
                double count = 1;
                for (int d = 0; d < 3; d++) {
                    count *= Math.floor(boxes[o + 3 + d] / cell) - Math.floor(boxes[o + d] / cell) + 1;
                }
                total += count;
            }
            return total;
        }

        private long floor(double x) {
            return (long) Math.floor(x / cell);
        }

        private static long key(long x, long y, long z) {
            return x * 0x9E3779B97F4A7C15L + y * 0xC2B2AE3D27D4EB4FL + z * 0x165667B19E3779F9L;
        }

        /** The objects whose boxes may meet [x0, x1] x [y0, y1] x [z0, z1], into out (cleared first). */
        void query(double x0, double y0, double z0, double x1, double y1, double z1, Ints out) {
            out.clear();
            query++;
            for (long x = floor(x0); x <= floor(x1); x++) {
                for (long y = floor(y0); y <= floor(y1); y++) {
                    for (long z = floor(z0); z <= floor(z1); z++) {
                        int[] objects = cells.get(key(x, y, z));
                        if (objects == null) {
                            continue;
                        }
                        for (int i : objects) {
                            if (stamp[i] != query) {
                                stamp[i] = query;
                                out.add(i);
                            }
                        }
                    }
                }
            }
        }
    }

    /** A growable list of ints. */
    static final class Ints {
        private int[] items = new int[8];
        private int size;

        void add(int value) {
            if (size == items.length) {
                items = Arrays.copyOf(items, 2 * size);
            }
            items[size++] = value;
        }

        int get(int i) {
            return items[i];
        }

        int size() {
            return size;
        }

        void clear() {
            size = 0;
        }

        int[] toArray() {
            return Arrays.copyOf(items, size);
        }
    }

    /** The violations as they are found, listing at most LISTED_PER_TRUTH of each truth. */
    private static final class Report {
        private final Map<String, List<Violation>> byTruth = new LinkedHashMap<>();
        private final Map<String, Integer> counts = new HashMap<>();

        Report() {
            for (String truth : List.of(TILED, ISOMETRIC, NOT_TORN, COVERED, ON_SURFACE)) {
                byTruth.put(truth, new ArrayList<>());
            }
        }

        void add(String truth, String message) {
            int count = counts.merge(truth, 1, Integer::sum);
            if (count <= LISTED_PER_TRUTH) {
                byTruth.get(truth).add(new Violation(truth, message));
            }
        }

        List<Violation> finish() {
            List<Violation> all = new ArrayList<>();
            byTruth.forEach((truth, list) -> {
                all.addAll(list);
                int count = counts.getOrDefault(truth, 0);
                if (count > LISTED_PER_TRUTH) {
                    all.add(new Violation(truth, (count - LISTED_PER_TRUTH) + " more violations of this truth not listed"));
                }
            });
            return List.copyOf(all);
        }
    }
}
