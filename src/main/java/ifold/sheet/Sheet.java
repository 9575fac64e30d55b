package ifold.sheet;

import ifold.geom.Tolerance;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

/**
 * One sheet of paper being folded: the fold engine of iFold, in which a fold costs what it
 * touches, not what has been folded before. A wrap folds a strip onto the triangles of a
 * surface; a fold script folds a whole sheet ({@link #rectangle}) in space.
 *
 * <p><b>The sheet.</b> The paper, [0, L] × [0, w] in paper coordinates (u, v), is cut into
 * convex faces over shared paper vertices; the faces tile the sheet exactly once, because every
 * cut splits one face into two along a line. Each face <em>rests on a host</em> (an integer: a
 * triangle of the surface, or a plane) and has a <em>pose</em>, the rigid motion from paper coordinates
 * into the host's 2D frame, so a face is congruent to its paper by construction. Its height
 * above the host is its <em>level</em> in the host's stack times the thickness.
 *
 * <p><b>The tail.</b> The strip not yet laid is one convex piece: the half-strip beyond the last
 * crease, with one pose and one host. A fold of the tail cuts it along a crease across the
 * strip, lays the part before the crease as a face, and composes the tail's pose with a
 * reflection (a flat fold) or with the development of the next host (a fold over an edge of the
 * surface). That is O(1) whatever came before: laid paper never moves with the tail.
 *
 * <p><b>Edits of laid paper.</b> {@link #edit() An edit} cuts faces along a line (of one host,
 * or of the sheet) and moves some of them to a host, over or under the paper there, with their
 * neighbours on the sheet given the new vertices; it journals what it changed. A <b>tuck</b> is
 * one: it folds the paper resting on one host beyond a line under the rest of that host's
 * paper, so it costs what lies on its host.
 *
 * <p><b>Stacks.</b> Each host keeps which of its overlapping faces lies above which: a face laid
 * over (a valley fold, seen from the strip's outer side) lies above every face of the host it
 * overlaps, one laid under (a mountain fold) below every one, and a tucked flap goes under the
 * paper it lands below, its own order reversed. Each new relation starts or ends at the face
 * just placed, so the order never has a cycle. A face's level is the longest chain of faces
 * below it: faces rest on what is under them, the first on the surface. An order implied by a
 * moved face that lies between and covers the other is not recorded again (a pile of N layers
 * keeps N relations, not N²); where a cut along the sheet takes such a face away, the order it
 * implied is recorded.
 */
public final class Sheet {
    /** Where the paper just folded lands: over the paper it overlaps, or under it. */
    public enum Placement { OVER, UNDER }

    /** Why the paper is creased along an edge of the sheet. */
    public enum Crease { TURN, GADGET, CROSSING, TUCK, FOLD }

    final double width;
    final double thickness;
    final double tolerance;
    /** The faces as placed on their hosts, and the tests of one against another. */
    final PlacedFaces placedFaces;
    /** Where each face laid lands in its host's stack. */
    final Landing landing = new Landing(this);

    double[] uv = new double[64];
    int vertexCount;

    final List<int[]> loops = new ArrayList<>();
    int[] hostOf = new int[16];
    /**
     * How each face came to be where it is: the kind of the fold of the tail that laid it (its
     * crease's ordinal + 1; 0 for the strip's first face, or a sheet's), plus {@link #TUCKED}
     * once a tuck has moved it, {@link #SEALED} once its host is {@link #settle settled}, and
     * {@link #LEFT_UNDER} once the strip has {@link #leaveUnder left it under} the paper laid
     * next on its host. A face cut from another inherits it.
     */
    byte[] originOf = new byte[16];
    static final int TUCKED = 16;
    static final int SEALED = 32;
    static final int LEFT_UNDER = 64;
    /** The kind of the tail's last crease, which the next face laid from the tail comes after; null before any. */
    Crease lastTailCrease;
    final List<Isometry2> poseOf = new ArrayList<>();
    /** The face to the left of each directed paper edge a → b. */
    final EdgeFaces faceOfEdge = new EdgeFaces();
    /**
     * The creases, keyed by their lower vertex << 32 | the higher: each its kind and the fold
     * that made it, as kind + {@link #CREASES}.length × fold (see {@link #creaseFold}).
     */
    final LongIntMap creases = new LongIntMap();
    static final Crease[] CREASES = Crease.values();
    /** The folds that made creases so far: the next one's number. */
    int creasingFolds;
    final StacksByHost stacks = new StacksByHost();

