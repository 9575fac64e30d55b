package ifold.wrap;

import static ifold.wrap.PathPlan.firstDirection;
import static ifold.wrap.PathPlan.likelyFaces;
import static ifold.wrap.PathPlan.overlapped;
import static ifold.wrap.PathPlan.passes;
import static ifold.wrap.Wrap.BYTES_PER_FACE;
import static ifold.wrap.Wrap.cornerName;
import static ifold.wrap.Wrap.cornersText;
import static ifold.wrap.Wrap.position;

import ifold.geom.SlantedEdges;
import ifold.geom.Tolerance;
import ifold.mesh.IndexedPolygons;
import ifold.refine.FacePreparation;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet.Placement;
import ifold.sheet.Sheet;
import ifold.sheet.Tuck;
import ifold.wrap.Wrap.FaceLimitException;
import ifold.wrap.Wrap.Kind;
import ifold.wrap.Wrap.Step;
import ifold.wrap.Wrap.Strip;
import ifold.wrap.Wrap.TailMove;
import ifold.wrap.Wrap.Watcher;
import ifold.wrap.Wrap.WrapException;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The folding of one strip along one path: for each triangle its passes and turns, the gadget
 * and the fold over the edge to the next, and the tucks once the strip leaves a host, each fold
 * recorded as a step ({@link Wrap} plans the paths and the width; this folds them).
 */
final class StripFolding {
    /**
     * The fewest tucks on one triangle before giving up; a host with a corner sharper than
     * 0.72° gets more ({@link #maxTucks}).
     */
    public static final int MAX_TUCKS = 1000;

    /**
     * The most tucks on one triangle of a host whose smallest corner is {@code degrees}: the
     * naïve tucks bounce a flap between the edges of a corner of θ degrees about 180/θ times
     * (601 on a triangle of the 0.3° corner in docs/wrap.md), so four times that, and never
     * fewer than {@link #MAX_TUCKS}. Past it the tucks are running away, not converging.
     */
    public static int maxTucks(double degrees) {
        return (int) Math.min(Integer.MAX_VALUE / 2, Math.max(MAX_TUCKS, Math.ceil(4 * 180 / degrees)));
    }

    /**
     * The sharpest corner of a host whose tucks have been seen to finish, in degrees: a 0.1°
     * corner wraps (5,416 tucks), and a needle of 0.0115° corners tears the strip at every width.
     */
    static final double SHARPEST_TUCKED = 0.1;

    private final IndexedPolygons mesh;
    private final PathPlan plan;
    private final int strip;
    private final double w;
    private final double thickness;
    private final double tolerance;
    private final double margin;
    private final List<Step> steps;
    private Sheet sheet;
    private int pathIndex;
    /** The caption's detail for the folds being made, and the pass they belong to. */
    private String detail = "";
    private final Map<String, String> details = new HashMap<>();
    private String passNote = "";
    private final int maxFaces;
    private Watcher watcher = Watcher.NONE;
    /** Triangles of earlier paths, and of all paths: for the watcher. */
    private int firstDone;
    private int totalTriangles;
    private final HostPieces pieces;
    private final HostFrame[] hostFrames;
    /** Per triangle of the mesh: from its frame (the planner's) into its host's (the sheet's). */
    private final Isometry2[] toHost;
    /** The triangle being wrapped's frame into its host's. */
    private Isometry2 intoHost;
    /**
     * Where the triangle being wrapped stops short of a sharp corner of its host at an end of its
     * base: the x of its frame that no turn, fold back or end passes towards that end (at the
     * roll's stop, that no fold's paper passes, save for {@link #stopSlack}); NaN where none.
     */
    private double stopX = Double.NaN;
    /** The end of the base that {@link #stopX} keeps clear: +1 its end at x = base length, -1 at x = 0. */
    private int stopSide;
    /**
     * Whether {@link #stopX} is where the roll round the apex stops covering the host's whole
     * width ({@link #stopShort}): there a fold's paper, not only its crease, keeps to it, save
     * for {@link #stopSlack}.
     */
    private boolean stopsAtRoll;
    /**
     * How much nearer the rolled apex than {@link #stopX} a fold's paper may reach: as much as
     * the host's far edge, at the host's corner to the base, comes nearer along the base.
     */
    private double stopSlack;
    /**
     * The end of the triangle being wrapped's base that is a true sharp corner of its host and
     * that it covers, not stopping short of it (+1 at x = base length, -1 at x = 0, 0 none), and
     * that end's x.
     */
    private int sharpSide;
    private double sharpX;
    /**
     * The true sharp vertex (a spike's apex) the strip begins at and ends rolled round
     * ({@link #rollApex}), -1 none; and for each host round it, how far from it the roll covers
     * the host's whole width, where that host's triangles stop short of it, and how far its
     * crease into the host reaches along the edge it crosses ({@link ApexRoll.Reach}).
     */
    private int rolledApex = -1;
    private Map<Integer, ApexRoll.Reach> rollCovers;
    /** The path's triangles (from 0) on each host, found when a triangle at a sharp corner first asks. */
    private Map<Integer, List<Integer>> pathOnHost;

    StripFolding(IndexedPolygons mesh, PathPlan plan, int strip, double width, double thickness, double tolerance, List<Step> steps,
            int maxFaces, HostPieces pieces, HostFrame[] hostFrames, Isometry2[] toHost) {
        this.pieces = pieces;
        this.hostFrames = hostFrames;
        this.toHost = toHost;
        this.maxFaces = maxFaces;
        this.mesh = mesh;
        this.plan = plan;
        this.strip = strip;
        this.w = width;
        this.thickness = thickness;
        this.tolerance = tolerance;
        // Just beyond the edges: far enough to see, and to clear the caps of the turns.
        this.margin = Math.max(width / 10, 2 * thickness);
        this.steps = steps;
    }

    Strip fold() throws FoldException, WrapException {
        int[] after = new int[plan.m];
        rolledApex = rollApex();
        for (int i = 0; i < plan.m; i++) {
            pathIndex = i;
            intoHost = toHost[plan.first + i];
            wrapTriangle(i);
            // The paper is tucked once the strip leaves the host: until then the tail lies on it.
            int host = hostOf(i);
            if (i + 1 == plan.m || hostOf(i + 1) != host) {
                tuckAll(i);
                sheet.settle(host);
            }
            after[i] = sheet.faceCount();
            watcher.wrapped(firstDone + i + 1, totalTriangles);
        }
        return new Strip(sheet, plan.first, plan.m, after);
    }

    private int hostOf(int i) {
        return pieces.hostOf[plan.first + i];
    }

    /** The triangle being wrapped, in words: its place on the path and its corners, and the fold being made. */
    String where() {
        return String.format(Locale.ROOT, "triangle %d of %d on the path (%s)%s", pathIndex + 1, plan.m,
                cornersText(mesh, plan.first + pathIndex), detail == null || detail.isEmpty() ? "" : ", " + detail);
    }

