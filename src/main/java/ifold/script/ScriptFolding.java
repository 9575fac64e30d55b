package ifold.script;

import static ifold.geom.Vectors.add;
import static ifold.geom.Vectors.cross;
import static ifold.geom.Vectors.dot;
import static ifold.geom.Vectors.sub;
import static ifold.geom.Vectors.turn;
import static ifold.geom.Vectors.unit;

import ifold.geom.Tolerance;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.SheetEdit;
import ifold.sheet.Sheet.Placement;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;

/**
 * A fold script played on the sheet engine, the one that wraps polyhedra ({@link Sheet}).
 *
 * <p>The paper rests on <em>planes</em>: each is a host of the sheet with a frame in space. The
 * sheet starts flat on the table, the plane z = 0, its top up. A fold turns the paper on one
 * side of its line about that line:
 * <ul>
 * <li>its line lies in one plane that holds paper (given on the paper, it is found on the top
 * layer there; given in space, it must lie in such a plane);
 * <li>a fold through the layers takes every face of that plane beyond the line, cut along it,
 * and whatever paper hangs from them in other planes; a flap fold takes the paper beyond the
 * crease on the unfolded sheet, wherever it lies now;
 * <li>valley turns the moving paper up, towards the plane's normal, about the line lifted to
 * the top of the layers there; mountain turns it down about the line on the plane. Paper turned
 * into a plane that holds paper already (a flat fold, 180°, lands back on its own plane) joins
 * that plane's stack, over the paper there if it comes from above, under it if from below, its
 * own order reversed where it turned over; paper turned into a new plane takes the plane along.
 * </ul>
 * Faces only ever move rigidly (their poses are composed with rigid motions), so they never
 * stretch; a face's height over its plane is its level in the plane's stack times the thickness.
 */
public final class ScriptFolding {
    private final Sheet sheet;
    private final List<HostFrame> frames = new ArrayList<>();
    private final double size;
    private final double planeTolerance;
    private final List<Step> steps = new ArrayList<>();
    private int maxFaces = DEFAULT_MAX_FACES;

    private ScriptFolding(double length, double width, double thickness) {
        size = Math.hypot(length, width);
        planeTolerance = Tolerance.ON_PLANE * size;
        // The table, lowered by half a thickness: the first layer's middle lies at z = 0.
        frames.add(new HostFrame(new double[] {0, 0, -thickness / 2}, new double[] {1, 0, 0}, new double[] {0, 1, 0},
                new double[] {0, 0, 1}, new double[6]));
        sheet = Sheet.rectangle(length, width, thickness, planeTolerance, 0, Isometry2.IDENTITY);
    }

    /**
     * One fold made: what it moved and how, and every face it changed, before and after, so that
     * an animation can step the paper back and forth without keeping a copy of it per fold.
     *
     * @param fold the script's fold
     * @param moved the faces that turned (after cutting)
     * @param axisPoint a point of the axis they turned about, in space
     * @param axisDirection its unit direction
     * @param angle the turn in radians, right-handed about the direction
     * @param facesAfter the sheet's faces after the fold
     * @param faces the faces whose loop, pose, host or level changed (those from facesBefore on are new)
     * @param facesBefore the faces before the fold
     * @param loopsBefore their loops before (null for a new face)
     * @param posesBefore their poses before (a new face: its parent's)
     * @param hostsBefore their hosts before (a new face: its parent's)
     * @param levelsBefore their levels before (a new face: its parent's)
     * @param loopsAfter their loops after
     * @param posesAfter their poses after
     * @param hostsAfter their hosts after
     * @param levelsAfter their levels after
     */
    public record Step(FoldScript.Step fold, int[] moved, double[] axisPoint, double[] axisDirection, double angle, int facesAfter,
            int[] faces, int facesBefore, int[][] loopsBefore, Isometry2[] posesBefore, int[] hostsBefore, int[] levelsBefore,
            int[][] loopsAfter, Isometry2[] posesAfter, int[] hostsAfter, int[] levelsAfter) {
    }

