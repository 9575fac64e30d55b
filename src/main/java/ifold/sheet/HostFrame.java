package ifold.sheet;

import static ifold.geom.Vectors.cross;
import static ifold.geom.Vectors.sub;
import static ifold.geom.Vectors.unit;

import ifold.geom.Tolerance;

/**
 * The plane of a triangle that paper rests on, with a 2D frame in it: an origin, two unit axes
 * and the outward unit normal ({@code ex × ey = n}, so counter-clockwise in the frame is
 * counter-clockwise seen from outside). Paper on the triangle lies at a height along n.
 *
 * @param origin x, y, z of the frame's origin
 * @param ex the frame's x axis
 * @param ey the frame's y axis
 * @param normal the outward normal
 * @param corners the triangle's corners in the frame, x0 y0 x1 y1 x2 y2, counter-clockwise
 * @param room for each edge of the corners' polygon (from corner k to corner k + 1), the stretches
 *     of it beyond which the bend of a flat fold may stand out less than {@link #OPEN} before it
 *     meets paper on the host across: from, to (distances along the edge from its first corner)
 *     and the slope (the distance beyond the edge over the height above this host), three numbers
 *     a stretch; null for an edge that limits nothing, and null where nothing limits any edge (a
 *     table, a plane in space). One edge of a host can border a convex turn along part of it and
 *     a coplanar host along the rest (a T-shaped face cut into convex pieces): a bend beside the
 *     one has the room the other lacks.
 * @param mitre for each edge of the corners' polygon, the stretches of it along which the surface
 *     across turns up towards the paper (a concave edge) by φ: from, to (distances along the edge
 *     from its first corner) and tan(φ/2), three numbers a stretch (null for an edge with none).
 *     Over such a stretch, paper at height z above this host keeps z·tan(φ/2) from the edge's
 *     line, on this side of the plane that halves the wedge of air above the edge (the mitre),
 *     where the paper of the host across keeps to the other side. An edge of a host can be
 *     concave in part only (a low block beside a tall one). Null where no edge is concave.
 * @param stops where a convex stretch of an edge ends at a corner of the surface with a face
 *     across it that rises in the way of paper bent over the edge ({@link Stop}); null where none
 */
