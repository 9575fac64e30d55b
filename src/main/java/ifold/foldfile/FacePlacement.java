package ifold.foldfile;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * Where each face of a crease pattern goes when it is folded: a rigid motion from the paper
 * (u, v, 0) into space. Faces are reached from the first along a tree of hinges (the creases
 * and flat edges between two faces); a face's motion is its parent's, after a turn about their
 * shared edge by the hinge's fold angle. Every hinge left out of the tree closes a cycle, whose
 * two faces must then agree on where their edge lies: a fold that does not close is refused.
 * The same tree, its angles scaled from 0 to 1, is the motion that folds the sheet.
 */
final class FacePlacement {
    private FacePlacement() {
    }

    /** A rigid motion of space, x → R x + t (R 3 × 3, rows first). */
    record Rigid(double[] r, double[] t) {
        static final Rigid IDENTITY = new Rigid(new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1}, new double[3]);

        double[] apply(double x, double y, double z) {
            return new double[] {r[0] * x + r[1] * y + r[2] * z + t[0], r[3] * x + r[4] * y + r[5] * z + t[1],
                r[6] * x + r[7] * y + r[8] * z + t[2]};
        }

        double[] turn(double[] v) {
            return new double[] {r[0] * v[0] + r[1] * v[1] + r[2] * v[2], r[3] * v[0] + r[4] * v[1] + r[5] * v[2],
                r[6] * v[0] + r[7] * v[1] + r[8] * v[2]};
        }