    /**
     * The folded paper.
     *
     * @param sheet the sheet, folded
     * @param frames the planes its faces rest on, by host
     * @param steps every fold in order
     */
    public record Result(Sheet sheet, HostFrame[] frames, List<Step> steps) {
    }

    /**
     * The most faces a script may fold the paper into unless told otherwise: folds that halve the
     * paper again and again double them. It bounds time, not memory as the wrap's limit does
     * ({@code Wrap.DEFAULT_MAX_FACES}, a gibibyte's worth): a fold through a pile compares the
     * layers it moves with those it lands on, so its cost grows as the square of the pile, where
     * the wrap's paper lies in many low stacks. Measured (whole runs of {@code ifold fold}, 2
     * cores): 13 halvings, 8,192 faces, 1.6 s; 14, 3.5 s; 15, 14 s; 16, 60 s; 17, 267 s, so that
     * the wrap's 671,088 would let halvings fold for hours before stopping them.
     */
    public static final int DEFAULT_MAX_FACES = 10_000;

    /**
     * Plays every fold of the script, writing the nanoseconds each took to {@code nanosPerFold};
     * refuses, naming the fold, one that would cut the paper into more than {@code maxFaces}
     * faces (it is checked once the fold has cut, before it moves anything: the faces then are
     * at most twice those before).
     */
    static Result play(FoldScript script, long[] nanosPerFold, int maxFaces) throws FoldScriptException {
        return play(script, nanosPerFold, maxFaces, null);
    }

    /** Told the paper as it stands after each fold, while the folds go on (the sheet changes after). */
    public interface AfterFold {
        void folded(int fold, Sheet sheet, HostFrame[] frames);
    }

    /** As {@link #play(FoldScript, long[], int)}, telling {@code after} (or nobody) the paper after each fold. */
    static Result play(FoldScript script, long[] nanosPerFold, int maxFaces, AfterFold after) throws FoldScriptException {
        ScriptFolding folding = new ScriptFolding(script.length(), script.width(), script.thickness());
        folding.maxFaces = maxFaces;
        List<FoldScript.Step> folds = script.steps();
        for (int i = 0; i < folds.size(); i++) {
            FoldScript.Step fold = folds.get(i);
            long start = System.nanoTime();
            try {
                folding.fold(fold);
            } catch (FoldException e) {
                throw new FoldScriptException(fold.line(), "fold " + (i + 1) + ": " + e.getMessage());
            }
            nanosPerFold[i] = System.nanoTime() - start;
            if (after != null) {
                after.folded(i, folding.sheet, folding.frames.toArray(new HostFrame[0]));
            }
        }
        return new Result(folding.sheet, folding.frames.toArray(new HostFrame[0]), List.copyOf(folding.steps));
    }

