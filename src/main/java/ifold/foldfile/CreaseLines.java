package ifold.foldfile;

import ifold.geom.Tolerance;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;

/**
 * The lines a crease pattern's creases lie on: which creases share one, and whether together
 * they run across the sheet from border to border, as folding the line across the whole sheet
 * creases it. Found by sorting, not by comparing every crease with every line: a pattern of
 * 10,000 parallel creases has 10,000 lines.
 */
final class CreaseLines {
    /** Directions closer than this (radians) are compared as one line's: it only narrows the search, {@link #onLine} decides. */
    private static final double ANGLE_WINDOW = Tolerance.FILE_PRECISION;

    private CreaseLines() {
    }

    /**
     * Groups the creases (u1, v1, u2, v2, ...) by the line they lie on, within {@code tolerance}.
     *
     * @return for each crease, its line's number (that of its longest crease)
     */
    static int[] group(List<double[]> creases, double tolerance) {
        int n = creases.size();
        double[] angle = new double[n];
        double[] offset = new double[n];
        for (int k = 0; k < n; k++) {
            double[] c = creases.get(k);
            double du = c[2] - c[0];
            double dv = c[3] - c[1];
            if (du < 0 || (du == 0 && dv < 0)) {
                du = -du;
                dv = -dv;
            }
            double a = Math.atan2(dv, du); // in [-pi/2, pi/2]
            if (a < -Math.PI / 2 + ANGLE_WINDOW) {
                // Nearly straight down is nearly straight up: one end of the range meets the other.
                a += Math.PI;
                du = -du;
                dv = -dv;
            }
            double length = Math.hypot(du, dv);
            angle[k] = a;
            offset[k] = (du * c[1] - dv * c[0]) / length;
        }
        Integer[] byAngle = new Integer[n];
        for (int k = 0; k < n; k++) {
            byAngle[k] = k;
        }
        Arrays.sort(byAngle, Comparator.comparingDouble(k -> angle[k]));
        int[] line = new int[n];
        Arrays.fill(line, -1);
        // Runs of nearly one direction, then within each, runs of nearly one offset; the creases
        // of such a run are on one line where the longest one's line holds their ends.
        for (int from = 0; from < n;) {
            int to = from + 1;
            while (to < n && angle[byAngle[to]] - angle[byAngle[to - 1]] <= ANGLE_WINDOW) {
                to++;
            }
            Integer[] run = Arrays.copyOfRange(byAngle, from, to);
            Arrays.sort(run, Comparator.comparingDouble(k -> offset[k]));
            for (int start = 0; start < run.length;) {
                int end = start + 1;
                while (end < run.length && offset[run[end]] - offset[run[end - 1]] <= tolerance) {
                    end++;
                }
                Integer[] near = Arrays.copyOfRange(run, start, end);
                Arrays.sort(near, Comparator.comparingDouble(k -> -length(creases.get(k))));
                List<Integer> representatives = new ArrayList<>();
                for (int k : near) {
                    double[] c = creases.get(k);
                    for (int r : representatives) {
                        if (onLine(creases.get(r), c[0], c[1], tolerance) && onLine(creases.get(r), c[2], c[3], tolerance)) {
                            line[k] = r;
                            break;
                        }
                    }
                    if (line[k] < 0) {
                        line[k] = k;
                        representatives.add(k);
                    }
                }
                start = end;
            }
            from = to;
        }
        return line;
    }

    /**
     * Refuses a crease whose line the pattern's creases do not cover from border to border of
     * the length × width sheet, naming its edge ({@code edges}: each crease's edge in the file)
     * and giving it in the file's coordinates ({@code box}: its lowest x and y).
     */
    static void checkBorderToBorder(List<double[]> creases, int[] line, List<Integer> edges, double length, double width,
            double tolerance, double[] box) throws CreasePattern.Refused {
        int n = creases.size();
        List<List<Integer>> members = new ArrayList<>();
        int[] index = new int[n];
        Arrays.fill(index, -1);
        for (int k = 0; k < n; k++) {
            if (index[line[k]] < 0) {
                index[line[k]] = members.size();
                members.add(new ArrayList<>());
            }
            members.get(index[line[k]]).add(k);
        }
        // A crease may stop this far short of the border: ends written with fewer digits than computed.
        double gapTolerance = 100 * tolerance;
        for (List<Integer> group : members) {
            double[] r = creases.get(line[group.get(0)]);
            double du = r[2] - r[0];
            double dv = r[3] - r[1];
            double norm = Math.hypot(du, dv);
            du /= norm;
            dv /= norm;
            // The chord of the line across the sheet, as t along (du, dv) from r's first end.
            double[] chord = {Double.NEGATIVE_INFINITY, Double.POSITIVE_INFINITY};
            slab(chord, r[0], du, length);
            slab(chord, r[1], dv, width);
            double[][] spans = new double[group.size()][];
            for (int i = 0; i < spans.length; i++) {
                double[] c = creases.get(group.get(i));
                double ta = du * (c[0] - r[0]) + dv * (c[1] - r[1]);
                double tb = du * (c[2] - r[0]) + dv * (c[3] - r[1]);
                spans[i] = new double[] {Math.min(ta, tb), Math.max(ta, tb), group.get(i)};
            }
            Arrays.sort(spans, Comparator.comparingDouble(s -> s[0]));
            double reach = chord[0];
            int last = (int) spans[0][2];
            for (double[] span : spans) {
                if (span[0] > reach + gapTolerance) {
                    break;
                }
                if (span[1] > reach) {
                    reach = span[1];
                    last = (int) span[2];
                }
            }
            if (reach < chord[1] - gapTolerance) {
                double[] c = creases.get(last);
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "edge %d: the crease (%s, %s)-(%s, %s) ends inside the"
                        + " paper: iFold folds each crease line across the whole sheet, so the creases on a line must run from border"
                        + " to border", edges.get(last), CreasePattern.fmt(c[0] + box[0]), CreasePattern.fmt(c[1] + box[1]),
                        CreasePattern.fmt(c[2] + box[0]), CreasePattern.fmt(c[3] + box[1])));
            }
        }
    }

    /** Narrows the chord to where the coordinate start + t * step lies in [0, extent]. */
    private static void slab(double[] chord, double start, double step, double extent) {
        if (step == 0) {
            return; // along the side: the other coordinate bounds it
        }
        double t1 = (0 - start) / step;
        double t2 = (extent - start) / step;
        chord[0] = Math.max(chord[0], Math.min(t1, t2));
        chord[1] = Math.min(chord[1], Math.max(t1, t2));
    }

    static boolean onLine(double[] line, double u, double v, double tolerance) {
        double du = line[2] - line[0];
        double dv = line[3] - line[1];
        return Math.abs(du * (v - line[1]) - dv * (u - line[0])) / Math.hypot(du, dv) <= tolerance;
    }

    private static double length(double[] c) {
        return Math.hypot(c[2] - c[0], c[3] - c[1]);
    }
}
