package ifold.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Map;

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
 * which the layers of the face across keep to from the other side); and so at an edge between
 * coplanar triangles of a plane region that is not convex, where the wrap may cut the region into
 * convex hosts (a cut: φ = 0, no mitre to keep from); and at the end of a convex edge where a
 * face at that corner rises across the edge (at least 30 degrees), whose layers stand out along
 * it as far as the stack is high over the cosine between the edge and that face's normal: paper
 * bent over the edge keeps from the corner by as much (a zone along the edge that long, a stack
 * wide, with no mitre);</li>
 * <li>{@link #NOT_TORN}: faces that are neighbours on the sheet are neighbours in space (or
 * joined by a cap across at most a few thicknesses), but for two squashed to a sliver in space
 * (paper whose layer ends by a concave edge, pressed onto the line where it ends: truth 2 holds
 * their corners to the creep zone);</li>
 * <li>{@link #COVERED}: random points of the model lie under paper (but within the creep zone
 * of a concave edge, truth 2, where thick paper stands back from the edge and the paper across
 * covers it; and beside paper that truth 2 let creep, within its creep zone: a fold nested along
 * a cut stands back along the whole of its crease, beyond where the folds wrapping it end);</li>
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
    static final double OFFSET_U = 0.3819660112501051;
    static final double OFFSET_V = 0.41421356237309515;
    /** A broken file can break a truth thousands of times; past this many, only the count is kept. */
    static final int LISTED_PER_TRUTH = 50;
    /** How far a convex face's total turning may be from 2 pi, radians (far below the 2 pi of a second turn). */
    static final double TURNING = 1e-6;
    /** The smallest grid cell, relative to the model size: only for degenerate (zero-extent) inputs. */
    static final double LEAST_CELL = 1e-6;

    // The file, as read. Indices are 0-based; faces keep their file order.
    /** Vertex positions, x y z interleaved. */
    final double[] xyz;
    /** Paper coordinates, u v interleaved. */
    final double[] uv;
    /** Face f's corners are cornerV/cornerT[faceStart[f] .. faceStart[f + 1]). */
    final int[] faceStart;
    /** The vertex (v) index of each corner. */
    final int[] cornerV;
    /** The paper coordinate (vt) index of each corner. */
    final int[] cornerT;
    /** The strip each face belongs to. */
    final int[] faceStrip;
    /** Whether each face is a cap (else paper). */
    final boolean[] faceCap;
    /** The file line each face is on, for messages. */
    final int[] faceLine;
    /** Each strip's name (what follows {@code o}). */
    final List<String> stripNames;
    /** Each strip's paper faces and cap faces. */
    final List<int[]> stripPaper;
    final List<int[]> stripCaps;
    /** Each strip's sheet: the least and largest u and v of its paper faces. */
    final double[] stripMinU;
    final double[] stripMinV;
    final double[] stripL;
    final double[] stripW;
    final int paperCount;
    final double worstIsometry;
    /** Set by the last check; NaN before one. */
    double farthestFromSurface = Double.NaN;

    /** How many violations of each truth the last check found, listed or not. */
    private Map<String, Integer> violationCounts = Map.of();
    /** Truth 5 of {@link WrapTruths}. */
    final TruthSurface surface = new TruthSurface(this);
    /** Truth 4 of {@link WrapTruths}. */
    final TruthCoverage coverage = new TruthCoverage(this);
    /** Truth 3 of {@link WrapTruths}. */
    final TruthNeighbours neighbours = new TruthNeighbours(this);
    /** Truth 2 of {@link WrapTruths}. */
    final TruthIsometry isometry = new TruthIsometry(this);
    /** Truth 1 of {@link WrapTruths}. */
    final TruthTiling tiling = new TruthTiling(this);

    WrapTruths(double[] xyz, double[] uv, Ints faceStart, Ints cornerV, Ints cornerT, Ints faceStrip,
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
                worst = Math.max(worst, isometry.isometryError(f, null));
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

    static void require(boolean condition, int lineNo, String message) {
        if (!condition) {
            throw new IllegalArgumentException("line " + lineNo + ": " + message);
        }
    }

    /** A 1-based (or negative, relative) OBJ index made 0-based; only elements already read count, as OBJ says. */
    static int index(String token, int count, int lineNo, String what) {
        int k = Integer.parseInt(token);
        int i = k > 0 ? k - 1 : count + k;
        require(k != 0 && i >= 0 && i < count, lineNo, what + " " + k + " is not among the " + count + " read so far");
        return i;
    }

    static double[] unbox(List<Double> list) {
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

    /**
     * How many violations of each truth (its name, as {@link #TILED}) the last {@link #check}
     * found, those it did not list too; the truths that hold are left out. Empty before any check.
     */
    public Map<String, Integer> violationCounts() {
        return violationCounts;
    }

    int faces() {
        return faceStrip.length;
    }

    /** "face 3 (line 17, strip-1)": the 1-based face number in file order, for messages. */
    String face(int f) {
        return "face " + (f + 1) + " (line " + faceLine[f] + ", " + stripNames.get(faceStrip[f]) + ")";
    }

    static String point(double... p) {
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
        TruthModel model = new TruthModel(modelTriangles);
        TruthReport report = new TruthReport();
        double eps = RELATIVE * model.size;
        double top = (maxStack + 1) * thickness;
        Faces geometry = new Faces(eps, model.size);
        tiling.checkStripsAreTiledOnce(report, eps);
        List<TruthIsometry.ConcaveSide> concave = TruthIsometry.concaveSides(model, eps);
        // Folds tucked along a cut between coplanar hosts stand back from it as at a concave edge.
        List<TruthIsometry.ConcaveSide> creepSides = new ArrayList<>(concave);
        creepSides.addAll(TruthIsometry.cutSides(model, eps));
        // Paper over a convex edge keeps from its end where a face rises across it, as far as that face's stack stands out.
        creepSides.addAll(TruthIsometry.stopSides(model, eps, top));
        boolean[] crept = new boolean[faces()];
        isometry.checkIsometry(report, creepSides, thickness, maxStack, eps, crept);
        neighbours.checkNotTorn(report, eps, 2 * top);
        // Beside crept paper the surface may lie bare as far as truth 2 let it creep: the widest
        // creep zone of a concave edge or a cut (the stack's height over a cut), or a thickness
        // where folds back to back on one crease stand back from it, under their bends.
        // (Only crept faces excuse a gap, and faces creep only where paper is thick.)
        double creepWidth = thickness;
        for (TruthIsometry.ConcaveSide side : creepSides) {
            creepWidth = Math.max(creepWidth, top * (side.mitre() + 1));
        }
        coverage.checkCovered(report, model, geometry, eps, top, coverageSamples, seed, thickness > 0 ? concave : List.of(), crept,
                creepWidth);
        surface.checkOnSurface(report, model, geometry, eps, top);
        violationCounts = report.counts();
        return report.finish();
    }

    // ---- Truth 1 ----

    // ---- Truth 2 ----

    // ---- Truth 3 ----

    // ---- Truth 4 ----

    // ---- Truth 5 ----

    // ---- Geometry of the file's faces ----

    double[] newellNormal(int f) {
        double[] n = new double[3];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            int i = 3 * cornerV[c];
            int j = 3 * cornerV[neighbours.nextCorner(f, c)];
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

    double[] centroid(int f) {
        double[] centre = new double[3];
        int n = faceStart[f + 1] - faceStart[f];
        for (int c = faceStart[f]; c < faceStart[f + 1]; c++) {
            for (int d = 0; d < 3; d++) {
                centre[d] += xyz[3 * cornerV[c] + d] / n;
            }
        }
        return centre;
    }

    static double distance(double[] a, int i, double[] b, int j) {
        double dx = a[i] - b[j];
        double dy = a[i + 1] - b[j + 1];
        double dz = a[i + 2] - b[j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Whether unit normals a and b are parallel within PARALLEL radians, either way round. */
    static boolean parallel(double[] a, double[] b) {
        double cx = a[1] * b[2] - a[2] * b[1];
        double cy = a[2] * b[0] - a[0] * b[2];
        double cz = a[0] * b[1] - a[1] * b[0];
        double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
        // NaN (a degenerate face) is parallel to nothing.
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), Math.abs(dot)) <= PARALLEL;
    }

    /** The paper faces' normals, centres and boxes in space, and a grid of them. */
    final class Faces {
        /** All paper faces, in file order; grid objects index this. */
        final int[] paper;
        /** Per paper face (by face index): unit normal, centroid, box, with NaN for caps. */
        private final double[] normals;
        private final double[] centres;
        private final double[] boxes;
        final TruthGrid grid;

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
            grid = new TruthGrid(paperBoxes, paper.length, TruthGrid.cellFor(paperBoxes, paper.length, LEAST_CELL * size + eps));
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
                int b = 3 * cornerV[neighbours.nextCorner(f, c)];
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
}