        /** This motion after {@code first}: first applies first. */
        Rigid after(Rigid first) {
            double[] m = new double[9];
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    m[3 * i + j] = r[3 * i] * first.r[j] + r[3 * i + 1] * first.r[3 + j] + r[3 * i + 2] * first.r[6 + j];
                }
            }
            double[] shift = apply(first.t[0], first.t[1], first.t[2]);
            return new Rigid(m, shift);
        }

        /** The turn by {@code angle} radians about the line through {@code point} along the unit {@code axis} (right-handed). */
        static Rigid turnAbout(double[] point, double[] axis, double angle) {
            double c = Math.cos(angle);
            double s = Math.sin(angle);
            double x = axis[0];
            double y = axis[1];
            double z = axis[2];
            double[] m = {c + x * x * (1 - c), x * y * (1 - c) - z * s, x * z * (1 - c) + y * s, y * x * (1 - c) + z * s, c + y * y * (1 - c),
                y * z * (1 - c) - x * s, z * x * (1 - c) - y * s, z * y * (1 - c) + x * s, c + z * z * (1 - c)};
            Rigid turn = new Rigid(m, new double[3]);
            double[] moved = turn.turn(point);
            return new Rigid(m, new double[] {point[0] - moved[0], point[1] - moved[1], point[2] - moved[2]});
        }
    }

    /**
     * A hinge of the tree: {@code face} hangs from {@code parent} along paper edge (a, b), turned
     * by {@code angle} radians about it (positive: a valley, the face rising on the paper's top
     * side), {@code edge} the file's edge there (-1 where none is listed).
     */
    record Hinge(int face, int parent, int a, int b, double angle, int edge) {
    }

    /** The faces' motions and the hinges that reach them, parents before children. */
    record Placed(Rigid[] faces, List<Hinge> hinges) {
    }

    /** The faces on either side of each paper edge: for each undirected vertex pair, {face left of a→b, face left of b→a} (-1: none). */
    static Map<Long, int[]> sides(int[][] faces) throws CreasePattern.Refused {
        Map<Long, int[]> sides = new HashMap<>();
        for (int f = 0; f < faces.length; f++) {
            int[] loop = faces[f];
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int[] pair = sides.computeIfAbsent(key(a, b), k -> new int[] {-1, -1});
                int side = a < b ? 0 : 1;
                if (pair[side] >= 0) {
                    throw new CreasePattern.Refused(String.format(Locale.ROOT, "faces %d and %d both run along the edge from vertex %d to %d the"
                            + " same way: the faces overlap on the paper or one is turned over", pair[side], f, a, b));
                }
                pair[side] = f;
            }
        }
        return sides;
    }

    static long key(int a, int b) {
        return ((long) Math.min(a, b) << 32) | Math.max(a, b);
    }

    /** What a walk over the hinges from face 0 meets. */
    interface Walk {
        /** Face g reached for the first time, from f across paper edge (a, b) (the file's {@code edge}, or -1). */
        void reached(int g, int f, int a, int b, int edge) throws CreasePattern.Refused;

        /** A hinge between faces f and g, both reached already (f the lower): one the tree leaves out, or a tree's seen again. */
        default void joins(int f, int g, int a, int b) {
        }

        /**
         * Face g starts another piece of paper, which no hinge joins to those before (a wrap's
         * second strip): refused, unless the walk places pieces apart.
         */
        default void root(int g) throws CreasePattern.Refused {
            throw new CreasePattern.Refused("face " + g + " is joined to face 0 by no crease or flat edge: iFold folds one piece of"
                    + " paper here");
        }
    }

    /**
     * Walks the hinges breadth first from face 0: across each paper edge two faces share, unless
     * the file makes it a border or a cut.
     *
     * @throws CreasePattern.Refused naming a face no hinge reaches: iFold folds one piece of paper
     */
    static void walk(int[][] faces, Map<Long, Integer> edgeOf, boolean[] hingeable, Walk walk) throws CreasePattern.Refused {
        Map<Long, int[]> sides = sides(faces);
        boolean[] reached = new boolean[faces.length];
        ArrayDeque<Integer> queue = new ArrayDeque<>();
        for (int root = 0; root < faces.length; root++) {
            if (reached[root]) {
                continue;
            }
            if (root > 0) {
                walk.root(root);
            }
            reached[root] = true;
            queue.add(root);
            walkFrom(faces, edgeOf, hingeable, walk, sides, reached, queue);
        }
    }

    /** The breadth-first walk from the faces queued, over the hinges, to every face they reach. */
    private static void walkFrom(int[][] faces, Map<Long, Integer> edgeOf, boolean[] hingeable, Walk walk, Map<Long, int[]> sides,
            boolean[] reached, ArrayDeque<Integer> queue) throws CreasePattern.Refused {
        while (!queue.isEmpty()) {
            int f = queue.poll();
            int[] loop = faces[f];
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int g = sides.get(key(a, b))[a < b ? 1 : 0];
                Integer edge = edgeOf.get(key(a, b));
                if (g < 0 || (edge != null && !hingeable[edge])) {
                    continue;
                }
                if (reached[g]) {
                    if (f < g) {
                        walk.joins(f, g, a, b);
                    }
                    continue;
                }
                reached[g] = true;
                walk.reached(g, f, a, b, edge == null ? -1 : edge);
                queue.add(g);
            }
        }
    }

    /**
     * The faces placed by their hinges' angles (radians, by edge; an edge the file does not list
     * is flat), from face 0 left where the paper lies.
     *
     * @param uv each vertex on the paper
     * @param hingeable whether an edge joins its faces (not a border or a cut)
     * @param tolerance how far two faces may disagree on a shared vertex
     * @throws CreasePattern.Refused naming the vertex where a cycle of hinges does not close, or
     *     a face no hinge reaches
     */
    static Placed byAngles(double[][] uv, int[][] faces, Map<Long, Integer> edgeOf, double[] angles, boolean[] hingeable, double tolerance)
            throws CreasePattern.Refused {
        Rigid[] motion = new Rigid[faces.length];
        List<Hinge> hinges = new ArrayList<>();
        List<long[]> closing = new ArrayList<>(); // {f, g, a, b} of hinges not in the tree
        motion[0] = Rigid.IDENTITY;
        walk(faces, edgeOf, hingeable, new Walk() {
            @Override
            public void reached(int g, int f, int a, int b, int edge) {
                double angle = edge < 0 ? 0 : angles[edge];
                motion[g] = motion[f].after(hinge(uv, faces[g], a, b, angle));
                hinges.add(new Hinge(g, f, a, b, angle, edge));
            }

            @Override
            public void joins(int f, int g, int a, int b) {
                closing.add(new long[] {f, g, a, b});
            }
        });
        for (long[] c : closing) {
            int f = (int) c[0];
            int g = (int) c[1];
            double[] apart = new double[2];
            for (int k = 0; k < 2; k++) {
                int v = (int) c[2 + k];
                double[] p = motion[f].apply(uv[v][0], uv[v][1], 0);
                double[] q = motion[g].apply(uv[v][0], uv[v][1], 0);
                apart[k] = Math.sqrt(Math.pow(p[0] - q[0], 2) + Math.pow(p[1] - q[1], 2) + Math.pow(p[2] - q[2], 2));
            }
            if (apart[0] <= tolerance && apart[1] <= tolerance) {
                continue;
            }
            // The cycle turns about the end where the two faces still meet: the vertex it goes round.
            int pivot = apart[0] <= tolerance ? (int) c[2] : apart[1] <= tolerance ? (int) c[3] : -1;
            int far = pivot == (int) c[2] ? (int) c[3] : (int) c[2];
            double gap = Math.max(apart[0], apart[1]);
            if (pivot >= 0) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "the folds around vertex %d (%s, %s) do not close: faces %d and"
                        + " %d, which meet along its crease to vertex %d, land %.3g apart there once folded by their fold angles", pivot,
                        CreasePattern.fmt(uv[pivot][0]), CreasePattern.fmt(uv[pivot][1]), f, g, far, gap));
            }
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "the folds do not close: faces %d and %d, which meet along the edge"
                    + " from vertex %d to %d, land %.3g apart once folded by their fold angles", f, g, c[2], c[3], gap));
        }
        return new Placed(motion, hinges);
    }

    /**
     * The turn of a face hanging on paper edge (a, b) by {@code angle} radians: about the edge,
     * its sense chosen so that a positive angle lifts the face to the paper's top side (+z).
     */
    static Rigid hinge(double[][] uv, int[] face, int a, int b, double angle) {
        double dx = uv[b][0] - uv[a][0];
        double dy = uv[b][1] - uv[a][1];
        double length = Math.hypot(dx, dy);
        return Rigid.turnAbout(new double[] {uv[a][0], uv[a][1], 0}, new double[] {dx / length, dy / length, 0},
                sense(uv, face, a, b) * angle);
    }

    /**
     * The sense of a hinge's turn about paper edge a → b that lifts its face to the paper's top
     * side: +1 where the face lies left of the edge (its corner farthest from the line), else -1.
     * Turning by +angle about the axis lifts points on its left to +z.
     */
    static double sense(double[][] uv, int[] face, int a, int b) {
        double dx = uv[b][0] - uv[a][0];
        double dy = uv[b][1] - uv[a][1];
        double side = 0;
        for (int v : face) {
            double cross = dx * (uv[v][1] - uv[a][1]) - dy * (uv[v][0] - uv[a][0]);
            side = Math.abs(cross) > Math.abs(side) ? cross : side;
        }
        return side > 0 ? 1 : -1;
    }

    /**
     * Each face's motion where its corners' places in space are given (a folded form): the one
     * taking its paper corners to them, found from its first corner and the two directions
     * from it that span the most.
     */
    static Rigid[] fromPlaces(double[][] uv, double[][] xyz, int[][] faces) {
        Rigid[] motion = new Rigid[faces.length];
        for (int f = 0; f < faces.length; f++) {
            int[] loop = faces[f];
            int o = loop[0];
            // The corner farthest from the first, and the one farthest from their line.
            int far = loop[1];
            for (int v : loop) {
                far = dist2(uv[v], uv[o]) > dist2(uv[far], uv[o]) ? v : far;
            }
            double[] e1 = unit(new double[] {uv[far][0] - uv[o][0], uv[far][1] - uv[o][1], 0});
            double[] x1 = unit(sub(xyz[far], xyz[o]));
            int wide = loop[1];
            double best = -1;
            for (int v : loop) {
                double cross = Math.abs(e1[0] * (uv[v][1] - uv[o][1]) - e1[1] * (uv[v][0] - uv[o][0]));
                if (cross > best) {
                    best = cross;
                    wide = v;
                }
            }
            double[] w = {uv[wide][0] - uv[o][0], uv[wide][1] - uv[o][1], 0};
            double along = dot(w, e1);
            double[] e2 = unit(new double[] {w[0] - along * e1[0], w[1] - along * e1[1], 0});
            double[] wx = sub(xyz[wide], xyz[o]);
            double[] x2 = unit(sub(wx, scale(x1, dot(wx, x1))));
            double[] e3 = cross(e1, e2);
            double[] x3 = cross(x1, x2);
            // R takes e1, e2, e3 to x1, x2, x3: R = X E^T.
            double[] r = new double[9];
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    r[3 * i + j] = x1[i] * e1[j] + x2[i] * e2[j] + x3[i] * e3[j];
                }
            }
            Rigid turn = new Rigid(r, new double[3]);
            double[] moved = turn.turn(new double[] {uv[o][0], uv[o][1], 0});
            motion[f] = new Rigid(r, sub(xyz[o], moved));
        }
        return motion;
    }

    /**
     * The hinges of a tree from face 0 over faces already placed: each hinge's angle the turn
     * about its edge from its parent's motion to its face's (a valley positive), a flat fold
     * (±180°) signed by {@code flatSign} (+1 valley, -1 mountain, by the edge; 0 where unknown:
     * a valley).
     */
    static List<Hinge> hingesOf(double[][] uv, int[][] faces, Rigid[] motion, Map<Long, Integer> edgeOf, boolean[] hingeable,
            int[] flatSign) throws CreasePattern.Refused {
        List<Hinge> hinges = new ArrayList<>();
        walk(faces, edgeOf, hingeable, new Walk() {
            @Override
            public void root(int g) {
                // Another piece (a wrap's next strip): where the folded state puts it, a root of its own.
                hinges.add(new Hinge(g, -1, -1, -1, 0, -1));
            }

            @Override
            public void reached(int g, int f, int a, int b, int edge) {
                hinges.add(hingeOf(uv, faces, motion, flatSign, g, f, a, b, edge));
            }
        });
        return hinges;
    }

    /** The hinge by which face g is reached from face f across paper edge (a, b): the turn between their placements about it. */
    private static Hinge hingeOf(double[][] uv, int[][] faces, Rigid[] motion, int[] flatSign, int g, int f, int a, int b, int edge) {
        // The paper's normal as each face carries it: the turn between them about the edge.
        double[] up = {0, 0, 1};
        double[] nf = motion[f].turn(up);
        double[] ng = motion[g].turn(up);
        double[] axisPaper = unit(new double[] {uv[b][0] - uv[a][0], uv[b][1] - uv[a][1], 0});
        double[] axis = motion[f].turn(axisPaper);
        double angle = Math.atan2(dot(cross(nf, ng), axis), dot(nf, ng));
        // The sense about the edge as the hinge turns the face (its side of the edge).
        angle *= sense(uv, faces[g], a, b);
        if (Math.PI - Math.abs(angle) < 1e-9) {
            angle = (edge >= 0 && flatSign[edge] < 0) ? -Math.PI : Math.PI;
        }
        return new Hinge(g, f, a, b, angle, edge);
    }

    /**
     * A folded form laid out flat: the paper coordinates of each vertex, found face by face along
     * a tree from face 0 (laid with its first edge along u), each face unfolded about the edge it
     * shares with its parent. A vertex shared by faces that unfold to different places is
     * refused: the form does not come from one flat sheet.
     */
    static double[][] develop(double[][] xyz, int[][] faces, Map<Long, Integer> edgeOf, boolean[] hingeable, double tolerance)
            throws CreasePattern.Refused {
        double[][] uv = new double[xyz.length][];
        int[] first = faces[0];
        double[] o = xyz[first[0]];
        double[] ex = unit(sub(xyz[first[1]], o));
        double[] n = faceNormal(xyz, first);
        double[] ey = cross(n, ex);
        for (int v : first) {
            double[] d = sub(xyz[v], o);
            uv[v] = new double[] {dot(d, ex), dot(d, ey)};
        }
        walk(faces, edgeOf, hingeable, (g, f, a, b, edge) -> {
            // g runs b → a; laid on the paper to the left of b → a, as f lies left of a → b.
            double[] axis3 = unit(sub(xyz[b], xyz[a]));
            double[] ng = faceNormal(xyz, faces[g]);
            double[] inward = cross(ng, scale(axis3, -1)); // left of b → a within g's plane
            double du = uv[b][0] - uv[a][0];
            double dv = uv[b][1] - uv[a][1];
            double length = Math.hypot(du, dv);
            double[] axis2 = {du / length, dv / length};
            double[] left2 = {axis2[1], -axis2[0]}; // left of b → a on the paper
            for (int v : faces[g]) {
                double[] d = sub(xyz[v], xyz[a]);
                double along = dot(d, axis3);
                double across = dot(d, inward);
                double[] place = {uv[a][0] + along * axis2[0] + across * left2[0], uv[a][1] + along * axis2[1] + across * left2[1]};
                if (uv[v] == null) {
                    uv[v] = place;
                } else if (Math.hypot(uv[v][0] - place[0], uv[v][1] - place[1]) > tolerance) {
                    throw new CreasePattern.Refused(String.format(Locale.ROOT, "the folded form does not unfold onto one flat sheet:"
                            + " vertex %d unfolds to two places %.3g apart (faces %d and %d)", v,
                            Math.hypot(uv[v][0] - place[0], uv[v][1] - place[1]), f, g));
                }
            }
        });
        return uv;
    }

    /** The unit normal of a face in space (Newell's method: any planar polygon). */
    static double[] faceNormal(double[][] xyz, int[] face) {
        double[] n = new double[3];
        for (int i = 0; i < face.length; i++) {
            double[] p = xyz[face[i]];
            double[] q = xyz[face[(i + 1) % face.length]];
            n[0] += (p[1] - q[1]) * (p[2] + q[2]);
            n[1] += (p[2] - q[2]) * (p[0] + q[0]);
            n[2] += (p[0] - q[0]) * (p[1] + q[1]);
        }
        return unit(n);
    }

    static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double[] scale(double[] a, double s) {
        return new double[] {a[0] * s, a[1] * s, a[2] * s};
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    static double[] unit(double[] a) {
        double length = Math.sqrt(dot(a, a));
        return length > 0 ? scale(a, 1 / length) : a;
    }

    private static double dist2(double[] a, double[] b) {
        return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]);
    }
}
