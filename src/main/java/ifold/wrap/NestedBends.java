package ifold.wrap;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * How far out the bend of each flat fold stands beyond its crease, so that thick paper folded
 * about one crease line can nest.
 *
 * <p>Paper folded flat over a stack wraps it like the cover of a book: flat on one layer, straight
 * across the stack's edge, flat on the other layer. Where no other fold shares its crease line
 * that wall stands on the crease itself: paper at levels between the two layers may then reach
 * the crease from beyond it and only touch the wall, as a valid layer order lets it (it never
 * goes across). Folds about one line whose layers nest (a tuck folds a whole stack under along
 * one edge) cannot all stand there: each steps out one thickness beyond the folds it wraps, the
 * creep of thick paper. A fold's <em>rank</em> is how many folds, one inside the next, it wraps
 * on its line: 0 for one that wraps none. Folds on one line with layers that neither nest nor
 * keep apart would cross at any thickness (a layer order of paper without thickness forbids
 * them); they keep rank 0.
 */
final class NestedBends {
    /**
     * A flat fold on one host, in that host's plane.
     *
     * @param host the host both layers rest on
     * @param ax one end of the crease
     * @param ay see ax
     * @param bx the other end
     * @param by see bx
     * @param nx the unit direction, across the crease, in which the bend stands out (away from both layers)
     * @param ny see nx
     * @param low the lower of the two layers' levels
     * @param high the higher
     */
    record Bend(int host, double ax, double ay, double bx, double by, double nx, double ny, int low, int high) {
    }

    /**
     * Creases meeting at less than about 6 degrees from in line are not mitred: their mitre lies
     * far out along them, and their walls nearly in one plane meet anyway.
     */
    private static final double MITRED_SINE = 0.1;

    private NestedBends() {
    }