    private void fold(FoldScript.Step fold) throws FoldScriptException, FoldException {
        int[] levelsBefore = sheet.levels();
        SheetEdit edit = sheet.edit();
        int host;
        double[] from2;
        double[] to2;
        // Whether the paper the fold is named by lies back up: its valley then turns away from
        // the plane's normal.
        boolean backUp;
        Set<Integer> moving = new HashSet<>();
        if (fold.flap()) {
            double u1 = fold.from().x;
            double v1 = fold.from().y;
            double u2 = fold.to().x;
            double v2 = fold.to().y;
            if (fold.moving() == FoldScript.Side.LEFT) {
                double[] swap = {u1, v1};
                u1 = u2;
                v1 = v2;
                u2 = swap[0];
                v2 = swap[1];
            }
            for (int f : edit.cutOnSheet(u1, v1, u2, v2)) {
                moving.add(f);
            }
            // The axis: the crease where it meets paper that stays, as that paper lies.
            int along = faceAlong(moving, u1, v1, u2, v2);
            if (along < 0) {
                throw new FoldException(String.format(Locale.ROOT, "the crease (%s, %s)-(%s, %s) does not cross the paper",
                        fmt(u1), fmt(v1), fmt(u2), fmt(v2)));
            }
            host = sheet.host(along);
            Isometry2 pose = sheet.pose(along);
            backUp = pose.mirrors();
            from2 = new double[] {pose.x(u1, v1), pose.y(u1, v1)};
            to2 = new double[] {pose.x(u2, v2), pose.y(u2, v2)};
            if (pose.mirrors()) {
                // The paper lies back up: its right, seen from its top, is the plane's left.
                double[] swap = from2;
                from2 = to2;
                to2 = swap;
            }
            // One axis turns the flap: the crease must run where it joins paper that stays, on
            // one line of one plane, not through layers lying elsewhere.
            for (int f : moving) {
                int[] loop = sheet.loop(f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    int g = sheet.faceAcross(a, b);
                    if (g >= 0 && !moving.contains(g) && (sheet.host(g) != host || !onLine(g, a, b, from2, to2))) {
                        throw new FoldException("the crease joins the flap to paper that stays in more than one place:"
                                + " a flap fold turns one flap about one line");
                    }
                }
            }
        } else {
            double[][] line = fold.onPaper() ? onTopLayer(fold) : inPlane(fold);
            host = (int) line[2][0];
            from2 = line[0];
            to2 = line[1];
            backUp = fold.onPaper() ? sheet.pose(namingFace(fold, host)).mirrors() : topLayerBackUp(host, from2, to2);
            if (fold.moving() == FoldScript.Side.LEFT) {
                double[] swap = from2;
                from2 = to2;
                to2 = swap;
            }
            for (int f : edit.cutOnHost(host, from2[0], from2[1], to2[0] - from2[0], to2[1] - from2[1])) {
                moving.add(f);
            }
            hanging(moving, host, from2, to2);
        }
        if (sheet.faceCount() > maxFaces) {
            throw new FoldException(String.format(Locale.ROOT, "it cuts the paper into %,d faces, more than the %d allowed"
                    + " (each fold through every layer can double them; --max-faces raises the limit)", sheet.faceCount(), maxFaces));
        }
        if (moving.isEmpty()) {
            throw new FoldException("nothing moves: no paper lies on that side of the line");
        }
        if (moving.size() == sheet.faceCount()) {
            throw new FoldException("everything moves: no paper lies on the other side of the line to fold it against");
        }
        edit.crease(moving, Sheet.Crease.FOLD);

        // The turn: about the line, the moving side (right of from -> to) turning towards the
        // plane's normal for a valley, away for a mountain.
        HostFrame plane = frames.get(host);
        double[] p = new double[3];
        double[] q = new double[3];
        plane.toSpace(from2[0], from2[1], 0, p, 0);
        plane.toSpace(to2[0], to2[1], 0, q, 0);
        double[] n = plane.normal();
        double[] direction = unit(sub(q, p));
        // Right of the direction, in the plane seen from its normal: direction × n.
        double[] right = cross(direction, n);
        double[] axis = cross(right, n); // = -direction: turning right towards n is positive about it
        // Valley and mountain are the paper's own: a valley turns the moving paper towards the
        // top side of the paper the fold is named by.
        boolean valley = (fold.kind() == FoldScript.Kind.VALLEY) != backUp;
        double angle = Math.toRadians(fold.degrees()) * (valley ? 1 : -1);
        // A valley turns about the top of the layers, a mountain about their bottom: either way
        // the moving paper turns clear of the paper that stays.
        double lift = valley ? (topLevel(host, levelsBefore) + 1) * sheet.thickness() : 0;
        double[] axisPoint = {p[0] + n[0] * lift, p[1] + n[1] * lift, p[2] + n[2] * lift};

        // Paper turned flat lands on the stack it is turned onto: within the layers of it.
        int deepest = 0;
        for (int level : levelsBefore) {
            deepest = Math.max(deepest, level + 1);
        }
        double layers = 2 * (deepest + 1) * sheet.thickness();
        Map<Integer, Set<Integer>> byHost = new LinkedHashMap<>();
        for (int f : moving) {
            byHost.computeIfAbsent(sheet.host(f), h -> new HashSet<>()).add(f);
        }
        for (Map.Entry<Integer, Set<Integer>> group : byHost.entrySet()) {
            HostFrame turned = rotate(frames.get(group.getKey()), axisPoint, axis, angle);
            int target = coplanar(turned, layers);
            if (target < 0) {
                frames.add(turned);
                edit.move(group.getValue(), frames.size() - 1, Isometry2.IDENTITY, Placement.OVER);
                continue;
            }
            HostFrame there = frames.get(target);
            // From above or below: where the paper is half way through its turn.
            HostFrame halfway = rotate(frames.get(group.getKey()), axisPoint, axis, angle / 2);
            double[] centre = centre(group.getValue(), halfway, null);
            double side = dot(sub(centre, there.origin()), there.normal());
            Placement placement = side >= 0 ? Placement.OVER : Placement.UNDER;
            edit.move(group.getValue(), target, frameChange(turned, there), placement);
        }

        // The journal, with what came after, for the animation.
        SheetEdit.Journal journal = edit.journal();
        int[] levelsAfter = sheet.levels();
        int facesBefore = journal.facesBefore();
        Map<Integer, Integer> index = new LinkedHashMap<>();
        List<int[]> loopsBefore = new ArrayList<>();
        List<Isometry2> posesBefore = new ArrayList<>();
        List<Integer> hostsBefore = new ArrayList<>();
        List<Integer> levelsOfBefore = new ArrayList<>();
        for (int k = 0; k < journal.changed().length; k++) {
            int f = journal.changed()[k];
            index.put(f, loopsBefore.size());
            loopsBefore.add(journal.loopsBefore()[k]);
            posesBefore.add(journal.posesBefore()[k]);
            hostsBefore.add(journal.hostsBefore()[k]);
            levelsOfBefore.add(levelsBefore[f]);
        }
        for (int f = 0; f < facesBefore; f++) {
            if (!index.containsKey(f) && levelsAfter[f] != levelsBefore[f]) {
                index.put(f, loopsBefore.size());
                loopsBefore.add(sheet.loop(f));
                posesBefore.add(sheet.pose(f));
                hostsBefore.add(sheet.host(f));
                levelsOfBefore.add(levelsBefore[f]);
            }
        }
        for (int g = facesBefore; g < sheet.faceCount(); g++) {
            int parent = journal.parentOf(g);
            int k = index.get(parent);
            index.put(g, loopsBefore.size());
            loopsBefore.add(null);
            posesBefore.add(posesBefore.get(k));
            hostsBefore.add(hostsBefore.get(k));
            levelsOfBefore.add(levelsOfBefore.get(k));
        }
        int[] faces = index.keySet().stream().mapToInt(Integer::intValue).toArray();
        int[][] loopsAfter = new int[faces.length][];
        Isometry2[] posesAfter = new Isometry2[faces.length];
        int[] hostsAfter = new int[faces.length];
        int[] levelsOfAfter = new int[faces.length];
        for (int k = 0; k < faces.length; k++) {
            int f = faces[k];
            loopsAfter[k] = sheet.loop(f);
            posesAfter[k] = sheet.pose(f);
            hostsAfter[k] = sheet.host(f);
            levelsOfAfter[k] = levelsAfter[f];
        }
        int[] moved = moving.stream().mapToInt(Integer::intValue).sorted().toArray();
        steps.add(new Step(fold, moved, axisPoint, unit(axis), angle, sheet.faceCount(), faces, facesBefore,
                loopsBefore.toArray(new int[0][]), posesBefore.toArray(new Isometry2[0]),
                hostsBefore.stream().mapToInt(Integer::intValue).toArray(), levelsOfBefore.stream().mapToInt(Integer::intValue).toArray(),
                loopsAfter, posesAfter, hostsAfter, levelsOfAfter));
    }