    int tailA;
    int tailB;
    int tailHost;
    Isometry2 tailPose;
    Placement tailPlacement = Placement.OVER;
    /** Whether the next piece of the tail laid lands over all it overlaps ({@link #liftTail}). */
    boolean tailLifted;
    /** The face the tail ran on from when it was lifted, on its host, for the next face laid; else -1. */
    int liftedFrom = -1;
    double length = Double.NaN;

    /** Each face's place in its stack's list of faces. */
    int[] slotOf = new int[16];
    /**
     * How far, relative to u, a crease's place on the tail may stray by the rounding of the
     * poses composed fold after fold: about the square root of the folds times the rounding of
     * one, 1e-16; a million folds, 1e-13; this leaves ten times that.
     */
    public static final double POSE_DRIFT = 1e-12;

    /**
     * A strip of width {@code width} whose start, the edge u = 0, lies on {@code host} where
     * {@code pose} puts it.
     *
     * @param tolerance lengths below it are nothing: points this close to a line lie on it
     */
    public Sheet(double width, double thickness, double tolerance, int host, Isometry2 pose) {
        if (!(width > 0) || !Double.isFinite(width)) {
            throw new IllegalArgumentException("the strip width must be a positive number, got " + width);
        }
        if (!(thickness >= 0) || !Double.isFinite(thickness)) {
            throw new IllegalArgumentException("the thickness must be zero or more, got " + thickness);
        }
        this.width = width;
        this.thickness = thickness;
        this.tolerance = tolerance;
        this.placedFaces = new PlacedFaces(this, tolerance);
        tailA = addVertex(0, 0);
        tailB = addVertex(0, width);
        tailHost = host;
        tailPose = pose;
    }

    /**
     * A whole sheet of {@code length} × {@code width} (paper coordinates [0, length] × [0,
     * width]), one face lying flat on {@code host} where {@code pose} puts it: the paper of a
     * fold script. It has no tail to fold; its laid paper is folded by {@link #edit() edits}.
     */
    public static Sheet rectangle(double length, double width, double thickness, double tolerance, int host, Isometry2 pose) {
        if (!(length > 0) || !Double.isFinite(length)) {
            throw new IllegalArgumentException("the sheet's length must be a positive number, got " + length);
        }
        Sheet sheet = new Sheet(width, thickness, tolerance, host, pose);
        int a = sheet.addVertex(length, 0);
        int b = sheet.addVertex(length, width);
        sheet.landing.addFace(new int[] {sheet.tailA, a, b, sheet.tailB}, host, pose, Placement.OVER, -1);
        sheet.length = length;
        return sheet;
    }

    // ---------------------------------------------------------------- the tail

    /**
     * Folds the tail flat along the line through (px, py) with direction (dx, dy) in the tail
     * host's frame: the tail before the line is laid, the rest is reflected over it and will
     * land {@code next} the paper it overlaps.
     *
     * @return the face laid
     * @throws FoldException if the line does not cross the tail ahead of its last crease
     */
    public int foldTail(double px, double py, double dx, double dy, Placement next, Crease kind) throws FoldException {
        int face = cutTail(px, py, dx, dy, kind);
        tailPose = Isometry2.reflection(px, py, dx, dy).after(tailPose);
        tailPlacement = next;
        return face;
    }

    /**
     * Folds the tail over an edge of the surface, the line through (px, py) with direction
     * (dx, dy) in the tail host's frame: the part beyond it goes onto {@code nextHost}, whose
     * frame {@code development} maps the current host's frame onto (the current host unfolded
     * about the edge into the next one's plane).
     *
     * @return the face laid
     */
    public int crossTail(double px, double py, double dx, double dy, int nextHost, Isometry2 development) throws FoldException {
        int face = cutTail(px, py, dx, dy, Crease.CROSSING);
        tailPose = development.after(tailPose);
        tailHost = nextHost;
        tailPlacement = Placement.OVER;
        return face;
    }

