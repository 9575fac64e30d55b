package ifold.check;

import java.io.IOException;
import java.io.Reader;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Whether the layers of a folded state are in an order paper could be in, read from its FOLD
 * file alone (its folded frame's {@code vertices_coords}, {@code faces_vertices} and
 * {@code faceOrders}): an independent check that shares no code with the fold engine.
 *
 * <p>Paper of no thickness, as FOLD means it. Faces that lie in one plane and overlap (in more
 * than a touch, as convex polygons) are layers, and the rules of flat folding apply to them:
 * <ul>
 * <li>every two of them are ordered ({@link Kind#UNORDERED}), and only one way
 *     ({@link Kind#CONTRADICTORY});
 * <li>no three that share a point are ordered in a cycle ({@link Kind#CYCLE}: transitivity);
 * <li>where two faces of one plane are joined by a crease folded flat (a taco: both lie on one
 *     side of the crease), no paper that goes on across the crease's line there lies between them
 *     ({@link Kind#TACO_TORTILLA}: a face the line runs through, paper joined flat across it, or
 *     paper leaving the plane there), and the two faces of another such crease on the same
 *     segment, on the same side, lie both between them or neither ({@link Kind#TACO_TACO});
 * <li>where pieces of paper go on across one line (flat, or bent to another plane: a wrap's
 *     edges of the model), they keep their order from one side to the other
 *     ({@link Kind#CROSSING}), as layers bent together do.
 * </ul>
 * Face numbers are FOLD's, from 0.
 */
public final class LayerOrder {
    private LayerOrder() {
    }

    /** What rule a violation breaks. */
    public enum Kind {
        UNORDERED("unordered"), CONTRADICTORY("contradictory"), CYCLE("cycle"), TACO_TORTILLA("tacoTortilla"),
        TACO_TACO("tacoTaco"), CROSSING("crossing");

        /** The name the report gives. */
        public final String key;

        Kind(String key) {
            this.key = key;
        }
    }

    /** One broken rule, the faces it concerns (FOLD's numbers) and what it is, in words. */
    public record Violation(Kind kind, int[] faces, String message) {
    }

    /**
     * What the check found.
     *
     * @param faces the faces of the folded state
     * @param planes the planes they lie in
     * @param layered pairs of faces of one plane that overlap
     * @param violations the violations of each kind
     * @param first the first few violations, in words
     */
    public record Result(int faces, int planes, long layered, Map<Kind, Integer> violations, List<Violation> first) {
        /** The most violations given in words. */
        public static final int LISTED = 10;

        public int total() {
            return violations.values().stream().mapToInt(Integer::intValue).sum();
        }

        public boolean valid() {
            return total() == 0;
        }

        /** One line for the terminal. */
        public String summary() {
            if (valid()) {
                return String.format(Locale.ROOT, "layer order: valid (%s on %s, %s of layers)", counted(faces, "face"),
                        counted(planes, "plane"), counted(layered, "pair"));
            }
            StringBuilder kinds = new StringBuilder();
            for (Map.Entry<Kind, Integer> entry : violations.entrySet()) {
                if (entry.getValue() > 0) {
                    kinds.append(kinds.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%,d %s", entry.getValue(),
                            entry.getKey().key));
                }
            }
            return String.format(Locale.ROOT, "layer order: %s (%s); the first: %s", counted(total(), "violation"), kinds,
                    first.get(0).message());
        }

        private static String counted(long n, String noun) {
            return String.format(Locale.ROOT, "%,d %s%s", n, noun, n == 1 ? "" : "s");
        }
    }

    /** Checks the folded state of a FOLD file's text. */
    public static Result check(CharSequence fold) throws IOException {
        return check(FoldedState.read(fold));
    }

    /** Checks the folded state of a FOLD file. */
    public static Result check(Reader fold) throws IOException {
        return check(FoldedState.read(fold));
    }

    static Result check(FoldedState state) {
        PlanarFaces faces = new PlanarFaces(state);
        Findings findings = new Findings();
        for (int[] pair : faces.contradictions) {
            findings.add(Kind.CONTRADICTORY, pair, "faces " + pair[0] + " and " + pair[1] + " are ordered both ways");
        }
        long layered = 0;
        for (int p = 0; p < faces.facesOf.size(); p++) {
            layered += planeLayers(faces, p, findings);
        }
        CreaseLayers.check(faces, findings);
        return new Result(state.faceCount, faces.facesOf.size(), layered, findings.counts, findings.first);
    }

    /** The violations found so far: counted by kind, the first few kept. */
    static final class Findings {
        final Map<Kind, Integer> counts = new EnumMap<>(Kind.class);
        final List<Violation> first = new ArrayList<>();

        Findings() {
            for (Kind kind : Kind.values()) {
                counts.put(kind, 0);
            }
        }

        void add(Kind kind, int[] faces, String message) {
            counts.merge(kind, 1, Integer::sum);
            if (first.size() < Result.LISTED) {
                first.add(new Violation(kind, faces, kind.key + ": " + message));
            }
        }
    }

    /**
     * The overlapping pairs of one plane: each must be ordered, and those that share a point
     * not in a cycle. Returns the number of pairs.
     */
    private static long planeLayers(PlanarFaces faces, int p, Findings findings) {
        int[] members = faces.facesOf.get(p);
        if (members.length < 2) {
            return 0;
        }
        PlanarFaces.Grid grid = faces.grid(p);
        // Edges lower → upper of the overlapping pairs, for the cycles.
        int[] lower = new int[16];
        int[] upper = new int[16];
        int edges = 0;
        long pairs = 0;
        // Each face against the later faces of the cells it meets, each of them once.
        int[][] found = {new int[16]};
        int[] count = new int[1];
        for (int f : members) {
            int mark = faces.nextMark();
            count[0] = 0;
            grid.forPolygon(faces.polygon[f], key -> {
                int[] list = grid.cells.get(key);
                for (int i = list[0]; i >= 1 && list[i] > f; i--) {
                    int g = list[i];
                    if (faces.marks[g] != mark) {
                        faces.marks[g] = mark;
                        if (count[0] == found[0].length) {
                            found[0] = Arrays.copyOf(found[0], 2 * count[0]);
                        }
                        found[0][count[0]++] = g;
                    }
                }
            });
            for (int k = 0; k < count[0]; k++) {
                int g = found[0][k];
                if (!faces.overlap(f, g)) {
                    continue;
                }
                pairs++;
                int order = faces.above(f, g);
                if (order == 0) {
                    findings.add(Kind.UNORDERED, new int[] {f, g}, "faces " + f + " and " + g
                            + " overlap in one plane, and the file does not say which lies above");
                    continue;
                }
                if (edges == lower.length) {
                    lower = Arrays.copyOf(lower, 2 * edges);
                    upper = Arrays.copyOf(upper, 2 * edges);
                }
                lower[edges] = order > 0 ? g : f;
                upper[edges] = order > 0 ? f : g;
                edges++;
            }
        }
        cycles(faces, members, lower, upper, edges, findings);
        return pairs;
    }

    /**
     * Faces of one plane ordered in a cycle: where the order of overlapping pairs has one (found
     * by peeling the faces nothing lies below), every three that lie in a cycle and share a point.
     */
    private static void cycles(PlanarFaces faces, int[] members, int[] lower, int[] upper, int edges, Findings findings) {
        int n = members.length;
        int[] index = faces.placeInPlane;
        int[] start = new int[n + 1];
        int[] below = new int[n];
        for (int e = 0; e < edges; e++) {
            start[index[lower[e]] + 1]++;
            below[index[upper[e]]]++;
        }
        for (int i = 0; i < n; i++) {
            start[i + 1] += start[i];
        }
        int[] aboveOf = new int[edges];
        int[] fill = Arrays.copyOf(start, n);
        for (int e = 0; e < edges; e++) {
            aboveOf[fill[index[lower[e]]]++] = index[upper[e]];
        }
        int[] queue = new int[n];
        int head = 0;
        int tail = 0;
        for (int i = 0; i < n; i++) {
            if (below[i] == 0) {
                queue[tail++] = i;
            }
        }
        while (head < tail) {
            int i = queue[head++];
            for (int k = start[i]; k < start[i + 1]; k++) {
                if (--below[aboveOf[k]] == 0) {
                    queue[tail++] = aboveOf[k];
                }
            }
        }
        if (tail == n) {
            return;
        }
        boolean[] left = new boolean[n];
        for (int i = 0; i < n; i++) {
            left[i] = below[i] > 0;
        }
        // f < g < h < f: g above f, h above g, f above h; each cycle once, from its least face.
        for (int i = 0; i < n; i++) {
            if (!left[i]) {
                continue;
            }
            for (int k = start[i]; k < start[i + 1]; k++) {
                int j = aboveOf[k];
                if (!left[j] || j < i) {
                    continue;
                }
                for (int m = start[j]; m < start[j + 1]; m++) {
                    int h = aboveOf[m];
                    if (!left[h] || h < i) {
                        continue;
                    }
                    int f = members[i];
                    int g = members[j];
                    int top = members[h];
                    if (faces.above(f, top) > 0 && shareAPoint(faces, f, g, top)) {
                        findings.add(Kind.CYCLE, new int[] {f, g, top}, "faces " + f + ", " + g + " and " + top
                                + " overlap at a point and each lies above the one before it");
                    }
                }
            }
        }
    }

    /** Whether three convex faces of one plane have more than a touch in common. */
    private static boolean shareAPoint(PlanarFaces faces, int f, int g, int h) {
        double[] common = clip(clip(faces.polygon[f], faces.polygon[g]), faces.polygon[h]);
        if (common.length < 6) {
            return false;
        }
        double area = 0;
        for (int i = 0; i < common.length; i += 2) {
            int j = (i + 2) % common.length;
            area += common[i] * common[j + 1] - common[j] * common[i + 1];
        }
        return area / 2 > faces.eps * faces.eps;
    }

    /** The part of convex polygon {@code subject} inside convex polygon {@code window} (both counter-clockwise). */
    static double[] clip(double[] subject, double[] window) {
        double[] out = subject;
        int n = window.length / 2;
        for (int i = 0; i < n && out.length >= 6; i++) {
            int j = (i + 1) % n;
            double ax = window[2 * i];
            double ay = window[2 * i + 1];
            double ex = window[2 * j] - ax;
            double ey = window[2 * j + 1] - ay;
            double[] in = out;
            double[] next = new double[in.length + 4];
            int count = 0;
            int m = in.length / 2;
            for (int k = 0; k < m; k++) {
                int l = (k + 1) % m;
                double sk = ex * (in[2 * k + 1] - ay) - ey * (in[2 * k] - ax);
                double sl = ex * (in[2 * l + 1] - ay) - ey * (in[2 * l] - ax);
                if (sk >= 0) {
                    if (count + 2 > next.length) {
                        next = Arrays.copyOf(next, 2 * next.length);
                    }
                    next[count++] = in[2 * k];
                    next[count++] = in[2 * k + 1];
                }
                if ((sk >= 0) != (sl >= 0)) {
                    double t = sk / (sk - sl);
                    if (count + 2 > next.length) {
                        next = Arrays.copyOf(next, 2 * next.length);
                    }
                    next[count++] = in[2 * k] + t * (in[2 * l] - in[2 * k]);
                    next[count++] = in[2 * k + 1] + t * (in[2 * l + 1] - in[2 * k + 1]);
                }
            }
            out = Arrays.copyOf(next, count);
        }
        return out;
    }
}