    private void wrapTriangle(int i) throws FoldException, WrapException {
        HostFrame frame = plan.frames[i];
        SlantedEdges edges = new SlantedEdges(frame.baseLength(), frame.apexX(), frame.altitude());
        double h = edges.h();
        boolean last = i == plan.m - 1;
        int k = passes(h, w);
        int d = firstDirection(plan, i, w);
        double[] hostCorners = hostFrames[hostOf(i)].corners();
        stopShort(i, frame, hostCorners);
        sharpEnd(i, frame, hostCorners);
        double drop = rolledDrop(i);
        boolean skip = drop > 0;
        if (skip) {
            h -= drop;
            k = passes(h, w);
        }
        double[] bottom = last || skip ? null : evenedUp(edges, k, d, i, hostCorners);
        if (bottom != null) {
            k = bottom.length;
        } else {
            bottom = new double[k];
            for (int j = 0; j < k; j++) {
                bottom[j] = h - (j + 1) * w;
            }
            if (!last || rolledApex >= 0 || lastTurnsShort(frame, k, h, hostCorners)) {
                int shortTurn = shortTurn(edges, k, d, hostCorners);
                for (int j = shortTurn + 1; j < k; j++) {
                    bottom[j] = (k - 1 - j) * w;
                }
            }
        }
        int host = plan.first + i;
        if (i == 0) {
            double start = d > 0 ? edges.leftmost(bottom[0], bottom[0] + w) - margin : edges.rightmost(bottom[0], bottom[0] + w) + margin;
            Isometry2 pose = d > 0 ? Isometry2.placement(start, bottom[0], 0, false)
                    : Isometry2.placement(start, bottom[0] + w, Math.PI, false);
            sheet = new Sheet(w, thickness, tolerance, hostOf(i), intoHost.after(pose));
        } else {
            checkEntry(d, bottom[0]);
        }
        int passes = k + (last && overlapped(plan, w) ? 1 : 0);
        // Where the strip runs back over the last pass to the corner it leaves by, the turn into
        // that pass, at the same corner, stands back from it (runsBackToCorner).
        double lastTurnFrom = !last && runsBackToCorner(i, k, d, hostCorners) ? SHORT_OF_CORNER * w
                : last && rolledApex >= 0 && k >= 2 && (k % 2 == 1 ? d : -d) != towardsRolledApex(i) ? rolledTurnFrom(frame) : 0;
        for (int j = 0; j + 1 < k; j++) {
            // Joined, not formatted: a wrap makes hundreds of thousands of these notes, and a
            // formatter each was a hundredth of what the 5,000-triangle torus allocated.
            passNote = "pass " + (j + 1) + " of " + passes;
            turn(edges, d, bottom[j], bottom[j + 1], j == k - 2 ? lastTurnFrom : 0, host);
            d = -d;
        }
        passNote = "pass " + k + " of " + passes;
        if (last && rolledApex >= 0) {
            if (d != towardsRolledApex(i)) {
                detail = "the strip turns back to roll round the apex";
                tailFold(Kind.OVERLAP, host, endOfPass(edges, d, bottom[k - 1]), 0, 0, 1, Placement.OVER);
                d = -d;
            }
            // The host is finished first: a flap tucked along an edge the roll then crosses
            // would be folded round the roll's crossing (a tuck's bend under its cap, 0.04 T
            // through it, on bench/corners' 5° and 10° spikes).
            tuckAll(i);
            roll(i);
        } else if (last) {
            double end = endOfPass(edges, d, bottom[k - 1]);
            if (overlapped(plan, w)) {
                detail = "the strip turns back to end at corner " + cornerName(plan.ends.end());
                tailFold(Kind.OVERLAP, host, end, 0, 0, 1, Placement.OVER);
                d = -d;
                end = endOfPass(edges, d, bottom[k - 1]);
            }
            detail = "";
            record(Kind.END, host, sheet.endTail(intoHost.x(end, 0), intoHost.y(end, 0), intoHost.dx(0, 1), intoHost.dy(0, 1)));
        } else {
            leave(i, edges, d);
        }
    }

    /**
     * The vertex the strip's end is rolled round, -1 none: the vertex v the first triangle is
     * entered at, where v is a true sharp vertex (angle sum under 90°) and the first triangle's
     * corner there is under the preparation's target (no preparation widens it), and the last
     * triangle's base ends at v ({@link Seam} tries the strip begun there). Paper kept on one face
     * by tucks lays 180°/θ layers where a side of the strip passes a corner of θ (72 on the
     * shared spike's 2.5° faces, each face having one); rolled round the apex, over the solid's
     * edges there, the strip's end corner lays 90°/Θ, Θ the vertex's angle sum (12 on the spike),
     * and the other triangles stop short of the apex where the roll covers their host. Else the
     * end of the last triangle's base at a needle face's tip, where the vertex is no spike
     * ({@link ApexRoll#needleEnd}, {@link ApexRoll#needleCoverage}): the roll covers the needle
     * alone, whose other triangles stop short of the tip, the first among them.
     */
    private int rollApex() {
        if (plan.m < 2) {
            return -1;
        }
        int v = plan.start[0];
        int last = plan.m - 1;
        if ((plan.baseFrom[last] == v || plan.baseTo[last] == v) && ApexRoll.sharpStart(mesh, plan.corners[0], v)) {
            rollCovers = ApexRoll.coverage(mesh, plan, pieces, v, last, w);
            return rollCovers == null ? -1 : v;
        }
        // A needle's tip at a vertex that is no spike: the last pass runs along the needle's edge
        // into it, and the roll covers the needle alone.
        for (int end : new int[] {plan.baseFrom[last], plan.baseTo[last]}) {
            int other = end == plan.baseFrom[last] ? plan.baseTo[last] : plan.baseFrom[last];
            if (ApexRoll.needleEnd(mesh, plan.corners[last], end, other)) {
                rollCovers = ApexRoll.needleCoverage(mesh, plan, pieces, hostFrames, end, last, w);
                if (rollCovers != null) {
                    return end;
                }
            }
        }
        return -1;
    }

    /**
     * How far short of the rolled apex a triangle of path triangle i's host stops: where the roll
     * stops covering the host's whole width. Nearer, the turns stopped there lie under the caps
     * of the roll's first creases over the host's edges, which reach as far (the spike's second,
     * 15 widths along an edge, crossed a tuck's bend along it 0.48 T deep with the turns at 0.9
     * of it, 4 pairs of caps; 8 at 0.3 of a width over the tangent of the face's angle).
     */
    private double rollReach(int i) {
        return rollCovers.get(hostOf(i)).whole();
    }

    /**
     * How far below its apex path triangle i's passes begin, where it is entered at the rolled
     * apex: the first triangle, or one the path comes back to the apex by (an irregular
     * pentagonal pyramid's path enters its apex twice; begun at the apex there, its first pass
     * crossed the apex with a side of the strip, under the roll's creases: 63 crossing pairs of
     * caps). Its passes begin where the whole band lies as far from the apex as the roll covers
     * the host's whole width or more (a band of height s below the apex reaches s / sin α along
     * an edge at α to the base); 0 for any other triangle.
     */
    private double rolledDrop(int i) {
        if (rolledApex < 0 || plan.start[i] != rolledApex || !rollCovers.containsKey(hostOf(i))) {
            return 0;
        }
        HostFrame frame = plan.frames[i];
        double h = frame.altitude();
        double x0 = frame.apexX();
        double sineFrom = h / Math.hypot(x0, h);
        double sineTo = h / Math.hypot(frame.baseLength() - x0, h);
        double drop = rollReach(i) * Math.min(sineFrom, sineTo);
        if (i > 0) {
            // Where a side runs along the host's edge that the roll first crosses into the host
            // by, the band meets that edge no nearer than that crease's cap reaches, farther
            // than R: nearer, the first pass, wider than the face there, was tucked over that
            // edge under the cap (the pentagonal pyramid: 4 crossing pairs of caps, 1.26 T deep).
            // Not the first triangle's: its host is the roll's own, entered last, and the spikes
            // so begun were left bare by their apex (coverage 1 − 2·10⁻⁵).
            ApexRoll.Reach reach = rollCovers.get(hostOf(i));
            for (int end : new int[] {plan.baseFrom[i], plan.baseTo[i]}) {
                if (ApexRoll.alongEntered(mesh, rolledApex, reach, end)) {
                    drop = Math.max(drop, reach.entering() * (end == plan.baseFrom[i] ? sineFrom : sineTo));
                }
            }
        }
        return drop;
    }

    /**
     * Where above the base the turn into the last pass of the last triangle lies beyond its edge
     * from the rolled apex, where that pass runs away from the apex and the strip back along it
     * to be rolled: the run back covers the band along the base up to the apex, so the turn need
     * not reach it. Its creases a width (and the margin) past where that edge leaves the band,
     * the farthest the pass before still covers the triangle above the band from: its corner
     * beyond the edge (the host's), tucked along it, then starts where the cap of the roll's
     * first crease over that edge ends, w / sin φ along it. Turned at the band's top, the tuck's
     * bend lay under that cap, 3 or 4 pairs of caps 0.04 T deep on bench/corners' 5° and 10°
     * spikes; turned at the apex, 4 pairs at 3°; 1.3 widths past, a hole (coverage 0.99976).
     */
    private double rolledTurnFrom(HostFrame frame) {
        double run = towardsRolledApex(plan.m - 1) < 0 ? frame.apexX() : frame.baseLength() - frame.apexX();
        return w + (w + margin) * frame.altitude() / run;
    }