    /**
     * Ends the strip square at the line through (px, py) with direction (dx, dy), which must
     * run across the strip: the paper reaches the line everywhere, and the strip's length L is
     * fixed there.
     *
     * @return the last face
     */
    public int endTail(double px, double py, double dx, double dy) throws FoldException {
        if (!Double.isNaN(length)) {
            throw new IllegalStateException("the strip has ended");
        }
        double[] at = creaseOnTail(px, py, dx, dy);
        double end = Math.max(at[0], at[1]);
        double startA = u(tailA);
        double startB = u(tailB);
        // The end may meet the last crease at one side of the strip (a hinge strip ending just
        // after a turn along a square's diagonal): its last face is then a triangle.
        boolean sameA = Math.abs(end - startA) <= tolerance;
        boolean sameB = Math.abs(end - startB) <= tolerance;
        if (!(end > Math.max(startA, startB) + tolerance) && !(sameA != sameB && end > Math.min(startA, startB) + tolerance)) {
            throw new FoldException("the strip's end lies behind its last crease");
        }
        int a = sameA ? tailA : addVertex(end, 0);
        int b = sameB ? tailB : addVertex(end, width);
        int[] loop = sameA ? new int[] {tailA, b, tailB} : sameB ? new int[] {tailA, a, tailB} : new int[] {tailA, a, b, tailB};
        int face = landing.addFace(loop, tailHost, tailPose, tailPlacement, tailHinge(loop));
        originOf[face] = (byte) (lastTailCrease == null ? 0 : lastTailCrease.ordinal() + 1);
        length = end;
        tailA = a;
        tailB = b;
        return face;
    }

    /**
     * Lays the next piece of the tail over all the paper it overlaps, as the first after a
     * crossing does, rather than just over the face it is folded from: the strip running on from
     * one triangle into the next of the same host lies on the paper it leaves, not between the
     * layers of its last folds.
     */
    public void liftTail() {
        tailLifted = true;
        tailPlacement = Placement.OVER;
    }

    /**
     * Leaves the paper resting on {@code host} under the paper laid there from now on, where the
     * order allows, as a wrap does when the strip runs on into the next triangle of the host
     * ({@link #liftTail}): a later face goes over such paper it overlaps where later paper
     * already lies over it or the face reaches across its crease, wherever the levels put it,
     * unless the order already holds that paper above the face's hinge. By levels alone, a later face folded from a low layer went
     * under the earlier triangle's excess it overlapped while a pass of its own before it lay
     * over that excess, and the two chains of layers then met in a cycle that left the next fold
     * no valid place (the 9 × 5 torus: a gadget threaded under the earlier triangle's pass, and
     * the pass folded from it caught between the layers of a turn it reached across). Unlike
     * {@link #settle}, a tuck's flap still goes under all of the host's paper.
     */
    public void leaveUnder(int host) {
        Stack stack = stacks.get(host);
        if (stack == null) {
            return;
        }
        for (int i = 0; i < stack.count; i++) {
            originOf[stack.faces[i]] |= LEFT_UNDER;
        }
    }

    /** The host the tail lies on. */
    public int tailHost() {
        return tailHost;
    }

    public Isometry2 tailPose() {
        return tailPose;
    }

    /** Paper coordinate u where the tail begins, on its edges v = 0 and v = w. */
    public double tailStart(boolean atWidth) {
        return u(atWidth ? tailB : tailA);
    }

    /** u and u at v = 0 and v = w where the host line meets the strip, as the tail lies. */
    double[] creaseOnTail(double px, double py, double dx, double dy) throws FoldException {
        Isometry2 inverse = tailPose.inverse();
        double pu = inverse.x(px, py);
        double pv = inverse.y(px, py);
        double du = inverse.dx(dx, dy);
        double dv = inverse.dy(dx, dy);
        if (!(Math.abs(dv) > Tolerance.DEGENERATE_AREA * Math.hypot(du, dv))) {
            throw new FoldException("the crease runs along the strip: a fold of the tail must cross it");
        }
        return new double[] {pu + (0 - pv) / dv * du, pu + (width - pv) / dv * du};
    }

