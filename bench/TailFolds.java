import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;

/**
 * N successive folds of a strip's tail (default 10,000): zig-zag passes five widths long, each
 * turned with a pair of 45° folds, on one big triangle's plane. Prints the time of the whole and
 * of each tenth (flat if a fold costs O(1)), the heap in use at the end, and how far the last
 * pass's pose has drifted from where exact arithmetic puts it.
 * Run by bench/wrap: java -cp 'build/install/ifold/lib/*' bench/TailFolds.java [N]
 */
public class TailFolds {
    public static void main(String[] args) throws Exception {
        int folds = args.length > 0 ? Integer.parseInt(args[0]) : 10_000;
        double w = 1;
        double pass = 5;
        long start = System.nanoTime();
        long[] tenth = new long[11];
        tenth[0] = start;
        Sheet sheet = new Sheet(w, w / 80, 1e-9 * pass * folds, 0, Isometry2.IDENTITY);
        double y = 0;
        int d = 1;
        double x1 = pass;
        for (int k = 0; k < folds; k += 2) {
            // A turn at x1: a valley fold down along the edge, a mountain fold back one width on.
            sheet.foldTail(x1, y + w, d, -1, Sheet.Placement.OVER, Sheet.Crease.TURN);
            sheet.foldTail(x1 + d * w, y, -d, -1, Sheet.Placement.UNDER, Sheet.Crease.TURN);
            y -= w;
            d = -d;
            x1 = d > 0 ? pass : 0;
            int done = k + 2;
            if (done * 10 % folds < 2 && done * 10 / folds < 11) {
                tenth[done * 10 / folds] = System.nanoTime();
            }
        }
        long end = System.nanoTime();
        // Exact: after 2k turns the tail runs in direction d along the band [y, y + w].
        Isometry2 pose = sheet.tailPose();
        double drift = Math.max(Math.abs(pose.dx(1, 0) - d), Math.abs(pose.dy(1, 0)));
        double edge = pose.y(sheet.tailStart(false), 0) - (d > 0 ? y : y + w);
        Runtime runtime = Runtime.getRuntime();
        System.gc();
        long used = runtime.totalMemory() - runtime.freeMemory();
        System.out.printf(java.util.Locale.ROOT, "%d tail folds: %.3f s in all, %.2f microseconds a fold; %d faces; heap in use %.1f MiB;"
                + " drift of the last pose %.1e (direction), %.1e (position)%n", folds, (end - start) * 1e-9,
                (end - start) * 1e-3 / folds, sheet.faceCount(), used / 1048576.0, drift, Math.abs(edge));
        StringBuilder tenths = new StringBuilder("milliseconds by tenth:");
        for (int i = 1; i <= 10; i++) {
            tenths.append(String.format(java.util.Locale.ROOT, " %.1f", (tenth[i] - tenth[i - 1]) * 1e-6));
        }
        System.out.println(tenths);
    }
}