    /** The direction (+1 along x, -1 against) of path triangle i's base towards the rolled apex, an end of it. */
    private int towardsRolledApex(int i) {
        return plan.baseFrom[i] == rolledApex ? -1 : 1;
    }

    /**
     * Rolls the strip's end round the rolled apex, its last pass (of path triangle i) running
     * into it with a side through it: the tail is folded over the line of the host's edge at the
     * apex that runs back into the strip from there (each crease through the apex, at the
     * angles the faces sum to from that side: 1.25°, 3.75°, … on the shared spike), onto the host
     * across, and so on round, until the next such edge would lie at 90° or more; then the strip
     * ends square through the apex. Each piece is a wedge of a face at the apex, under the strip's
     * far side, and lands over what it meets: 90°/Θ layers at the apex, Θ the angle sum.
     */
    private void roll(int i) throws FoldException, WrapException {
        double[] apexP = position(mesh, rolledApex);
        int cameFrom = -1;
        // At most one fold a degree of the 90° rolled, for faces of a degree: a guard, not a limit
        // met (36 folds on the spike, 90 on the 1° one of bench/corners).
        for (int round = 0; round < 10000; round++) {
            int host = sheet.tailHost();
            HostFrame f = hostFrames[host];
            int[] cs = pieces.corners[host];
            int n = cs.length;
            int ka = -1;
            for (int k = 0; k < n; k++) {
                if (cs[k] == rolledApex) {
                    ka = k;
                }
            }
            Isometry2 pose = sheet.tailPose();
            Isometry2 inv = pose.inverse();
            double ax = f.localX(apexP);
            double ay = f.localY(apexP);
            // The side of the strip through the apex, and into the strip from it.
            double va = inv.y(ax, ay);
            int s = va < w / 2 ? 1 : -1;
            int next = -1;
            for (int c : new int[] {cs[(ka + 1) % n], cs[(ka + n - 1) % n]}) {
                if (c == cameFrom) {
                    continue;
                }
                double[] cp = position(mesh, c);
                double du = inv.dx(f.localX(cp) - ax, f.localY(cp) - ay);
                double dv = inv.dy(f.localX(cp) - ax, f.localY(cp) - ay);
                // Back along the strip from the apex and into it: the edge the tail crosses next.
                // Not one along the strip's side (a needle's edge under the last pass, rounded
                // either way): no fold crosses the strip there.
                if (du < 0 && s * dv > Tolerance.RELATIVE_EQUALITY * -du) {
                    next = c;
                }
            }
            if (next < 0) {
                detail = "the strip's end rolled round the apex";
                record(Kind.END, plan.first + i, sheet.endTail(ax, ay, pose.dx(0, 1), pose.dy(0, 1)));
                return;
            }
            int across = ApexRoll.hostAcross(pieces, host, rolledApex, next);
            if (across < 0) {
                throw new IllegalStateException("no host across the edge " + rolledApex + "-" + next + " of the rolled apex");
            }
            HostFrame g = hostFrames[across];
            double[] cp = position(mesh, next);
            Isometry2 development = Isometry2.taking(ax, ay, f.localX(cp), f.localY(cp), g.localX(apexP), g.localY(apexP), g.localX(cp), g.localY(cp));
            int hostBefore = sheet.tailHost();
            Isometry2 before = sheet.tailPose();
            detail = "roll round the apex";
            int face = sheet.crossTail(ax, ay, f.localX(cp) - ax, f.localY(cp) - ay, across, development);
            recordTail(Kind.EDGE_CROSSING, plan.first + i, face, hostBefore, before, true);
            cameFrom = next;
        }
        throw new IllegalStateException("the roll does not end");
    }

    /**
     * Whether the last triangle of a path, whose k passes a width apart from its apex would reach
     * beyond its base, takes a short turn as the others do, its last pass lying on the base: where
     * the base lies on its host's edge. The overhang would be tucked under there, all along the
     * base and, where the base ends at a corner of the host, bounced there with the turn into it:
     * on the tetrahedron, 8 of the 13 layers at the deepest point, a corner of the host the first
     * and last triangles share. Where the base lies inside the host the overhang lies flat beside
     * it, and the passes stay a width apart (the shared hex_prism, whose last triangle fans from
     * a hexagon's corner, had 23 layers rather than 22 with the short turn). A lone triangle
     * (the demos: its last pass may be laid back over itself) is wrapped as before.
     */
    private boolean lastTurnsShort(HostFrame frame, int k, double h, double[] host) {
        if (plan.m == 1 || k < 2) {
            return false;
        }
        // The middle of the base, pushed out by half the overhang: off the host where the base lies on its edge.
        double out = -Math.max(margin, k * w - h) / 2;
        return !insideConvex(host, intoHost.x(frame.baseLength() / 2, out), intoHost.y(frame.baseLength() / 2, out));
    }

    /**
     * Whether triangle i's k passes, the first running in direction d, bring its last pass away
     * from the end of its base it leaves by, where that end is a corner of its host of about
     * 60° or of 100° to 120° ({@link #standsBackAt}). The strip then folds back at the other
     * end and runs back over the whole last pass to that corner, where it turns into the next
     * triangle, the gadget's crease through the corner: the run back covers the triangle's tip
     * there, and the turn into the last pass, at the same corner, need not. Placed against the
     * base it reached round the corner, off both the host's edges, and was tucked into it, 6 of
     * the 10 layers at the deepest point of the tetrahedron, octahedron and icosahedron (the
     * tip of a triangle of 90°, 30° and 60° at a corner of a face, left by that corner, its
     * three passes running the last towards the face's centre), the run back and its gadget the
     * other 4. So that turn lies beyond the slanted edge from {@link #SHORT_OF_CORNER} of a
     * width above the base, as for a band that high ({@link #turn}).
     */
    private boolean runsBackToCorner(int i, int k, int d, double[] host) {
        if (k < 2) {
            return false;
        }
        int towardsExit = plan.start[i + 1] == plan.baseTo[i] ? 1 : -1;
        int lastDirection = k % 2 == 1 ? d : -d;
        return lastDirection != towardsExit
                && standsBackAt(cornerAngle(towardsExit > 0 ? plan.baseTo[i] : plan.baseFrom[i], hostOf(i), host));
    }

    /**
     * How far above the base the turn into a last pass that the strip runs back over to a
     * corner ({@link #runsBackToCorner}) lies beyond the slanted edge, in widths. On the
     * tetrahedron, octahedron and icosahedron 0.2 to 0.7 give 9 layers with coverage 1 (the
     * tetrahedron's OBJ 3 % more faces than before at 0.2 to 0.6, 3 % fewer at 0.7), 0.8 and
     * more 10, the turn then on another triangle's by the face's edge.
     */
    static final double SHORT_OF_CORNER = 0.5;

    /**
     * Whether the turn into a last pass run back over to a host's corner of {@code degrees}
     * stands back from it ({@link #runsBackToCorner}): at about 60° ({@link #nearSixty}), and
     * from 100° to 120° (the dodecahedron's 108°: 13 -> 12 layers). Not wider: the shared
     * house's 130° corners 14 -> 16 (figure3's 159° 20 -> 18); nor at any corner: the cube
     * 13 -> 15, house 16, long_box 15, and the 576-triangle torus 3 crossing pairs.
     */
    static boolean standsBackAt(double degrees) {
        return nearSixty(degrees) || degrees >= 100 && degrees <= 120;
    }