    int cutTail(double px, double py, double dx, double dy, Crease kind) throws FoldException {
        if (!Double.isNaN(length)) {
            throw new IllegalStateException("the strip has ended");
        }
        double[] at = creaseOnTail(px, py, dx, dy);
        double startA = u(tailA);
        double startB = u(tailB);
        // Along the strip's sides, points are told apart by their distance from the crease, not
        // along the side: a crease at a small angle φ to the sides moves by the tolerance where
        // its ends move by tolerance / sin φ (a turn onto a 14° corner's pass, whose crease
        // ends where the crossing's begins, is such a case).
        // Where the strip is long, its poses have drifted by more than the tolerance: each fold
        // composes the tail's pose once more, and its rounding grows with u (the cube at width
        // 2e-4: 163,000 folds on, u = 24,724, a crossing designed to meet a turn's crease on the
        // strip's side missed it by 3.2e-9 against a tolerance of 2.4e-9).
        double along = Math.abs(at[1] - at[0]);
        double apart = toleranceAt(Math.max(Math.abs(startA), Math.abs(startB))) * Math.hypot(along, width) / width;
        if (at[0] < startA - apart || at[1] < startB - apart) {
            throw new FoldException("the crease crosses the one before it on the strip: folds must follow one another along it");
        }
        boolean sameA = at[0] <= startA + apart;
        boolean sameB = at[1] <= startB + apart;
        if (sameA && sameB) {
            throw new FoldException("the crease lies on the one before it");
        }
        int a = sameA ? tailA : addVertex(at[0], 0);
        int b = sameB ? tailB : addVertex(at[1], width);
        int[] loop = sameA ? new int[] {tailA, b, tailB} : sameB ? new int[] {tailA, a, tailB} : new int[] {tailA, a, b, tailB};
        int face = landing.addFace(loop, tailHost, tailPose, tailPlacement, tailHinge(loop));
        originOf[face] = (byte) (lastTailCrease == null ? 0 : lastTailCrease.ordinal() + 1);
        lastTailCrease = kind;
        creases.put(undirected(a, b), kind.ordinal() + CREASES.length * creasingFolds++);
        tailA = a;
        tailB = b;
        tailPose = tailPose.anchoredAt(u(a), 0); // kept about where the tail now begins: exact however long the strip
        return face;
    }

    // ---------------------------------------------------------------- tucks

    /**
     * Tucks the paper resting on {@code host} to the right of the directed line through (px, py)
     * with direction (dx, dy) under the host's other paper: faces the line crosses are cut, the
     * part beyond it is reflected over the line and slid under what it lands below.
     *
     * @throws FoldException if nothing lies beyond the line, or the paper beyond it is joined to
     *     the rest by anything but the line (tucking it would tear the strip)
     */
    public Tuck tuck(int host, double px, double py, double dx, double dy) throws FoldException {
        return TuckPlacement.tuck(this, host, px, py, dx, dy);
    }

    /**
     * How many faces {@link #tuck} along the same line would add, where they could take the sheet
     * past {@code maxFaces} (else 0): one for each face resting on {@code host} that the line cuts
     * through (its part beyond the line), counted without cutting, so that a limit on faces can
     * stop a tuck before it makes them (a tuck at a needle's corner cut through its 243,096
     * passes' turns, 302,253 faces at once). A tuck cuts at most every face on its host, and the
     * count walks them all as the tuck's cut does again, so it is taken only near the limit.
     */
    public int tuckCutsPast(int maxFaces, int host, double px, double py, double dx, double dy) {
        Stack stack = stacks.get(host);
        if (stack == null || (long) faceCount() + stack.count <= maxFaces) {
            return 0;
        }
        return tuckCuts(stack, px, py, dx, dy);
    }

