package ifold.wrap;

import ifold.sheet.LongIntMap;
import ifold.sheet.Polygons2;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

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
 *
 * <p>Found once for a strip's flat folds ({@link #of}), the lines also serve where bends cannot
 * stand out as far as their ranks ask ({@link #keepNested}: those they wrap stand out less
 * still) and where two creases meet at a corner ({@link #mitres}: a row stops on the other's
 * wall rather than run through it).
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

    /**
     * How far past square a crease may leave a corner and still be taken as square to a row's
     * crease: directions of creases are good to rounding over their length (3e-13 radians on the
     * polycube L, whose creases meet square at the reflex corner of its top), and a crease square
     * to the row's leaves into its band.
     */
    private static final double SQUARE_SLACK = 1e-9;

    private final List<Bend> bends;
    private final double tolerance;
    /** The bends of each line (one line and one side of it, on one host). */
    private final List<List<Integer>> lines = new ArrayList<>();
    /** Each bend's line, an index into {@link #lines}. */
    private final int[] lineOf;
    /** Where along its line each bend runs, from the line's first bend's end a. */
    private final double[] from;
    private final double[] to;
    private final int[] ranks;
    /** Each bend's partner back to back on its line (a fold on the other side of it, overlapping it along the line and in levels), or -1. */
    private final int[] backToBack;
    /**
     * Each bend's own host where the bends are met in their planes' frames ({@link
     * #mitres(double[], CoplanarHosts)}), else null.
     */
    private int[] ownHosts;
    /** Whether each end's row was last stopped by {@link #mitres} on the bends of another host of its plane. */
    private boolean[] acrossHosts;

    private NestedBends(List<Bend> bends, double tolerance) {
        this.bends = bends;
        this.tolerance = tolerance;
        this.lineOf = new int[bends.size()];
        this.from = new double[bends.size()];
        this.to = new double[bends.size()];
        this.ranks = new int[bends.size()];
        this.backToBack = new int[bends.size()];
        Arrays.fill(backToBack, -1);
    }

    /**
     * The bends grouped by line and ranked. Bends are on one line where their ends lie within
     * {@code tolerance} of each other's line (the creases of one fold line, computed to
     * rounding), and they overlap where they share more than {@code tolerance} of it.
     */
    static NestedBends of(List<Bend> bends, double tolerance) {
        NestedBends nested = new NestedBends(bends, tolerance);
        if (!(tolerance > 0)) {
            for (int k = 0; k < bends.size(); k++) {
                nested.lineOf[k] = k; // each alone
                nested.lines.add(List.of(k));
            }
            return nested;
        }
        Integer[] byHost = new Integer[bends.size()];
        for (int k = 0; k < byHost.length; k++) {
            byHost[k] = k;
        }
        Arrays.sort(byHost, (i, j) -> Integer.compare(bends.get(i).host(), bends.get(j).host()));
        for (int from = 0; from < byHost.length;) {
            int to = from;
            while (to < byHost.length && bends.get(byHost[to]).host() == bends.get(byHost[from]).host()) {
                to++;
            }
            List<Integer> onHost = Arrays.asList(byHost).subList(from, to);
            from = to;
            for (List<Integer> line : lines(bends, onHost, tolerance, true)) {
                for (int k : line) {
                    nested.lineOf[k] = nested.lines.size();
                }
                nested.lines.add(line);
                nested.span(line);
                nested.rank(line);
            }
            for (List<Integer> both : lines(bends, onHost, tolerance, false)) {
                nested.backToBack(both);
            }
        }
        return nested;
    }

    /**
     * Each bend's partner back to back with it, or -1: a fold on the same crease line facing it
     * from the other side, overlapping it along the line and in levels, both of rank 0 (a hinge
     * strip's two turns in one square fold along its one diagonal). Their walls would stand on
     * the one line; thick, each stands back half a thickness ({@link ConcaveWalls}).
     */
    int[] backToBack() {
        return backToBack.clone();
    }

    /** Finds the bends back to back among those of one line, both sides. */
    private void backToBack(List<Integer> line) {
        if (line.size() < 2 || line.size() > MOST_BACK_TO_BACK) {
            return;
        }
        Bend first = bends.get(line.get(0));
        double dx = first.bx() - first.ax();
        double dy = first.by() - first.ay();
        double length = Polygons2.length(dx, dy);
        for (int i : line) {
            for (int j : line) {
                Bend a = bends.get(i);
                Bend b = bends.get(j);
                if (i >= j || ranks[i] != 0 || ranks[j] != 0 || a.nx() * b.nx() + a.ny() * b.ny() > -0.5
                        || Math.max(a.low(), b.low()) >= Math.min(a.high(), b.high())) {
                    continue;
                }
                double ai = ((a.ax() - first.ax()) * dx + (a.ay() - first.ay()) * dy) / length;
                double bi = ((a.bx() - first.ax()) * dx + (a.by() - first.ay()) * dy) / length;
                double aj = ((b.ax() - first.ax()) * dx + (b.ay() - first.ay()) * dy) / length;
                double bj = ((b.bx() - first.ax()) * dx + (b.by() - first.ay()) * dy) / length;
                if (Math.min(Math.max(ai, bi), Math.max(aj, bj)) - Math.max(Math.min(ai, bi), Math.min(aj, bj)) > tolerance) {
                    backToBack[i] = j;
                    backToBack[j] = i;
                }
            }
        }
    }

    /** Lines with more bends than this are not searched for bends back to back (each pair is tried). */
    private static final int MOST_BACK_TO_BACK = 64;

    /** Each bend's rank: 0 where it wraps no fold of its line, else one more than the highest rank it wraps. */
    int[] ranks() {
        return ranks.clone();
    }

    /** The width, in radians, of the buckets of direction that {@link #lines} sorts creases into. */
    private static final double DIRECTION_BUCKET = 1e-4;

    /**
     * The bends of one host grouped by line, and by side where {@code oneSide}. A line's direction is its longest crease's,
     * good to rounding (a short crease's is not: the ends of a crease a thousandth of the host
     * long, each good to 1e-12, turn it by 1e-9); so the longest come first, each line is filed
     * under its direction, in buckets {@link #DIRECTION_BUCKET} wide, by its offset across that
     * direction, and a crease joins the line its ends lie within {@code tolerance} of, looked
     * for among the lines of its bucket and the two beside it whose offsets are near its own.
     */
    private static List<List<Integer>> lines(List<Bend> bends, List<Integer> onHost, double tolerance, boolean oneSide) {
        // Longest first: by length, packed with the place in onHost in a long (lengths are not negative).
        long[] keyed = new long[onHost.size()];
        for (int i = 0; i < keyed.length; i++) {
            keyed[i] = ((long) Float.floatToIntBits((float) length(bends.get(onHost.get(i)))) << 32) | i;
        }
        Arrays.sort(keyed);
        Integer[] byLength = new Integer[keyed.length];
        for (int i = 0; i < keyed.length; i++) {
            byLength[keyed.length - 1 - i] = onHost.get((int) (keyed[i] & 0xFFFFFFFFL));
        }
        double span = 0;
        double originX = bends.get(byLength[0]).ax();
        double originY = bends.get(byLength[0]).ay();
        for (int k : byLength) {
            Bend bend = bends.get(k);
            span = Math.max(span, Math.max(Polygons2.length(bend.ax() - originX, bend.ay() - originY),
                    Polygons2.length(bend.bx() - originX, bend.by() - originY)));
        }
        int bucketCount = (int) Math.ceil(Math.PI / DIRECTION_BUCKET);
        // Offsets measured along a bucket's own normal, for lines up to a bucket apart in
        // direction: within span·(two buckets) of each other where the lines are the same.
        double window = 2 * DIRECTION_BUCKET * span + 2 * tolerance;
        // Each bucket's lines by offset, in arrays: a wrap files a million creases, a few hundred
        // a host, and maps of boxed offsets were a third of the time it took.
        LongIntMap bucketIndex = new LongIntMap();
        List<Offsets> buckets = new ArrayList<>();
        List<List<Integer>> groups = new ArrayList<>();
        for (int k : byLength) {
            Bend bend = bends.get(k);
            double direction = Math.atan2(bend.by() - bend.ay(), bend.bx() - bend.ax());
            direction = direction < 0 ? direction + Math.PI : direction;
            int bucket = Math.min(bucketCount - 1, (int) (direction / DIRECTION_BUCKET));
            double midX = (bend.ax() + bend.bx()) / 2 - originX;
            double midY = (bend.ay() + bend.by()) / 2 - originY;
            int found = -1;
            for (int db = -1; db <= 1 && found < 0; db++) {
                int b = Math.floorMod(bucket + db, bucketCount);
                int index = bucketIndex.get(b, -1);
                if (index < 0) {
                    continue;
                }
                Offsets lines = buckets.get(index);
                double offset = offset(b, midX, midY);
                double high = offset + window;
                for (int at = lines.from(offset - window); at < lines.size && Double.compare(lines.offsets[at], high) <= 0 && found < 0; at++) {
                    int[] near = lines.groups[at];
                    for (int i = 0; i < lines.counts[at]; i++) {
                        int g = near[i];
                        Bend line = bends.get(groups.get(g).get(0));
                        if ((!oneSide || bend.nx() * line.nx() + bend.ny() * line.ny() > 0) && distanceToLine(bend.ax(), bend.ay(), line) <= tolerance
                                && distanceToLine(bend.bx(), bend.by(), line) <= tolerance) {
                            found = g;
                            break;
                        }
                    }
                }
            }
            if (found < 0) {
                found = groups.size();
                groups.add(new ArrayList<>());
                int index = bucketIndex.get(bucket, -1);
                if (index < 0) {
                    index = buckets.size();
                    buckets.add(new Offsets());
                    bucketIndex.put(bucket, index);
                }
                buckets.get(index).add(offset(bucket, midX, midY), found);
            }
            groups.get(found).add(k);
        }
        return groups;
    }

    /**
     * The lines of one bucket of direction by their offsets, in order as {@link Double#compare}
     * has them (as a sorted map of them would), each offset's lines in the order filed.
     */
    private static final class Offsets {
        double[] offsets = new double[4];
        int[][] groups = new int[4][];
        int[] counts = new int[4];
        int size;

        /** The first place whose offset is not below {@code low}. */
        int from(double low) {
            int lo = 0;
            int hi = size;
            while (lo < hi) {
                int mid = (lo + hi) >>> 1;
                if (Double.compare(offsets[mid], low) < 0) {
                    lo = mid + 1;
                } else {
                    hi = mid;
                }
            }
            return lo;
        }

        void add(double offset, int group) {
            int at = from(offset);
            if (at < size && Double.compare(offsets[at], offset) == 0) {
                if (counts[at] == groups[at].length) {
                    groups[at] = Arrays.copyOf(groups[at], 2 * counts[at]);
                }
                groups[at][counts[at]++] = group;
                return;
            }
            if (size == offsets.length) {
                offsets = Arrays.copyOf(offsets, 2 * size);
                groups = Arrays.copyOf(groups, 2 * size);
                counts = Arrays.copyOf(counts, 2 * size);
            }
            System.arraycopy(offsets, at, offsets, at + 1, size - at);
            System.arraycopy(groups, at, groups, at + 1, size - at);
            System.arraycopy(counts, at, counts, at + 1, size - at);
            offsets[at] = offset;
            groups[at] = new int[] {group};
            counts[at] = 1;
            size++;
        }
    }

    /** The offset of point (x, y) across the middle direction of bucket b. */
    private static double offset(int bucket, double x, double y) {
        double direction = (bucket + 0.5) * DIRECTION_BUCKET;
        return -x * Math.sin(direction) + y * Math.cos(direction);
    }

    private static double length(Bend bend) {
        return Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
    }

    private static long key(long cx, long cy) {
        return cx * 0x9E3779B97F4A7C15L ^ cy;
    }

    private static double distanceToLine(double x, double y, Bend line) {
        double dx = line.bx() - line.ax();
        double dy = line.by() - line.ay();
        return Math.abs((x - line.ax()) * dy - (y - line.ay()) * dx) / Polygons2.length(dx, dy);
    }

    /** Where along the line each of its bends runs, from the first one's end a. */
    private void span(List<Integer> line) {
        Bend first = bends.get(line.get(0));
        double dx = first.bx() - first.ax();
        double dy = first.by() - first.ay();
        double length = Polygons2.length(dx, dy);
        dx /= length;
        dy /= length;
        for (int k : line) {
            Bend bend = bends.get(k);
            double ta = (bend.ax() - first.ax()) * dx + (bend.ay() - first.ay()) * dy;
            double tb = (bend.bx() - first.ax()) * dx + (bend.by() - first.ay()) * dy;
            from[k] = Math.min(ta, tb);
            to[k] = Math.max(ta, tb);
        }
    }

    /**
     * Ranks the bends of one line, the narrowest first: a bend wraps another that overlaps it
     * along the line and whose layers lie strictly between its own.
     */
    private void rank(List<Integer> line) {
        if (line.size() < 2) {
            return;
        }
        Integer[] order = line.toArray(new Integer[0]);
        Arrays.sort(order, (i, j) -> Integer.compare(gap(bends.get(i)), gap(bends.get(j))));
        for (int oi = 0; oi < order.length; oi++) {
            int outer = order[oi];
            int rank = 0;
            for (int oj = 0; oj < oi; oj++) {
                int inner = order[oj];
                if (wraps(outer, inner)) {
                    rank = Math.max(rank, ranks[inner] + 1);
                }
            }
            ranks[outer] = rank;
        }
    }

    /**
     * How much of their line two bends share, as a share of the tolerance, before one wraps the
     * other: half a thousandth of a thickness, half the depth from which the collision check
     * counts contact. At the tolerance's own hundredth of a thickness, two passes of the
     * 100 × 1 × 1 box overlapping by 2.4e-6 (0.002 T) along one line stood at one rank, their
     * bends on each other.
     */
    private static final double SHARED = 0.05;

    /** Whether bend {@code outer} wraps bend {@code inner} of its line: its layers strictly between, overlapping along it. */
    private boolean wraps(int outer, int inner) {
        Bend o = bends.get(outer);
        Bend i = bends.get(inner);
        return o.low() < i.low() && i.high() < o.high() && Math.min(to[outer], to[inner]) - Math.max(from[outer], from[inner]) > tolerance * SHARED;
    }

    /**
     * Keeps the bends of each line nested where some could not stand out as far as their ranks
     * ask ({@code out}, changed in place): a bend wrapped by one that stands out less stands out
     * no farther than that one's share for its rank, out(outer)·rank(inner)/rank(outer); where
     * the outer stands on its crease, so do those it wraps (their walls then meet in one plane,
     * which the collision check reports, rather than the inner folds running outside the outer).
     */
    void keepNested(double[] out) {
        for (List<Integer> line : lines) {
            if (line.size() < 2) {
                continue;
            }
            // The outermost first, so that a limit passes inwards through every level of nesting.
            Integer[] order = line.toArray(new Integer[0]);
            Arrays.sort(order, (i, j) -> Integer.compare(gap(bends.get(j)), gap(bends.get(i))));
            for (int oi = 0; oi < order.length; oi++) {
                int outer = order[oi];
                if (ranks[outer] == 0) {
                    continue;
                }
                for (int oj = oi + 1; oj < order.length; oj++) {
                    int inner = order[oj];
                    if (wraps(outer, inner)) {
                        out[inner] = Math.min(out[inner], out[outer] * ranks[inner] / ranks[outer]);
                    }
                }
            }
        }
    }

    /**
     * Where the rows of bends that stand out ({@code out} above 0) end, along their creases:
     * where a bend on another line of the same host (or of the same plane: {@link
     * #mitres(double[], CoplanarHosts)}) ends at the same point, with layers overlapping this
     * one's, and its crease leaves that point into the band this bend's row
     * stands out over (between the crease and the direction it stands out in), the row stepped
     * out whole would run through that bend's wall: it stops short where it would enter that
     * bend, on that one's line moved out by its {@code out} where that bend stands out towards
     * the row, on its crease where it stands out away from it, mitred as the edges of a picture
     * frame are: the farthest short of the creases met, turning from its own, up to the first
     * that stands on its crease (those beyond cross the row nearer its end). Entry 2k is how far
     * bend k's row runs on past its end (ax, ay), along the crease and away from its other end
     * (negative: it stops short of it), 2k + 1 the same at
     * (bx, by). Corners nearly in line ({@link #MITRED_SINE}), whose mitre lies more than about
     * ten times as far along as the rows stand out, and creases too short to stop half their
     * length short, are left square.
     */
    double[] mitres(double[] out) {
        return mitres(out, null);
    }

    /**
     * {@link #mitres(double[])} with the bends of coplanar hosts ({@code planes}; null: each host
     * a plane of its own) met in their plane's frame: where a non-convex face is cut into convex
     * hosts, the bends standing out over two hosts' convex edges that meet at a reflex corner of
     * the face lean into the same notch (on the polycube L, 26 crossing pairs of caps, 1.95 T
     * deep), and their rows stop on each other as rows of one host do. The lines and ranks stay
     * each host's.
     */
    double[] mitres(double[] out, CoplanarHosts planes) {
        if (planes == null || planes.eachAlone()) {
            return mitresInFrames(out);
        }
        List<Bend> inPlanes = new ArrayList<>(bends.size());
        for (Bend bend : bends) {
            inPlanes.add(planes.inPlane(bend));
        }
        NestedBends met = new NestedBends(inPlanes, tolerance);
        System.arraycopy(lineOf, 0, met.lineOf, 0, lineOf.length);
        met.ownHosts = new int[bends.size()];
        for (int k = 0; k < bends.size(); k++) {
            met.ownHosts[k] = bends.get(k).host();
        }
        double[] past = met.mitresInFrames(out);
        acrossHosts = met.acrossHosts;
        return past;
    }

    /** Whether end e's row (2k for bend k's end a, 2k + 1 for b) stops on the bends of another host of its plane, at a reflex corner of their face. */
    boolean mitredAcrossHosts(int e) {
        return acrossHosts != null && acrossHosts[e];
    }

    /** {@link #mitres(double[])} for the bends as framed: a corner's ends meet where their frame and coordinates agree. */
    private double[] mitresInFrames(double[] out) {
        double[] past = new double[2 * bends.size()];
        acrossHosts = new boolean[2 * bends.size()];
        if (!(tolerance > 0)) {
            return past;
        }
        // The ends in cells a tolerance across, each cell's in order of the direction in which
        // its crease leaves it: thousands of creases can end at one corner, and only those
        // leaving it into a row's band, the first from the row's own crease, matter.
        int endCount = 2 * bends.size();
        // Only the cells that rows standing out look in are kept, and the ends that lie in them.
        LongIntMap cellIds = new LongIntMap();
        int cellCount = 0;
        long[] near = new long[9];
        for (int e = 0; e < endCount; e++) {
            if (out[e / 2] > 0) {
                for (int k = near(e, near) - 1; k >= 0; k--) {
                    if (cellIds.get(near[k], -1) < 0) {
                        cellIds.put(near[k], cellCount++);
                    }
                }
            }
        }
        int[] cellOf = new int[endCount];
        int kept = 0;
        for (int e = 0; e < endCount; e++) {
            cellOf[e] = cellIds.get(cell(e), -1);
            kept += cellOf[e] >= 0 ? 1 : 0;
        }
        // Each cell's ends, cell after cell (start[c] to start[c + 1]), each cell's by direction.
        int[] start = new int[cellCount + 1];
        for (int e = 0; e < endCount; e++) {
            if (cellOf[e] >= 0) {
                start[cellOf[e] + 1]++;
            }
        }
        for (int c = 0; c < cellCount; c++) {
            start[c + 1] += start[c];
        }
        int[] ends = new int[kept];
        int[] fill = Arrays.copyOf(start, cellCount);
        for (int e = 0; e < endCount; e++) {
            if (cellOf[e] >= 0) {
                ends[fill[cellOf[e]]++] = e;
            }
        }
        double[] angle = new double[kept];
        for (int c = 0; c < cellCount; c++) {
            sortByDirection(ends, angle, start[c], start[c + 1]);
        }
        // Runs: a cell's ends of one line, next to each other in that order. For one row and one
        // run the stop moves with how far the run's bends stand out alone, so the least (or most)
        // of those among the run's bends whose layers meet the row's is the one to stop on; a
        // corner where a tuck folded a hundred layers along one edge is one run.
        int[] runStart = new int[kept + 1];
        double[] runAngle = new double[kept];
        int[] runLow = new int[kept];
        int[] runHigh = new int[kept];
        int[] cellRuns = new int[cellCount + 1];
        int runs = 0;
        for (int c = 0; c < cellCount; c++) {
            cellRuns[c] = runs;
            for (int i = start[c]; i < start[c + 1];) {
                int j = i;
                runLow[runs] = Integer.MAX_VALUE;
                runHigh[runs] = Integer.MIN_VALUE;
                while (j < start[c + 1] && lineOf[ends[j] / 2] == lineOf[ends[i] / 2]) {
                    runLow[runs] = Math.min(runLow[runs], bends.get(ends[j] / 2).low());
                    runHigh[runs] = Math.max(runHigh[runs], bends.get(ends[j] / 2).high());
                    j++;
                }
                runStart[runs] = i;
                runAngle[runs] = angle[i];
                runs++;
                i = j;
            }
        }
        cellRuns[cellCount] = runs;
        runStart[runs] = kept;
        double least = Math.asin(MITRED_SINE);
        boolean[] wall = new boolean[1];
        for (int e = 0; e < 2 * bends.size(); e++) {
            if (!(out[e / 2] > 0)) {
                continue;
            }
            Bend bend = bends.get(e / 2);
            double own = leaving(e);
            // Which way from the crease the bend stands out: counter-clockwise (+1) or clockwise.
            double intoX = Math.cos(own);
            double intoY = Math.sin(own);
            int side = intoX * bend.ny() - intoY * bend.nx() > 0 ? 1 : -1;
            for (int at = near(e, near) - 1; at >= 0; at--) {
                int c = cellIds.get(near[at], -1);
                if (c < 0) {
                    continue;
                }
                int from = cellRuns[c];
                int n = cellRuns[c + 1] - from;
                // From just past the crease's own direction, turning towards the side it stands out on.
                int k = Arrays.binarySearch(runAngle, from, from + n, wrap(own + side * least));
                k = (k >= 0 ? k : -k - 1) - from;
                if (side < 0) {
                    k--;
                }
                for (int step = 0; step < n; step++, k += side) {
                    int run = from + Math.floorMod(k, n);
                    double turn = side * wrap(runAngle[run] - own);
                    if (turn < least || turn > Math.PI - least) {
                        break; // out of the band (or round past it, back to the crease)
                    }
                    // A crease of the same host leaving beyond square stands out away from the
                    // row; one of another host of the plane, met at a reflex corner of their face,
                    // stands out into the same notch however wide it is (figure3's corners turn by
                    // 8 to 23 degrees: rows leaning into them crossed in 69 pairs unmitred).
                    boolean otherHost = ownHosts != null && ownHosts[ends[runStart[run]] / 2] != ownHosts[e / 2];
                    if (turn > Math.PI / 2 + SQUARE_SLACK && !otherHost) {
                        continue;
                    }
                    if (lineOf[ends[runStart[run]] / 2] == lineOf[e / 2] || runLow[run] >= bend.high() || bend.low() >= runHigh[run]) {
                        continue;
                    }
                    double stop = stop(e, ends, runStart[run], runStart[run + 1], out, wall);
                    if (stop < past[e]) {
                        past[e] = stop;
                        acrossHosts[e] = otherHost;
                    }
                    if (wall[0]) {
                        // A wall on its crease: those turned farther from the row's crease
                        // cross the row nearer its end, and stop it less.
                        break;
                    }
                }
            }
        }
        return past;
    }

    /**
     * How far end e's row runs on past its end to stop on the rows of the run ends[from..to) (one
     * line's): on the least out of those whose layers meet e's, or the most where the stop
     * moves the other way with it; 0 where no mitre is taken. {@code wall[0]} says whether one
     * of them stands on its crease.
     */
    private double stop(int e, int[] ends, int from, int to, double[] out, boolean[] wall) {
        Bend bend = bends.get(e / 2);
        Bend line = bends.get(ends[from] / 2);
        double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
        double dx = (bend.bx() - bend.ax()) / length * (e % 2 == 0 ? -1 : 1);
        double dy = (bend.by() - bend.ay()) / length * (e % 2 == 0 ? -1 : 1);
        boolean least = dx * line.nx() + dy * line.ny() > 0;
        int best = -1;
        wall[0] = false;
        for (int i = from; i < to; i++) {
            int f = ends[i];
            Bend other = bends.get(f / 2);
            if (Polygons2.length(x(f) - x(e), y(f) - y(e)) <= tolerance && other.low() < bend.high() && bend.low() < other.high()) {
                wall[0] |= out[f / 2] == 0;
                if (best < 0 || (least ? out[f / 2] < out[best / 2] : out[f / 2] > out[best / 2])) {
                    best = f;
                }
            }
        }
        return best < 0 ? 0 : mitre(e, best, out);
    }

    /**
     * How far end e's row runs on past its end to stop on the row of the bend whose end f lies
     * at the same point, where the mitre is taken; 0 where it is not.
     */
    private double mitre(int e, int f, double[] out) {
        Bend bend = bends.get(e / 2);
        Bend other = bends.get(f / 2);
        double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
        // The crease's direction away from its other end.
        double dx = (bend.bx() - bend.ax()) / length * (e % 2 == 0 ? -1 : 1);
        double dy = (bend.by() - bend.ay()) / length * (e % 2 == 0 ? -1 : 1);
        // The other's bend fills the band from its crease out to its row: (p - o)·m from 0 to
        // out'. The row's end, x + out·n + t·d, stops where the row, coming from its own crease's
        // far end, enters that band: on the other's row where it comes from beyond it (across <
        // 0), on its crease where it comes from the side its layers lie on (across > 0: the other
        // stands out away from this row, and a row stopped on its row instead would cross the
        // whole bend; on the torus such rows ran through the lower facet of a bend over a convex
        // edge that stood out away from them).
        double across = dx * other.nx() + dy * other.ny();
        // Rows of two hosts of one plane, met at a reflex corner of their face, stop where the
        // corner's two bands halve it, each as far along as it stands out: stopped on the
        // other's row, the nested bends of each side, standing out by their ranks, ended on
        // lines of their own, and crossed those of the other side between them (t_prism's
        // folds along the bar's underside and the stem's side, at the corners where they meet).
        boolean twoHosts = ownHosts != null && ownHosts[e / 2] != ownHosts[f / 2];
        double enters = across > 0 ? 0 : twoHosts ? out[e / 2] : out[f / 2];
        double t = (enters - out[e / 2] * (bend.nx() * other.nx() + bend.ny() * other.ny())
                - ((x(e) - x(f)) * other.nx() + (y(e) - y(f)) * other.ny())) / across;
        // However far along the mitre lies, short of it the row runs through the other's bend
        // wherever their layers meet: only corners nearly in line (MITRED_SINE) are left square.
        // Held to 4 times the two outs, a random frustum's bend of levels 1 to 4 ran its row 7.5 T
        // past its corner through the wall of levels 1 to 18 beside it: 5 crossing pairs of caps,
        // 0.99 T deep. Both were folds of a tuck along one edge of a side face's 94° corner; where
        // that fold reached past the corner, the tuck along the corner's other edge folded it
        // under, to 7.6° off the first edge.
        boolean taken = Math.abs(across) > MITRED_SINE && t < 0 && -t < length / 2;
        return taken ? t : 0;
    }

    /**
     * Sorts ends[from..to) by the direction their creases leave them, into angle[from..to) as
     * well: by the direction to 1.5e-9 radians, each packed with its place in a long.
     */
    private void sortByDirection(int[] ends, double[] angle, int from, int to) {
        long[] keyed = new long[to - from];
        for (int i = from; i < to; i++) {
            long turn = (long) ((leaving(ends[i]) + Math.PI) / (2 * Math.PI) * (1L << 32));
            keyed[i - from] = Math.min(turn, (1L << 32) - 1) << 31 | (i - from);
        }
        Arrays.sort(keyed);
        int[] sorted = new int[to - from];
        for (int i = 0; i < keyed.length; i++) {
            sorted[i] = ends[from + (int) (keyed[i] & ((1L << 31) - 1))];
        }
        System.arraycopy(sorted, 0, ends, from, sorted.length);
        for (int i = from; i < to; i++) {
            angle[i] = leaving(ends[i]);
        }
    }

    /** The direction, in radians, in which end e's crease leaves it: towards the bend's other end. */
    private double leaving(int e) {
        Bend bend = bends.get(e / 2);
        double sign = e % 2 == 0 ? 1 : -1;
        return Math.atan2(sign * (bend.by() - bend.ay()), sign * (bend.bx() - bend.ax()));
    }

    /** An angle brought into [-pi, pi). */
    private static double wrap(double angle) {
        return angle - 2 * Math.PI * Math.floor((angle + Math.PI) / (2 * Math.PI));
    }

    /**
     * The cells that hold the ends at end e's point, into {@code cells}; returns how many: its
     * own, and those beside it where e lies within a tenth of a cell of their side (the ends of
     * creases that meet agree to rounding).
     */
    private int near(int e, long[] cells) {
        double gx = x(e) / tolerance;
        double gy = y(e) / tolerance;
        long cx = (long) Math.floor(gx);
        long cy = (long) Math.floor(gy);
        int host = bends.get(e / 2).host();
        int n = 0;
        for (long i = gx - cx < 0.1 ? -1 : 0; i <= (cx + 1 - gx < 0.1 ? 1 : 0); i++) {
            for (long j = gy - cy < 0.1 ? -1 : 0; j <= (cy + 1 - gy < 0.1 ? 1 : 0); j++) {
                cells[n++] = cell(host, cx + i, cy + j);
            }
        }
        return n;
    }

    /** Where end e lies: bend e / 2's end a for even e, b for odd. */
    private double x(int e) {
        Bend bend = bends.get(e / 2);
        return e % 2 == 0 ? bend.ax() : bend.bx();
    }

    private double y(int e) {
        Bend bend = bends.get(e / 2);
        return e % 2 == 0 ? bend.ay() : bend.by();
    }

    /**
     * The cell of end e in a grid of cells a tolerance across, one grid a host: every host's
     * frame has its origin at one of its corners, where thousands of ends of other hosts lie
     * at the same coordinates.
     */
    private long cell(int e) {
        return cell(bends.get(e / 2).host(), (long) Math.floor(x(e) / tolerance), (long) Math.floor(y(e) / tolerance));
    }

    private static long cell(int host, long cx, long cy) {
        return (key(cx, cy) * 31 + host) & Long.MAX_VALUE; // a LongIntMap's keys are not negative
    }

    private static int gap(Bend bend) {
        return bend.high() - bend.low();
    }

}