    /**
     * The bottoms of the passes of triangle i when its k passes, the first running in direction
     * d, would bring the last towards the end of its base the strip does not leave by, and the
     * fold back there would lie off the host over other triangles' gadgets or tucked flaps (a
     * pile of the fold backs of the triangles fanning at a corner, tucked under there): k + 1
     * passes, two of their turns shifting by less than a width, each by half of what one short
     * turn would, their gadgets lying flat on the host and on no other triangle's gadget. Where
     * that end is a corner of the host, the fold back would reach round the corner, off both its
     * edges, and be tucked there onto the turns of the triangles fanning at it (on the
     * tetrahedron, 6 of the 11 layers at the deepest point): there the passes are evened up
     * whatever lies there, by the two turns nearest the middle whose gadgets lie on the host and
     * on no other's, else by the two nearest the middle (not where the gadget of one of those
     * lies off the host beyond two of its edges, round a corner). Null where the last pass runs the right
     * way, where the fold back at the wrong end lies on the host or on no pile and that end is no
     * corner of the host, on a host with a corner under 20° unless the wrong end is that corner
     * and the triangle does not stop short of it ({@link #stopShort}: evened up there as at a
     * corner), or where no two turns have their gadgets so. A triangle that stops short of a
     * sharp corner and leaves by it is evened up the other way: its last pass runs away from
     * that corner, the fold back lying at the other end; where it stops where the roll round
     * that corner stops covering its host ({@link #stopsAtRoll}), into the corner, to the stop.
     */
    private double[] evenedUp(SlantedEdges edges, int k, int d, int i, double[] host) {
        int towardsExit = plan.start[i + 1] == plan.baseTo[i] ? 1 : -1;
        int lastDirection = k % 2 == 1 ? d : -d;
        // Only where fold backs pile up: where the one at the wrong end would be tucked, over paper
        // of other triangles' gadgets or tucks already there. Everywhere, the torus of 5,000
        // triangles made 674,259 faces rather than 641,752 (more than the default limit) for no
        // layer fewer: its small hosts have their fold backs apart.
        // Left by a sharp corner it stops short of (the next triangle entered there): its last
        // pass runs away from the corner and the strip back along it to the turn into the next,
        // rather than into the corner and a fold back beyond it, so that its last pass, the fold
        // back and the next first pass are not three sides of the strip round the corner (a
        // square pyramid of 2.5° faces had two such corners of a face, 216 layers, now 74).
        // At the roll's stop the other way: the next triangle begins short of the apex too
        // (rolledDrop), its first pass and the turn into it beyond the stop, and a last pass run
        // away from the apex and back to that turn left the band between them bare (the irregular
        // pentagonal pyramid: coverage 1 − 9·10⁻⁷); run into the apex, it reaches the stop.
        boolean leavesBySharp = !Double.isNaN(stopX) && plan.start[i + 1] == (stopSide > 0 ? plan.baseTo[i] : plan.baseFrom[i]);
        if (leavesBySharp ? k < 2 || (lastDirection == towardsExit) == stopsAtRoll
                : k < 2 || lastDirection == towardsExit || gadgetOnHost(edges, lastDirection, 0, w, host)) {
            return null;
        }
        // At a corner of the host: the fold back would reach round it, off both its edges, and the
        // passes are evened up whatever lies there (the tetrahedron, octahedron and icosahedron
        // 11 -> 10 layers, figure3 24 -> 20).
        double wrongCorner = cornerAngle(lastDirection > 0 ? plan.baseTo[i] : plan.baseFrom[i], hostOf(i), host);
        // At a true sharp corner that this triangle covers (it does not stop short of it): the last
        // pass and the fold back would each reach round the corner with a side of the strip, where
        // the turn into a last pass running away from it is one side; each side there is about
        // 180°/θ layers of flaps bounced between the corner's edges (the shared spike's faces 144
        // layers by the apex, 80 evened up).
        boolean sharpEnd = wrongCorner < FacePreparation.TARGET_ANGLE && Double.isNaN(stopX);
        boolean atCorner = leavesBySharp || sharpEnd || roundsCorner(wrongCorner);
        if (!atCorner && clearOf(gadgetRegion(edges, lastDirection, 0, w), hostOf(i), true)) {
            return null;
        }
        if (!sharpEnd && !leavesBySharp && smallestAngle(host) < FacePreparation.TARGET_ANGLE) {
            // A true sharp corner of the solid, which no preparation widens: its tucks fold the
            // paper about lines by its convex edges, where nested folds have no room to stand
            // apart, and the turns moved put two of them on one line there (on the shared spike,
            // a pair of caps lay on each other, a thousandth of a thickness wide). Left as it was,
            // but at the corner itself (above).
            return null;
        }
        double h = edges.h();
        int passes = k + 1;
        double half = (h - (k - 1) * w) / 2;
        // The turns whose gadgets lie on the host as the passes would lie a width apart, and on no
        // gadget of another triangle, nearest the middle first. Over another's gadget, a gadget's
        // fold could have to land inside the other's fold and reach across its crease, which no
        // order of the layers allows (the long boxes' end faces met that).
        int middle = (passes - 2) / 2;
        List<Integer> onHost = new ArrayList<>();
        // At a corner of about 60°, a gadget whose bottom lies along the host's edge (the lowest
        // turn's, the base along the edge) is on the host to the tolerance: decided by rounding,
        // the icosahedron's faces counted it off where the tetrahedron's and octahedron's counted
        // it on, and took the two turns by the apex instead, a gadget on the gadgets where two
        // triangles leave by the face's centre (10 layers there). Elsewhere as it was: at wider
        // corners and over piles so counted, t_prism's pairs in one plane were 61 rather than 38
        // and the 576-triangle torus had one.
        double onEdge = nearSixty(wrongCorner) ? tolerance : 0;
        for (int j = 0; j + 1 < passes; j++) {
            if (gadgetOnHost(edges, turnSide(j, d), h - (j + 2) * w, h - j * w, host, onEdge)) {
                onHost.add(j);
            }
        }
        onHost.sort((a, b) -> Integer.compare(Math.abs(a - middle), Math.abs(b - middle)));
        List<Integer> chosen = new ArrayList<>();
        for (int j : onHost) {
            if (chosen.size() < 2 && clearOf(gadgetRegion(edges, turnSide(j, d), h - (j + 2) * w, h - j * w), hostOf(i), false)) {
                chosen.add(j);
            }
        }
        if (atCorner) {
            // Over other gadgets, then off the host, rather than round the corner; but a gadget
            // off the host beyond two of its edges goes round a corner itself, tucked twice there
            // with the gadgets of the triangles fanning at it, and the triangle is left as it was.
            // At a strip wider than half the widest every turn of a few passes reaches off the
            // host: on the 320-triangle icosphere two triangles' gadgets so tucked at a face's
            // corner, their hinges far apart in the stack, had the flaps of one tuck interleave
            // (at 0.75 of the widest, 828 violations of the layer order, 25 layers).
            for (int j : onHost) {
                if (chosen.size() < 2 && !chosen.contains(j)) {
                    chosen.add(j);
                }
            }
            for (int j = 0; chosen.size() < 2 && j + 1 < passes; j++) {
                int nearest = -1;
                for (int t = 0; t + 1 < passes; t++) {
                    if (!chosen.contains(t) && (nearest < 0 || Math.abs(t - middle) < Math.abs(nearest - middle))) {
                        nearest = t;
                    }
                }
                if (edgesBeyond(gadgetRegion(edges, turnSide(nearest, d), h - (nearest + 2) * w, h - nearest * w), host) > 1) {
                    return null;
                }
                chosen.add(nearest);
            }
        }
        if (chosen.size() < 2) {
            return null;
        }
        int first = Math.min(chosen.get(0), chosen.get(1));
        int second = Math.max(chosen.get(0), chosen.get(1));
        double[] bottom = new double[passes];
        for (int j = 0; j < passes; j++) {
            bottom[j] = j <= first ? h - (j + 1) * w : j <= second ? h - j * w - half : (passes - 1 - j) * w;
        }
        // Where they lie with the passes so shifted.
        for (int j : atCorner ? new int[0] : new int[] {first, second}) {
            if (!gadgetOnHost(edges, turnSide(j, d), bottom[j + 1], bottom[j] + w, host)
                    || !clearOf(gadgetRegion(edges, turnSide(j, d), bottom[j + 1], bottom[j] + w), hostOf(i), false)) {
                return null;
            }
        }
        return bottom;
    }

