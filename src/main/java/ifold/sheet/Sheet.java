package ifold.sheet;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
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

    private final double width;
    private final double thickness;
    private final double tolerance;
    /** The faces as placed on their hosts, and the tests of one against another. */
    private final PlacedFaces placedFaces;

    private double[] uv = new double[64];
    private int vertexCount;

    private final List<int[]> loops = new ArrayList<>();
    private int[] hostOf = new int[16];
    /**
     * How each face came to be where it is: the kind of the fold of the tail that laid it (its
     * crease's ordinal + 1; 0 for the strip's first face, or a sheet's), plus {@link #TUCKED}
     * once a tuck has moved it, and {@link #SEALED} once its host is {@link #settle settled}. A
     * face cut from another inherits it.
     */
    private byte[] originOf = new byte[16];
    private static final int TUCKED = 16;
    private static final int SEALED = 32;
    /** The kind of the tail's last crease, which the next face laid from the tail comes after; null before any. */
    private Crease lastTailCrease;
    private final List<Isometry2> poseOf = new ArrayList<>();
    /** The face to the left of each directed paper edge a → b, keyed a << 32 | b. */
    private final LongIntMap faceOfEdge = new LongIntMap();
    /**
     * The creases, keyed by their lower vertex << 32 | the higher: each its kind and the fold
     * that made it, as kind + {@link #CREASES}.length × fold (see {@link #creaseFold}).
     */
    private final LongIntMap creases = new LongIntMap();
    private static final Crease[] CREASES = Crease.values();
    /** The folds that made creases so far: the next one's number. */
    private int creasingFolds;
    private final Map<Integer, Stack> stacks = new HashMap<>();

    private int tailA;
    private int tailB;
    private int tailHost;
    private Isometry2 tailPose;
    private Placement tailPlacement = Placement.OVER;
    /** Whether the next piece of the tail laid lands over all it overlaps ({@link #liftTail}). */
    private boolean tailLifted;
    /** The face the tail ran on from when it was lifted, on its host, for the next face laid; else -1. */
    private int liftedFrom = -1;
    private double length = Double.NaN;

    /** Each face's place in its stack's list of faces. */
    private int[] slotOf = new int[16];
    /**
     * How far, relative to u, a crease's place on the tail may stray by the rounding of the
     * poses composed fold after fold: about the square root of the folds times the rounding of
     * one, 1e-16; a million folds, 1e-13; this leaves ten times that.
     */
    private static final double POSE_DRIFT = 1e-12;

    /** From how many faces a stack finds the faces a new one overlaps through a grid rather than by looking at all. */
    private static final int GRID_FROM = 32;

    /** The faces resting on one host and their order. */
    private final class Stack {
        int[] faces = new int[8];
        int count;
        /** Pairs (above << 32 | below) of overlapping faces. */
        LongList above = new LongList();
        int[] levels;
        int top = -1;
        /**
         * The faces by where they lie, once the stack is big enough. A face that moves or leaves
         * stays listed where it was ({@link #near} passes over it, and the faces it finds are
         * only candidates): the grid is made again once those are as many as the faces, not at
         * each tuck, which cost a big host's every face each time.
         */
        FaceGrid grid;
        /** The faces listed in the grid since it was made, those gone or moved since included. */
        int gridListed;

        void add(int f) {
            if (count == faces.length) {
                faces = Arrays.copyOf(faces, 2 * count);
            }
            slotOf[f] = count;
            faces[count++] = f;
            levels = null;
            if (grid != null) {
                grid.add(f, placedFaces.polygon(f));
                gridListed++;
            }
        }

        void remove(Set<Integer> gone) {
            int n = 0;
            for (int i = 0; i < count; i++) {
                if (!gone.contains(faces[i])) {
                    slotOf[faces[i]] = n;
                    faces[n++] = faces[i];
                }
            }
            count = n;
            levels = null;
        }

        /**
         * The places in the stack, in order, of the faces that may overlap face f (listed in the
         * grid cells its polygon meets): all of them while the stack is small.
         */
        int[] near(int f) {
            if (grid != null && gridListed > 2 * count + GRID_FROM) {
                grid = null; // more listed faces gone or moved than there are faces
            }
            if (count >= GRID_FROM && grid == null) {
                double[][] polygons = new double[count][];
                for (int i = 0; i < count; i++) {
                    polygons[i] = placedFaces.polygon(faces[i]);
                }
                grid = new FaceGrid(FaceGrid.cellFor(polygons, count, 2 * width));
                for (int i = 0; i < count; i++) {
                    grid.add(faces[i], polygons[i]);
                }
                gridListed = count;
            }
            int[] listed = grid == null ? null : grid.near(placedFaces.polygon(f));
            if (listed != null) {
                // Faces that left the stack stay listed: only those still in it, by their place.
                int[] slots = new int[listed.length];
                int n = 0;
                for (int g : listed) {
                    if (g != f && slotOf[g] < count && faces[slotOf[g]] == g) {
                        slots[n++] = slotOf[g];
                    }
                }
                slots = Arrays.copyOf(slots, n);
                Arrays.sort(slots);
                return slots;
            }
            int[] all = new int[count];
            for (int i = 0; i < count; i++) {
                all[i] = i;
            }
            return all;
        }
    }

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
        sheet.addFace(new int[] {sheet.tailA, a, b, sheet.tailB}, host, pose, Placement.OVER, -1);
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
        if (!(end > Math.max(startA, startB) + tolerance)) {
            throw new FoldException("the strip's end lies behind its last crease");
        }
        int a = addVertex(end, 0);
        int b = addVertex(end, width);
        int[] loop = {tailA, a, b, tailB};
        int face = addFace(loop, tailHost, tailPose, tailPlacement, tailHinge(loop));
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
    private double[] creaseOnTail(double px, double py, double dx, double dy) throws FoldException {
        Isometry2 inverse = tailPose.inverse();
        double pu = inverse.x(px, py);
        double pv = inverse.y(px, py);
        double du = inverse.dx(dx, dy);
        double dv = inverse.dy(dx, dy);
        if (!(Math.abs(dv) > 1e-12 * Math.hypot(du, dv))) {
            throw new FoldException("the crease runs along the strip: a fold of the tail must cross it");
        }
        return new double[] {pu + (0 - pv) / dv * du, pu + (width - pv) / dv * du};
    }

    private int cutTail(double px, double py, double dx, double dy, Crease kind) throws FoldException {
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
        int face = addFace(loop, tailHost, tailPose, tailPlacement, tailHinge(loop));
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
     * What a tuck did.
     *
     * @param host the host whose paper was tucked
     * @param moved the faces that turned under (after cutting)
     * @param px a point of the tuck line, in the host's frame
     * @param py its y
     * @param dx the line's direction; the paper on its right turned
     * @param dy its y
     * @param facesBefore the faces of the sheet before the tuck: those from it on were cut off by it
     * @param changed the faces that were there before and were cut or moved
     * @param loopsBefore their loops before the tuck
     * @param posesBefore their poses before the tuck
     */
    public record Tuck(int host, int[] moved, double px, double py, double dx, double dy, int facesBefore, int[] changed,
            int[][] loopsBefore, Isometry2[] posesBefore) {
    }

    /**
     * Tucks the paper resting on {@code host} to the right of the directed line through (px, py)
     * with direction (dx, dy) under the host's other paper: faces the line crosses are cut, the
     * part beyond it is reflected over the line and slid under what it lands below.
     *
     * @throws FoldException if nothing lies beyond the line, or the paper beyond it is joined to
     *     the rest by anything but the line (tucking it would tear the strip)
     */
    public Tuck tuck(int host, double px, double py, double dx, double dy) throws FoldException {
        if (stacks.get(host) == null) {
            throw new FoldException("no paper rests on triangle " + host);
        }
        Edit edit = edit();
        int[] beyond = edit.cutOnHost(host, px, py, dx, dy);
        if (beyond.length == 0) {
            throw new FoldException("nothing to tuck: no paper on triangle " + host + " lies beyond the line");
        }
        Set<Integer> moving = new HashSet<>();
        for (int f : beyond) {
            moving.add(f);
        }
        double length = Math.hypot(dx, dy);
        double nx = dy / length;
        double ny = -dx / length;
        double c = nx * px + ny * py;
        // The flap may be joined to the rest only along the tuck line.
        for (int f : moving) {
            int[] loop = loops.get(f);
            Isometry2 pose = poseOf.get(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int across = faceOfEdge.get(directed(b, a), -1);
                if (across < 0 || moving.contains(across)) {
                    continue;
                }
                double da = nx * pose.x(u(a), v(a)) + ny * pose.y(u(a), v(a)) - c;
                double db = nx * pose.x(u(b), v(b)) + ny * pose.y(u(b), v(b)) - c;
                // On the line to twice the tolerance: the crease's ends and the line were each
                // placed to the tolerance (a 4,000-triangle torus had a turn's crease end 1.003
                // tolerances off the tuck line along the same triangle edge); far along a long
                // strip, to the tolerance its poses' rounding has grown to.
                if (Math.abs(da) > 2 * toleranceAt(u(a)) || Math.abs(db) > 2 * toleranceAt(u(b))) {
                    throw new FoldException("tucking under triangle " + host + " would tear the strip: paper beyond the line"
                            + " is joined to paper that stays by a crease off the line");
                }
            }
        }
        edit.crease(moving, Crease.TUCK);
        edit.tuckUnder(moving, Isometry2.reflection(px, py, dx, dy), nx, ny, c);
        for (int f : moving) {
            originOf[f] |= TUCKED;
        }
        Edit.Journal journal = edit.journal();
        int[] moved = moving.stream().mapToInt(Integer::intValue).sorted().toArray();
        return new Tuck(host, moved, px, py, dx, dy, journal.facesBefore(), journal.changed(), journal.loopsBefore(),
                journal.posesBefore());
    }

    /** Begins an edit of the laid paper: cuts and moves of faces, journaled. */
    public Edit edit() {
        return new Edit();
    }

    /**
     * An edit of the paper already laid, as a fold of it makes: cut faces along a line, then
     * move some of them to a host (the same one, reflected, or another) over or under the paper
     * there. Every face it cuts or moves is journaled with its loop, pose and host before, for
     * the animation.
     */
    public final class Edit {
        private final int facesBefore = loops.size();
        private final Map<Integer, Integer> journalIndex = new HashMap<>();
        private final List<Integer> changedFaces = new ArrayList<>();
        private final List<int[]> loopsBefore = new ArrayList<>();
        private final List<Isometry2> posesBefore = new ArrayList<>();
        private final List<Integer> hostsBefore = new ArrayList<>();
        private final Map<Long, Integer> splitOfEdge = new HashMap<>();
        /** Faces whose shape changed (cut, or made by a cut): their relations are checked again. */
        private final Set<Integer> reshaped = new HashSet<>();
        /** For each face made by a cut, the face it was cut from. */
        private final List<Integer> parents = new ArrayList<>();
        /** Whether a cut ran along a line on the sheet rather than on a host. */
        private boolean sheetCut;

        private Edit() {
        }

        /**
         * What the edit did.
         *
         * @param facesBefore the faces before it: those from it on were cut off by it
         * @param changed the faces there before that it cut or moved
         * @param loopsBefore their loops before
         * @param posesBefore their poses before
         * @param hostsBefore their hosts before
         * @param parents for each face made by the edit (facesBefore, facesBefore + 1, ...), the
         *     face there before that it was cut from
         */
        public record Journal(int facesBefore, int[] changed, int[][] loopsBefore, Isometry2[] posesBefore, int[] hostsBefore,
                int[] parents) {
            /** The face there before the edit that face g was cut from (g itself if it was there). */
            public int parentOf(int g) {
                return g < facesBefore ? g : parents[g - facesBefore];
            }
        }

        public Journal journal() {
            return new Journal(facesBefore, changedFaces.stream().mapToInt(Integer::intValue).toArray(),
                    loopsBefore.toArray(new int[0][]), posesBefore.toArray(new Isometry2[0]),
                    hostsBefore.stream().mapToInt(Integer::intValue).toArray(), parents.stream().mapToInt(Integer::intValue).toArray());
        }

        private void note(int f) {
            if (f < facesBefore && !journalIndex.containsKey(f)) {
                journalIndex.put(f, changedFaces.size());
                changedFaces.add(f);
                loopsBefore.add(loops.get(f));
                posesBefore.add(poseOf.get(f));
                hostsBefore.add(hostOf[f]);
            }
        }

        /**
         * Cuts the faces on {@code host} that the directed line through (px, py) with direction
         * (dx, dy), in the host's frame, crosses.
         *
         * @return the faces of the host right of the line, after cutting
         */
        public int[] cutOnHost(int host, double px, double py, double dx, double dy) {
            Stack stack = stacks.get(host);
            if (stack == null) {
                return new int[0];
            }
            double length = Math.hypot(dx, dy);
            double nx = dy / length; // right of the direction
            double ny = -dx / length;
            double c = nx * px + ny * py;
            return cut(Arrays.copyOf(stack.faces, stack.count), nx, ny, c, false);
        }

        /**
         * Cuts every face the directed line through paper points (u1, v1) and (u2, v2) crosses,
         * wherever it lies.
         *
         * @return the faces right of the line on the sheet (seen from its top), after cutting
         */
        public int[] cutOnSheet(double u1, double v1, double u2, double v2) {
            double du = u2 - u1;
            double dv = v2 - v1;
            double length = Math.hypot(du, dv);
            double nu = dv / length;
            double nv = -du / length;
            double c = nu * u1 + nv * v1;
            sheetCut = true;
            int[] all = new int[loops.size()];
            for (int f = 0; f < all.length; f++) {
                all[f] = f;
            }
            return cut(all, nu, nv, c, true);
        }

        /**
         * Cuts those of {@code faces} that the line n·p = c crosses (p in their host's frame, or
         * on the sheet): each keeps its near side, a new face takes the far side.
         *
         * @return the faces beyond the line, after cutting
         */
        private int[] cut(int[] faces, double nx, double ny, double c, boolean onSheet) {
            List<Integer> beyond = new ArrayList<>();
            Map<Integer, Map<Integer, Integer>> partsByHost = new HashMap<>();
            for (int f : faces) {
                double[] range = range(f, nx, ny, c, onSheet);
                if (range[1] <= tolerance) {
                    continue;
                }
                note(f);
                if (range[0] >= -tolerance) {
                    beyond.add(f);
                    continue;
                }
                int g = split(f, nx, ny, c, onSheet, splitOfEdge, this);
                partsByHost.computeIfAbsent(hostOf[f], h -> new HashMap<>()).put(f, g);
                beyond.add(g);
            }
            // Each new part inherits its face's relations, in one pass over each stack's (a cut
            // across a deep stack splits thousands of faces); those that no longer overlap are
            // dropped later.
            for (Map.Entry<Integer, Map<Integer, Integer>> entry : partsByHost.entrySet()) {
                Stack stack = stacks.get(entry.getKey());
                Map<Integer, Integer> partOf = entry.getValue();
                LongList inherited = new LongList();
                for (int r = 0; r < stack.above.size(); r++) {
                    long pair = stack.above.get(r);
                    Integer upper = partOf.get((int) (pair >>> 32));
                    Integer lower = partOf.get((int) pair);
                    if (upper != null) {
                        inherited.add(((long) upper << 32) | (pair & 0xffffffffL));
                    }
                    if (lower != null) {
                        inherited.add((pair & ~0xffffffffL) | lower);
                    }
                    if (upper != null && lower != null) {
                        inherited.add(((long) upper << 32) | lower);
                    }
                }
                stack.above.addAll(inherited);
            }
            return beyond.stream().mapToInt(Integer::intValue).toArray();
        }

        private double[] range(int f, double nx, double ny, double c, boolean onSheet) {
            int[] loop = loops.get(f);
            Isometry2 pose = poseOf.get(f);
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (int v : loop) {
                double d = onSheet ? nx * u(v) + ny * v(v) - c : nx * pose.x(u(v), v(v)) + ny * pose.y(u(v), v(v)) - c;
                min = Math.min(min, d);
                max = Math.max(max, d);
            }
            return new double[] {min, max};
        }

        /** Marks the paper edges between {@code moving} faces and the rest as creases of {@code kind}, where they are not creases already. */
        public void crease(Set<Integer> moving, Crease kind) {
            int value = kind.ordinal() + CREASES.length * creasingFolds++;
            for (int f : moving) {
                int[] loop = loops.get(f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    int across = faceOfEdge.get(directed(b, a), -1);
                    if (across >= 0 && !moving.contains(across) && creases.get(undirected(a, b), -1) < 0) {
                        creases.put(undirected(a, b), value);
                    }
                }
            }
        }

        /**
         * Moves {@code faces}, all resting on one host, to {@code toHost} (which may be the same):
         * each pose is composed with {@code frameChange}, which maps the old host's frame to the
         * new one's. Their order among themselves is kept, or reversed where the change mirrors
         * (the paper turned over); where they overlap paper already on the new host they land
         * {@code placement} it.
         */
        public void move(Set<Integer> faces, int toHost, Isometry2 frameChange, Placement placement) {
            move(faces, toHost, frameChange, placement, null, null);
        }

        /**
         * Tucks {@code faces}, resting on one host, across the fold line (nx, ny)·p = c: as
         * {@link #move} does with {@link Placement#UNDER}, their own order reversed, so that
         * their layers nest about the line as they did before (flat folding's taco-taco
         * condition), but not so that paper going on across the line to another host (a strip
         * crossing the edge) lies between the flap and the paper it is folded from, its hinges:
         * the flap would wrap around that strip, which paper cannot (taco-tortilla). The flap
         * goes as one: under all it overlaps but such strips below the lowest of its hinges (the
         * staying faces it is joined to) and the paper below them (in the stack's order, through
         * its relations): just above those. Paper that only lies near them stays above the flap,
         * so that a fold of the strip whose crease lies on the tuck line itself (a turn's bottom
         * along a host's edge) nests inside the tuck rather than interleaving with it
         * (taco-taco). A flap with hinges on either side of such a strip (a pass's end that
         * turns beyond the line and comes back around it) still wraps it; it happens at the
         * widest strip on the cube.
         */
        public void tuckUnder(Set<Integer> faces, Isometry2 reflection, double nx, double ny, double c) {
            if (faces.isEmpty()) {
                return;
            }
            int host = hostOf[faces.iterator().next()];
            Stack stack = stacks.get(host);
            int[] levels = levels(stack);
            Map<Integer, Integer> levelOf = new HashMap<>();
            for (int i = 0; i < stack.count; i++) {
                levelOf.put(stack.faces[i], levels[i]);
            }
            // The flap's pieces: paper beyond the line joined on the sheet, each with its hinges.
            Map<Integer, Integer> pieceOf = new HashMap<>();
            int pieces = 0;
            for (int f : faces) {
                if (pieceOf.containsKey(f)) {
                    continue;
                }
                ArrayDeque<Integer> open = new ArrayDeque<>(List.of(f));
                pieceOf.put(f, pieces);
                while (!open.isEmpty()) {
                    int[] loop = loops.get(open.poll());
                    for (int k = 0; k < loop.length; k++) {
                        int across = faceOfEdge.get(directed(loop[(k + 1) % loop.length], loop[k]), -1);
                        if (across >= 0 && faces.contains(across) && !pieceOf.containsKey(across)) {
                            pieceOf.put(across, pieces);
                            open.add(across);
                        }
                    }
                }
                pieces++;
            }
            int[] lowestHinge = new int[pieces];
            Arrays.fill(lowestHinge, Integer.MAX_VALUE);
            Set<Integer> hinges = new HashSet<>();
            Map<Integer, Set<Integer>> hingesOf = new HashMap<>();
            List<Integer> crossing = new ArrayList<>();
            for (int i = 0; i < stack.count; i++) {
                int f = stack.faces[i];
                int[] loop = loops.get(f);
                Isometry2 pose = poseOf.get(f);
                boolean moves = faces.contains(f);
                for (int k = 0; k < loop.length; k++) {
                    int a = loop[k];
                    int b = loop[(k + 1) % loop.length];
                    int across = faceOfEdge.get(directed(b, a), -1);
                    if (across < 0) {
                        continue;
                    }
                    if (moves && !faces.contains(across) && hostOf[across] == host) {
                        int piece = pieceOf.get(f);
                        lowestHinge[piece] = Math.min(lowestHinge[piece], levelOf.get(across));
                        hinges.add(across);
                        hingesOf.computeIfAbsent(piece, p -> new HashSet<>()).add(across);
                    } else if (!moves && hostOf[across] != host && onLine(pose, a, nx, ny, c) && onLine(pose, b, nx, ny, c)) {
                        crossing.add(f);
                    }
                }
            }
            // A strip below the lowest hinge by level, or below any hinge by the stack's order (a
            // piece whose hinges lie both at the strip's level, beside it, and above it).
            Map<Integer, List<Integer>> below = crossing.isEmpty() ? new HashMap<>() : related(stack, true);
            Map<Integer, Set<Integer>> overStrip = new HashMap<>();
            if (!crossing.isEmpty()) {
                Map<Integer, List<Integer>> above = related(stack, false);
                for (int strip : crossing) {
                    Set<Integer> reached = new HashSet<>();
                    ArrayDeque<Integer> open = new ArrayDeque<>(List.of(strip));
                    while (!open.isEmpty()) {
                        for (int g : above.getOrDefault(open.poll(), List.of())) {
                            if (!faces.contains(g) && reached.add(g)) {
                                open.add(g);
                            }
                        }
                    }
                    overStrip.put(strip, reached);
                }
            }
            List<Set<Integer>> under = new ArrayList<>();
            for (int piece = 0; piece < pieces; piece++) {
                Set<Integer> set = new HashSet<>();
                ArrayDeque<Integer> open = new ArrayDeque<>();
                Set<Integer> ownHinges = hingesOf.getOrDefault(piece, Set.of());
                for (int f : crossing) {
                    boolean belowHinge = levelOf.get(f) < lowestHinge[piece]
                            || ownHinges.stream().anyMatch(overStrip.get(f)::contains);
                    if (belowHinge && set.add(f)) {
                        open.add(f);
                    }
                }
                closeDownwards(set, open, below, faces, null);
                under.add(set);
            }
            move(faces, host, reflection, Placement.UNDER, new TuckPlace(pieceOf, under, below, hinges, lowestHinge), levelOf);
        }


        private boolean onLine(Isometry2 pose, int p, double nx, double ny, double c) {
            return Math.abs(nx * pose.x(u(p), v(p)) + ny * pose.y(u(p), v(p)) - c) <= tolerance;
        }

        /**
         * As {@link #move(Set, int, Isometry2, Placement)}; with a {@code tuckPlace} (not null),
         * a tuck ({@link #tuckUnder}), placed as {@link #placeTucked} says, with the stack's
         * levels before the move {@code levelBefore}.
         */
        private void move(Set<Integer> faces, int toHost, Isometry2 frameChange, Placement placement, TuckPlace tuckPlace,
                Map<Integer, Integer> levelBefore) {
            if (faces.isEmpty()) {
                return;
            }
            int fromHost = hostOf[faces.iterator().next()];
            Stack from = stacks.get(fromHost);
            boolean mirrors = frameChange.mirrors();
            LongList kept = new LongList();
            LongList carried = new LongList();
            // Marks by face, not set lookups: a stack folded again and again holds many relations.
            // (Kept by the sheet and told apart by a count, not cleared: a tuck must not cost the
            // whole sheet.)
            int moves = nextMark();
            for (int f : faces) {
                mark[f] = moves;
            }
            int cut = nextMark();
            for (int f : reshaped) {
                cutMark[f] = cut;
            }
            // A cut along a line on the sheet can take away paper that lay between two faces that
            // stay, wherever they lie: their order, implied through it, is then recorded itself.
            Map<Integer, List<Integer>> stayingAbove = new HashMap<>();
            Map<Integer, List<Integer>> stayingBelow = new HashMap<>();
            for (int r = 0; r < from.above.size(); r++) {
                long pair = from.above.get(r);
                int upper = (int) (pair >>> 32);
                int lower = (int) pair;
                boolean upperMoves = mark[upper] == moves;
                boolean lowerMoves = mark[lower] == moves;
                if (upperMoves != lowerMoves) {
                    if (sheetCut) {
                        (upperMoves ? stayingBelow : stayingAbove).computeIfAbsent(upperMoves ? upper : lower, k -> new ArrayList<>())
                                .add(upperMoves ? lower : upper);
                    }
                    continue; // they lay side by side before; where the moved paper lands is decided below
                }
                if ((cutMark[upper] == cut || cutMark[lower] == cut) && !placedFaces.overlap(upper, lower)) {
                    continue; // a face cut by the line keeps only the relations of the part that overlaps
                }
                if (upperMoves) {
                    carried.add(mirrors ? ((long) lower << 32) | upper : pair);
                } else {
                    kept.add(pair);
                }
            }
            for (Map.Entry<Integer, List<Integer>> entry : stayingAbove.entrySet()) {
                for (int upper : entry.getValue()) {
                    for (int lower : stayingBelow.getOrDefault(entry.getKey(), List.of())) {
                        if (placedFaces.overlap(upper, lower)) {
                            kept.add(((long) upper << 32) | lower);
                        }
                    }
                }
            }
            from.above = kept;
            from.remove(faces);
            for (int f : faces) {
                note(f);
                if (hostOf[f] != fromHost) {
                    throw new IllegalArgumentException("the faces moved together must rest on one host");
                }
                poseOf.set(f, frameChange.after(poseOf.get(f)));
                hostOf[f] = toHost;
                placedFaces.forget(f);
            }
            Stack to = stacks.computeIfAbsent(toHost, h -> new Stack());
            if (tuckPlace != null) {
                placeTucked(faces, to, carried, tuckPlace, levelBefore);
                to.levels = null;
                from.levels = null;
                return;
            }
            // Each moved face lands over (or under) the faces it overlaps, unless a moved face it
            // rests on, and that holds all of it, lies between: the order is then implied, and a
            // stack folded again and again would otherwise hold every pair of its layers.
            Map<Integer, List<Integer>> between = new HashMap<>();
            for (int r = 0; r < carried.size(); r++) {
                long pair = carried.get(r);
                int upper = (int) (pair >>> 32);
                int lower = (int) pair;
                if (placement == Placement.OVER) {
                    between.computeIfAbsent(upper, k -> new ArrayList<>()).add(lower);
                } else {
                    between.computeIfAbsent(lower, k -> new ArrayList<>()).add(upper);
                }
            }
            // A face there already that the moved face overlaps too, lying directly between and
            // holding all of where the two overlap, implies the order as well: paper folded onto a
            // pile lands on its top layer, not on each, or a pleat of n folds would hold n²
            // relations and each fold cost what the pile holds. (The order is kept where the
            // face between later leaves: see stayingAbove.)
            Between direct = new Between(to.above, placement);
            for (int f : faces) {
                int holds = placedFaces.nextHoldsStamp();
                for (int i = 0; i < to.count; i++) {
                    int g = to.faces[i];
                    // First the cheap cases, without even asking whether f and g overlap: a face
                    // directly on f's side of g that holds all of g, or all of f, holds all of
                    // where they overlap. Each fold of a pleat lands on a pile whose every layer
                    // holds the one below: asked of each pair of layers, the pile of n folds cost
                    // n² overlaps (24 s for 10,000 creases).
                    boolean implied = false;
                    for (int k = direct.start(g); k < direct.end(g) && !implied; k++) {
                        int h = direct.face(k);
                        implied = placedFaces.holdsFace(h, g) || placedFaces.holdsAll(h, f, holds);
                    }
                    if (implied || !placedFaces.overlap(f, g)) {
                        continue;
                    }
                    for (int h : between.getOrDefault(f, List.of())) {
                        if (placedFaces.contains(h, f) && placedFaces.overlap(h, g)) {
                            implied = true;
                            break;
                        }
                    }
                    for (int k = direct.start(g); k < direct.end(g) && !implied; k++) {
                        int h = direct.face(k);
                        implied = placedFaces.overlap(f, h) && placedFaces.holdsOverlap(h, f, g);
                    }
                    if (!implied) {
                        to.above.add(placement == Placement.OVER ? ((long) f << 32) | g : ((long) g << 32) | f);
                    }
                }
            }
            to.above.addAll(carried);
            for (int f : faces) {
                to.add(f);
            }
            to.levels = null;
            from.levels = null;
        }
    }

    /**
     * Where a tuck's flap goes, piece by piece (paper beyond the line joined on the sheet, each
     * {@code pieceOf} it): above the staying faces {@code under} it (strips crossing the tuck
     * line below the piece's hinges, {@code lowestHinge} the lowest, and the paper below them,
     * through the stack's relations {@code below}), under the rest; {@code hinges} are the
     * staying faces the flap is joined to.
     */
    private record TuckPlace(Map<Integer, Integer> pieceOf, List<Set<Integer>> under, Map<Integer, List<Integer>> below,
            Set<Integer> hinges, int[] lowestHinge) {
    }

    /**
     * The order of tucked {@code faces}, as {@link Edit#tuckUnder} places them: each piece above
     * the staying paper {@code place.under()} says and below the rest, in their own order
     * {@code carried}. A layer of paper a piece goes above goes on above it where it continues on
     * the host, folded or flat, into paper the piece overlaps (below its hinges): the piece cannot
     * pass through it, nor lie between the two layers of its fold (taco-tortilla). A piece over
     * another in the flap's own order goes over all the other goes over, so that the order has
     * no cycle.
     */
    private void placeTucked(Set<Integer> faces, Stack to, LongList carried, TuckPlace place, Map<Integer, Integer> levelBefore) {
        List<Set<Integer>> under = place.under();
        Map<Integer, List<Integer>> facesOfPiece = new HashMap<>();
        for (int f : faces) {
            facesOfPiece.computeIfAbsent(place.pieceOf().get(f), k -> new ArrayList<>()).add(f);
        }
        for (int piece = 0; piece < under.size(); piece++) {
            closeOverFolds(under.get(piece), facesOfPiece.getOrDefault(piece, List.of()), faces, place, place.lowestHinge()[piece],
                    levelBefore);
        }
        // A piece above another goes above all that one does.
        boolean grew = under.size() > 1;
        while (grew) {
            grew = false;
            for (int r = 0; r < carried.size(); r++) {
                long pair = carried.get(r);
                int upper = place.pieceOf().get((int) (pair >>> 32));
                int lower = place.pieceOf().get((int) pair);
                if (upper != lower) {
                    grew |= under.get(upper).addAll(under.get(lower));
                }
            }
        }
        // A face f goes over or under each staying face g it overlaps, but the order is not
        // recorded where a face h directly next to g on f's side holds all of where f and g
        // overlap: f over h over g, or f under h under g, implies it (and still does when h is cut
        // by a later line, whose pieces hold the overlap's pieces). At a sharp corner each flap
        // overlaps every layer bounced there before: recorded pair by pair, the stack of a 1°
        // corner held 200,000 relations, which every later tuck walked.
        StackOrder order = new StackOrder(to);
        int[] sideOf = new int[to.count]; // by slot: +1 where f goes over, -1 under, 0 apart
        List<Integer> overlapping = new ArrayList<>();
        for (int f : faces) {
            Set<Integer> pieceUnder = under.get(place.pieceOf().get(f));
            overlapping.clear();
            for (int i : to.near(f)) {
                int g = to.faces[i];
                if (placedFaces.overlap(f, g)) {
                    sideOf[i] = (originOf[g] & SEALED) != 0 || pieceUnder.contains(g) ? 1 : -1;
                    overlapping.add(g);
                }
            }
            for (int g : overlapping) {
                int side = sideOf[slotOf[g]];
                boolean implied = false;
                int[] next = side > 0 ? order.upper : order.lower;
                int[] start = side > 0 ? order.upperStart : order.lowerStart;
                double[] common = null; // where f and g overlap, found once a face might hold it
                // A few of g's neighbours at most: the face at the foot of a tall stack of passes has
                // thousands, and recording the pair is always right, only less economical.
                int end = Math.min(start[slotOf[g] + 1], start[slotOf[g]] + WITNESSES);
                for (int k = start[slotOf[g]]; k < end && !implied; k++) {
                    int h = next[k];
                    if (sideOf[slotOf[h]] == side) {
                        common = common != null ? common : placedFaces.overlapOf(f, g);
                        implied = common != null && placedFaces.containsPoints(placedFaces.polygon(h), common);
                    }
                }
                if (!implied) {
                    to.above.add(side > 0 ? ((long) f << 32) | g : ((long) g << 32) | f);
                }
            }
            for (int g : overlapping) {
                sideOf[slotOf[g]] = 0;
            }
        }
        to.above.addAll(carried);
        for (int f : faces) {
            to.add(f);
        }
    }

    /**
     * Adds to {@code under} every face below those in {@code open}, through a stack's relations
     * {@code below}, but the {@code moving}; each face added goes to {@code added} too, if given.
     */
    private static void closeDownwards(Set<Integer> under, ArrayDeque<Integer> open, Map<Integer, List<Integer>> below,
            Set<Integer> moving, ArrayDeque<Integer> added) {
        while (!open.isEmpty()) {
            for (int g : below.getOrDefault(open.poll(), List.of())) {
                if (!moving.contains(g) && under.add(g)) {
                    open.add(g);
                    if (added != null) {
                        added.add(g);
                    }
                }
            }
        }
    }

    /**
     * A stack's relations by face: the faces directly below each ({@code byUpper}), or directly
     * above each.
     */
    private static Map<Integer, List<Integer>> related(Stack stack, boolean byUpper) {
        Map<Integer, List<Integer>> related = new HashMap<>();
        for (int r = 0; r < stack.above.size(); r++) {
            long pair = stack.above.get(r);
            int upper = (int) (pair >>> 32);
            int lower = (int) pair;
            related.computeIfAbsent(byUpper ? upper : lower, k -> new ArrayList<>()).add(byUpper ? lower : upper);
        }
        return related;
    }

    /**
     * Adds to {@code under} the staying faces that continue a face of it on the host (across an
     * edge of the sheet) into paper the {@code piece} overlaps, below its lowest hinge, with all
     * paper below them.
     */
    private void closeOverFolds(Set<Integer> under, List<Integer> piece, Set<Integer> faces, TuckPlace place, int lowestHinge,
            Map<Integer, Integer> levelBefore) {
        ArrayDeque<Integer> open = new ArrayDeque<>(under);
        while (!open.isEmpty()) {
            int g = open.poll();
            int[] loop = loops.get(g);
            for (int k = 0; k < loop.length; k++) {
                int across = faceOfEdge.get(directed(loop[(k + 1) % loop.length], loop[k]), -1);
                if (across < 0 || hostOf[across] != hostOf[g] || faces.contains(across) || under.contains(across)
                        || place.hinges().contains(across) || levelBefore.get(across) >= lowestHinge) {
                    continue;
                }
                boolean overlapped = false;
                for (int f : piece) {
                    if (placedFaces.overlap(f, across)) {
                        overlapped = true;
                        break;
                    }
                }
                if (overlapped) {
                    under.add(across);
                    open.add(across);
                    closeDownwards(under, new ArrayDeque<>(List.of(across)), place.below(), faces, open);
                }
            }
        }
    }

    /**
     * Cuts face f along the line n·p = c: f keeps the part on the near side, a new face the
     * part beyond, which is returned. Each crossing edge gets one new vertex, shared with the
     * face across it on the sheet, which is given the vertex too so that no edge of the sheet
     * ends in the middle of another.
     */
    private int split(int f, double nx, double ny, double c, boolean onSheet, Map<Long, Integer> splitOfEdge, Edit edit) {
        int[] loop = loops.get(f);
        Isometry2 pose = poseOf.get(f);
        int n = loop.length;
        double[] d = new double[n];
        for (int i = 0; i < n; i++) {
            int v = loop[i];
            d[i] = onSheet ? nx * u(v) + ny * v(v) - c : nx * pose.x(u(v), v(v)) + ny * pose.y(u(v), v(v)) - c;
        }
        int[] withSplits = new int[2 * n];
        int[] side = new int[2 * n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            withSplits[m] = loop[i];
            side[m++] = d[i] > tolerance ? 1 : d[i] < -tolerance ? -1 : 0;
            if ((d[i] > tolerance && d[j] < -tolerance) || (d[i] < -tolerance && d[j] > tolerance)) {
                int a = loop[i];
                int b = loop[j];
                Integer split = splitOfEdge.get(undirected(a, b));
                if (split == null) {
                    double t = d[i] / (d[i] - d[j]);
                    split = addVertex(u(a) + t * (u(b) - u(a)), v(a) + t * (v(b) - v(a)));
                    splitOfEdge.put(undirected(a, b), split);
                    insertAcross(a, b, split, edit);
                }
                withSplits[m] = split;
                side[m++] = 0;
            }
        }
        int[] near = new int[m];
        int[] far = new int[m];
        int nearCount = 0;
        int farCount = 0;
        for (int i = 0; i < m; i++) {
            if (side[i] <= 0) {
                near[nearCount++] = withSplits[i];
            }
            if (side[i] >= 0) {
                far[farCount++] = withSplits[i];
            }
        }
        unregister(f);
        loops.set(f, Arrays.copyOf(near, nearCount));
        placedFaces.forget(f);
        register(f);
        int g = loops.size();
        loops.add(Arrays.copyOf(far, farCount));
        poseOf.add(pose);
        ensureFaceCapacity(g + 1);
        hostOf[g] = hostOf[f];
        originOf[g] = originOf[f];
        register(g);
        edit.reshaped.add(f);
        edit.reshaped.add(g);
        edit.parents.add(f < edit.facesBefore ? f : edit.parents.get(f - edit.facesBefore));
        stacks.get(hostOf[f]).add(g);
        return g;
    }

    /** Gives the face across edge a → b (the one holding b → a) the vertex m between b and a. */
    private void insertAcross(int a, int b, int m, Edit edit) {
        int g = faceOfEdge.get(directed(b, a), -1);
        if (g < 0) {
            return; // the strip's own border
        }
        edit.note(g);
        int[] loop = loops.get(g);
        int[] longer = new int[loop.length + 1];
        int k = 0;
        for (int i = 0; i < loop.length; i++) {
            longer[k++] = loop[i];
            if (loop[i] == b && loop[(i + 1) % loop.length] == a) {
                longer[k++] = m;
            }
        }
        faceOfEdge.remove(directed(b, a), -1);
        faceOfEdge.put(directed(b, m), g);
        faceOfEdge.put(directed(m, a), g);
        loops.set(g, longer);
        placedFaces.forget(g);
        int crease = creases.remove(undirected(a, b), -1);
        if (crease >= 0) {
            creases.put(undirected(a, m), crease);
            creases.put(undirected(m, b), crease);
        }
    }

    // ---------------------------------------------------------------- faces and stacks

    /**
     * The face a piece of the tail about to be laid as {@code loop} is folded from: the face
     * laid last, across the tail's start, where it rests on the tail's host; -1 where there is
     * none (the strip's first face, or the first on a host after a crossing).
     */
    private int tailHinge(int[] loop) {
        if (tailLifted) {
            tailLifted = false;
            int before = faceOfEdge.get(directed(loop[0], loop[loop.length - 1]), -1);
            liftedFrom = before >= 0 && hostOf[before] == tailHost ? before : -1;
            return -1;
        }
        liftedFrom = -1;
        int before = faceOfEdge.get(directed(loop[0], loop[loop.length - 1]), -1);
        return before >= 0 && hostOf[before] == tailHost ? before : -1;
    }

    /**
     * Lays a new face on {@code host}. Folded from {@code hinge} (a face of the same host, or
     * -1), it goes just over (or under) it, as paper folded about a crease lands on the layer it
     * is folded from: in the stack's order by levels, with the hinge last of its level (first,
     * under), it lies above the faces that come before the hinge and below those after. Paper
     * crossing the crease above the hinge then stays outside the fold, not between its two
     * layers (flat folding's taco-tortilla condition). Without a hinge it lands over (under)
     * every face it overlaps.
     */
    private int addFace(int[] loop, int host, Isometry2 pose, Placement placement, int hinge) {
        int f = loops.size();
        loops.add(loop);
        poseOf.add(pose);
        ensureFaceCapacity(f + 1);
        hostOf[f] = host;
        register(f);
        Stack stack = stacks.computeIfAbsent(host, h -> new Stack());
        int[] levels = hinge >= 0 ? levels(stack) : null;
        int hingeLevel = hinge >= 0 ? levels[slotOf[hinge]] : -1;
        // The new face's level is one more than the highest below it; where every face it lies
        // under stands higher still (it landed over all it overlaps, or just under a hinge with
        // room below), no other level changes, and the stack's levels are kept rather than found
        // again at the next fold (a strip folded over and over on one plane would cost the square).
        int[] known = stack.levels;
        int level = 0;
        int lowestAbove = Integer.MAX_VALUE;
        List<Integer> touching = new ArrayList<>();
        Map<Integer, Boolean> overOf = new HashMap<>();
        for (int i : stack.near(f)) {
            int g = stack.faces[i];
            if (placedFaces.overlap(f, g)) {
                boolean over = placement == Placement.OVER;
                if ((originOf[g] & SEALED) != 0) {
                    over = true;
                } else if (hinge >= 0) {
                    over = placement == Placement.OVER ? levels[i] <= hingeLevel : levels[i] < hingeLevel;
                }
                touching.add(g);
                overOf.put(g, over);
            }
        }
        if (hinge >= 0) {
            outOfFolds(f, hinge, stack, levels, touching, overOf);
        } else if (liftedFrom >= 0 && overOf.containsKey(liftedFrom)) {
            outOfLiftedFold(f, liftedFrom, stack, touching, overOf);
        }
        liftedFrom = -1;
        for (int g : touching) {
            boolean over = overOf.get(g);
            int i = slotOf[g];
            stack.above.add(over ? ((long) f << 32) | g : ((long) g << 32) | f);
            if (known != null && over) {
                level = Math.max(level, known[i] + 1);
            } else if (known != null) {
                lowestAbove = Math.min(lowestAbove, known[i]);
            }
        }
        stack.add(f);
        if (known != null && level < lowestAbove) {
            int[] grown = known.length >= stack.faces.length ? known : Arrays.copyOf(known, stack.faces.length);
            grown[stack.count - 1] = level;
            stack.levels = grown;
            stack.top = Math.max(stack.top, level);
        }
        return f;
    }

    /**
     * Keeps a new face out of the folds it overlaps: the order by levels puts it just over (or
     * under) its hinge, and above or below each other face by its level, but levels compare
     * faces of different places of a stack only loosely, and a face it lands under whose fold
     * partner (the face across a crease, on this host) it lands over would lie between the two
     * layers of their fold, reaching across the crease (taco-tortilla). So the faces it overlaps
     * that are joined by creases it reaches across go together, a chain of them as one: the new
     * face goes over all of such a group or under all of it, the side most of it already has
     * (the hinge's, where the hinge is one of them), unless that would contradict the order
     * already there (a face it lies under below one it would go over, or the other way), and
     * then the other side; where neither fits, the chain carries the paper the order puts with it
     * ({@link #carryAlong}). Turned one by one, a gadget's chain of three layers, two creases,
     * was only turned from one fold into the other. Then the new face leaves the pockets of folds
     * it does not reach across where it can ({@link #outOfPockets}).
     */
    private void outOfFolds(int f, int hinge, Stack stack, int[] levels, List<Integer> touching, Map<Integer, Boolean> overOf) {
        double[] placedF = placedFaces.polygon(f);
        Map<Integer, Integer> acrossParent = new HashMap<>();
        Set<Integer> joinedAcross = new HashSet<>();
        List<int[]> pockets = new ArrayList<>();
        for (int g : touching) {
            int[] loop = loops.get(g);
            Isometry2 pose = poseOf.get(g);
            for (int k = 0; k < loop.length; k++) {
                int a = loop[k];
                int b = loop[(k + 1) % loop.length];
                if (crease(a, b) == null) {
                    continue;
                }
                int d = faceOfEdge.get(directed(b, a), -1);
                if (d < g || !overOf.containsKey(d)) {
                    continue; // each crease once, from its face of the smaller number
                }
                if (crosses(placedF, pose.x(u(a), v(a)), pose.y(u(a), v(a)), pose.x(u(b), v(b)), pose.y(u(b), v(b)))) {
                    join(acrossParent, g, d);
                    joinedAcross.add(g);
                    joinedAcross.add(d);
                } else if (overOf.get(g) != overOf.get(d) && g != hinge && d != hinge) {
                    pockets.add(new int[] {g, d});
                }
            }
        }
        if (joinedAcross.isEmpty() && pockets.isEmpty()) {
            return;
        }
        List<Map<Integer, List<Integer>>> relations = new ArrayList<>(2); // below, above: found once needed
        Map<Integer, Boolean> forced = null;
        Map<Integer, List<Integer>> unitOf = new HashMap<>(); // each face of a group: the group
        for (List<Integer> group : groups(acrossParent, joinedAcross)) {
            for (int g : group) {
                unitOf.put(g, group);
            }
            int over = 0;
            for (int g : group) {
                over += overOf.get(g) ? 1 : 0;
            }
            if (over == 0 || over == group.size()) {
                continue;
            }
            if (relations.isEmpty()) {
                relations.add(related(stack, true));
                relations.add(related(stack, false));
            }
            forced = forced != null ? forced : forcedSides(f, hinge, touching, overOf, relations);
            if (!uniform(group, hinge, overOf, relations, forced)) {
                carryAlong(group, 2 * over >= group.size(), overOf, forced, relations);
            }
        }
        if (!pockets.isEmpty()) {
            outOfPockets(f, hinge, stack, levels, touching, pockets, unitOf, overOf, relations, forced);
        }
    }

    /**
     * The sides a new face must take, whatever its tentative sides by level: over its hinge and
     * all below it (under, and all above, for a face laid under its hinge), and, for paper that
     * reaches across its own crease with the hinge, the side of the hinge that paper is on (it
     * lies over both, or under both).
     */
    private Map<Integer, Boolean> forcedSides(int f, int hinge, List<Integer> touching, Map<Integer, Boolean> overOf,
            List<Map<Integer, List<Integer>>> relations) {
        boolean overHinge = overOf.get(hinge);
        Set<Integer> belowHinge = reachedFrom(hinge, relations.get(0));
        Set<Integer> aboveHinge = reachedFrom(hinge, relations.get(1));
        Map<Integer, Boolean> forced = new HashMap<>();
        forced.put(hinge, overHinge);
        for (int g : overHinge ? belowHinge : aboveHinge) {
            forced.put(g, overHinge);
        }
        int[] loop = loops.get(f);
        int a = loop[loop.length - 1];
        int b = loop[0];
        Isometry2 pose = poseOf.get(f);
        for (int g : touching) {
            if (g != hinge && (belowHinge.contains(g) || aboveHinge.contains(g))
                    && crosses(placedFaces.polygon(g), pose.x(u(a), v(a)), pose.y(u(a), v(a)), pose.x(u(b), v(b)), pose.y(u(b), v(b)))) {
                forced.put(g, belowHinge.contains(g));
            }
        }
        return forced;
    }

    /**
     * Where a group of fold layers cannot be put on one side of a new face without changing its
     * tentative side to other paper: the group goes to one side after all, and the paper the
     * order then puts there (below the group for over, above for under) goes with it, where none
     * of that paper's side is {@code forced} the other way; the side most of the group has, else
     * the other. A turn laid over a neighbour's turn, both folded over paper of their own, met
     * this on a random star-shaped solid.
     */
    private static void carryAlong(List<Integer> group, boolean first, Map<Integer, Boolean> overOf, Map<Integer, Boolean> forced,
            List<Map<Integer, List<Integer>>> relations) {
        for (boolean side : new boolean[] {first, !first}) {
            Set<Integer> reached = new HashSet<>(group);
            ArrayDeque<Integer> open = new ArrayDeque<>(group);
            boolean possible = true;
            while (!open.isEmpty() && possible) {
                int g = open.poll();
                Boolean must = forced.get(g);
                possible = must == null || must == side;
                for (int next : relations.get(side ? 0 : 1).getOrDefault(g, List.of())) {
                    if (reached.add(next)) {
                        open.add(next);
                    }
                }
            }
            if (possible) {
                for (int g : reached) {
                    if (overOf.containsKey(g)) {
                        overOf.put(g, side);
                    }
                }
                return;
            }
        }
    }

    /**
     * Keeps a new face out of the pockets of folds it lands in without reaching their creases
     * where its order with one layer of the fold is free: a layer neither above its hinge nor
     * below it in the stack's order, placed only by its level. Paper folded on from the new face
     * (its next turn) reaches across the pocket's crease, and would then be caught between the
     * new face's fold and the pocket's (a turn landing in the pocket of a neighbour's turn, and
     * the next fold over it). The free layer goes to the other's side, where the order allows.
     */
    private void outOfPockets(int f, int hinge, Stack stack, int[] levels, List<Integer> touching, List<int[]> pockets,
            Map<Integer, List<Integer>> unitOf, Map<Integer, Boolean> overOf, List<Map<Integer, List<Integer>>> relations,
            Map<Integer, Boolean> forcedSoFar) {
        Map<Integer, Boolean> forced = forcedSoFar;
        if (relations.isEmpty()) {
            relations.add(related(stack, true));
            relations.add(related(stack, false));
        }
        Set<Integer> bound = reachedFrom(hinge, relations.get(0));
        bound.addAll(reachedFrom(hinge, relations.get(1)));
        int hingeLevel = levels[slotOf[hinge]];
        for (int[] pocket : pockets) {
            int g = pocket[0];
            int d = pocket[1];
            boolean gBound = bound.contains(g);
            boolean dBound = bound.contains(d);
            if ((gBound && dBound) || overOf.get(g) == overOf.get(d)) {
                continue;
            }
            // Both free: the layer nearer the hinge's level keeps its side, and the other follows,
            // with the layers it goes with (those joined by creases the new face reaches across).
            boolean gKeeps = gBound || (!dBound
                    && Math.abs(levels[slotOf[g]] - hingeLevel) <= Math.abs(levels[slotOf[d]] - hingeLevel));
            List<Integer> keeper = unitOf.getOrDefault(gKeeps ? g : d, List.of(gKeeps ? g : d));
            List<Integer> follower = unitOf.getOrDefault(gKeeps ? d : g, List.of(gKeeps ? d : g));
            if (keeper == follower) {
                continue; // one group, made uniform already: the new face is not between them
            }
            boolean side = overOf.get(gKeeps ? g : d);
            if (!contradicts(follower, side, overOf, relations.get(side ? 0 : 1))) {
                for (int h : follower) {
                    overOf.put(h, side);
                }
            } else if (!gBound && !dBound && !contradicts(keeper, !side, overOf, relations.get(side ? 1 : 0))) {
                for (int h : keeper) {
                    overOf.put(h, !side);
                }
            } else {
                forced = forced != null ? forced : forcedSides(f, hinge, touching, overOf, relations);
                List<Integer> both = new ArrayList<>(keeper);
                both.addAll(follower);
                carryAlong(both, side, overOf, forced, relations);
            }
        }
    }

    /** Joins g and d in a forest of parents. */
    private static void join(Map<Integer, Integer> parent, int g, int d) {
        int rg = root(parent, g);
        int rd = root(parent, d);
        if (rg != rd) {
            parent.put(rg, rd);
        }
    }

    /** The faces {@code joined} in a forest of parents, tree by tree. */
    private static Collection<List<Integer>> groups(Map<Integer, Integer> parent, Set<Integer> joined) {
        Map<Integer, List<Integer>> groupOf = new HashMap<>();
        for (int g : joined) {
            groupOf.computeIfAbsent(root(parent, g), r -> new ArrayList<>()).add(g);
        }
        return groupOf.values();
    }

    /**
     * Puts a new face over all of {@code group} or under all of it, where the order allows: the
     * side most of it has (the hinge's, where the hinge is one of them), else the other, so long
     * as no tentative side of other paper must change, nor a side {@code forced} on one of the
     * group; whether it could. {@code relations} holds the stack's relations, downwards and
     * upwards.
     */
    private static boolean uniform(List<Integer> group, int hinge, Map<Integer, Boolean> overOf,
            List<Map<Integer, List<Integer>>> relations, Map<Integer, Boolean> forced) {
        int over = 0;
        for (int g : group) {
            over += overOf.get(g) ? 1 : 0;
        }
        boolean first = group.contains(hinge) ? overOf.get(hinge) : 2 * over >= group.size();
        for (boolean side : group.contains(hinge) ? new boolean[] {first} : new boolean[] {first, !first}) {
            boolean allowed = true;
            for (int g : group) {
                Boolean must = forced.get(g);
                allowed &= must == null || must == side;
            }
            if (allowed && !contradicts(group, side, overOf, relations.get(side ? 0 : 1))) {
                for (int g : group) {
                    overOf.put(g, side);
                }
                return true;
            }
        }
        return false;
    }

    /**
     * Keeps paper out of the flat fold between a face laid on after a lifted tail (over all it
     * overlaps, {@link #liftTail}) and the face {@code from} it runs on from, its hinge on the
     * sheet: paper over {@code from} that reaches across their crease would lie between the two
     * layers (taco-tortilla: a gadget's last turn, the strip running on into the next triangle
     * of the host, and an earlier pass over the gadget). The new face goes under such paper, and
     * under all the paper it overlaps above it, unless that contradicts the order already there.
     */
    private void outOfLiftedFold(int f, int from, Stack stack, List<Integer> touching, Map<Integer, Boolean> overOf) {
        int[] loop = loops.get(f);
        int a = loop[loop.length - 1];
        int b = loop[0];
        Isometry2 pose = poseOf.get(f);
        double ax = pose.x(u(a), v(a));
        double ay = pose.y(u(a), v(a));
        double bx = pose.x(u(b), v(b));
        double by = pose.y(u(b), v(b));
        Map<Integer, List<Integer>> aboveOf = null;
        Set<Integer> overFrom = null;
        for (int g : touching) {
            if (g == from || !overOf.get(g) || (originOf[g] & SEALED) != 0 || !crosses(placedFaces.polygon(g), ax, ay, bx, by)) {
                continue;
            }
            if (aboveOf == null) {
                aboveOf = related(stack, false);
                overFrom = reachedFrom(from, aboveOf);
            }
            if (!overFrom.contains(g)) {
                continue;
            }
            List<Integer> group = new ArrayList<>();
            for (int h : reachedFrom(g, aboveOf)) {
                if (overOf.containsKey(h)) {
                    group.add(h);
                }
            }
            group.add(g);
            if (!contradicts(group, false, overOf, aboveOf)) {
                for (int h : group) {
                    overOf.put(h, false);
                }
            }
        }
    }

    /** The faces reached from g (g not among them, unless on a cycle) through relations {@code onward}. */
    private static Set<Integer> reachedFrom(int g, Map<Integer, List<Integer>> onward) {
        Set<Integer> reached = new HashSet<>();
        ArrayDeque<Integer> open = new ArrayDeque<>(List.of(g));
        while (!open.isEmpty()) {
            for (int next : onward.getOrDefault(open.poll(), List.of())) {
                if (reached.add(next)) {
                    open.add(next);
                }
            }
        }
        return reached;
    }

    /** The root of g in a forest of parents (g itself where it has none). */
    private static int root(Map<Integer, Integer> parent, int g) {
        int r = g;
        while (parent.containsKey(r)) {
            r = parent.get(r);
        }
        return r;
    }

    /**
     * Whether a new face going over ({@code side}) or under every face of {@code group} would
     * contradict the order: over a face means over all below it ({@code onward}: the stack's
     * relations downwards), none of which may be one it lies under; under, likewise upwards.
     */
    private static boolean contradicts(List<Integer> group, boolean side, Map<Integer, Boolean> overOf,
            Map<Integer, List<Integer>> onward) {
        Set<Integer> reached = new HashSet<>(group);
        ArrayDeque<Integer> open = new ArrayDeque<>();
        for (int g : group) {
            if (overOf.get(g) != side) {
                open.add(g);
            }
        }
        while (!open.isEmpty()) {
            for (int next : onward.getOrDefault(open.poll(), List.of())) {
                if (reached.add(next)) {
                    Boolean nextOver = overOf.get(next);
                    if (nextOver != null && nextOver != side) {
                        return true;
                    }
                    open.add(next);
                }
            }
        }
        return false;
    }

    /** Whether convex polygon xy reaches across the segment (a, b): on both sides of its line, over a length of it. */
    private boolean crosses(double[] xy, double ax, double ay, double bx, double by) {
        double dx = bx - ax;
        double dy = by - ay;
        double length = Math.hypot(dx, dy);
        if (!(length > tolerance)) {
            return false;
        }
        double nx = dy / length;
        double ny = -dx / length;
        double c = nx * ax + ny * ay;
        int n = xy.length / 2;
        boolean left = false;
        boolean right = false;
        for (int k = 0; k < n; k++) {
            double side = nx * xy[2 * k] + ny * xy[2 * k + 1] - c;
            left |= side < -tolerance;
            right |= side > tolerance;
        }
        if (!(left && right)) {
            return false;
        }
        // The part of the segment inside the polygon: t in [t0, t1] along a → b.
        double t0 = 0;
        double t1 = 1;
        double orientation = Math.signum(Polygons2.twiceArea(xy, n));
        for (int k = 0; k < n && t0 < t1; k++) {
            int j = (k + 1) % n;
            double ex = xy[2 * j] - xy[2 * k];
            double ey = xy[2 * j + 1] - xy[2 * k + 1];
            // Inside: orientation × (e × (p - corner k)) >= 0, at p = a + t (b - a).
            double at = orientation * (ex * (ay - xy[2 * k + 1]) - ey * (ax - xy[2 * k]));
            double slope = orientation * (ex * dy - ey * dx);
            if (Math.abs(slope) < 1e-300) {
                if (at < 0) {
                    return false;
                }
            } else if (slope > 0) {
                t0 = Math.max(t0, -at / slope);
            } else {
                t1 = Math.min(t1, -at / slope);
            }
        }
        return (t1 - t0) * length > tolerance;
    }

    private void ensureFaceCapacity(int n) {
        if (n > hostOf.length) {
            hostOf = Arrays.copyOf(hostOf, Math.max(n, 2 * hostOf.length));
            originOf = Arrays.copyOf(originOf, hostOf.length);
            slotOf = Arrays.copyOf(slotOf, hostOf.length);
        }
    }

    private void register(int f) {
        int[] loop = loops.get(f);
        for (int i = 0; i < loop.length; i++) {
            faceOfEdge.put(directed(loop[i], loop[(i + 1) % loop.length]), f);
        }
    }

    private void unregister(int f) {
        int[] loop = loops.get(f);
        for (int i = 0; i < loop.length; i++) {
            faceOfEdge.remove(directed(loop[i], loop[(i + 1) % loop.length]), -1);
        }
    }

    /** Per-face marks for one pass over a stack, told apart by {@link #nextMark()} rather than cleared. */
    private int[] mark = new int[16];
    private int[] cutMark = new int[16];
    private int markCount;
    /** Scratch: each face's place in the stack whose levels are being found. */
    private int[] placeInStack = new int[16];

    private int nextMark() {
        if (mark.length < loops.size()) {
            mark = Arrays.copyOf(mark, Math.max(loops.size(), 2 * mark.length));
            cutMark = Arrays.copyOf(cutMark, mark.length);
        }
        return ++markCount;
    }

    /**
     * The faces of a stack directly over each (for paper landing over it) or directly under
     * each (landing under), from its relations, as compressed rows by face.
     */
    private final class Between {
        private final int[] start;
        private final int[] faces;

        Between(LongList above, Placement placement) {
            int relations = above.size();
            start = new int[loops.size() + 1];
            faces = new int[relations];
            for (int r = 0; r < relations; r++) {
                start[from(above.get(r), placement) + 1]++;
            }
            for (int f = 0; f < loops.size(); f++) {
                start[f + 1] += start[f];
            }
            int[] fill = Arrays.copyOf(start, loops.size());
            for (int r = 0; r < relations; r++) {
                long pair = above.get(r);
                int f = from(pair, placement);
                faces[fill[f]++] = placement == Placement.OVER ? (int) (pair >>> 32) : (int) pair;
            }
        }

        /** The face a relation is listed under: its lower face for paper landing over, its upper one for paper landing under. */
        private static int from(long pair, Placement placement) {
            return placement == Placement.OVER ? (int) pair : (int) (pair >>> 32);
        }

        int start(int g) {
            return start[g];
        }

        int end(int g) {
            return start[g + 1];
        }

        int face(int k) {
            return faces[k];
        }
    }

    /** The most faces next to g tried as witnesses that an order with g is implied. */
    private static final int WITNESSES = 16;

    /**
     * A stack's relations by face, both ways, indexed by the faces' places in the stack: for the
     * face in place i, the faces directly above it are {@code upper[upperStart[i] ..
     * upperStart[i + 1]]}, those directly below {@code lower[lowerStart[i] .. lowerStart[i + 1]]}.
     * Sized by the stack, not the sheet: a tuck must not cost the whole sheet.
     */
    private final class StackOrder {
        final int[] upperStart;
        final int[] upper;
        final int[] lowerStart;
        final int[] lower;

        StackOrder(Stack stack) {
            int relations = stack.above.size();
            upperStart = new int[stack.count + 1];
            lowerStart = new int[stack.count + 1];
            upper = new int[relations];
            lower = new int[relations];
            for (int r = 0; r < relations; r++) {
                long pair = stack.above.get(r);
                upperStart[slotOf[(int) pair] + 1]++;
                lowerStart[slotOf[(int) (pair >>> 32)] + 1]++;
            }
            for (int i = 0; i < stack.count; i++) {
                upperStart[i + 1] += upperStart[i];
                lowerStart[i + 1] += lowerStart[i];
            }
            int[] upperFill = Arrays.copyOf(upperStart, stack.count);
            int[] lowerFill = Arrays.copyOf(lowerStart, stack.count);
            for (int r = 0; r < relations; r++) {
                long pair = stack.above.get(r);
                int above = (int) (pair >>> 32);
                int below = (int) pair;
                upper[upperFill[slotOf[below]]++] = above;
                lower[lowerFill[slotOf[above]]++] = below;
            }
        }
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

    private int[] levels(Stack stack) {
        if (stack.levels != null) {
            return stack.levels;
        }
        // Faces by their place in the stack, and the relations as arrays (compressed rows): a
        // stack folded over and over holds hundreds of thousands of them.
        int n = stack.count;
        if (placeInStack.length < loops.size()) {
            placeInStack = new int[Math.max(loops.size(), 2 * placeInStack.length)];
        }
        int[] index = placeInStack; // only the stack's own faces are read, and all are written first
        for (int i = 0; i < n; i++) {
            index[stack.faces[i]] = i;
        }
        int relations = stack.above.size();
        int[] uppers = new int[relations];
        int[] lowers = new int[relations];
        int[] below = new int[n]; // how many faces lie directly below each, still to place
        int[] start = new int[n + 1];
        for (int r = 0; r < relations; r++) {
            long pair = stack.above.get(r);
            uppers[r] = index[(int) (pair >>> 32)];
            lowers[r] = index[(int) pair];
            below[uppers[r]]++;
            start[lowers[r] + 1]++;
        }
        for (int i = 0; i < n; i++) {
            start[i + 1] += start[i];
        }
        int[] fill = Arrays.copyOf(start, n);
        int[] over = new int[relations];
        for (int r = 0; r < relations; r++) {
            over[fill[lowers[r]]++] = uppers[r];
        }
        int[] level = new int[n];
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
                int upper = over[k];
                level[upper] = Math.max(level[upper], level[i] + 1);
                if (--below[upper] == 0) {
                    queue[tail++] = upper;
                }
            }
        }
        if (tail != n) {
            throw new IllegalStateException("the stack on host has a cycle: a face lies above itself");
        }
        int top = -1;
        for (int l : level) {
            top = Math.max(top, l);
        }
        stack.top = top;
        stack.levels = new int[stack.faces.length];
        for (int i = 0; i < n; i++) {
            stack.levels[i] = level[i];
        }
        return stack.levels;
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

    /** The faces resting on {@code host}. */
    public int[] facesOn(int host) {
        Stack stack = stacks.get(host);
        return stack == null ? new int[0] : Arrays.copyOf(stack.faces, stack.count);
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
        return faceOfEdge.get(directed(b, a), -1);
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

    private int addVertex(double u, double v) {
        if (2 * vertexCount + 2 > uv.length) {
            uv = Arrays.copyOf(uv, 2 * uv.length);
        }
        uv[2 * vertexCount] = u;
        uv[2 * vertexCount + 1] = v;
        return vertexCount++;
    }

    private static long directed(int a, int b) {
        return ((long) a << 32) | (b & 0xffffffffL);
    }

    private static long undirected(int a, int b) {
        return directed(Math.min(a, b), Math.max(a, b));
    }
}