    /**
     * Whether the top layer that the line crosses on {@code host} lies back up (false where
     * none does: the line misses the paper, which the fold then reports).
     */
    private boolean topLayerBackUp(int host, double[] from, double[] to) {
        double dx = to[0] - from[0];
        double dy = to[1] - from[1];
        double length = Math.hypot(dx, dy);
        int[] levels = sheet.levels();
        int best = -1;
        for (int f : sheet.facesOn(host)) {
            double[] xy = sheet.placed(f);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int k = 0; k < xy.length; k += 2) {
                double d = (dx * (xy[k + 1] - from[1]) - dy * (xy[k] - from[0])) / length;
                min = Math.min(min, d);
                max = Math.max(max, d);
            }
            if (min < -sheet.tolerance() && max > sheet.tolerance() && (best < 0 || levels[f] > levels[best])) {
                best = f;
            }
        }
        return best >= 0 && sheet.pose(best).mirrors();
    }

    /** Whether paper edge a → b lies on the crease through (u1, v1) in direction (du, dv) of that length. */
    private boolean onCrease(int a, int b, double u1, double v1, double du, double dv, double length) {
        double da = (du * (sheet.v(a) - v1) - dv * (sheet.u(a) - u1)) / length;
        double db = (du * (sheet.v(b) - v1) - dv * (sheet.u(b) - u1)) / length;
        return Math.abs(da) <= sheet.tolerance() && Math.abs(db) <= sheet.tolerance() && a != b;
    }

    /** A face beyond the crease with an edge on it, or failing that one on the near side; -1 if none touches it. */
    private int faceAlong(Set<Integer> moving, double u1, double v1, double u2, double v2) {
        double du = u2 - u1;
        double dv = v2 - v1;
        double length = Math.hypot(du, dv);
        // The paper that stays along the crease lies across the moving paper's edges on it: the
        // first such face, found from them, not from every face of the sheet (a pleat of n folds
        // asked n² faces).
        int staying = -1;
        for (int f : moving) {
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int across = sheet.faceAcross(a, b);
                if (onCrease(a, b, u1, v1, du, dv, length) && across >= 0 && !moving.contains(across)
                        && (staying < 0 || across < staying)) {
                    staying = across;
                }
            }
        }
        if (staying >= 0) {
            return staying;
        }
        int found = -1;
        for (int f = 0; f < sheet.faceCount(); f++) {
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                if (onCrease(a, b, u1, v1, du, dv, length)) {
                    if (!moving.contains(f)) {
                        return f; // the paper that stays holds the crease where it is
                    }
                    found = f;
                }
            }
        }
        return found;
    }

    /** The two points of a line given on the paper, on the top layer where each lies: {from, to, {host}} in the host's frame. */
    private double[][] onTopLayer(FoldScript.Step fold) throws FoldScriptException {
        int a = topFaceAt(fold.from().x, fold.from().y, -1);
        if (a < 0) {
            throw notOnPaper(fold, fold.from().x, fold.from().y);
        }
        int host = sheet.host(a);
        int b = topFaceAt(fold.to().x, fold.to().y, host);
        if (b < 0) {
            if (topFaceAt(fold.to().x, fold.to().y, -1) < 0) {
                throw notOnPaper(fold, fold.to().x, fold.to().y);
            }
            throw new FoldScriptException(fold.line(), String.format(Locale.ROOT,
                    "paper points (%s, %s) and (%s, %s) lie in different planes: a fold line lies in one",
                    fmt(fold.from().x), fmt(fold.from().y), fmt(fold.to().x), fmt(fold.to().y)));
        }
        Isometry2 pa = sheet.pose(a);
        Isometry2 pb = sheet.pose(b);
        return new double[][] {{pa.x(fold.from().x, fold.from().y), pa.y(fold.from().x, fold.from().y)},
            {pb.x(fold.to().x, fold.to().y), pb.y(fold.to().x, fold.to().y)}, {host}};
    }

    private static FoldScriptException notOnPaper(FoldScript.Step fold, double u, double v) {
        return new FoldScriptException(fold.line(), String.format(Locale.ROOT, "paper point (%s, %s) is not on the paper", fmt(u), fmt(v)));
    }

    /**
     * The paper a fold given on the paper is named by: the top layer at the line's first point.
     * A first point on a crease lies on the layers either side of it; the one the line runs into
     * from there names the fold, so that a line reads the same from either end of a crease.
     */
    private int namingFace(FoldScript.Step fold, int host) {
        double t = 1e-6; // a millionth of the way to the second point: off the crease, still in the face beside it
        int face = topFaceAt(fold.from().x + t * (fold.to().x - fold.from().x), fold.from().y + t * (fold.to().y - fold.from().y), host);
        return face >= 0 ? face : topFaceAt(fold.from().x, fold.from().y, host);
    }

    /** The face holding paper point (u, v) that lies highest in its stack (on {@code host}, if not -1), or -1. */
    private int topFaceAt(double u, double v, int host) {
        int best = -1;
        int bestLevel = -1;
        int[] levels = sheet.levels();
        for (int f = 0; f < sheet.faceCount(); f++) {
            if (host >= 0 && sheet.host(f) != host) {
                continue;
            }
            int[] loop = sheet.loop(f);
            boolean inside = true;
            for (int i = 0; i < loop.length && inside; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                double cross = (sheet.u(b) - sheet.u(a)) * (v - sheet.v(a)) - (sheet.v(b) - sheet.v(a)) * (u - sheet.u(a));
                double length = Math.hypot(sheet.u(b) - sheet.u(a), sheet.v(b) - sheet.v(a));
                inside = cross >= -sheet.tolerance() * length;
            }
            if (inside && levels[f] > bestLevel) {
                best = f;
                bestLevel = levels[f];
            }
        }
        return best;
    }

    /**
     * A line given in space: the plane holding paper that it lies in (within the layers on it),
     * or failing that the one its first point lies in, and its points in that plane's frame.
     * Only the line's direction along the plane counts.
     */
    private double[][] inPlane(FoldScript.Step fold) throws FoldScriptException {
        double[] a = {fold.from().x, fold.from().y, fold.from().z};
        double[] b = {fold.to().x, fold.to().y, fold.to().z};
        double reach = (sheet.stackLevels() + 1) * sheet.thickness() + 1e-7 * size;
        int through = -1;
        for (int pass = 0; pass < 2 && through < 0; pass++) {
            for (int h = 0; h < frames.size() && through < 0; h++) {
                HostFrame frame = frames.get(h);
                boolean onIt = Math.abs(frame.height(a)) <= reach && (pass == 1 || Math.abs(frame.height(b)) <= reach);
                if (onIt && sheet.facesOn(h).length > 0) {
                    through = h;
                }
            }
        }
        if (through < 0) {
            throw new FoldScriptException(fold.line(), "the fold line lies in no plane that holds paper: a fold turns paper about a line on it");
        }
        HostFrame frame = frames.get(through);
        double[][] line = {{frame.localX(a), frame.localY(a)}, {frame.localX(b), frame.localY(b)}, {through}};
        if (Math.hypot(line[1][0] - line[0][0], line[1][1] - line[0][1]) <= planeTolerance) {
            throw new FoldScriptException(fold.line(), "the fold line runs straight across the paper: it needs a direction along it");
        }
        return line;
    }

    /**
     * Adds to {@code moving} the paper in other planes that hangs from it (joined to it on the
     * sheet), and refuses a fold that would tear the paper: one where moving paper is joined to
     * paper that stays anywhere but along the fold line.
     */
    private void hanging(Set<Integer> moving, int host, double[] from, double[] to) throws FoldException {
        // Paper in another plane hinged on the line itself (a flap standing on it) lies, on the
        // sheet, across the hinge from the paper that stays: it turns with the moving side.
        for (int f : sheet.facesOn(host)) {
            if (moving.contains(f)) {
                continue;
            }
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int g = sheet.faceAcross(a, b);
                if (g >= 0 && sheet.host(g) != host && !moving.contains(g) && onLine(f, a, b, from, to)) {
                    moving.add(g);
                }
            }
        }
        List<Integer> queue = new ArrayList<>(moving);
        for (int head = 0; head < queue.size(); head++) {
            int f = queue.get(head);
            int[] loop = sheet.loop(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int g = sheet.faceAcross(a, b);
                if (g < 0 || moving.contains(g)) {
                    continue;
                }
                if (sheet.host(g) != host) {
                    moving.add(g);
                    queue.add(g);
                } else if (!onLine(g, a, b, from, to)) { // g stays, on the fold's plane: the join must lie on the line
                    throw new FoldException("the fold would tear the paper: paper that turns is joined to paper that stays"
                            + " by a crease off the fold line");
                }
            }
        }
    }

    private boolean onLine(int face, int a, int b, double[] from, double[] to) {
        Isometry2 pose = sheet.pose(face);
        double dx = to[0] - from[0];
        double dy = to[1] - from[1];
        double length = Math.hypot(dx, dy);
        for (int v : new int[] {a, b}) {
            double x = pose.x(sheet.u(v), sheet.v(v)) - from[0];
            double y = pose.y(sheet.u(v), sheet.v(v)) - from[1];
            if (Math.abs(dx * y - dy * x) / length > sheet.tolerance() * 10) {
                return false;
            }
        }
        return true;
    }

    /** The top level on a host before the fold (a face cut off by it stands at its parent's level). */
    private int topLevel(int host, int[] levelsBefore) {
        int top = -1;
        for (int f : sheet.facesOn(host)) {
            if (f < levelsBefore.length) {
                top = Math.max(top, levelsBefore[f]);
            }
        }
        return top;
    }

    /** A host whose plane the frame lies in (either way up), or within {@code layers} of, or -1. */
    private int coplanar(HostFrame frame, double layers) {
        for (int h = 0; h < frames.size(); h++) {
            HostFrame other = frames.get(h);
            if (Math.abs(Math.abs(dot(frame.normal(), other.normal())) - 1) <= Tolerance.RELATIVE_EQUALITY
                    && Math.abs(other.height(frame.origin())) <= layers + planeTolerance) {
                return h;
            }
        }
        return -1;
    }

    /** The motion from one frame's coordinates to another's, in the same plane. */
    private static Isometry2 frameChange(HostFrame from, HostFrame to) {
        double c = dot(from.ex(), to.ex());
        double s = dot(from.ex(), to.ey());
        double length = Math.hypot(c, s);
        // ey of the source, seen in the target: (-s, c) if the frames agree, (s, -c) if one is turned over.
        boolean mirrored = dot(from.normal(), to.normal()) < 0;
        return Isometry2.placement(to.localX(from.origin()), to.localY(from.origin()), Math.atan2(s / length, c / length), mirrored);
    }

    private double[] centre(Set<Integer> faces, HostFrame frame, int[] levels) {
        double[] sum = new double[3];
        int count = 0;
        double[] point = new double[3];
        for (int f : faces) {
            double[] xy = sheet.placed(f);
            for (int k = 0; k < xy.length; k += 2) {
                frame.toSpace(xy[k], xy[k + 1], levels == null ? 0 : (levels[f] + 0.5) * sheet.thickness(), point, 0);
                for (int axis = 0; axis < 3; axis++) {
                    sum[axis] += point[axis];
                }
                count++;
            }
        }
        return new double[] {sum[0] / count, sum[1] / count, sum[2] / count};
    }

    /** The frame turned by {@code angle} about the line through {@code point} with direction {@code axis}. */
    static HostFrame rotate(HostFrame frame, double[] point, double[] axis, double angle) {
        double[] k = unit(axis);
        double[] origin = add(point, turn(sub(frame.origin(), point), k, angle));
        return new HostFrame(origin, turn(frame.ex(), k, angle), turn(frame.ey(), k, angle), turn(frame.normal(), k, angle),
                frame.corners().clone());
    }

    static String fmt(double value) {
        return value == Math.rint(value) && Math.abs(value) < 1e15 ? Long.toString((long) value) : Double.toString(value);
    }
}