    /**
     * How many edges of the convex polygon {@code host} (counter-clockwise, x y pairs) some
     * corner of the quadrilateral {@code region} lies beyond, by more than the tolerance.
     */
    private int edgesBeyond(double[] region, double[] host) {
        int n = host.length / 2;
        int beyond = 0;
        for (int a = 0; a < n; a++) {
            int b = (a + 1) % n;
            double ex = host[2 * b] - host[2 * a];
            double ey = host[2 * b + 1] - host[2 * a + 1];
            double slack = tolerance * Math.hypot(ex, ey);
            boolean out = false;
            for (int q = 0; q < region.length && !out; q += 2) {
                out = ex * (region[q + 1] - host[2 * a + 1]) - ey * (region[q] - host[2 * a]) < -slack;
            }
            beyond += out ? 1 : 0;
        }
        return beyond;
    }

    /**
     * Whether a fold back round a host's corner of {@code degrees} is evened up whatever lies
     * there: at a corner of about 60°, where two triangles of the refinement fan with 30° corners
     * (the tetrahedron's, octahedron's and icosahedron's faces), and at corners of 100° and wider
     * (the dodecahedron's 108°, hex_prism's 120°, figure3's); not at or near right angles (the
     * polycubes' and the tori's near-square hosts: a polycube of 6 cubes 18 -> 20 layers, the
     * torus of 5,000 triangles 686,076 faces, past the default limit; with corners from 95° the
     * 576-triangle torus had a pair in one plane), nor at the 45° of square_frame's (24 -> 26).
     */
    static boolean roundsCorner(double degrees) {
        return nearSixty(degrees) || degrees >= 100;
    }

    /** Whether a host's corner of {@code degrees} is one of about 60°, where two triangles of the refinement fan with 30° corners. */
    static boolean nearSixty(double degrees) {
        return degrees >= 50 && degrees <= 80;
    }

    /** The angle in degrees of the host's corner at vertex v of the mesh (its corners {@code c}), NaN where v is none. */
    private double cornerAngle(int v, int host, double[] c) {
        int[] corners = pieces.corners[host];
        for (int k = 0; k < corners.length; k++) {
            if (corners[k] == v) {
                return angleAt(c, k);
            }
        }
        return Double.NaN;
    }

    /** The region a gadget beyond the slanted edge on {@code side}, from height {@code low} to {@code top}, takes, in the host's frame. */
    private double[] gadgetRegion(SlantedEdges edges, int side, double low, double top) {
        double bottom = Math.max(0, low);
        double reach = margin + 2 * w;
        double atBottom = side > 0 ? edges.right(bottom) : edges.left(bottom);
        double atTop = side > 0 ? edges.right(top) : edges.left(top);
        double[] triangleFrame = {atBottom, bottom, atBottom + side * reach, bottom, atTop + side * reach, top, atTop, top};
        double[] region = new double[8];
        for (int k = 0; k < 8; k += 2) {
            region[k] = intoHost.x(triangleFrame[k], triangleFrame[k + 1]);
            region[k + 1] = intoHost.y(triangleFrame[k], triangleFrame[k + 1]);
        }
        return region;
    }

    /**
     * Whether a region of the host overlaps no face of a turn gadget there, nor ({@code tucked})
     * any tucked flap (none before the first triangle).
     */
    private boolean clearOf(double[] region, int host, boolean tucked) {
        if (sheet == null) {
            return true;
        }
        for (int f : sheet.facesNear(host, region)) {
            if (sheet.laidAfter(f) == Sheet.Crease.GADGET || tucked && sheet.tucked(f)) {
                double[] gadget = sheet.placed(f);
                if (Polygons2.overlap(region, 4, gadget, gadget.length / 2, sheet.tolerance())) {
                    return false;
                }
            }
        }
        return true;
    }

    /** The side (+1 along x, -1 against) of the slanted edge that turn j lies beyond, the first pass running in direction d. */
    private static int turnSide(int j, int d) {
        return j % 2 == 0 ? d : -d;
    }

    /** Whether a gadget beyond the slanted edge on {@code side}, from height {@code low} to {@code top}, lies on the host. */
    private boolean gadgetOnHost(SlantedEdges edges, int side, double low, double top, double[] host) {
        return gadgetOnHost(edges, side, low, top, host, 0);
    }

    /** The same, a gadget within {@code slack} outside the host's edges counted on it (none: strictly as computed). */
    private boolean gadgetOnHost(SlantedEdges edges, int side, double low, double top, double[] host, double slack) {
        for (double y : new double[] {Math.max(0, low), top}) {
            double x = side > 0 ? edges.right(y) : edges.left(y);
            double beyond = x + side * (margin + 2 * w);
            double px = intoHost.x(beyond, y);
            double py = intoHost.y(beyond, y);
            if (slack > 0 ? !insideConvex(host, px, py, slack) : !insideConvex(host, px, py)) {
                return false;
            }
        }
        return true;
    }

    /**
     * Which turn of a triangle's k passes, the first running in direction d, shifts by less
     * than a width (the first pass runs along the apex, the last along the exit edge, the
     * rest a width apart): the one after pass j. Its gadget of four folds reaches two widths
     * beyond the slanted edge; where that lies on the host (a coplanar neighbour) it stays
     * flat there, where it lies beyond the host's edge it is tucked under, and at a corner of
     * the host tucked twice: the cube's faces had 17 of their 24 layers from gadgets of four
     * triangles fanning at one corner, each turning at the last pass, by the base's corner.
     * So: the turn nearest the middle whose gadget lies on the host; else the middle one.
     */
    private int shortTurn(SlantedEdges edges, int k, int d, double[] host) {
        int middle = (k - 2) / 2;
        int best = -1;
        for (int j = 0; j + 1 < k; j++) {
            boolean onHost = gadgetOnHost(edges, turnSide(j, d), (k - 2 - j) * w, edges.h() - j * w, host);
            if (onHost && (best < 0 || Math.abs(j - middle) < Math.abs(best - middle))) {
                best = j;
            }
        }
        return best < 0 ? middle : best;
    }

    /** Whether (x, y) lies inside the counter-clockwise convex polygon {@code c}, or within {@code slack} outside an edge. */
    private static boolean insideConvex(double[] c, double x, double y, double slack) {
        int n = c.length / 2;
        for (int a = 0; a < n; a++) {
            int b = (a + 1) % n;
            double ex = c[2 * b] - c[2 * a];
            double ey = c[2 * b + 1] - c[2 * a + 1];
            if (ex * (y - c[2 * a + 1]) - ey * (x - c[2 * a]) < -slack * Math.hypot(ex, ey)) {
                return false;
            }
        }
        return true;
    }

    /** Whether (x, y) lies inside the counter-clockwise convex polygon {@code c} (x, y pairs). */
    private static boolean insideConvex(double[] c, double x, double y) {
        int n = c.length / 2;
        for (int a = 0; a < n; a++) {
            int b = (a + 1) % n;
            if ((c[2 * b] - c[2 * a]) * (y - c[2 * a + 1]) - (c[2 * b + 1] - c[2 * a + 1]) * (x - c[2 * a]) < 0) {
                return false;
            }
        }
        return true;
    }

    /** Where a pass in the band [y, y + w] running in direction d ends: just beyond the slanted edge ahead. */
    private double endOfPass(SlantedEdges edges, int d, double y) {
        return stopped(d, d > 0 ? edges.rightmost(y, y + w) + margin : edges.leftmost(y, y + w) - margin);
    }

    /** A fold at x of a pass running in direction d, moved back to {@link #stopX} where it would pass it. */
    private double stopped(int d, double x) {
        return stopped(d, x, 0);
    }

    /**
     * The same for a fold whose paper reaches {@code beyond} past its crease in direction d (a
     * turn's 45° fold and the band it lays, or its gadgets' band: a width): where the stop is the
     * roll's ({@link #stopsAtRoll}) that paper keeps to it too; elsewhere the crease alone.
     */
    private double stopped(int d, double x, double beyond) {
        if (Double.isNaN(stopX) || d != stopSide) {
            return x;
        }
        double limit = stopsAtRoll ? stopX + d * (stopSlack - beyond) : stopX;
        return d > 0 ? Math.min(x, limit) : Math.max(x, limit);
    }

