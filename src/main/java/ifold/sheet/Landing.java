package ifold.sheet;

import ifold.sheet.Sheet.Placement;
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
 * Where a face laid on a sheet lands in its host's stack: just over (or under) the face it is
 * folded from, and out of the folds and pockets of the paper it overlaps (flat folding's
 * taco-tortilla condition).
 */
final class Landing {
    private final Sheet sheet;

    Landing(Sheet sheet) {
        this.sheet = sheet;
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
    int addFace(int[] loop, int host, Isometry2 pose, Placement placement, int hinge) {
        int f = sheet.loops.size();
        sheet.loops.add(loop);
        sheet.poseOf.add(pose);
        sheet.ensureFaceCapacity(f + 1);
        sheet.hostOf[f] = host;
        sheet.register(f);
        Stack stack = sheet.stacks.computeIfAbsent(host, h -> new Stack(sheet));
        int[] levels = hinge >= 0 ? sheet.levels(stack) : null;
        int hingeLevel = hinge >= 0 ? levels[sheet.slotOf[hinge]] : -1;
        // The new face's level is one more than the highest below it; where every face it lies
        // under stands higher still (it landed over all it overlaps, or just under a hinge with
        // room below), no other level changes, and the stack's levels are kept rather than found
        // again at the next fold (a strip folded over and over on one plane would cost the square).
        int[] known = stack.levels;
        int level = 0;
        int lowestAbove = Integer.MAX_VALUE;
        List<Integer> touching = new ArrayList<>();
        Map<Integer, Boolean> overOf = new HashMap<>();
        List<Integer> leftUnder = null;
        for (int i : stack.near(f)) {
            int g = stack.faces[i];
            if (sheet.placedFaces.overlap(f, g)) {
                boolean over = placement == Placement.OVER;
                if ((sheet.originOf[g] & Sheet.SEALED) != 0) {
                    over = true;
                } else if (hinge >= 0) {
                    over = placement == Placement.OVER ? levels[i] <= hingeLevel : levels[i] < hingeLevel;
                    if (!over && (sheet.originOf[g] & Sheet.LEFT_UNDER) != 0 && (sheet.originOf[hinge] & Sheet.LEFT_UNDER) == 0) {
                        leftUnder = leftUnder != null ? leftUnder : new ArrayList<>();
                        leftUnder.add(g);
                    }
                }
                touching.add(g);
                overOf.put(g, over);
            }
        }
        if (leftUnder != null) {
            overLeftPaper(f, hinge, stack, leftUnder, overOf);
        }
        if (hinge >= 0) {
            outOfFolds(f, hinge, stack, levels, touching, overOf);
        } else if (sheet.liftedFrom >= 0 && overOf.containsKey(sheet.liftedFrom)) {
            outOfLiftedFold(f, sheet.liftedFrom, stack, touching, overOf);
        }
        sheet.liftedFrom = -1;
        for (int g : touching) {
            boolean over = overOf.get(g);
            int i = sheet.slotOf[g];
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
     * Puts a new face over paper of an earlier triangle of the host ({@link Sheet#leaveUnder})
     * that its level put it under, where later paper already lies over that paper or the new
     * face reaches across a crease joining it to other paper it overlaps: over each such face g,
     * unless the order holds g above the hinge, or puts below g paper the new face lies under
     * (the order would have a cycle). Under g, the new face would close a chain from the later
     * paper over g back to itself through faces of different places, which levels do not see;
     * or, reaching across g's crease, lie between g and the layer across it where the level put
     * that layer below (a turn between an earlier gadget's layers, on turned box 1 of
     * bench/random-solids).
     */
    private void overLeftPaper(int f, int hinge, Stack stack, List<Integer> leftUnder, Map<Integer, Boolean> overOf) {
        Stack.Related downwards = Stack.related(stack, true);
        Stack.Related upwards = Stack.related(stack, false);
        Set<Integer> aboveHinge = reachedFrom(hinge, upwards);
        for (int g : leftUnder) {
            if ((laterPaperAbove(g, upwards) || foldReachedAcross(f, g, overOf)) && !aboveHinge.contains(g)
                    && !contradicts(List.of(g), true, overOf, downwards)) {
                overOf.put(g, true);
            }
        }
    }

    /** Whether new face f reaches across a crease joining face g to other paper it overlaps. */
    private boolean foldReachedAcross(int f, int g, Map<Integer, Boolean> overOf) {
        double[] placedF = sheet.placedFaces.polygon(f);
        int[] loop = sheet.loops.get(g);
        Isometry2 pose = sheet.poseOf.get(g);
        for (int k = 0; k < loop.length; k++) {
            int a = loop[k];
            int b = loop[(k + 1) % loop.length];
            if (sheet.crease(a, b) != null && overOf.containsKey(sheet.faceOfEdge.get(b, a, -1))
                    && crosses(placedF, pose.x(sheet.u(a), sheet.v(a)), pose.y(sheet.u(a), sheet.v(a)),
                            pose.x(sheet.u(b), sheet.v(b)), pose.y(sheet.u(b), sheet.v(b)))) {
                return true;
            }
        }
        return false;
    }

    /** Whether the order holds face g below a face laid since its paper was left under ({@link Sheet#leaveUnder}). */
    private boolean laterPaperAbove(int g, Stack.Related upwards) {
        Set<Integer> reached = new HashSet<>();
        ArrayDeque<Integer> open = new ArrayDeque<>(List.of(g));
        while (!open.isEmpty()) {
            for (int next : upwards.of(open.poll())) {
                if ((sheet.originOf[next] & (Sheet.LEFT_UNDER | Sheet.SEALED)) == 0) {
                    return true;
                }
                if (reached.add(next)) {
                    open.add(next);
                }
            }
        }
        return false;
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
        double[] placedF = sheet.placedFaces.polygon(f);
        Map<Integer, Integer> acrossParent = new HashMap<>();
        Set<Integer> joinedAcross = new HashSet<>();
        List<int[]> pockets = new ArrayList<>();
        for (int g : touching) {
            int[] loop = sheet.loops.get(g);
            Isometry2 pose = sheet.poseOf.get(g);
            for (int k = 0; k < loop.length; k++) {
                int a = loop[k];
                int b = loop[(k + 1) % loop.length];
                if (sheet.crease(a, b) == null) {
                    continue;
                }
                int d = sheet.faceOfEdge.get(b, a, -1);
                if (d < g || !overOf.containsKey(d)) {
                    continue; // each crease once, from its face of the smaller number
                }
                if (crosses(placedF, pose.x(sheet.u(a), sheet.v(a)), pose.y(sheet.u(a), sheet.v(a)), pose.x(sheet.u(b), sheet.v(b)), pose.y(sheet.u(b), sheet.v(b)))) {
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
        List<Stack.Related> relations = new ArrayList<>(2); // below, above: found once needed
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
                relations.add(Stack.related(stack, true));
                relations.add(Stack.related(stack, false));
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
            List<Stack.Related> relations) {
        boolean overHinge = overOf.get(hinge);
        Set<Integer> belowHinge = reachedFrom(hinge, relations.get(0));
        Set<Integer> aboveHinge = reachedFrom(hinge, relations.get(1));
        Map<Integer, Boolean> forced = new HashMap<>();
        forced.put(hinge, overHinge);
        for (int g : overHinge ? belowHinge : aboveHinge) {
            forced.put(g, overHinge);
        }
        int[] loop = sheet.loops.get(f);
        int a = loop[loop.length - 1];
        int b = loop[0];
        Isometry2 pose = sheet.poseOf.get(f);
        for (int g : touching) {
            if (g != hinge && (belowHinge.contains(g) || aboveHinge.contains(g))
                    && crosses(sheet.placedFaces.polygon(g), pose.x(sheet.u(a), sheet.v(a)), pose.y(sheet.u(a), sheet.v(a)), pose.x(sheet.u(b), sheet.v(b)), pose.y(sheet.u(b), sheet.v(b)))) {
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
            List<Stack.Related> relations) {
        for (boolean side : new boolean[] {first, !first}) {
            Set<Integer> reached = new HashSet<>(group);
            ArrayDeque<Integer> open = new ArrayDeque<>(group);
            boolean possible = true;
            while (!open.isEmpty() && possible) {
                int g = open.poll();
                Boolean must = forced.get(g);
                possible = must == null || must == side;
                for (int next : relations.get(side ? 0 : 1).of(g)) {
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
            Map<Integer, List<Integer>> unitOf, Map<Integer, Boolean> overOf, List<Stack.Related> relations,
            Map<Integer, Boolean> forcedSoFar) {
        Map<Integer, Boolean> forced = forcedSoFar;
        if (relations.isEmpty()) {
            relations.add(Stack.related(stack, true));
            relations.add(Stack.related(stack, false));
        }
        Set<Integer> bound = reachedFrom(hinge, relations.get(0));
        bound.addAll(reachedFrom(hinge, relations.get(1)));
        int hingeLevel = levels[sheet.slotOf[hinge]];
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
                    && Math.abs(levels[sheet.slotOf[g]] - hingeLevel) <= Math.abs(levels[sheet.slotOf[d]] - hingeLevel));
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
            List<Stack.Related> relations, Map<Integer, Boolean> forced) {
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
     * overlaps, {@link Sheet#liftTail}) and the face {@code from} it runs on from, its hinge on the
     * sheet: paper over {@code from} that reaches across their crease would lie between the two
     * layers (taco-tortilla: a gadget's last turn, the strip running on into the next triangle
     * of the host, and an earlier pass over the gadget). The new face goes under such paper, and
     * under all the paper it overlaps above it, unless that contradicts the order already there.
     */
    private void outOfLiftedFold(int f, int from, Stack stack, List<Integer> touching, Map<Integer, Boolean> overOf) {
        int[] loop = sheet.loops.get(f);
        int a = loop[loop.length - 1];
        int b = loop[0];
        Isometry2 pose = sheet.poseOf.get(f);
        double ax = pose.x(sheet.u(a), sheet.v(a));
        double ay = pose.y(sheet.u(a), sheet.v(a));
        double bx = pose.x(sheet.u(b), sheet.v(b));
        double by = pose.y(sheet.u(b), sheet.v(b));
        Stack.Related aboveOf = null;
        Set<Integer> overFrom = null;
        for (int g : touching) {
            if (g == from || !overOf.get(g) || (sheet.originOf[g] & Sheet.SEALED) != 0 || !crosses(sheet.placedFaces.polygon(g), ax, ay, bx, by)) {
                continue;
            }
            if (aboveOf == null) {
                aboveOf = Stack.related(stack, false);
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
    private static Set<Integer> reachedFrom(int g, Stack.Related onward) {
        Set<Integer> reached = new HashSet<>();
        ArrayDeque<Integer> open = new ArrayDeque<>(List.of(g));
        while (!open.isEmpty()) {
            for (int next : onward.of(open.poll())) {
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
            Stack.Related onward) {
        Set<Integer> reached = new HashSet<>(group);
        ArrayDeque<Integer> open = new ArrayDeque<>();
        for (int g : group) {
            if (overOf.get(g) != side) {
                open.add(g);
            }
        }
        while (!open.isEmpty()) {
            for (int next : onward.of(open.poll())) {
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
        if (!(length > sheet.tolerance)) {
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
            left |= side < -sheet.tolerance;
            right |= side > sheet.tolerance;
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
        return (t1 - t0) * length > sheet.tolerance;
    }
}
