package ifold.foldfile;

import ifold.sheet.Polygons2;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A layer order for a crease pattern folded flat, where the file gives none: which of every two
 * faces that overlap lies above, such that paper could be folded so. The conditions are those of
 * flat folding (as Jason Ku's Flat-Folder states them): the two faces of a crease lie as its
 * valley or mountain says; a face through which a crease's line runs lies above both of its
 * faces or below both (taco–tortilla); two creases on one line whose flaps lie on one side nest
 * or lie apart, never interleave (taco–taco); and no three faces over one point lie in a cycle
 * (transitivity). Each condition is propagated as soon as all its pairs but one are decided;
 * what propagation leaves open is searched, depth first.
 */
final class LayerSolver {
    /** The most choices the search makes before it gives up on an order. */
    static final long MOST_CHOICES = 500_000;

    /**
     * A crease folded flat between faces f and g along the segment (x1, y1)-(x2, y2) of the
     * folded state, a valley or a mountain seen from the paper's top side; or, not {@code
     * folded}, a flat edge, across which the paper runs on (a tortilla's seam).
     */
    record FlatCrease(int f, int g, boolean valley, double x1, double y1, double x2, double y2, boolean folded) {
        /** A crease folded flat, a valley or a mountain. */
        FlatCrease(int f, int g, boolean valley, double x1, double y1, double x2, double y2) {
            this(f, g, valley, x1, y1, x2, y2, true);
        }

        /** A flat edge between f and g (F): the paper goes on across it unfolded. */
        static FlatCrease join(int f, int g, double x1, double y1, double x2, double y2) {
            return new FlatCrease(f, g, false, x1, y1, x2, y2, false);
        }
    }

    /** One condition on up to four pairs: the pairs (a, b) it reads, and the kind that says how. */
    private record Condition(int kind, int[] faces) {
    }

    private static final int FIXED = 0;
    private static final int SAME_SIDE = 1;
    private static final int NESTED = 2;
    private static final int NO_CYCLE = 3;
    private static final int SAME_ORDER = 4;

    private final double[][] polygons;
    private final Map<Long, Integer> variable = new HashMap<>();
    private final List<long[]> pairs = new ArrayList<>();
    private byte[] value;
    private final List<Condition> conditions = new ArrayList<>();
    private List<List<Integer>> watching;
    private long choices;
    /** What the last broken condition says, for the refusal. */
    private String conflict;
    /** Each face's place in an order of the pairs decided so far (Kahn's; faces in a cycle last, in their numbers' order). */
    private int[] rank;
    /** Whether the last search stopped at {@link #MOST_CHOICES} rather than finding no order. */
    private boolean gaveUp;

    private LayerSolver(double[][] polygons) {
        this.polygons = polygons;
    }

    /**
     * The faces bottom up (each face above every face before it that it overlaps).
     *
     * @param polygons each face in the folded state's plane (x, y pairs, convex)
     * @param faceUp whether each face shows its top side up (+z)
     * @param tolerance overlaps thinner than this are none (as the layer-order check counts them)
     * @param lineTolerance creases this close lie on one line, and a crease this close to a face's
     *     edge runs along it, not through the face: the file's rounding
     * @throws CreasePattern.Refused naming the faces where no order satisfies the conditions
     */
    static int[] order(double[][] polygons, boolean[] faceUp, List<FlatCrease> creases, double tolerance, double lineTolerance)
            throws CreasePattern.Refused {
        LayerSolver solver = new LayerSolver(polygons);
        solver.findPairs(tolerance);
        solver.value = new byte[solver.pairs.size()];
        for (FlatCrease crease : creases) {
            if (!crease.folded()) {
                continue;
            }
            // A valley lays g on f's top side: above f where f shows its top side up.
            boolean gAbove = crease.valley() == faceUp[crease.f()];
            if (solver.variable.containsKey(key(crease.f(), crease.g()))) {
                solver.conditions.add(new Condition(FIXED, gAbove ? new int[] {crease.g(), crease.f()} : new int[] {crease.f(), crease.g()}));
            }
        }
        solver.tacos(creases, lineTolerance);
        // Transitivity: a condition for each three faces over one point, where they are not too
        // many (they guide the search: without them it wanders among orders with cycles); where
        // they are (a pleat of 400 creases has ten million), asked for lazily. Either way, the
        // order found is searched for a cycle, whose condition is then added, until none is.
        solver.transitivity(tolerance);
        for (int round = 0;; round++) {
            solver.watch();
            java.util.Arrays.fill(solver.value, (byte) 0);
            solver.choices = 0;
            solver.gaveUp = false;
            if (!solver.solve()) {
                throw new CreasePattern.Refused(solver.gaveUp || solver.conflict == null ? String.format(Locale.ROOT, "no layer order found"
                        + " in %,d choices: iFold's search gives up here (the pattern may fold flat all the same)", MOST_CHOICES)
                        : solver.conflict);
            }
            int[] cycle = solver.cycle();
            if (cycle == null) {
                return solver.bottomUp();
            }
            // A cycle over one point breaks transitivity; one over none (a pinwheel's) is a true
            // layer order, but a stack of layers cannot hold it either: both are forbidden, and
            // the search goes on for an order without.
            if (round >= MOST_ROUNDS) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "no layer order without a cycle found in %,d rounds: the last"
                        + " put faces %s in a cycle, which iFold's stacks cannot hold", MOST_ROUNDS, java.util.Arrays.toString(cycle)));
            }
            solver.conditions.add(new Condition(NO_CYCLE, cycle));
        }
    }

    /** How many times a cycle of three may be found and forbidden before the search gives up. */
    static final int MOST_ROUNDS = 2_000;

    private static long key(int a, int b) {
        return ((long) Math.min(a, b) << 32) | Math.max(a, b);
    }

    /** The most pairs of overlapping faces ordered: a pleat of 2,000 layers has two million, at about half a kilobyte each. */
    static final int MOST_PAIRS = 2_000_000;

    private void findPairs(double tolerance) throws CreasePattern.Refused {
        int n = polygons.length;
        double[][] boxes = new double[n][];
        Integer[] byX = new Integer[n];
        for (int f = 0; f < n; f++) {
            boxes[f] = Polygons2.bounds(polygons[f]);
            byX[f] = f;
        }
        Arrays.sort(byX, (a, b) -> Double.compare(boxes[a][0], boxes[b][0]));
        for (int i = 0; i < n; i++) {
            int f = byX[i];
            for (int j = i + 1; j < n && boxes[byX[j]][0] < boxes[f][2] - tolerance; j++) {
                int g = byX[j];
                if (boxes[g][1] < boxes[f][3] - tolerance && boxes[f][1] < boxes[g][3] - tolerance
                        && Polygons2.overlap(polygons[f], polygons[f].length / 2, polygons[g], polygons[g].length / 2, tolerance)) {
                    variable.put(key(f, g), pairs.size());
                    pairs.add(new long[] {Math.min(f, g), Math.max(f, g)});
                    if (pairs.size() > MOST_PAIRS) {
                        throw new CreasePattern.Refused(String.format(Locale.ROOT, "folded flat, its faces overlap in more than %,d pairs,"
                                + " more than iFold orders at once (a pleat of 2,000 layers has as many): fold it line by line, as a"
                                + " rectangle creased from border to border", MOST_PAIRS));
                    }
                }
            }
        }
    }

    private boolean overlaps(int a, int b) {
        return variable.containsKey(key(a, b));
    }

    /**
     * The conditions of creases that meet on one line or run through a face: taco–tortilla
     * (a face the crease's line runs through, or the face of a flat edge on the line on the
     * crease's side, lies above both of its faces or below both), taco–taco (two creases on one
     * line, their flaps on one side, nest or lie apart) and tortilla–tortilla (paper running on
     * across two flat edges on one line keeps its order on both sides).
     */
    private void tacos(List<FlatCrease> creases, double tolerance) {
        for (int i = 0; i < creases.size(); i++) {
            FlatCrease c = creases.get(i);
            if (c.folded() && overlaps(c.f(), c.g())) {
                for (int h = 0; h < polygons.length; h++) {
                    if (h != c.f() && h != c.g() && overlaps(h, c.f()) && overlaps(h, c.g()) && crosses(h, c, tolerance)) {
                        conditions.add(new Condition(SAME_SIDE, new int[] {h, c.f(), c.g()}));
                    }
                }
            }
            for (int j = i + 1; j < creases.size(); j++) {
                FlatCrease d = creases.get(j);
                if (!collinearOverlap(c, d, tolerance)) {
                    continue;
                }
                if (c.folded() && d.folded()) {
                    if (overlaps(c.f(), c.g()) && overlaps(d.f(), d.g()) && side(c, c.f()) == side(c, d.f()) && overlaps(c.f(), d.f())
                            && overlaps(c.f(), d.g()) && overlaps(c.g(), d.f()) && overlaps(c.g(), d.g())) {
                        conditions.add(new Condition(NESTED, new int[] {c.f(), c.g(), d.f(), d.g()}));
                    }
                } else if (c.folded() != d.folded()) {
                    FlatCrease taco = c.folded() ? c : d;
                    FlatCrease seam = c.folded() ? d : c;
                    // The seam's face on the taco's side is a face the taco's line runs along.
                    int h = side(taco, seam.f()) == side(taco, taco.f()) ? seam.f() : seam.g();
                    if (h != taco.f() && h != taco.g() && overlaps(h, taco.f()) && overlaps(h, taco.g())) {
                        conditions.add(new Condition(SAME_SIDE, new int[] {h, taco.f(), taco.g()}));
                    }
                } else {
                    double sideOfCf = side(c, c.f());
                    int a = c.f();
                    int b = c.g();
                    int e = side(c, d.f()) == sideOfCf ? d.f() : d.g();
                    int g = e == d.f() ? d.g() : d.f();
                    if (a != e && b != g && overlaps(a, e) && overlaps(b, g)) {
                        conditions.add(new Condition(SAME_ORDER, new int[] {a, e, b, g}));
                    }
                }
            }
        }
    }

    /** Whether the crease's segment runs through face h's inside, not only along its edge. */
    private boolean crosses(int h, FlatCrease c, double tolerance) {
        double[] polygon = polygons[h];
        int n = polygon.length / 2;
        // Clip the segment to the polygon (convex; either winding), then ask that what is left
        // stands off every edge of it.
        double t0 = 0;
        double t1 = 1;
        double dx = c.x2() - c.x1();
        double dy = c.y2() - c.y1();
        double orientation = Math.signum(Polygons2.twiceArea(polygon, n));
        for (int i = 0, j = n - 1; i < n; j = i++) {
            // Inward normal of edge j → i.
            double ex = polygon[2 * i] - polygon[2 * j];
            double ey = polygon[2 * i + 1] - polygon[2 * j + 1];
            double length = Math.hypot(ex, ey);
            if (!(length > 0)) {
                continue;
            }
            double nx = -ey / length * orientation;
            double ny = ex / length * orientation;
            // Inside by more than the tolerance: n · (p - a) > tolerance.
            double start = nx * (c.x1() - polygon[2 * j]) + ny * (c.y1() - polygon[2 * j + 1]) - tolerance;
            double rate = nx * dx + ny * dy;
            if (Math.abs(rate) < 1e-300) {
                if (start <= 0) {
                    return false;
                }
                continue;
            }
            double t = -start / rate;
            if (rate > 0) {
                t0 = Math.max(t0, t);
            } else {
                t1 = Math.min(t1, t);
            }
        }
        return (t1 - t0) * Math.hypot(dx, dy) > tolerance;
    }

    private static boolean collinearOverlap(FlatCrease a, FlatCrease b, double tolerance) {
        double dx = a.x2() - a.x1();
        double dy = a.y2() - a.y1();
        double length = Math.hypot(dx, dy);
        double ux = dx / length;
        double uy = dy / length;
        double off1 = Math.abs(-uy * (b.x1() - a.x1()) + ux * (b.y1() - a.y1()));
        double off2 = Math.abs(-uy * (b.x2() - a.x1()) + ux * (b.y2() - a.y1()));
        if (off1 > tolerance || off2 > tolerance) {
            return false;
        }
        double s1 = ux * (b.x1() - a.x1()) + uy * (b.y1() - a.y1());
        double s2 = ux * (b.x2() - a.x1()) + uy * (b.y2() - a.y1());
        return Math.min(length, Math.max(s1, s2)) - Math.max(0, Math.min(s1, s2)) > tolerance;
    }

    /** Which side of the crease's line face f's middle lies on. */
    private double side(FlatCrease c, int f) {
        double[] polygon = polygons[f];
        int n = polygon.length / 2;
        double cx = 0;
        double cy = 0;
        for (int i = 0; i < n; i++) {
            cx += polygon[2 * i] / n;
            cy += polygon[2 * i + 1] / n;
        }
        return Math.signum((c.x2() - c.x1()) * (cy - c.y1()) - (c.y2() - c.y1()) * (cx - c.x1()));
    }

    /** The most conditions of three faces over one point set before the search; beyond, transitivity is asked for lazily. */
    static final int MOST_TRIPLES = 400_000;

    /** For each two faces that overlap, each third over their common part: no cycle among the three; none where they are too many. */
    private void transitivity(double tolerance) {
        List<List<Integer>> neighbours = new ArrayList<>();
        for (int f = 0; f < polygons.length; f++) {
            neighbours.add(new ArrayList<>());
        }
        for (long[] pair : pairs) {
            neighbours.get((int) pair[0]).add((int) pair[1]);
            neighbours.get((int) pair[1]).add((int) pair[0]);
        }
        long candidates = 0;
        for (long[] pair : pairs) {
            for (int c : neighbours.get((int) pair[1])) {
                candidates += c > pair[1] && overlaps((int) pair[0], c) ? 1 : 0;
            }
            if (candidates > MOST_TRIPLES) {
                return;
            }
        }
        for (long[] pair : pairs) {
            int a = (int) pair[0];
            int b = (int) pair[1];
            double[] common = null;
            for (int c : neighbours.get(b)) {
                if (c > b && overlaps(a, c)) {
                    common = common != null ? common : intersection(polygons[a], polygons[b], tolerance);
                    if (common != null && intersection(common, polygons[c], tolerance) != null) {
                        conditions.add(new Condition(NO_CYCLE, new int[] {a, b, c}));
                        conditions.add(new Condition(NO_CYCLE, new int[] {a, c, b}));
                    }
                }
            }
        }
    }

    /** The common part of two convex polygons, or null where it has no area beyond the tolerance. */
    static double[] intersection(double[] a, double[] b, double tolerance) {
        double[] part = a;
        int n = b.length / 2;
        double orientation = Math.signum(Polygons2.twiceArea(b, n));
        for (int i = 0, j = n - 1; i < n && part != null; j = i++) {
            double ex = b[2 * i] - b[2 * j];
            double ey = b[2 * i + 1] - b[2 * j + 1];
            // Keep the side of edge j → i that b lies on: outward normal · p <= c.
            double nx = ey * orientation;
            double ny = -ex * orientation;
            double c = nx * b[2 * j] + ny * b[2 * j + 1];
            double length = Math.hypot(nx, ny);
            if (length > 0) {
                part = Polygons2.clip(part, part.length / 2, nx / length, ny / length, c / length - tolerance, tolerance);
            }
        }
        return part;
    }

    /** Whether face a lies above face b, as decided: +1 yes, -1 no, 0 not yet. */
    private int above(int a, int b) {
        int v = value[variable.get(key(a, b))];
        return a < b ? v : -v;
    }

    /** Whether the condition can still hold: 1 it holds, 0 undecided, -1 broken. */
    private int holds(Condition c) {
        int[] f = c.faces();
        switch (c.kind()) {
            case FIXED -> {
                return above(f[0], f[1]);
            }
            case SAME_SIDE -> {
                int x = above(f[0], f[1]);
                int y = above(f[0], f[2]);
                return x == 0 || y == 0 ? 0 : x == y ? 1 : -1;
            }
            case NESTED -> {
                int ca = above(f[2], f[0]);
                int cb = above(f[2], f[1]);
                int da = above(f[3], f[0]);
                int db = above(f[3], f[1]);
                if (ca == 0 || cb == 0 || da == 0 || db == 0) {
                    return 0;
                }
                return (ca != cb) == (da != db) ? 1 : -1;
            }
            case SAME_ORDER -> {
                int x = above(f[0], f[1]);
                int y = above(f[2], f[3]);
                return x == 0 || y == 0 ? 0 : x == y ? 1 : -1;
            }
            default -> {
                // A cycle, each face below the next and the last below the first: broken where all are so.
                boolean open = false;
                for (int i = 0; i < f.length; i++) {
                    int up = above(f[(i + 1) % f.length], f[i]);
                    if (up == -1) {
                        return 1;
                    }
                    open |= up == 0;
                }
                return open ? 0 : -1;
            }
        }
    }

    private void watch() {
        watching = new ArrayList<>();
        for (int v = 0; v < pairs.size(); v++) {
            watching.add(new ArrayList<>());
        }
        for (int k = 0; k < conditions.size(); k++) {
            for (int v : variables(conditions.get(k))) {
                watching.get(v).add(k);
            }
        }
    }

    /** The pairs a condition reads. */
    private int[] variables(Condition c) {
        int[] f = c.faces();
        return switch (c.kind()) {
            case FIXED -> new int[] {variable.get(key(f[0], f[1]))};
            case SAME_SIDE -> new int[] {variable.get(key(f[0], f[1])), variable.get(key(f[0], f[2]))};
            case NESTED -> new int[] {variable.get(key(f[2], f[0])), variable.get(key(f[2], f[1])), variable.get(key(f[3], f[0])),
                variable.get(key(f[3], f[1]))};
            case SAME_ORDER -> new int[] {variable.get(key(f[0], f[1])), variable.get(key(f[2], f[3]))};
            default -> {
                int[] vars = new int[f.length];
                for (int i = 0; i < f.length; i++) {
                    vars[i] = variable.get(key(f[i], f[(i + 1) % f.length]));
                }
                yield vars;
            }
        };
    }

    /**
     * Decides what the conditions force from the pairs on {@code trail} onwards, adding each pair
     * it decides to the trail; false where a condition breaks.
     */
    private boolean propagate(ArrayDeque<Integer> queue, List<Integer> trail) {
        while (!queue.isEmpty()) {
            int v = queue.poll();
            for (int k : watching.get(v)) {
                Condition c = conditions.get(k);
                int state = holds(c);
                if (state == -1) {
                    conflict = describe(c);
                    return false;
                }
                if (state == 1) {
                    continue;
                }
                int open = -1;
                int count = 0;
                for (int w : variables(c)) {
                    if (value[w] == 0) {
                        open = w;
                        count++;
                    }
                }
                if (count != 1) {
                    continue;
                }
                value[open] = 1;
                boolean up = holds(c) != -1;
                value[open] = -1;
                boolean down = holds(c) != -1;
                if (!up && !down) {
                    value[open] = 0;
                    conflict = describe(c);
                    return false;
                }
                if (up && down) {
                    value[open] = 0;
                    continue;
                }
                value[open] = (byte) (up ? 1 : -1);
                trail.add(open);
                queue.add(open);
            }
        }
        return true;
    }

    private boolean solve() {
        List<Integer> trail = new ArrayList<>();
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        // The fixed pairs first: the creases' own.
        for (Condition c : conditions) {
            if (c.kind() == FIXED) {
                int v = variable.get(key(c.faces()[0], c.faces()[1]));
                byte want = (byte) (c.faces()[0] < c.faces()[1] ? 1 : -1);
                if (value[v] == -want) {
                    conflict = describe(c);
                    return false;
                }
                if (value[v] == 0) {
                    value[v] = want;
                    trail.add(v);
                    queue.add(v);
                }
            }
        }
        if (!propagate(queue, trail)) {
            return false;
        }
        conflict = null;
        // Most patterns are decided by one order: the faces ranked by what is decided (each above
        // what it lies on), every open pair set as the ranks say. It holds no cycle; where it
        // breaks no condition, it is the answer without a search.
        rank = ranks();
        List<Integer> guessed = new ArrayList<>();
        for (int v = 0; v < value.length; v++) {
            if (value[v] == 0) {
                value[v] = preferred(v);
                guessed.add(v);
            }
        }
        boolean holds = true;
        for (Condition c : conditions) {
            if (holds(c) == -1) {
                holds = false;
                break;
            }
        }
        if (holds) {
            return true;
        }
        undo(guessed);
        return search();
    }

    private int[] ranks() {
        int n = polygons.length;
        int[] order = kahn(n, decidedOver());
        int[] ranks = new int[n];
        java.util.Arrays.fill(ranks, -1);
        int next = 0;
        for (int f : order) {
            if (f >= 0) {
                ranks[f] = next++;
            }
        }
        for (int f = 0; f < n; f++) {
            if (ranks[f] < 0) {
                ranks[f] = next++;
            }
        }
        return ranks;
    }

    /** For each face, the faces decided to lie above it. */
    private List<List<Integer>> decidedOver() {
        List<List<Integer>> over = new ArrayList<>();
        for (int f = 0; f < polygons.length; f++) {
            over.add(new ArrayList<>());
        }
        for (int v = 0; v < pairs.size(); v++) {
            if (value[v] != 0) {
                int a = (int) pairs.get(v)[0];
                int b = (int) pairs.get(v)[1];
                over.get(value[v] > 0 ? b : a).add(value[v] > 0 ? a : b);
            }
        }
        return over;
    }

    /**
     * The faces bottom up by {@code over} (each face's list of those above it): Kahn's order, each
     * face after all below it; the faces a cycle holds back are left out, their places -1 at the
     * end.
     */
    static int[] kahn(int n, List<List<Integer>> over) {
        int[] below = new int[n];
        for (List<Integer> above : over) {
            for (int g : above) {
                below[g]++;
            }
        }
        ArrayDeque<Integer> ready = new ArrayDeque<>();
        for (int f = 0; f < n; f++) {
            if (below[f] == 0) {
                ready.add(f);
            }
        }
        int[] order = new int[n];
        java.util.Arrays.fill(order, -1);
        int count = 0;
        while (!ready.isEmpty()) {
            int f = ready.poll();
            order[count++] = f;
            for (int g : over.get(f)) {
                if (--below[g] == 0) {
                    ready.add(g);
                }
            }
        }
        return order;
    }

    /** The value the ranks prefer for pair v: its lower-numbered face above where it ranks higher. */
    private byte preferred(int v) {
        return (byte) (rank[(int) pairs.get(v)[0]] > rank[(int) pairs.get(v)[1]] ? 1 : -1);
    }

    /**
     * Faces that lie in a cycle as decided (each below the next, the last below the first), as
     * few as the pairs between them allow, or null where the pairs hold no cycle.
     */
    private int[] cycle() {
        int n = polygons.length;
        List<List<Integer>> over = decidedOver();
        // A cycle by depth-first search (colours: 0 new, 1 on the path, 2 done).
        int[] colour = new int[n];
        int[] parent = new int[n];
        for (int start = 0; start < n; start++) {
            if (colour[start] != 0) {
                continue;
            }
            ArrayDeque<int[]> stack = new ArrayDeque<>();
            stack.push(new int[] {start, 0});
            colour[start] = 1;
            parent[start] = -1;
            while (!stack.isEmpty()) {
                int[] top = stack.peek();
                int f = top[0];
                if (top[1] < over.get(f).size()) {
                    int g = over.get(f).get(top[1]++);
                    if (colour[g] == 0) {
                        colour[g] = 1;
                        parent[g] = f;
                        stack.push(new int[] {g, 0});
                    } else if (colour[g] == 1) {
                        List<Integer> cycle = new ArrayList<>();
                        for (int x = f; x != g; x = parent[x]) {
                            cycle.add(x);
                        }
                        cycle.add(g);
                        java.util.Collections.reverse(cycle); // g below ... below f below g
                        return shortened(cycle);
                    }
                } else {
                    colour[f] = 2;
                    stack.pop();
                }
            }
        }
        return null;
    }

    /**
     * A cycle (each face below the next, the last below the first) shortened where a face and
     * the one two after it overlap: to three where they lie against it, else without the face
     * between.
     */
    private int[] shortened(List<Integer> cycle) {
        List<Integer> c = new ArrayList<>(cycle);
        while (c.size() > 3) {
            boolean cut = false;
            for (int i = 0; i < c.size() && !cut; i++) {
                int a = c.get(i);
                int b = c.get((i + 1) % c.size());
                int d = c.get((i + 2) % c.size());
                if (!overlaps(a, d)) {
                    continue;
                }
                if (above(a, d) > 0) {
                    return new int[] {a, b, d}; // a below b below d below a
                }
                c.remove((i + 1) % c.size()); // a below d: the cycle without b
                cut = true;
            }
            if (!cut) {
                break;
            }
        }
        return c.stream().mapToInt(Integer::intValue).toArray();
    }

    /**
     * Decides the open pairs, each group that conditions join on its own (a choice in one
     * cannot undo another's: searching them together would try every combination of their dead
     * ends), depth first within a group, in the order conditions reach its pairs from its first.
     */
    private boolean search() {
        int[] group = new int[value.length];
        java.util.Arrays.fill(group, -1);
        for (int start = 0; start < value.length; start++) {
            if (value[start] != 0 || group[start] >= 0) {
                continue;
            }
            // The group: the open pairs reached from this one through conditions not yet met.
            List<Integer> pairsInGroup = new ArrayList<>();
            ArrayDeque<Integer> reach = new ArrayDeque<>();
            group[start] = start;
            reach.add(start);
            while (!reach.isEmpty()) {
                int v = reach.poll();
                pairsInGroup.add(v);
                for (int k : watching.get(v)) {
                    Condition c = conditions.get(k);
                    if (holds(c) == 1) {
                        continue;
                    }
                    for (int w : variables(c)) {
                        if (value[w] == 0 && group[w] < 0) {
                            group[w] = start;
                            reach.add(w);
                        }
                    }
                }
            }
            if (!searchGroup(pairsInGroup)) {
                return false;
            }
        }
        return true;
    }

    /** Decides the open pairs of one group, depth first, undoing a dead end back to the latest choice with its other value left. */
    private boolean searchGroup(List<Integer> order) {
        ArrayDeque<int[]> decisions = new ArrayDeque<>();
        ArrayDeque<List<Integer>> trails = new ArrayDeque<>();
        int at = nextOpen(order, 0);
        byte choice = at < order.size() ? preferred(order.get(at)) : 1;
        while (true) {
            if (at == order.size()) {
                return true;
            }
            if (++choices > MOST_CHOICES) {
                gaveUp = true;
                return false;
            }
            int next = order.get(at);
            List<Integer> trail = new ArrayList<>();
            ArrayDeque<Integer> queue = new ArrayDeque<>();
            value[next] = choice;
            trail.add(next);
            queue.add(next);
            if (propagate(queue, trail)) {
                decisions.push(new int[] {at, choice});
                trails.push(trail);
                at = nextOpen(order, at + 1);
                choice = at < order.size() ? preferred(order.get(at)) : 1;
                continue;
            }
            undo(trail);
            if (choice == preferred(next)) {
                choice = (byte) -choice;
                continue;
            }
            while (true) {
                if (decisions.isEmpty()) {
                    return false;
                }
                int[] decision = decisions.pop();
                undo(trails.pop());
                if (decision[1] == preferred(order.get(decision[0]))) {
                    at = decision[0];
                    choice = (byte) -decision[1];
                    break;
                }
            }
        }
    }

    private int nextOpen(List<Integer> order, int from) {
        int at = from;
        while (at < order.size() && value[order.get(at)] != 0) {
            at++;
        }
        return at;
    }

    private void undo(List<Integer> trail) {
        for (int v : trail) {
            value[v] = 0;
        }
    }

    private String describe(Condition c) {
        int[] f = c.faces();
        return switch (c.kind()) {
            case FIXED -> String.format(Locale.ROOT, "faces %d and %d cannot lie as their crease says", f[0], f[1]);
            case SAME_SIDE -> String.format(Locale.ROOT, "no layer order found: the crease between faces %d and %d runs through face %d,"
                    + " which must then lie above both or below both, and the order found so far cannot", f[1], f[2], f[0]);
            case NESTED -> String.format(Locale.ROOT, "no layer order found: the creases between faces %d and %d and between faces %d"
                    + " and %d lie on one line and the order found so far interleaves them", f[0], f[1], f[2], f[3]);
            case SAME_ORDER -> String.format(Locale.ROOT, "no layer order found: faces %d and %d run on across a flat edge as faces %d"
                    + " and %d do, and the order found so far changes there", f[0], f[2], f[1], f[3]);
            default -> "no layer order without a cycle found: faces " + java.util.Arrays.toString(f) + " lay in one in every order tried (a pinwheel's"
                    + " layers do), which iFold's stacks cannot hold";
        };
    }

    /** The faces bottom up: each after every face it lies above (Kahn's order of the decided pairs). */
    private int[] bottomUp() throws CreasePattern.Refused {
        int[] order = kahn(polygons.length, decidedOver());
        if (order.length > 0 && order[order.length - 1] < 0) {
            throw new CreasePattern.Refused("the layers found lie in a cycle over no one point, which iFold's stacks cannot hold");
        }
        return order;
    }
}