    /**
     * Sets {@link #stopX} for triangle i: where an end V of its base is a corner of its host
     * under {@link #STOPS_SHORT_BELOW} (a true sharp corner of the solid), its base lies
     * inside the host, and another triangle of the host covers the host's
     * whole width near V (one entered at V, whose first passes run across the corner, or one
     * whose base lies along the host's edge from V, whose last pass spans the host there):
     * {@link #STOP_SHORT} of the distance from V at which a strip's width along one of the
     * corner's edges spans the corner. Its turns towards V would lie beyond V, and each piece
     * of paper there bounces between the corner's edges about 180°/θ times, laying as many
     * layers (on the shared spike, 216 of its 218 layers were the flaps of such turns). One
     * that leaves by V runs its last pass away from V ({@link #evenedUp}) and back.
     */
    private void stopShort(int i, HostFrame frame, double[] hostCorners) {
        stopX = Double.NaN;
        stopsAtRoll = false;
        if (rolledApex >= 0 && (i > 0 || plan.start[0] != rolledApex) && (plan.baseFrom[i] == rolledApex || plan.baseTo[i] == rolledApex)
                && rollCovers.containsKey(hostOf(i))) {
            double reach = rollReach(i);
            stopSide = plan.baseTo[i] == rolledApex ? 1 : -1;
            stopX = stopSide > 0 ? frame.baseLength() - reach : reach;
            // The turns' paper keeps to the stop, not only their creases: a turn's 45° fold laid a
            // width of paper nearer the apex, beyond the host's edge there, and its tuck's bend lay
            // under the cap of the roll's crease over that edge (a tetrahedral spike 12 high with
            // its apex off centre: 12 crossing pairs of caps, 0.98 T deep, R − w to R from the
            // apex). And the roll covers the host's far edge only to R, which lies nearer along
            // the base by the host's corner there: folds at R left a sliver by that edge bare
            // (coverage 1 − 1.4·10⁻⁹ on the shared spike with the turns kept so).
            stopsAtRoll = true;
            stopSlack = reach * (1 - Math.cos(Math.toRadians(cornerAngle(rolledApex, hostOf(i), hostCorners))));
            if (plan.start[0] != rolledApex) {
                // A needle's tip (ApexRoll.needleEnd): the last pass covers the needle's far edge
                // only to R, where a turn stopped at R, its 45° fold cutting the corner by that
                // edge, covers it from half a width farther out (tet15b's 1.3° needle, rolled
                // before its knife's edge ruled the roll out: a sliver bare, 5·10⁻⁸ of the area;
                // half a width of slack 1.7·10⁻¹², a width none).
                stopSlack = Math.max(stopSlack, NEEDLE_STOP_SLACK * w);
            }
            return;
        }
        if (!baseInsideHost(i, frame, hostCorners)) {
            return;
        }
        for (int side : new int[] {-1, 1}) {
            int v = side > 0 ? plan.baseTo[i] : plan.baseFrom[i];
            double degrees = cornerAngle(v, hostOf(i), hostCorners);
            if (degrees < STOPS_SHORT_BELOW && coveredAt(i, v, hostCorners)) {
                double reach = STOP_SHORT * w / Math.tan(Math.toRadians(degrees));
                stopX = side > 0 ? frame.baseLength() - reach : reach;
                stopSide = side;
                return;
            }
        }
    }

    /** Sets {@link #sharpSide} for triangle i, once {@link #stopShort} has set whether it stops short. */
    private void sharpEnd(int i, HostFrame frame, double[] hostCorners) {
        sharpSide = 0;
        for (int side : new int[] {-1, 1}) {
            int v = side > 0 ? plan.baseTo[i] : plan.baseFrom[i];
            if (Double.isNaN(stopX) && cornerAngle(v, hostOf(i), hostCorners) < FacePreparation.TARGET_ANGLE) {
                sharpSide = side;
                sharpX = side > 0 ? frame.baseLength() : 0;
            }
        }
    }

    /**
     * How near a sharp corner of its host a triangle stopped short of it turns, as a share of
     * the distance at which a strip's width along one of the corner's edges spans the corner.
     * On the shared spike 0.1 to 0.5 cover the surface and give the same layers; at 0.75 a
     * sliver by the apex is left bare (coverage 0.9999999).
     */
    static final double STOP_SHORT = 0.5;

    /**
     * How much nearer a needle's rolled tip than where its last pass stops covering the needle's
     * whole width a stopped fold's paper may reach, in widths ({@link #stopShort}): one, the most
     * a stopped turn's 45° fold cuts off by the needle's far edge.
     */
    static final double NEEDLE_STOP_SLACK = 1;

    /**
     * The corners, in degrees, at which triangles stop short ({@link #stopShort}): an eighth of
     * 180°, a little past the preparation's target of 20° (no corner it leaves is sharper). At
     * the target itself the tucks still piled up: tetrahedral spikes of 20.1° and 20.5° faces
     * laid 29 layers, 26 of them tucks, 21° 22 and 22° 21; stopping short they lay 18, 18, 18 and
     * 16, and 16 at 22.4°; at 23° the wrap does as well without (20). No model of models/ or the
     * shared polyhedra has a corner between, and each wraps the same to the byte.
     */
    static final double STOPS_SHORT_BELOW = 22.5;

    /** Whether path triangle i's base lies inside its host rather than along the host's edge. */
    private boolean baseInsideHost(int i, HostFrame frame, double[] hostCorners) {
        Isometry2 into = toHost[plan.first + i];
        double x = frame.baseLength() / 2;
        return insideConvex(hostCorners, into.x(x, -margin), into.y(x, -margin));
    }

    /**
     * Whether another triangle of path triangle i's host, with a corner at vertex v, covers the
     * host's whole width near v: one entered at v, or one whose base lies along the host's edge.
     */
    private boolean coveredAt(int i, int v, double[] hostCorners) {
        if (pathOnHost == null) {
            // Once, and only for a path with a triangle at a sharp corner: a walk of the path for
            // each such triangle would cost a needle of many corners the square of its triangles.
            pathOnHost = new HashMap<>();
            for (int j = 0; j < plan.m; j++) {
                pathOnHost.computeIfAbsent(hostOf(j), host -> new ArrayList<>()).add(j);
            }
        }
        for (int j : pathOnHost.get(hostOf(i))) {
            if (j == i || (plan.baseFrom[j] != v && plan.baseTo[j] != v && plan.start[j] != v)) {
                continue;
            }
            if (plan.start[j] == v || !baseInsideHost(j, plan.frames[j], hostCorners)) {
                return true;
            }
        }
        return false;
    }

    /**
     * How far the tail coming in may stray from the first pass it must lie along, relative: a
     * check that the planner's frames agree, far above the rounding of the poses composed fold
     * after fold, not a tolerance of the geometry.
     */
    private static final double ENTRY_SLACK = 1e-6;

    /** The tail came in over the edge before: it must lie along the first pass, running in direction d. */
    private void checkEntry(int d, double bottom) {
        Isometry2 pose = intoHost.inverse().after(sheet.tailPose());
        double along = pose.dx(1, 0);
        double across = pose.dy(1, 0);
        double edgeY = pose.y(sheet.tailStart(false), 0);
        double expected = d > 0 ? bottom : bottom + w;
        if (Math.abs(along - d) > ENTRY_SLACK || Math.abs(across) > ENTRY_SLACK || Math.abs(edgeY - expected) > ENTRY_SLACK * Math.max(1, w)) {
            throw new IllegalStateException(String.format(Locale.ROOT,
                    "the strip came into triangle %d off its first pass (direction %.3g %.3g, edge at %.6g, expected %.6g)",
                    pathIndex + 1, along, across, edgeY, expected));
        }
    }