    /**
     * The rank of each bend: 0 where it wraps no fold of its line, else one more than the highest
     * rank it wraps. Bends are on one line where their ends lie within {@code tolerance} of each
     * other's line, and they overlap where they share more than {@code tolerance} of it.
     */
    static int[] ranks(List<Bend> bends, double tolerance) {
        int[] ranks = new int[bends.size()];
        if (bends.isEmpty() || !(tolerance > 0)) {
            return ranks;
        }
        Map<Integer, List<Integer>> byHost = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            byHost.computeIfAbsent(bends.get(k).host(), h -> new ArrayList<>()).add(k);
        }
        for (List<Integer> onHost : byHost.values()) {
            for (List<Integer> line : lines(bends, onHost, tolerance)) {
                rank(bends, line, tolerance, ranks);
            }
        }
        return ranks;
    }

    /**
     * The bends of one host grouped by line and side. A line is keyed by the foot of the
     * perpendicular to it from a point well away from every bend: lines nearly the same have
     * feet nearly the same, found in a grid of cells {@code tolerance} across.
     */
    private static List<List<Integer>> lines(List<Bend> bends, List<Integer> onHost, double tolerance) {
        double minX = Double.POSITIVE_INFINITY;
        double minY = Double.POSITIVE_INFINITY;
        double maxX = Double.NEGATIVE_INFINITY;
        double maxY = Double.NEGATIVE_INFINITY;
        for (int k : onHost) {
            Bend bend = bends.get(k);
            minX = Math.min(minX, Math.min(bend.ax(), bend.bx()));
            minY = Math.min(minY, Math.min(bend.ay(), bend.by()));
            maxX = Math.max(maxX, Math.max(bend.ax(), bend.bx()));
            maxY = Math.max(maxY, Math.max(bend.ay(), bend.by()));
        }
        double span = Math.max(maxX - minX, maxY - minY) + tolerance;
        // Far from every bend and on no line through two of them in any likely direction, so a
        // line's foot moves with its direction as much as with its offset.
        double ox = minX - 10 * span;
        double oy = minY - 7.3 * span;
        Map<Long, List<Integer>> cells = new HashMap<>();
        int[] group = new int[onHost.size()];
        List<List<Integer>> groups = new ArrayList<>();
        double[] foot = new double[2];
        for (int i = 0; i < onHost.size(); i++) {
            Bend bend = bends.get(onHost.get(i));
            foot(bend, ox, oy, foot);
            long cx = (long) Math.floor((foot[0] - ox) / tolerance);
            long cy = (long) Math.floor((foot[1] - oy) / tolerance);
            group[i] = -1;
            for (long dx = -1; dx <= 1 && group[i] < 0; dx++) {
                for (long dy = -1; dy <= 1 && group[i] < 0; dy++) {
                    List<Integer> cell = cells.get(key(cx + dx, cy + dy));
                    if (cell == null) {
                        continue;
                    }
                    for (int j : cell) {
                        Bend other = bends.get(onHost.get(j));
                        if (sameLine(bend, other, tolerance) && bend.nx() * other.nx() + bend.ny() * other.ny() > 0) {
                            group[i] = group[j];
                            break;
                        }
                    }
                }
            }
            if (group[i] < 0) {
                group[i] = groups.size();
                groups.add(new ArrayList<>());
            }
            groups.get(group[i]).add(onHost.get(i));
            cells.computeIfAbsent(key(cx, cy), c -> new ArrayList<>()).add(i);
        }
        return groups;
    }

    private static long key(long cx, long cy) {
        return cx * 0x9E3779B97F4A7C15L ^ cy;
    }

    private static void foot(Bend bend, double ox, double oy, double[] out) {
        double dx = bend.bx() - bend.ax();
        double dy = bend.by() - bend.ay();
        double t = ((ox - bend.ax()) * dx + (oy - bend.ay()) * dy) / (dx * dx + dy * dy);
        out[0] = bend.ax() + t * dx;
        out[1] = bend.ay() + t * dy;
    }

    private static boolean sameLine(Bend a, Bend b, double tolerance) {
        return distanceToLine(b.ax(), b.ay(), a) <= tolerance && distanceToLine(b.bx(), b.by(), a) <= tolerance
                && distanceToLine(a.ax(), a.ay(), b) <= tolerance && distanceToLine(a.bx(), a.by(), b) <= tolerance;
    }

    private static double distanceToLine(double x, double y, Bend line) {
        double dx = line.bx() - line.ax();
        double dy = line.by() - line.ay();
        return Math.abs((x - line.ax()) * dy - (y - line.ay()) * dx) / Math.hypot(dx, dy);
    }

    /**
     * Ranks the bends of one line, the narrowest first: a bend wraps another that overlaps it
     * along the line and whose layers lie strictly between its own.
     */
    private static void rank(List<Bend> bends, List<Integer> line, double tolerance, int[] ranks) {
        if (line.size() < 2) {
            return;
        }
        int n = line.size();
        double[][] span = spans(bends, line);
        double[] from = span[0];
        double[] to = span[1];
        Integer[] order = new Integer[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        Arrays.sort(order, (i, j) -> Integer.compare(gap(bends.get(line.get(i))), gap(bends.get(line.get(j)))));
        for (int oi = 0; oi < n; oi++) {
            int i = order[oi];
            Bend outer = bends.get(line.get(i));
            int rank = 0;
            for (int oj = 0; oj < oi; oj++) {
                int j = order[oj];
                Bend inner = bends.get(line.get(j));
                if (wraps(outer, inner, from[i], to[i], from[j], to[j], tolerance)) {
                    rank = Math.max(rank, ranks[line.get(j)] + 1);
                }
            }
            ranks[line.get(i)] = rank;
        }
    }

    /**
     * Where the rows of bends that stand out end, along their creases: where a bend on another
     * line of the same host ends at the same point, with layers overlapping this one's, and the
     * row stepped out whole would run past that one's (its line moved out by its {@code out})
     * and through its wall, the row stops short on that line, mitred as the edges of a picture
     * frame are. Entry 2k is how far bend k's row runs on past its end (ax, ay), along the
     * crease and away from its other end (negative: it stops short of it), 2k + 1 the same at
     * (bx, by). Corners nearly in line, whose mitre lies far off, and creases too short to
     * stop half their length short, are left square.
     */
    static double[] mitres(List<Bend> bends, double[] out, double tolerance) {
        double[] past = new double[2 * bends.size()];
        if (!(tolerance > 0)) {
            return past;
        }
        Map<Long, List<Integer>> cells = new HashMap<>();
        for (int e = 0; e < 2 * bends.size(); e++) {
            cells.computeIfAbsent(cell(bends.get(e / 2), e % 2, tolerance), c -> new ArrayList<>()).add(e);
        }
        for (int e = 0; e < 2 * bends.size(); e++) {
            Bend bend = bends.get(e / 2);
            if (!(out[e / 2] > 0)) {
                continue;
            }
            double x = e % 2 == 0 ? bend.ax() : bend.bx();
            double y = e % 2 == 0 ? bend.ay() : bend.by();
            // The crease's direction away from its other end.
            double length = Math.hypot(bend.bx() - bend.ax(), bend.by() - bend.ay());
            double dx = (bend.bx() - bend.ax()) / length * (e % 2 == 0 ? -1 : 1);
            double dy = (bend.by() - bend.ay()) / length * (e % 2 == 0 ? -1 : 1);
            long cx = (long) Math.floor(x / tolerance);
            long cy = (long) Math.floor(y / tolerance);
            for (long i = -1; i <= 1; i++) {
                for (long j = -1; j <= 1; j++) {
                    for (int f : cells.getOrDefault(key(cx + i, cy + j), List.of())) {
                        Bend other = bends.get(f / 2);
                        double ox = f % 2 == 0 ? other.ax() : other.bx();
                        double oy = f % 2 == 0 ? other.ay() : other.by();
                        if (f / 2 == e / 2 || other.host() != bend.host() || Math.hypot(ox - x, oy - y) > tolerance
                                || sameLine(bend, other, tolerance) || other.low() >= bend.high() || bend.low() >= other.high()) {
                            continue;
                        }
                        // The row's end x + out·n + t·d lies on the other's row: (p - o)·m = outOther.
                        double across = dx * other.nx() + dy * other.ny();
                        double t = (out[f / 2] - out[e / 2] * (bend.nx() * other.nx() + bend.ny() * other.ny())
                                - ((x - ox) * other.nx() + (y - oy) * other.ny())) / across;
                        if (Math.abs(across) > MITRED_SINE && t < 0 && -t <= 4 * (out[e / 2] + out[f / 2])
                                && -t < length / 2) {
                            past[e] = Math.min(past[e], t);
                        }
                    }
                }
            }
        }
        return past;
    }

    private static long cell(Bend bend, int end, double tolerance) {
        double x = end == 0 ? bend.ax() : bend.bx();
        double y = end == 0 ? bend.ay() : bend.by();
        return key((long) Math.floor(x / tolerance), (long) Math.floor(y / tolerance));
    }

    /** Whether {@code outer} wraps {@code inner} on their line: its layers strictly between, overlapping along it. */
    private static boolean wraps(Bend outer, Bend inner, double outerFrom, double outerTo, double innerFrom, double innerTo,
            double tolerance) {
        return outer.low() < inner.low() && inner.high() < outer.high()
                && Math.min(outerTo, innerTo) - Math.max(outerFrom, innerFrom) > tolerance;
    }

    /**
     * Keeps the bends of each line nested where some could not stand out as far as their ranks
     * ask ({@code out}, changed in place): a bend wrapped by one that stands out less stands out
     * no farther than that one's share for its rank, out(outer)·rank(inner)/rank(outer); where
     * the outer stands on its crease, so do those it wraps (their walls then meet in one plane,
     * which the collision check reports, rather than the inner folds running outside the outer).
     */
    static void keepNested(List<Bend> bends, int[] ranks, double[] out, double tolerance) {
        if (bends.isEmpty() || !(tolerance > 0)) {
            return;
        }
        Map<Integer, List<Integer>> byHost = new HashMap<>();
        for (int k = 0; k < bends.size(); k++) {
            byHost.computeIfAbsent(bends.get(k).host(), h -> new ArrayList<>()).add(k);
        }
        for (List<Integer> onHost : byHost.values()) {
            for (List<Integer> line : lines(bends, onHost, tolerance)) {
                if (line.size() < 2) {
                    continue;
                }
                double[][] span = spans(bends, line);
                Integer[] order = new Integer[line.size()];
                for (int i = 0; i < order.length; i++) {
                    order[i] = i;
                }
                // The outermost first, so that a limit passes inwards through every level of nesting.
                Arrays.sort(order, (i, j) -> Integer.compare(gap(bends.get(line.get(j))), gap(bends.get(line.get(i)))));
                for (int oi = 0; oi < order.length; oi++) {
                    int i = order[oi];
                    int outer = line.get(i);
                    for (int oj = oi + 1; oj < order.length; oj++) {
                        int j = order[oj];
                        int inner = line.get(j);
                        if (ranks[outer] > 0 && wraps(bends.get(outer), bends.get(inner), span[0][i], span[1][i], span[0][j], span[1][j],
                                tolerance)) {
                            out[inner] = Math.min(out[inner], out[outer] * ranks[inner] / ranks[outer]);
                        }
                    }
                }
            }
        }
    }

    /** Where along their line (from the first's end a, along it) each bend of {@code line} runs: from[i] = span[0][i], to[i] = span[1][i]. */
    private static double[][] spans(List<Bend> bends, List<Integer> line) {
        Bend first = bends.get(line.get(0));
        double dx = first.bx() - first.ax();
        double dy = first.by() - first.ay();
        double length = Math.hypot(dx, dy);
        dx /= length;
        dy /= length;
        double[][] span = new double[2][line.size()];
        for (int i = 0; i < line.size(); i++) {
            Bend bend = bends.get(line.get(i));
            double ta = (bend.ax() - first.ax()) * dx + (bend.ay() - first.ay()) * dy;
            double tb = (bend.bx() - first.ax()) * dx + (bend.by() - first.ay()) * dy;
            span[0][i] = Math.min(ta, tb);
            span[1][i] = Math.max(ta, tb);
        }
        return span;
    }

    private static int gap(Bend bend) {
        return bend.high() - bend.low();
    }
}
