package ifold.sheet;

import ifold.sheet.Sheet.Crease;
import ifold.sheet.Sheet.Placement;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * A tuck: the paper resting on one host beyond a line folded under the rest of that host's
 * paper ({@link Sheet#tuck}), and where its flap goes in the stack.
 */
final class TuckPlacement {
    private TuckPlacement() {
    }

    /**
     * Tucks the paper resting on {@code host} to the right of the directed line through (px, py)
     * with direction (dx, dy) under the host's other paper: faces the line crosses are cut, the
     * part beyond it is reflected over the line and slid under what it lands below.
     *
     * @throws FoldException if nothing lies beyond the line, or the paper beyond it is joined to
     *     the rest by anything but the line (tucking it would tear the strip)
     */
    static Tuck tuck(Sheet sheet, int host, double px, double py, double dx, double dy) throws FoldException {
        if (sheet.stacks.get(host) == null) {
            throw new FoldException("no paper rests on triangle " + host);
        }
        SheetEdit edit = sheet.edit();
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
            int[] loop = sheet.loops.get(f);
            Isometry2 pose = sheet.poseOf.get(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int across = sheet.faceOfEdge.get(b, a, -1);
                if (across < 0 || moving.contains(across)) {
                    continue;
                }
                double da = nx * pose.x(sheet.u(a), sheet.v(a)) + ny * pose.y(sheet.u(a), sheet.v(a)) - c;
                double db = nx * pose.x(sheet.u(b), sheet.v(b)) + ny * pose.y(sheet.u(b), sheet.v(b)) - c;
                // On the line to twice the tolerance: the crease's ends and the line were each
                // placed to the tolerance (a 4,000-triangle torus had a turn's crease end 1.003
                // tolerances off the tuck line along the same triangle edge); far along a long
                // strip, to the tolerance its poses' rounding has grown to.
                if (Math.abs(da) > 2 * sheet.toleranceAt(sheet.u(a)) || Math.abs(db) > 2 * sheet.toleranceAt(sheet.u(b))) {
                    throw new FoldException("tucking under triangle " + host + " would tear the strip: paper beyond the line"
                            + " is joined to paper that stays by a crease off the line");
                }
            }
        }
        edit.crease(moving, Crease.TUCK);
        edit.tuckUnder(moving, Isometry2.reflection(px, py, dx, dy), nx, ny, c);
        for (int f : moving) {
            sheet.originOf[f] |= Sheet.TUCKED;
        }
        SheetEdit.Journal journal = edit.journal();
        int[] moved = moving.stream().mapToInt(Integer::intValue).sorted().toArray();
        return new Tuck(host, moved, px, py, dx, dy, journal.facesBefore(), journal.changed(), journal.loopsBefore(),
                journal.posesBefore());
    }

    /**
     * Tucks {@code faces}, resting on one host, across the fold line (nx, ny)·p = c: as
     * {@link SheetEdit#move} does with {@link Placement#UNDER}, their own order reversed, so that
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
    static void tuckUnder(SheetEdit edit, Sheet sheet, Set<Integer> faces, Isometry2 reflection, double nx, double ny, double c) {
        if (faces.isEmpty()) {
            return;
        }
        int host = sheet.hostOf[faces.iterator().next()];
        Stack stack = sheet.stacks.get(host);
        int[] levels = sheet.levels(stack);
        // Each face's level by face, in the sheet's scratch array (read only for this stack's
        // faces, all written here), and the flap marked: a boxed map of the whole stack, and a
        // set lookup for each of its faces, were a tenth of the 5,000-triangle torus's tucks.
        int[] levelOf = sheet.levelsByFace();
        for (int i = 0; i < stack.count; i++) {
            levelOf[stack.faces[i]] = levels[i];
        }
        int flap = sheet.nextMark();
        for (int f : faces) {
            sheet.mark[f] = flap;
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
                int[] loop = sheet.loops.get(open.poll());
                for (int k = 0; k < loop.length; k++) {
                    int across = sheet.faceOfEdge.get(loop[(k + 1) % loop.length], loop[k], -1);
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
            int[] loop = sheet.loops.get(f);
            Isometry2 pose = sheet.poseOf.get(f);
            boolean moves = sheet.mark[f] == flap;
            for (int k = 0; k < loop.length; k++) {
                int a = loop[k];
                int b = loop[(k + 1) % loop.length];
                // A staying face's edge matters only on the tuck line: looked up only there (the
                // lookups missed the cache for every edge of the stack).
                if (!moves && !(onLine(sheet, pose, a, nx, ny, c) && onLine(sheet, pose, b, nx, ny, c))) {
                    continue;
                }
                int across = sheet.faceOfEdge.get(b, a, -1);
                if (across < 0) {
                    continue;
                }
                if (moves && sheet.mark[across] != flap && sheet.hostOf[across] == host) {
                    int piece = pieceOf.get(f);
                    lowestHinge[piece] = Math.min(lowestHinge[piece], levelOf[across]);
                    hinges.add(across);
                    hingesOf.computeIfAbsent(piece, p -> new HashSet<>()).add(across);
                } else if (!moves && sheet.hostOf[across] != host) {
                    crossing.add(f);
                }
            }
        }
        // A strip below the lowest hinge by level, or below any hinge by the stack's order (a
        // piece whose hinges lie both at the strip's level, beside it, and above it).
        Stack.Related below = crossing.isEmpty() ? Stack.Related.NONE : Stack.related(stack, true);
        Map<Integer, Set<Integer>> overStrip = new HashMap<>();
        if (!crossing.isEmpty()) {
            Stack.Related above = Stack.related(stack, false);
            for (int strip : crossing) {
                Set<Integer> reached = new HashSet<>();
                ArrayDeque<Integer> open = new ArrayDeque<>(List.of(strip));
                while (!open.isEmpty()) {
                    for (int g : above.of(open.poll())) {
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
                boolean belowHinge = levelOf[f] < lowestHinge[piece]
                        || ownHinges.stream().anyMatch(overStrip.get(f)::contains);
                if (belowHinge && set.add(f)) {
                    open.add(f);
                }
            }
            closeDownwards(set, open, below, faces, null);
            under.add(set);
        }
        edit.move(faces, host, reflection, Placement.UNDER, new TuckPlace(pieceOf, under, below, hinges, lowestHinge), levelOf);
    }

    private static boolean onLine(Sheet sheet, Isometry2 pose, int p, double nx, double ny, double c) {
        return Math.abs(nx * pose.x(sheet.u(p), sheet.v(p)) + ny * pose.y(sheet.u(p), sheet.v(p)) - c) <= sheet.tolerance;
    }

    /**
     * Where a tuck's flap goes, piece by piece (paper beyond the line joined on the sheet, each
     * {@code pieceOf} it): above the staying faces {@code under} it (strips crossing the tuck
     * line below the piece's hinges, {@code lowestHinge} the lowest, and the paper below them,
     * through the stack's relations {@code below}), under the rest; {@code hinges} are the
     * staying faces the flap is joined to.
     */
    record TuckPlace(Map<Integer, Integer> pieceOf, List<Set<Integer>> under, Stack.Related below,
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
    static void placeTucked(Sheet sheet, Set<Integer> faces, Stack to, LongList carried, TuckPlace place, int[] levelBefore) {
        List<Set<Integer>> under = place.under();
        Map<Integer, List<Integer>> facesOfPiece = new HashMap<>();
        for (int f : faces) {
            facesOfPiece.computeIfAbsent(place.pieceOf().get(f), k -> new ArrayList<>()).add(f);
        }
        for (int piece = 0; piece < under.size(); piece++) {
            closeOverFolds(sheet, under.get(piece), facesOfPiece.getOrDefault(piece, List.of()), faces, place, place.lowestHinge()[piece],
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
        StackOrder order = new StackOrder(sheet, to);
        int[] sideOf = new int[to.count]; // by slot: +1 where f goes over, -1 under, 0 apart
        List<Integer> overlapping = new ArrayList<>();
        for (int f : faces) {
            Set<Integer> pieceUnder = under.get(place.pieceOf().get(f));
            overlapping.clear();
            for (int i : to.near(f)) {
                int g = to.faces[i];
                if (sheet.placedFaces.overlap(f, g)) {
                    sideOf[i] = (sheet.originOf[g] & Sheet.SEALED) != 0 || pieceUnder.contains(g) ? 1 : -1;
                    overlapping.add(g);
                }
            }
            for (int g : overlapping) {
                int side = sideOf[sheet.slotOf[g]];
                boolean implied = false;
                int[] next = side > 0 ? order.upper : order.lower;
                int[] start = side > 0 ? order.upperStart : order.lowerStart;
                int common = -1; // the corners of where f and g overlap (PlacedFaces.overlap), found once a face might hold it
                // A few of g's neighbours at most: the face at the foot of a tall stack of passes has
                // thousands, and recording the pair is always right, only less economical.
                int end = Math.min(start[sheet.slotOf[g] + 1], start[sheet.slotOf[g]] + WITNESSES);
                for (int k = start[sheet.slotOf[g]]; k < end && !implied; k++) {
                    int h = next[k];
                    if (sideOf[sheet.slotOf[h]] == side) {
                        common = common >= 0 ? common : sheet.placedFaces.overlapInPlace(f, g);
                        implied = common > 0 && sheet.placedFaces.containsPoints(sheet.placedFaces.polygon(h), sheet.placedFaces.overlap, common);
                    }
                }
                if (!implied) {
                    to.above.add(side > 0 ? ((long) f << 32) | g : ((long) g << 32) | f);
                }
            }
            for (int g : overlapping) {
                sideOf[sheet.slotOf[g]] = 0;
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
    static void closeDownwards(Set<Integer> under, ArrayDeque<Integer> open, Stack.Related below,
            Set<Integer> moving, ArrayDeque<Integer> added) {
        while (!open.isEmpty()) {
            for (int g : below.of(open.poll())) {
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
     * Adds to {@code under} the staying faces that continue a face of it on the host (across an
     * edge of the sheet) into paper the {@code piece} overlaps, below its lowest hinge, with all
     * paper below them.
     */
    private static void closeOverFolds(Sheet sheet, Set<Integer> under, List<Integer> piece, Set<Integer> faces, TuckPlace place, int lowestHinge,
            int[] levelBefore) {
        ArrayDeque<Integer> open = new ArrayDeque<>(under);
        while (!open.isEmpty()) {
            int g = open.poll();
            int[] loop = sheet.loops.get(g);
            for (int k = 0; k < loop.length; k++) {
                int across = sheet.faceOfEdge.get(loop[(k + 1) % loop.length], loop[k], -1);
                if (across < 0 || sheet.hostOf[across] != sheet.hostOf[g] || faces.contains(across) || under.contains(across)
                        || place.hinges().contains(across) || levelBefore[across] >= lowestHinge) {
                    continue;
                }
                boolean overlapped = false;
                for (int f : piece) {
                    if (sheet.placedFaces.overlap(f, across)) {
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

    /** The most faces next to g tried as witnesses that an order with g is implied. */
    private static final int WITNESSES = 16;

    /**
     * A stack's relations by face, both ways, indexed by the faces' places in the stack: for the
     * face in place i, the faces directly above it are {@code upper[upperStart[i] ..
     * upperStart[i + 1]]}, those directly below {@code lower[lowerStart[i] .. lowerStart[i + 1]]}.
     * Sized by the stack, not the sheet: a tuck must not cost the whole sheet.
     */
    private static final class StackOrder {
        final int[] upperStart;
        final int[] upper;
        final int[] lowerStart;
        final int[] lower;

        StackOrder(Sheet sheet, Stack stack) {
            int relations = stack.above.size();
            upperStart = new int[stack.count + 1];
            lowerStart = new int[stack.count + 1];
            upper = new int[relations];
            lower = new int[relations];
            for (int r = 0; r < relations; r++) {
                long pair = stack.above.get(r);
                upperStart[sheet.slotOf[(int) pair] + 1]++;
                lowerStart[sheet.slotOf[(int) (pair >>> 32)] + 1]++;
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
                upper[upperFill[sheet.slotOf[below]]++] = above;
                lower[lowerFill[sheet.slotOf[above]]++] = below;
            }
        }
    }
}
