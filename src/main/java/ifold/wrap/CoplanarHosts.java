package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.sheet.HostFrame;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The hosts that lie in one plane, each with the rigid motion from its frame into its plane's.
 *
 * <p>A non-convex face is cut into convex hosts, each with a frame of its own, but the paper on
 * them shares the air above the face: where two of them meet at a reflex corner of the face, the
 * bends standing out over each one's convex edge lean into the same notch, and only in one frame
 * can their rows be mitred against each other ({@link NestedBends#mitres}). A plane's frame is
 * that of its first host, so a host alone in its plane keeps its own coordinates exactly.
 */
final class CoplanarHosts {
    /** Each host's plane: the index of the plane's first host. */
    private final int[] planeOf;
    /**
     * For each host, six numbers: the rotation into its plane's frame (the plane's x of its x
     * and y axes, then the plane's y of them) and where its origin lies in that frame.
     */
    private final double[] motion;

    private CoplanarHosts(int[] planeOf, double[] motion) {
        this.planeOf = planeOf;
        this.motion = motion;
    }

    /**
     * The planes of {@code frames}: hosts whose outward normals agree to within {@link
     * Tolerance#COPLANAR_COSINE} and whose origins lie within {@code tolerance} of each other's
     * plane are in one.
     */
    static CoplanarHosts of(HostFrame[] frames, double tolerance) {
        int[] planeOf = new int[frames.length];
        double[] motion = new double[6 * frames.length];
        // Each plane's first host filed in a cell of a grid over the normal and the offset: a
        // hinge strip's millions of squares, or a polycube's hundreds of planes, are found
        // without trying every plane. Coplanar hosts agree far closer than a tenth of a cell, so
        // one that lies that near a cell's side is looked for across it too.
        double offsetCell = tolerance > 0 ? OFFSET_CELLS * tolerance : 1;
        Map<Long, List<Integer>> planes = new HashMap<>();
        long[] cells = new long[16];
        for (int h = 0; h < frames.length; h++) {
            HostFrame frame = frames[h];
            double[] n = frame.normal();
            double[] at = {n[0] / NORMAL_CELL, n[1] / NORMAL_CELL, n[2] / NORMAL_CELL, dot(n, frame.origin()) / offsetCell};
            int plane = h;
            int count = cells(at, cells);
            for (int c = 0; c < count && plane == h; c++) {
                for (int first : planes.getOrDefault(cells[c], List.of())) {
                    if (coplanar(frames[first], frame, tolerance)) {
                        plane = first;
                        break;
                    }
                }
            }
            planeOf[h] = plane;
            if (plane == h) {
                planes.computeIfAbsent(cells[0], key -> new ArrayList<>()).add(h);
                motion[6 * h] = 1;
                motion[6 * h + 3] = 1;
                continue;
            }
            HostFrame to = frames[plane];
            motion[6 * h] = dot(frame.ex(), to.ex());
            motion[6 * h + 1] = dot(frame.ey(), to.ex());
            motion[6 * h + 2] = dot(frame.ex(), to.ey());
            motion[6 * h + 3] = dot(frame.ey(), to.ey());
            motion[6 * h + 4] = to.localX(frame.origin());
            motion[6 * h + 5] = to.localY(frame.origin());
        }
        return new CoplanarHosts(planeOf, motion);
    }

    /** The side of a cell of the grid over a normal's coordinates. */
    private static final double NORMAL_CELL = 1e-6;

    /** The side of a cell of the grid over a plane's offset, in tolerances. */
    private static final double OFFSET_CELLS = 1e3;

    /**
     * The keys of the cells a point of the grid ({@code at}, in cells) is looked for in, into
     * {@code keys}; returns how many: its own first, then those across each side it lies within
     * a tenth of a cell of.
     */
    private static int cells(double[] at, long[] keys) {
        long[] own = new long[at.length];
        int[] step = new int[at.length];
        for (int i = 0; i < at.length; i++) {
            own[i] = (long) Math.floor(at[i]);
            double within = at[i] - own[i];
            step[i] = within < 0.1 ? -1 : within > 0.9 ? 1 : 0;
        }
        int count = 0;
        for (int pick = 0; pick < 1 << at.length; pick++) {
            long key = 17;
            boolean taken = true;
            for (int i = 0; i < at.length; i++) {
                boolean across = (pick >> i & 1) == 1;
                taken &= !across || step[i] != 0;
                key = key * 0x9E3779B97F4A7C15L + own[i] + (across ? step[i] : 0);
            }
            if (taken) {
                keys[count++] = key;
            }
        }
        return count;
    }

    private static boolean coplanar(HostFrame a, HostFrame b, double tolerance) {
        double[] o = b.origin();
        return 1 - dot(a.normal(), b.normal()) <= Tolerance.COPLANAR_COSINE && Math.abs(a.height(o)) <= tolerance;
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /** The hosts in each plane of more than one host, by the plane's first host. */
    Map<Integer, List<Integer>> shared() {
        Map<Integer, List<Integer>> hosts = new HashMap<>();
        for (int h = 0; h < planeOf.length; h++) {
            if (planeOf[h] != h) {
                hosts.computeIfAbsent(planeOf[h], first -> new ArrayList<>(List.of(first))).add(h);
            }
        }
        return hosts;
    }

    /** The plane of host h: its first host's index. */
    int planeOf(int h) {
        return planeOf[h];
    }

    /** Whether every host is alone in its plane (a convex solid's faces): nothing to meet across hosts. */
    boolean eachAlone() {
        for (int h = 0; h < planeOf.length; h++) {
            if (planeOf[h] != h) {
                return false;
            }
        }
        return true;
    }

    /**
     * {@code bend} (in its host's frame) in its plane's frame, filed under the plane: the same
     * record where the host is its plane's first.
     */
    NestedBends.Bend inPlane(NestedBends.Bend bend) {
        int h = bend.host();
        if (planeOf[h] == h) {
            return bend;
        }
        return new NestedBends.Bend(planeOf[h], x(h, bend.ax(), bend.ay()), y(h, bend.ax(), bend.ay()), x(h, bend.bx(), bend.by()),
                y(h, bend.bx(), bend.by()), turnedX(h, bend.nx(), bend.ny()), turnedY(h, bend.nx(), bend.ny()), bend.low(), bend.high());
    }

    private double x(int h, double x, double y) {
        return motion[6 * h + 4] + turnedX(h, x, y);
    }

    private double y(int h, double x, double y) {
        return motion[6 * h + 5] + turnedY(h, x, y);
    }

    private double turnedX(int h, double x, double y) {
        return motion[6 * h] * x + motion[6 * h + 1] * y;
    }

    private double turnedY(int h, double x, double y) {
        return motion[6 * h + 2] * x + motion[6 * h + 3] * y;
    }
}