    private int tuckCuts(Stack stack, double px, double py, double dx, double dy) {
        double length = Math.hypot(dx, dy);
        double nx = dy / length; // right of the direction, as the cut has it
        double ny = -dx / length;
        double c = nx * px + ny * py;
        int cuts = 0;
        for (int i = 0; i < stack.count; i++) {
            int f = stack.faces[i];
            int[] loop = loops.get(f);
            Isometry2 pose = poseOf.get(f);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int v : loop) {
                double d = nx * pose.x(u(v), v(v)) + ny * pose.y(u(v), v(v)) - c;
                min = Math.min(min, d);
                max = Math.max(max, d);
            }
            // As SheetEdit's cut tells them: beyond the line and short of it, each by more than the tolerance.
            cuts += max > tolerance && min < -tolerance ? 1 : 0;
        }
        return cuts;
    }

    /** Begins an edit of the laid paper: cuts and moves of faces, journaled. */
    public SheetEdit edit() {
        return new SheetEdit(this);
    }

    // ---------------------------------------------------------------- faces and stacks

    /**
     * The face a piece of the tail about to be laid as {@code loop} is folded from: the face
     * laid last, across the tail's start, where it rests on the tail's host; -1 where there is
     * none (the strip's first face, or the first on a host after a crossing).
     */
    int tailHinge(int[] loop) {
        if (tailLifted) {
            tailLifted = false;
            int before = faceOfEdge.get(loop[0], loop[loop.length - 1], -1);
            liftedFrom = before >= 0 && hostOf[before] == tailHost ? before : -1;
            return -1;
        }
        liftedFrom = -1;
        int before = faceOfEdge.get(loop[0], loop[loop.length - 1], -1);
        return before >= 0 && hostOf[before] == tailHost ? before : -1;
    }

    void ensureFaceCapacity(int n) {
        if (n > hostOf.length) {
            hostOf = Arrays.copyOf(hostOf, Math.max(n, 2 * hostOf.length));
            originOf = Arrays.copyOf(originOf, hostOf.length);
            slotOf = Arrays.copyOf(slotOf, hostOf.length);
        }
    }

    void register(int f) {
        int[] loop = loops.get(f);
        for (int i = 0; i < loop.length; i++) {
            faceOfEdge.put(loop[i], loop[(i + 1) % loop.length], f);
        }
    }

    void unregister(int f) {
        int[] loop = loops.get(f);
        for (int i = 0; i < loop.length; i++) {
            faceOfEdge.remove(loop[i], loop[(i + 1) % loop.length], -1);
        }
    }

    /** Per-face marks for one pass over a stack, told apart by {@link #nextMark()} rather than cleared. */
    int[] mark = new int[16];
    int[] cutMark = new int[16];
    /** Per-face marks of the faces leaving a stack ({@link Stack#remove}), by a stamp of {@link #nextMark()}. */
    int[] goneMark = new int[16];
    int markCount;
    /** Scratch: each face's place in the stack whose levels are being found. */
    int[] placeInStack = new int[16];
    /** Scratch: the working arrays of {@link Stack#findLevels}, grown as needed. */
    private final int[][] levelScratch = new int[7][];

    int[] levelScratch(int which, int size) {
        int[] scratch = levelScratch[which];
        if (scratch == null || scratch.length < size) {
            scratch = new int[Math.max(size, scratch == null ? 16 : 2 * scratch.length)];
            levelScratch[which] = scratch;
        }
        return scratch;
    }

    /** Scratch: for each face a cut split, the part cut off it (-1 for every other face, kept so between cuts). */
    private int[] partOfFace = new int[0];

    /** {@link #partOfFace}, as long as the sheet has faces. */
    int[] partOfFace() {
        if (partOfFace.length < loops.size()) {
            int old = partOfFace.length;
            partOfFace = Arrays.copyOf(partOfFace, Math.max(loops.size(), 2 * old));
            Arrays.fill(partOfFace, old, partOfFace.length, -1);
        }
        return partOfFace;
    }

    /** Scratch: each face's level in the stack being tucked, before the tuck ({@link #levelsByFace}). */
    private int[] levelByFace = new int[16];

    /**
     * The scratch array for levels by face, as long as the sheet has faces: a tuck writes its
     * stack's levels there and reads only those (a stack's, not the sheet's: a tuck must not
     * cost the whole sheet).
     */
    int[] levelsByFace() {
        if (levelByFace.length < loops.size()) {
            levelByFace = Arrays.copyOf(levelByFace, Math.max(loops.size(), 2 * levelByFace.length));
        }
        return levelByFace;
    }

    int nextMark() {
        if (mark.length < loops.size()) {
            mark = Arrays.copyOf(mark, Math.max(loops.size(), 2 * mark.length));
            cutMark = Arrays.copyOf(cutMark, mark.length);
            goneMark = Arrays.copyOf(goneMark, mark.length);
        }
        return ++markCount;
    }

    /**
     * Finishes the paper resting on {@code host}, as a wrap does when the strip leaves it: paper
     * laid there later lies over it, and a later tuck's flap goes between the two, under the
     * new paper only (the strip coming back to a finished stack cannot slide between the
     * layers of its folds). Forgets the corners and boxes kept of its faces too, which speed
     * the folds and tucks on it: they were a sixth of the memory the paper takes (they are made
     * again if asked).
     */
    public void settle(int host) {
        Stack stack = stacks.get(host);
        if (stack == null) {
            return;
        }
        stack.grid = null;
        for (int i = 0; i < stack.count; i++) {
            int f = stack.faces[i];
            originOf[f] |= SEALED;
            placedFaces.release(f);
        }
    }

    /**
     * How many tests of one face's polygon against another's the sheet has made since it was
     * made: the costly part of folding, which tests and benchmarks watch grow with the folds.
     */
    public long polygonTests() {
        return placedFaces.polygonTests();
    }

    /** Face f's corners in its host's frame, x0 y0 x1 y1 ... */
    public double[] placed(int f) {
        int[] loop = loops.get(f);
        Isometry2 pose = poseOf.get(f);
        double[] xy = new double[2 * loop.length];
        for (int i = 0; i < loop.length; i++) {
            int v = loop[i];
            xy[2 * i] = pose.x(u(v), v(v));
            xy[2 * i + 1] = pose.y(u(v), v(v));
        }
        return xy;
    }

    int[] levels(Stack stack) {
        return stack.findLevels();
    }

    /** Face f's level in its host's stack: 0 on the surface. */
    public int level(int f) {
        Stack stack = stacks.get(hostOf[f]);
        int[] levels = levels(stack);
        for (int i = 0; i < stack.count; i++) {
            if (stack.faces[i] == f) {
                return levels[i];
            }
        }
        throw new IllegalArgumentException("face " + f + " is not on its host");
    }

    /** Every face's level, indexed by face. */
    public int[] levels() {
        int[] all = new int[faceCount()];
        for (Stack stack : stacks.values()) {
            int[] levels = levels(stack);
            for (int i = 0; i < stack.count; i++) {
                all[stack.faces[i]] = levels[i];
            }
        }
        return all;
    }

    /** The highest level of the paper on {@code host}: -1 where none rests there. */
    public int topLevel(int host) {
        Stack stack = stacks.get(host);
        if (stack == null || stack.count == 0) {
            return -1;
        }
        levels(stack);
        return stack.top;
    }

    /** The levels in the deepest stack of any host (its top level + 1). */
    public int stackLevels() {
        int deepest = 0;
        for (Stack stack : stacks.values()) {
            levels(stack);
            deepest = Math.max(deepest, stack.top + 1);
        }
        return deepest;
    }

    /**
     * The order relations the stacks hold, all hosts together: a pile of n layers holds about
     * n, not n² (see the class comment), and each fold costs what they are.
     */
    public int orderRelations() {
        int relations = 0;
        for (Stack stack : stacks.values()) {
            relations += stack.above.size();
        }
        return relations;
    }

    /** The levels of the faces on {@code host}, in the order {@link #facesOn} gives them. */
    public int[] levelsOn(int host) {
        Stack stack = stacks.get(host);
        return stack == null ? new int[0] : Arrays.copyOf(levels(stack), stack.count);
    }

    /** The faces resting on {@code host}. */
    public int[] facesOn(int host) {
        Stack stack = stacks.get(host);
        return stack == null ? new int[0] : Arrays.copyOf(stack.faces, stack.count);
    }

    /**
     * How far the paper on {@code host} reaches beyond the line through (px, py) with unit normal
     * (nx, ny): the most of n·(q − p) over its faces' corners q (negative infinity where no paper
     * rests there). From the corners the sheet keeps of each face until it changes, not made
     * anew: a wrap asks this of each edge of a host before each tuck, and making every face's
     * corners each time was a gigabyte of garbage on the 5,000-triangle torus.
     */
    public double farthestBeyond(int host, double px, double py, double nx, double ny) {
        Stack stack = stacks.get(host);
        double farthest = Double.NEGATIVE_INFINITY;
        if (stack == null) {
            return farthest;
        }
        for (int i = 0; i < stack.count; i++) {
            double[] xy = placedFaces.polygon(stack.faces[i]);
            for (int k = 0; k < xy.length; k += 2) {
                farthest = Math.max(farthest, nx * (xy[k] - px) + ny * (xy[k + 1] - py));
            }
        }
        return farthest;
    }

    /** The faces on {@code host} that may overlap a polygon (x y each, on the host's frame): those near it in the stack's grid, or all. */
    public int[] facesNear(int host, double[] polygon) {
        Stack stack = stacks.get(host);
        if (stack == null) {
            return new int[0];
        }
        int[] slots = stack.near(polygon, -1);
        int[] faces = new int[slots.length];
        for (int i = 0; i < slots.length; i++) {
            faces[i] = stack.faces[slots[i]];
        }
        return faces;
    }

    // ---------------------------------------------------------------- reading

    public double width() {
        return width;
    }

    public double thickness() {
        return thickness;
    }

    public double tolerance() {
        return tolerance;
    }

    /**
     * The distance within which points of the paper at {@code u} along the strip, placed by the
     * tail's poses, are one: the tolerance, or where the strip is long the rounding its poses
     * have gathered, which grows with u ({@link #POSE_DRIFT}).
     */
    public double toleranceAt(double u) {
        return Math.max(tolerance, POSE_DRIFT * Math.abs(u));
    }

    /** The strip's length L, once it has ended. */
    public double length() {
        return length;
    }

    public int vertexCount() {
        return vertexCount;
    }

    public double u(int vertex) {
        return uv[2 * vertex];
    }

    public double v(int vertex) {
        return uv[2 * vertex + 1];
    }

    public int faceCount() {
        return loops.size();
    }

    /** Face f's paper vertices, counter-clockwise on the sheet seen from its top. */
    public int[] loop(int f) {
        return loops.get(f).clone();
    }

    /** How many paper vertices face f's loop has ({@link #loop}, without its copy). */
    public int loopLength(int f) {
        return loops.get(f).length;
    }

    /**
     * The i-th paper vertex of face f's loop ({@link #loop}): for loops walked once a point, where
     * a copy of the loop each time was a million arrays on a 5,000-triangle wrap.
     */
    public int loopVertex(int f, int i) {
        return loops.get(f)[i];
    }

    public int host(int f) {
        return hostOf[f];
    }

    public Isometry2 pose(int f) {
        return poseOf.get(f);
    }

    /**
     * The kind of the fold of the tail after which face f was laid (the paper it is part of:
     * a pass after a turn, a gadget's paper, a strip come over an edge), or null for the first
     * face; kept when the face is cut or tucked.
     */
    public Crease laidAfter(int f) {
        int kind = (originOf[f] & (TUCKED - 1)) - 1;
        return kind < 0 ? null : CREASES[kind];
    }

    /** Whether a tuck has moved face f (or the face it was cut from). */
    public boolean tucked(int f) {
        return (originOf[f] & TUCKED) != 0;
    }

    /** The face on the other side of paper edge a → b of a face, or -1 at the strip's border. */
    public int faceAcross(int a, int b) {
        return faceOfEdge.get(b, a, -1);
    }

    /** The crease along paper edge (a, b), or null where the paper is flat or the edge is the border. */
    public Crease crease(int a, int b) {
        int crease = creases.get(undirected(a, b), -1);
        return crease < 0 ? null : CREASES[crease % CREASES.length];
    }

    /**
     * Which fold made the crease along paper edge (a, b), counting the folds that made creases
     * from 0 (a crease split by a later cut keeps its fold), or -1 where there is none: the
     * order to fold a crease pattern back in.
     */
    public int creaseFold(int a, int b) {
        int crease = creases.get(undirected(a, b), -1);
        return crease < 0 ? -1 : crease / CREASES.length;
    }

    int addVertex(double u, double v) {
        if (2 * vertexCount + 2 > uv.length) {
            uv = Arrays.copyOf(uv, 2 * uv.length);
        }
        uv[2 * vertexCount] = u;
        uv[2 * vertexCount + 1] = v;
        return vertexCount++;
    }

    static long directed(int a, int b) {
        return ((long) a << 32) | (b & 0xffffffffL);
    }

    static long undirected(int a, int b) {
        return directed(Math.min(a, b), Math.max(a, b));
    }
}