public record HostFrame(double[] origin, double[] ex, double[] ey, double[] normal, double[] corners, double[][] room, double[][] mitre,
        Stop[] stops) {

    /**
     * The end of a convex stretch of edge {@code edge} at a corner of the surface where a face
     * across the corner (host {@code wall}) lies in the wedge of air over the edge: where a convex
     * edge of a polycube runs on as a concave one, or runs into a wall. Paper bent over the edge
     * there would run into that face's layers; so paper on the edge's line keeps from the corner,
     * along the edge, as far as that face's stack is high times {@code slope} (1 where the edge
     * leaves the face square to it; 1/cos of the angle between the edge and the face's normal).
     *
     * @param edge the edge of the corners' polygon
     * @param at where the stretch ends: its distance along the edge from the edge's first corner
     * @param toward +1 where the stretch runs on from there towards the edge's second corner, -1
     *     towards its first
     * @param wall the host of the face across the corner
     * @param slope how far along the edge paper keeps per height of that face's stack
     * @param beside tan(φ/2) of a concave stretch that ends at the corner on another host of
     *     this one's plane, on this edge's line, where the stretch runs on as the convex one (the
     *     face cut into hosts at the corner); 0 where none does
     */
    public record Stop(int edge, double at, double toward, int wall, double slope, double beside) {
        /** A stop with no concave stretch beside it on another host. */
        public Stop(int edge, double at, double toward, int wall, double slope) {
            this(edge, at, toward, wall, slope, 0);
        }

        /** This stop with {@code beside} the concave stretch's tan(φ/2). */
        public Stop beside(double tan) {
            return new Stop(edge, at, toward, wall, slope, tan);
        }
    }

    /*
     * A wrap's path triangle has a frame of its own: its exit edge from the origin along the x
     * axis (corners 0 and 1), the corner it is entered by above it (corner 2).
     */

    /** In a path triangle's frame: the length of its base, the edge on the x axis from the origin. */
    public double baseLength() {
        return corners[2];
    }

    /** In a path triangle's frame: how far along the base the corner above it lies. */
    public double apexX() {
        return corners[4];
    }

    /** In a path triangle's frame: the height of the corner above the base, the triangle's altitude from that corner. */
    public double altitude() {
        return corners[5];
    }

    /** The most a bend leans out beyond a crease: at 45 degrees, as far out as it rises. */
    public static final double OPEN = 1;

    /**
     * The largest mitre (tan of the half turn) that marks a cut between coplanar hosts, not a
     * turn: the paper keeps from no mitre this small ({@link #mitred}), only the walls of folds
     * tucked along the cut stand back from it ({@code ConcaveWalls}).
     */
    public static final double CUT_TAN = 1e-6;

    /** A frame whose edges limit no bend. */
    public HostFrame(double[] origin, double[] ex, double[] ey, double[] normal, double[] corners) {
        this(origin, ex, ey, normal, corners, null, null, null);
    }

    /** This frame with {@code room} beyond its edges and the {@code mitre} of each (see the record's description; either may be null). */
    public HostFrame withEdges(double[][] room, double[][] mitre) {
        if (room != null && room.length != corners.length / 2 || mitre != null && mitre.length != corners.length / 2) {
            throw new IllegalArgumentException("edges given for " + (room != null ? room.length : mitre.length) + " edges, the polygon has "
                    + corners.length / 2);
        }
        return new HostFrame(origin, ex, ey, normal, corners, room, mitre, stops);
    }

    /** This frame with the {@code stops} of its edges (see {@link Stop}; null for none). */
    public HostFrame withStops(Stop[] stops) {
        for (Stop stop : stops == null ? new Stop[0] : stops) {
            if (stop.edge() < 0 || stop.edge() >= corners.length / 2) {
                throw new IllegalArgumentException("a stop on edge " + stop.edge() + " of a polygon of " + corners.length / 2 + " edges");
            }
        }
        return new HostFrame(origin, ex, ey, normal, corners, room, mitre, stops);
    }

    /**
     * Moves frame point {@code point} (x, y), an end of a crease over an edge (its paper running
     * on to the points {@code over}, x, y pairs, across it), along the edge to where a {@link
     * Stop} keeps such paper, where it lies on the edge's line within {@code tolerance} nearer
     * the stop than that: {@code wallTop[h]} is how high the stack of host h stands. Paper on the
     * edge that does not go over it (its crease runs along another edge) stays.
     *
     * @return whether it moved
     */
    public boolean stopped(double[] wallTop, double tolerance, double[] over, double[] point) {
        if (stops == null || over == null) {
            return false;
        }
        boolean moved = false;
        for (Stop stop : stops) {
            double keep = wallTop[stop.wall()] * stop.slope();
            if (!(keep > 0)) {
                continue;
            }
            double[] edge = edge(stop.edge());
            double tx = edge[2] / edge[4];
            double ty = edge[3] / edge[4];
            double off = (point[0] - edge[0]) * -ty + (point[1] - edge[1]) * tx;
            double s = (point[0] - edge[0]) * tx + (point[1] - edge[1]) * ty;
            double from = (s - stop.at()) * stop.toward();
            if (Math.abs(off) > tolerance || from < -tolerance || from >= keep || !anyOnLine(over, edge, tolerance)) {
                continue;
            }
            double to = stop.at() + stop.toward() * keep;
            point[0] += (to - s) * tx;
            point[1] += (to - s) * ty;
            moved = true;
        }
        return moved;
    }

    /** Whether any of the points (x, y pairs) lies on the line of {@code edge} ({@link #edge}) within {@code tolerance}. */
    private static boolean anyOnLine(double[] points, double[] edge, double tolerance) {
        for (int i = 0; i + 1 < points.length; i += 2) {
            if (Math.abs((points[i] - edge[0]) * edge[3] - (points[i + 1] - edge[1]) * edge[2]) / edge[4] <= tolerance) {
                return true;
            }
        }
        return false;
    }

    /**
     * Where paper at frame point (x, y) and {@code height} above this host lies once mitred at
     * its concave edges ({@link #mitre}): moved in from each such edge's line to
     * height·tan(φ/2) from it where it lies nearer, along a concave stretch ({@link #keepFrom});
     * into {@code out} (x, y). A layer of a stack that runs up to a concave edge would otherwise
     * run into the layers of the host across. Where two concave edges meet at a sharp corner a
     * move off one brings the point nearer the other: after a few rounds it goes where the two
     * mitres meet.
     *
     * @return whether the point moved
     */
    public boolean mitred(double x, double y, double height, double[] out) {
        return mitred(x, y, Double.NaN, Double.NaN, height, out);
    }

    /**
     * {@link #mitred(double, double, double, double[])} for a corner of a piece of paper that
     * lies wholly beside the same stretches of concave edges as its point (bx, by) does (NaN:
     * the corner's own place, as it moves): a corner on the line where a stretch ends belongs to
     * the piece on its side, mitred or not as the piece is.
     */
    public boolean mitred(double x, double y, double bx, double by, double height, double[] out) {
        out[0] = x;
        out[1] = y;
        if (mitre == null || !(height > 0)) {
            return false;
        }
        boolean own = Double.isNaN(bx);
        int n = corners.length / 2;
        boolean moved = false;
        for (int round = 0; round < 4; round++) {
            boolean again = false;
            for (int k = 0; k < n; k++) {
                double tan = mitreAt(k, own ? out[0] : bx, own ? out[1] : by);
                if (tan > CUT_TAN && keepFrom(k, height * tan, out)) {
                    again = moved = true;
                }
            }
            if (!again) {
                return moved;
            }
        }
        // Two concave edges at a corner sharper than 90 degrees: straight to where their mitres meet.
        double[] keep = new double[n];
        for (int k = 0; k < n; k++) {
            double tan = mitreAt(k, own ? out[0] : bx, own ? out[1] : by);
            keep[k] = tan > CUT_TAN ? height * tan : 0;
        }
        meetNearest(keep, out);
        return moved;
    }

    /**
     * Moves point p, which falls short of the lines {@code keep[k]} in from edges k (0: no line),
     * to where two of those lines meet: of the pairs that hold it between them, the meeting
     * nearest p. A pair holds it where it falls short of both, or where moved straight in from
     * the one it falls short of it would fall short of the other. Each pair it fell short of one
     * of met in turn, the last won: in a pit (a triangle whose three edges are concave) paper by
     * one corner went where the two edges of another corner meet, across the triangle (a bumpy
     * sphere's squashed slivers stretched from end to end of an edge, 0.14 in space for 3e-5 on
     * the sheet, its layers "creeping" 1,304 thicknesses); and paper on an edge whose mitre is
     * a hair's breadth (a turn of 0.0024 degrees), moved in by the hair and left short again by
     * rounding round after round, went to the far end of that edge, where the next edge's mitre
     * meets it (the elephant with holes, 1,503 thicknesses).
     *
     * @return whether p moved
     */
    public boolean meetNearest(double[] keep, double[] p) {
        int n = corners.length / 2;
        double least = Double.POSITIVE_INFINITY;
        double nearestX = p[0];
        double nearestY = p[1];
        double[] q = new double[2];
        for (int k = 0; k < n; k++) {
            for (int j = k + 1; j < n; j++) {
                if (keep[k] > 0 && keep[j] > 0 && holds(k, keep[k], j, keep[j], p)) {
                    q[0] = Double.NaN; // left so where the lines do not meet in the polygon: no distance
                    meet(k, keep[k], j, keep[j], q);
                    double distance = Math.hypot(q[0] - p[0], q[1] - p[1]);
                    if (distance < least) {
                        least = distance;
                        nearestX = q[0];
                        nearestY = q[1];
                    }
                }
            }
        }
        if (least == Double.POSITIVE_INFINITY) {
            return false;
        }
        p[0] = nearestX;
        p[1] = nearestY;
        return true;
    }

    /** Whether the lines {@code keepK} in from edge k and {@code keepJ} in from edge j hold point p between them ({@link #meetNearest}). */
    private boolean holds(int k, double keepK, int j, double keepJ, double[] p) {
        double shortK = keepK - inside(k, p);
        double shortJ = keepJ - inside(j, p);
        boolean beforeK = shortK > keepK * 1e-9;
        boolean beforeJ = shortJ > keepJ * 1e-9;
        if (beforeK && beforeJ) {
            return true;
        }
        if (!beforeK && !beforeJ) {
            return false;
        }
        // Straight in from the one it falls short of: short of the other then?
        int from = beforeK ? k : j;
        int other = beforeK ? j : k;
        double need = beforeK ? shortK : shortJ;
        double dx = edgeDx(from);
        double dy = edgeDy(from);
        double length = Polygons2.length(dx, dy);
        double[] moved = {p[0] - dy / length * need, p[1] + dx / length * need};
        double keepOther = beforeK ? keepJ : keepK;
        return keepOther - inside(other, moved) > keepOther * 1e-9;
    }

    /**
     * tan(φ/2) of the concave stretch of edge k beside frame point (x, y): its projection on
     * the edge within the stretch, or beyond the edge's end where the stretch runs to it (near a
     * corner of the host the paper across still rises; where the edge turns convex part way,
     * it does not); 0 if none.
     */
    public double mitreAt(int k, double x, double y) {
        if (mitre == null || mitre[k] == null) {
            return 0;
        }
        // The edge read in place, not as edge(k): tens of millions of calls place a big wrap's paper.
        double dx = edgeDx(k);
        double dy = edgeDy(k);
        double length = Polygons2.length(dx, dy);
        double s = ((x - corners[2 * k]) * dx + (y - corners[2 * k + 1]) * dy) / length;
        double near = Tolerance.ON_PLANE * length;
        double most = 0;
        for (int i = 0; i + 2 < mitre[k].length; i += 3) {
            boolean fromStart = mitre[k][i] <= near;
            boolean toEnd = mitre[k][i + 1] >= length - near;
            if ((fromStart || s >= mitre[k][i] - near) && (toEnd || s <= mitre[k][i + 1] + near)) {
                most = Math.max(most, mitre[k][i + 2]);
            }
        }
        return most;
    }

    /**
     * tan(φ/2) of the concave stretches of edge k that the segment from (ax, ay) to (bx, by)
     * along it shares more than {@code tolerance} of, the most of them; 0 if none.
     */
    public double mitreAlong(int k, double ax, double ay, double bx, double by, double tolerance) {
        if (mitre == null || mitre[k] == null) {
            return 0;
        }
        double[] edge = edge(k);
        double sa = ((ax - edge[0]) * edge[2] + (ay - edge[1]) * edge[3]) / edge[4];
        double sb = ((bx - edge[0]) * edge[2] + (by - edge[1]) * edge[3]) / edge[4];
        double most = 0;
        for (int i = 0; i + 2 < mitre[k].length; i += 3) {
            if (Math.min(mitre[k][i + 1], Math.max(sa, sb)) - Math.max(mitre[k][i], Math.min(sa, sb)) > tolerance) {
                most = Math.max(most, mitre[k][i + 2]);
            }
        }
        return most;
    }

    /** Whether edge k has a concave stretch. */
    public boolean concave(int k) {
        return mitre != null && mitre[k] != null;
    }

    /** How far frame point p lies in from the line of edge k (negative beyond it). */
    public double inside(int k, double[] p) {
        double dx = edgeDx(k);
        double dy = edgeDy(k);
        return ((p[0] - corners[2 * k]) * -dy + (p[1] - corners[2 * k + 1]) * dx) / Polygons2.length(dx, dy);
    }

    /** Moves p to where the lines {@code keepK} in from edge k and {@code keepJ} in from edge j meet, if they do, and it lies in the polygon. */
    public void meet(int k, double keepK, int j, double keepJ, double[] p) {
        double[] a = edge(k);
        double[] b = edge(j);
        double ax = -a[3] / a[4];
        double ay = a[2] / a[4];
        double bx = -b[3] / b[4];
        double by = b[2] / b[4];
        double det = ax * by - ay * bx;
        if (Math.abs(det) < Tolerance.RELATIVE_EQUALITY) {
            return; // parallel: no corner
        }
        double ck = keepK + ax * a[0] + ay * a[1];
        double cj = keepJ + bx * b[0] + by * b[1];
        double[] q = {(ck * by - cj * ay) / det, (ax * cj - bx * ck) / det};
        for (int i = 0; i < corners.length / 2; i++) {
            if (edge(i)[4] > 0 && inside(i, q) < -Tolerance.ON_PLANE * (Math.abs(q[0]) + Math.abs(q[1]) + 1)) {
                return; // the host is too narrow there for both stacks
            }
        }
        p[0] = q[0];
        p[1] = q[1];
    }

    /**
     * Moves the frame point {@code point} (x, y) in from the line of edge k of the corners'
     * polygon until it lies {@code keep} from it, where it lies nearer: straight in, or, where
     * that would take it out across another edge (near a corner sharper than 90 degrees), along
     * that edge's line; and never out of the polygon (a groove narrower than the stacks of its two
     * walls leaves the paper nearer than its mitre, where it meets the paper across).
     *
     * @return whether it moved
     */
    public boolean keepFrom(int k, double keep, double[] point) {
        double dx = edgeDx(k);
        double dy = edgeDy(k);
        double length = Polygons2.length(dx, dy);
        // Inwards: left of the edge, the polygon running counter-clockwise.
        return keepFromLine(corners[2 * k], corners[2 * k + 1], -dy / length, dx / length, k, keep, point);
    }

    /** Whether {@link #keepFrom} moves {@code point}: it lies nearer the line of edge k than {@code keep} (the same sums, so the same answer). */
    public boolean keepsFrom(int k, double keep, double[] point) {
        double dx = edgeDx(k);
        double dy = edgeDy(k);
        double length = Polygons2.length(dx, dy);
        return need(corners[2 * k], corners[2 * k + 1], -dy / length, dx / length, keep, point) > keep * 1e-12;
    }

    /** How far the point must move towards (nx, ny) to lie {@code keep} from the line through (px, py); it moves where more than rounding. */
    private static double need(double px, double py, double nx, double ny, double keep, double[] point) {
        return keep - ((point[0] - px) * nx + (point[1] - py) * ny);
    }

    /**
     * {@link #keepFrom} for any line: through (px, py), {@code keep} from it towards the unit
     * normal (nx, ny), sliding along an edge of the polygon where straight would leave it; edge
     * {@code skip} (the line's own, or -1) is not slid along.
     */
    public boolean keepFromLine(double px, double py, double nx, double ny, int skip, double keep, double[] point) {
        int k = skip;
        double need = need(px, py, nx, ny, keep, point);
        if (!(need > keep * 1e-12)) {
            return false;
        }
        double dx = nx;
        double dy = ny;
        double amount = need;
        int n = corners.length / 2;
        for (int j = 0; j < n; j++) {
            double otherDx = edgeDx(j);
            double otherDy = edgeDy(j);
            double otherLength = Polygons2.length(otherDx, otherDy);
            if (j == k || !(otherLength > 0)) {
                continue;
            }
            double mx = -otherDy / otherLength;
            double my = otherDx / otherLength;
            double inside = (point[0] - corners[2 * j]) * mx + (point[1] - corners[2 * j + 1]) * my;
            double after = inside + amount * (dx * mx + dy * my);
            if (after < Math.min(inside, 0)) {
                // Along edge j's line, the way that leads in from edge k: edge j's own distance stays.
                double tx = otherDx / otherLength;
                double ty = otherDy / otherLength;
                double towards = tx * nx + ty * ny;
                if (Math.abs(towards) > 1e-3) {
                    dx = Math.signum(towards) * tx;
                    dy = Math.signum(towards) * ty;
                    amount = need / Math.abs(towards);
                }
                break;
            }
        }
        // No farther than the polygon lets it go: each edge's distance stays at least what it was, or 0.
        for (int j = 0; j < n; j++) {
            double otherDx = edgeDx(j);
            double otherDy = edgeDy(j);
            double otherLength = Polygons2.length(otherDx, otherDy);
            if (!(otherLength > 0)) {
                continue;
            }
            double mx = -otherDy / otherLength;
            double my = otherDx / otherLength;
            double towards = dx * mx + dy * my;
            if (towards < 0) {
                double inside = (point[0] - corners[2 * j]) * mx + (point[1] - corners[2 * j + 1]) * my;
                amount = Math.min(amount, Math.max(0, inside - Math.min(inside, 0)) / -towards);
            }
        }
        if (!(amount > 0)) {
            return false;
        }
        point[0] += amount * dx;
        point[1] += amount * dy;
        return true;
    }

    /**
     * The room beyond the crease from (ax, ay) to (bx, by) in this frame: the least of the
     * stretches of edges it lies along (its ends within {@code tolerance} of the edge's line)
     * that it shares more than {@code tolerance} of, or {@link #OPEN} for a crease along none.
     */
    public double roomBeyond(double ax, double ay, double bx, double by, double tolerance) {
        double least = OPEN;
        if (room == null) {
            return least;
        }
        int n = corners.length / 2;
        for (int k = 0; k < n; k++) {
            if (room[k] == null || !along(k, ax, ay, bx, by, tolerance)) {
                continue;
            }
            double[] edge = edge(k);
            double ta = ((ax - edge[0]) * edge[2] + (ay - edge[1]) * edge[3]) / edge[4];
            double tb = ((bx - edge[0]) * edge[2] + (by - edge[1]) * edge[3]) / edge[4];
            for (int i = 0; i + 2 < room[k].length; i += 3) {
                double shared = Math.min(room[k][i + 1], Math.max(ta, tb)) - Math.max(room[k][i], Math.min(ta, tb));
                if (shared > tolerance) {
                    least = Math.min(least, room[k][i + 2]);
                }
            }
        }
        return least;
    }

    /**
     * The room beyond edge k by frame point (x, y): the least of its stretches that the point's
     * projection on the edge lies within {@code reach} of, or beyond the edge's end where the
     * stretch runs to it; {@link #OPEN} where none does. A stretch of no room counts only where
     * the bend reaches into it, from the point to its row {@code lean} along the edge, by more
     * than {@code tolerance} (how far apart the sheet's points are one).
     */
    private double roomBy(int k, double x, double y, double reach, double lean, double tolerance) {
        if (room[k] == null) {
            return OPEN;
        }
        double[] edge = edge(k);
        double s = ((x - edge[0]) * edge[2] + (y - edge[1]) * edge[3]) / edge[4];
        double near = Tolerance.ON_PLANE * edge[4];
        double least = OPEN;
        for (int i = 0; i + 2 < room[k].length; i += 3) {
            boolean fromStart = room[k][i] <= near;
            boolean toEnd = room[k][i + 1] >= edge[4] - near;
            if (room[k][i + 2] == 0) {
                // A stretch of no room (a host in the same plane, across a cut) counts only where
                // the bend, from its crease's point to its row, reaches into it: a crease along a
                // convex stretch that ends where the cut begins (a reflex corner of the face), or
                // one whose row leans away from a cut beginning there (square_frame's diagonals
                // from its inner corners), leans over its own stretch alone. The crease's point
                // is good to the sheet's tolerance: at a reflex corner of the big torus's flat
                // bottom ring (its hosts' corners 93.6 degrees) a crease along the inner edge
                // ended 1.1e-9 inside the cut's stretch from the corner, beyond 2 * near
                // (5.7e-10), and its nest of folds was held onto its line, walls on each other.
                double slack = Math.max(2 * near, tolerance);
                if (s + Math.max(0, lean) >= room[k][i] + slack && s + Math.min(0, lean) <= room[k][i + 1] - slack) {
                    least = Math.min(least, room[k][i + 2]);
                }
                continue;
            }
            if ((fromStart || s >= room[k][i] - reach) && (toEnd || s <= room[k][i + 1] + reach)) {
                least = Math.min(least, room[k][i + 2]);
            }
        }
        return least;
    }

    /**
     * Whether the segment from (ax, ay) to (bx, by) in this frame lies along the line of edge k
     * of the corners' polygon (from corner k to corner k + 1): both its ends within
     * {@code tolerance} of that line.
     */
    public boolean along(int k, double ax, double ay, double bx, double by, double tolerance) {
        double[] edge = edge(k);
        double px = edge[0];
        double py = edge[1];
        double dx = edge[2];
        double dy = edge[3];
        double length = edge[4];
        return length > 0 && Math.abs((ax - px) * dy - (ay - py) * dx) / length <= tolerance
                && Math.abs((bx - px) * dy - (by - py) * dx) / length <= tolerance;
    }

    /** Edge k of the corners' polygon, from corner k to corner k + 1: {x, y of its start, dx, dy, its length}. */
    public double[] edge(int k) {
        double dx = edgeDx(k);
        double dy = edgeDy(k);
        return new double[] {corners[2 * k], corners[2 * k + 1], dx, dy, Polygons2.length(dx, dy)};
    }

    /** Edge k's run along x, {@code edge(k)[2]} without the array. */
    private double edgeDx(int k) {
        return corners[2 * ((k + 1) % (corners.length / 2))] - corners[2 * k];
    }

    /** Edge k's run along y, {@code edge(k)[3]} without the array. */
    private double edgeDy(int k) {
        return corners[2 * ((k + 1) % (corners.length / 2)) + 1] - corners[2 * k + 1];
    }

    /**
     * The frame of triangle (a, b, c), counter-clockwise seen from outside, with its origin at
     * a and its x axis along a → b: corner a is (0, 0), b is (|ab|, 0), c lies above the x axis.
     *
     * @throws IllegalArgumentException if the triangle has no area
     */
    public static HostFrame onEdge(double[] a, double[] b, double[] c) {
        double[] ex = unit(sub(b, a));
        double[] n = unit(cross(sub(b, a), sub(c, a)));
        if (!(Double.isFinite(ex[0]) && Double.isFinite(n[0]))) {
            throw new IllegalArgumentException("a triangle with no area cannot hold paper");
        }
        double[] ey = cross(n, ex);
        HostFrame frame = new HostFrame(a.clone(), ex, ey, n, new double[6]);
        double[] corners = frame.corners;
        corners[2] = frame.localX(b);
        corners[3] = 0;
        corners[4] = frame.localX(c);
        corners[5] = frame.localY(c);
        return frame;
    }

    /**
     * How far, at most {@code out}, a bend may stand out from the point (x, y) of its crease in
     * the unit direction (nx, ny), leaning out at {@code slope} (distance out per height) from
     * {@code height} above this host, and stay within the room beyond every edge of the host:
     * its farthest point no farther beyond an edge's line than its height times that edge's room.
     * A crease inside the host at a small angle to an edge would otherwise lean out over it.
     * The point is good to {@code tolerance}: a bend reaching into a stretch of no room by no
     * more than that, from a crease ending by it, is not held by it.
     */
    public double lean(double x, double y, double nx, double ny, double height, double slope, double out, double tolerance) {
        if (room == null) {
            return out;
        }
        double most = out;
        int n = corners.length / 2;
        for (int k = 0; k < n; k++) {
            double[] edge = edge(k);
            double px = edge[0];
            double py = edge[1];
            double dx = edge[2];
            double dy = edge[3];
            double length = edge[4];
            if (!(length > 0)) {
                continue;
            }
            // The stretches of the edge the bend could reach beside: as far along it as it leans.
            double reach = Math.abs(nx * dx + ny * dy) / length * out + Tolerance.ON_PLANE * length;
            double edgeRoom = roomBy(k, x, y, reach, (nx * dx + ny * dy) / length * out, tolerance);
            if (edgeRoom >= OPEN) {
                continue;
            }
            // The edge's outward normal: the corners run counter-clockwise.
            double mx = dy / length;
            double my = -dx / length;
            double beyond = (x - px) * mx + (y - py) * my;
            // Standing out along the edge's line to rounding, it comes no nearer beyond it.
            double across = Math.abs(nx * mx + ny * my) <= Tolerance.ON_PLANE ? 0 : nx * mx + ny * my;
            double towards = across - edgeRoom / slope;
            if (towards > 0) {
                most = Math.min(most, Math.max(0, (height * edgeRoom - beyond) / towards));
            }
        }
        return most;
    }

    /** Frame coordinate x of the 3D point p (its projection on the plane). */
    public double localX(double[] p) {
        return (p[0] - origin[0]) * ex[0] + (p[1] - origin[1]) * ex[1] + (p[2] - origin[2]) * ex[2];
    }

    public double localY(double[] p) {
        return (p[0] - origin[0]) * ey[0] + (p[1] - origin[1]) * ey[1] + (p[2] - origin[2]) * ey[2];
    }

    /** Height of p above the plane, along the outward normal. */
    public double height(double[] p) {
        return (p[0] - origin[0]) * normal[0] + (p[1] - origin[1]) * normal[1] + (p[2] - origin[2]) * normal[2];
    }

    /** The 3D point at frame coordinates (x, y) and {@code height} along the normal, into {@code out} at {@code offset}. */
    public void toSpace(double x, double y, double height, double[] out, int offset) {
        for (int i = 0; i < 3; i++) {
            out[offset + i] = origin[i] + x * ex[i] + y * ey[i] + height * normal[i];
        }
    }


}