    /**
     * A turn beyond a slanted edge from the pass in band [y, y + w] running in direction d to the
     * band [next, next + w], just beyond that edge over the heights from {@code from} (where
     * above next: short of the corner the edge makes with the base) to y + w.
     */
    private void turn(SlantedEdges edges, int d, double y, double next, double from, int host) throws FoldException, WrapException {
        double low = Math.max(next, from);
        double x1 = stopped(d, d > 0 ? edges.rightmost(low, y + w) + margin : edges.leftmost(low, y + w) - margin, w);
        if (d == sharpSide && Math.abs(x1 - d * margin - sharpX) <= Tolerance.RELATIVE_EQUALITY * w) {
            // The turn into the pass along the base, at a true sharp corner this triangle covers:
            // its creases meet at the corner itself, no margin beyond it. Paper beyond the corner,
            // however little, reaches round it and bounces there (the shared spike 81 layers with
            // a margin of a hundredth of a width, 74 with none; the 1° spike 198 and 180, the
            // 180/θ of one side of the strip).
            x1 = sharpX;
        }
        double shift = y - next;
        if (Math.abs(shift - w) <= Tolerance.RELATIVE_EQUALITY * w) {
            // A valley fold lays the strip back across itself along the edge, a mountain fold
            // one width on lays it flat beside the pass it left, running back.
            detail = passNote + ": turn, 45° valley fold";
            tailFold(Kind.ZIGZAG_TURN, host, x1, y + w, d, -1, Placement.OVER);
            detail = passNote + ": turn, 45° mountain fold";
            double[] corner = tailCorner(x1 + d * w, y);
            tailFold(Kind.ZIGZAG_TURN, host, corner[0], corner[1], -d, -1, Placement.UNDER);
            return;
        }
        // Two 90° turn gadgets: down a vertical band [x1, x1 + w] beyond the edge, then back
        // along the next pass; the fold across the vertical band sets where the next pass lies.
        double middle = x1 + d * w / 2;
        detail = passNote + ": shift by less than a width, two 90° gadgets";
        tailFold(Kind.TURN_GADGET, host, x1 + d * w, 0, 0, 1, Placement.OVER);
        tailFold(Kind.TURN_GADGET, host, middle, y + w / 2, -d, -1, Placement.OVER);
        tailFold(Kind.TURN_GADGET, host, 0, next, 1, 0, Placement.OVER);
        tailFold(Kind.TURN_GADGET, host, middle, next + w / 2, -d, 1, Placement.UNDER);
    }

    /** From the last pass of triangle i (band [0, w], direction d) into the first pass of triangle i + 1. */
    private void leave(int i, SlantedEdges edges, int d) throws FoldException, WrapException {
        HostFrame here = plan.frames[i];
        HostFrame there = plan.frames[i + 1];
        int host = plan.first + i;
        double[] a = position(mesh, plan.baseFrom[i]);
        double[] b = position(mesh, plan.baseTo[i]);
        Isometry2 development = Isometry2.taking(0, 0, here.baseLength(), 0,
                there.localX(a), there.localY(a), there.localX(b), there.localY(b));
        Isometry2 back = development.inverse();
        int dNext = firstDirection(plan, i + 1, w);
        double centre = there.altitude() - rolledDrop(i + 1) - w / 2;
        double cx = back.x(0, centre);
        double cy = back.y(0, centre);
        double ox = back.dx(dNext, 0);
        double oy = back.dy(dNext, 0);
        if (!(oy < 0)) {
            throw new IllegalStateException("the next triangle's first pass does not run away from the edge");
        }
        // The gadget's turn crease: through where the two bands' centre lines meet, along the
        // line that reflects the strip running back (-d) onto the next pass's direction.
        double t = (w / 2 - cy) / oy;
        double meetX = cx + t * ox;
        double lx = -d + ox;
        double ly = oy;
        double reach = Math.abs(w / 2 * lx / ly);
        double fold = d > 0 ? Math.max(stopped(d, edges.rightmost(0, w) + margin), meetX + reach)
                : Math.min(stopped(d, edges.leftmost(0, w) - margin), meetX - reach);
        detail = "fold back across the strip";
        tailFold(Kind.TURN_GADGET, host, fold, 0, 0, 1, Placement.OVER);
        detail = "turn to run along the next triangle's first pass";
        tailFold(Kind.TURN_GADGET, host, meetX, w / 2, lx, ly, Placement.OVER);
        detail = "";
        int nextHost = hostOf(i + 1);
        if (nextHost == hostOf(i)) {
            // The next triangle lies in this one's plane, on the same host: the strip runs on
            // flat, over the paper it leaves, as it would over the edge.
            sheet.liftTail();
            sheet.leaveUnder(hostOf(i));
            return;
        }
        Isometry2 next = toHost[plan.first + i + 1];
        tailCross(Kind.EDGE_CROSSING, host, 0, 0, 1, 0, nextHost, next.after(development).after(intoHost.inverse()));
        // The crease over the edge must lie on the edge itself: paper beyond its ends would be
        // joined to paper on both triangles' excess, which no tuck could then fold away.
        Isometry2 pose = next.inverse().after(sheet.tailPose());
        double edgeLength = here.baseLength();
        // The first pass of the next triangle runs with one side through the corner the strip
        // enters by, an end of the edge: that side meets the edge at its end, to twice the
        // tolerance across the strip (a crease's end is snapped to the one before it within
        // the tolerance, and the corner is placed to it), which a side at a small angle θ to
        // the edge stretches along it by 1 / sin θ. Tori of 4,000 to 5,000 triangles met
        // corners 1.0 to 1.2 tolerances beyond their edges' ends, and were refused. Far along
        // a long strip, to the tolerance its poses' rounding has grown to (the cube at width
        // 1e-4 was refused here, three quarters of its 60,000 along).
        double sine = Math.abs(back.dy(pose.dx(1, 0), pose.dy(1, 0)));
        for (boolean side : new boolean[] {false, true}) {
            double u = sheet.tailStart(side);
            double slack = 2 * sheet.toleranceAt(u) / Math.max(sine, 1e-3);
            double v = side ? w : 0;
            double x = back.x(pose.x(u, v), pose.y(u, v));
            if (x < -slack || x > edgeLength + slack) {
                throw new FoldException(String.format(Locale.ROOT,
                        "triangle %d of %d on the path (%s): the strip would cross the edge to the next triangle beyond its end",
                        i + 1, plan.m, cornersText(mesh, host)));
            }
        }
    }

    /**
     * Tucks the paper resting on triangle i's host beyond the host's edges under it, the edge
     * with paper farthest beyond it first.
     */
    private void tuckAll(int i) throws FoldException, WrapException {
        int host = hostOf(i);
        double[] c = hostFrames[host].corners();
        int n = c.length / 2;
        int limit = maxTucks(smallestAngle(c));
        for (int tucks = 0; ; tucks++) {
            int edge = -1;
            double farthest = sheet.tolerance();
            for (int e = 0; e < n; e++) {
                double beyond = farthestBeyond(host, c, e);
                if (beyond > farthest) {
                    farthest = beyond;
                    edge = e;
                }
            }
            if (edge < 0) {
                return;
            }
            if (tucks == limit) {
                throw new WrapException(String.format(Locale.ROOT, "triangle %d of %d on the path (%s): the excess is not"
                        + " hidden after %d tucks: the naive tuck-under bounces paper between the edges of a corner as"
                        + " sharp as %.2g degrees; a narrower strip may help", i + 1, plan.m, cornersText(mesh, plan.first + i),
                        limit, smallestAngle(c)));
            }
            int from = edge;
            int to = (edge + 1) % n;
            checkLimit(sheet.tuckCutsPast(maxFaces, host, c[2 * from], c[2 * from + 1], c[2 * to] - c[2 * from], c[2 * to + 1] - c[2 * from + 1]));
            Tuck tuck;
            try {
                tuck = sheet.tuck(host, c[2 * from], c[2 * from + 1], c[2 * to] - c[2 * from], c[2 * to + 1] - c[2 * from + 1]);
            } catch (FoldException e) {
                double corner = smallestAngle(c);
                if (corner >= SHARPEST_TUCKED) {
                    throw e;
                }
                // Say what to change: no width helps here (each tears, or passes the face limit).
                throw new FoldException(String.format(Locale.ROOT, "%s; a corner of %.2g degrees is sharper than the naive"
                        + " tuck-under can hide paper in (iFold wraps corners of %s degrees and wider, at any width): widen it",
                        e.getMessage(), corner, SHARPEST_TUCKED));
            }
            steps.add(new Step(Kind.TUCK, strip, plan.first + i, pathIndex, plan.m, -1, tuck, sheet.faceCount(), null,
                    shared("tuck " + (tucks + 1) + ": excess folded under " + edgeName(i, host, from, to))));
            checkFaces();
        }
    }

    /** A lone triangle's edge by the corners the user named A, B and C; any other "an edge". */
    private String edgeName(int i, int host, int from, int to) {
        if (plan.m != 1) {
            return "along an edge";
        }
        int[] corners = pieces.corners[host];
        String a = null;
        String b = null;
        for (int k = 0; k < 3; k++) {
            a = plan.corners[i][k] == corners[from] ? cornerName(k) : a;
            b = plan.corners[i][k] == corners[to] ? cornerName(k) : b;
        }
        return a != null && b != null ? "along edge " + a + b : "along an edge";
    }

    /** A convex polygon's smallest angle in degrees, from its corners in its frame. */
    private static double smallestAngle(double[] c) {
        double smallest = 180;
        for (int k = 0; k < c.length / 2; k++) {
            smallest = Math.min(smallest, angleAt(c, k));
        }
        return smallest;
    }

    /** A convex polygon's angle at corner k in degrees, from its corners in its frame. */
    private static double angleAt(double[] c, int k) {
        int n = c.length / 2;
        int a = (k + 1) % n;
        int b = (k + n - 1) % n;
        double ux = c[2 * a] - c[2 * k];
        double uy = c[2 * a + 1] - c[2 * k + 1];
        double vx = c[2 * b] - c[2 * k];
        double vy = c[2 * b + 1] - c[2 * k + 1];
        return Math.toDegrees(Math.abs(Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy)));
    }

    /** How far the paper on the host reaches beyond edge e of the triangle (corners counter-clockwise: outside is to the right). */
    private double farthestBeyond(int host, double[] c, int e) {
        int from = e;
        int to = (e + 1) % (c.length / 2);
        double dx = c[2 * to] - c[2 * from];
        double dy = c[2 * to + 1] - c[2 * from + 1];
        double length = Math.hypot(dx, dy);
        return sheet.farthestBeyond(host, c[2 * from], c[2 * from + 1], dy / length, -dx / length);
    }

    /**
     * Where the paper has the point (x, y) of the triangle's frame that a turn's two creases
     * share: the tail's start on the side nearest it, mapped by the tail's pose, where that
     * lies within a quarter width of it; else (x, y). The mountain crease goes
     * through the paper's own corner rather than the designed one: the two differ by rounding
     * in the poses, the engine snaps the crease's end to the corner, and each turn's fold about
     * a line that missed its crease by that much moved the paper on by it; over thousands of
     * passes (a 10 × 10 × 0.03 plate's triangles) the paper fell past a tolerance behind its
     * design, and the turn was refused as crossing the crease before it.
     */
    private double[] tailCorner(double x, double y) {
        Isometry2 pose = intoHost.inverse().after(sheet.tailPose());
        double[] best = {x, y};
        double nearest = w / 4; // the other side's start lies about a width away
        for (boolean side : new boolean[] {false, true}) {
            double u = sheet.tailStart(side);
            double v = side ? w : 0;
            double px = pose.x(u, v);
            double py = pose.y(u, v);
            double off = Math.hypot(px - x, py - y);
            if (off <= nearest) {
                nearest = off;
                best = new double[] {px, py};
            }
        }
        return best;
    }

    /** A flat fold of the tail, recorded as a step with where the tail lay before and after. */
    private void tailFold(Kind kind, int host, double px, double py, double dx, double dy, Placement next)
            throws FoldException, WrapException {
        int hostBefore = sheet.tailHost();
        Isometry2 before = sheet.tailPose();
        int face = sheet.foldTail(intoHost.x(px, py), intoHost.y(px, py), intoHost.dx(dx, dy), intoHost.dy(dx, dy), next, kind.crease());
        recordTail(kind, host, face, hostBefore, before, next == Placement.OVER);
    }

    /** The fold of the tail over an edge onto the next triangle, recorded likewise. */
    private void tailCross(Kind kind, int host, double px, double py, double dx, double dy, int nextHost, Isometry2 development)
            throws FoldException, WrapException {
        int hostBefore = sheet.tailHost();
        Isometry2 before = sheet.tailPose();
        int face = sheet.crossTail(intoHost.x(px, py), intoHost.y(px, py), intoHost.dx(dx, dy), intoHost.dy(dx, dy), nextHost, development);
        recordTail(kind, host, face, hostBefore, before, true);
    }

    /** Tells {@code watcher} of this path's triangles as the {@code first}-th and on of {@code total}. */
    void watch(Watcher watcher, int first, int total) {
        this.watcher = watcher;
        this.firstDone = first;
        this.totalTriangles = total;
    }

    /**
     * Stops the wrap at the fold that takes the paper past the limit, before memory runs out,
     * saying what limit the whole path would likely need: the faces so far, over the share
     * of the path's passes and triangles folded (weighed as on a shared host, {@link #likelyFaces}).
     */
    private void checkFaces() throws FaceLimitException {
        if (watcher.stopped()) {
            throw new java.util.concurrent.CancellationException("the wrap was stopped");
        }
        checkLimit(0);
    }

    /**
     * Throws if the sheet's faces, with the {@code cuts} the next tuck would make (0 after any
     * other fold), pass the limit: a tuck is stopped before it cuts, for one at a sharp corner
     * cuts through every pass's turn at once (on the triangle with a corner of 0.001°, from
     * 663,767 faces to 966,020 in one tuck), and the paper it made went half a gibibyte past
     * the limit.
     */
    private void checkLimit(int cuts) throws FaceLimitException {
        long faces = (long) sheet.faceCount() + cuts;
        if (faces > maxFaces) {
            double done = 0;
            double all = 0;
            for (int i = 0; i < plan.m; i++) {
                double weight = likelyFaces(passes(plan.frames[i].altitude(), sheet.width()), false);
                all += weight;
                done += i <= pathIndex ? weight : 0;
            }
            long whole = (long) Math.ceil(faces * all / done);
            long enough = (long) Math.ceil(whole * 1.1 / 1000) * 1000; // a tenth to spare, in thousands
            throw new FaceLimitException(String.format(Locale.ROOT, "the strip %s %,d faces of paper on triangle %d of %d on the "
                    + "path (%s)%s, more than the limit of %,d faces; at this rate the whole path makes about %,d, and a limit "
                    + "of %d (about %,d MiB) would likely let it finish", cuts == 0 ? "has" : "would have", faces, pathIndex + 1,
                    plan.m, cornersText(mesh, plan.first + pathIndex), cuts == 0 ? ""
                    : String.format(Locale.ROOT, " once its next tuck cuts through %,d more", cuts), maxFaces, whole, enough, enough * BYTES_PER_FACE >> 20));
        }
    }

    private void recordTail(Kind kind, int host, int face, int hostBefore, Isometry2 before, boolean over) throws FaceLimitException {
        checkFaces();
        TailMove move = new TailMove(hostBefore, before, sheet.tailHost(), sheet.tailPose(), sheet.tailStart(false),
                sheet.tailStart(true), over);
        steps.add(new Step(kind, strip, host, pathIndex, plan.m, face, null, sheet.faceCount(), move, shared(detail)));
    }

    private void record(Kind kind, int host, int face) throws FaceLimitException {
        checkFaces();
        steps.add(new Step(kind, strip, host, pathIndex, plan.m, face, null, sheet.faceCount(), null, shared(detail)));
    }

    /**
     * One copy of each caption detail: a wrap records hundreds of thousands of steps, and
     * their details are a few dozen texts ("pass 2 of 5: turn, 45° valley fold"), each made
     * anew by its fold; the copies were a twentieth of the memory the paper takes.
     */
    private String shared(String text) {
        return text == null ? null : details.computeIfAbsent(text, t -> t);
    }
}
