package ifold.foldfile;

import ifold.geom.Tolerance;
import ifold.sheet.FoldedStateSheet;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A FOLD file folded all at once, as Origami Simulator folds: every crease turning together
 * from flat to its fold angle. It takes what a FOLD file can hold:
 * <ul>
 * <li>a crease pattern and its folded state ({@code file_frames}, as iFold writes): the faces
 * go where that state puts them, in its layer order;</li>
 * <li>a crease pattern with fold angles other than flat (a box's net): each face placed by
 * turning about the creases from the first face, every cycle of creases checked to close;</li>
 * <li>a crease pattern folded flat (mountains and valleys, no order): each vertex checked for
 * Maekawa's and Kawasaki's conditions, the faces reflected into place, and a layer order found
 * ({@link LayerSolver});</li>
 * <li>a folded form alone (3D vertices, as the FOLD repository's box): its faces unfolded onto
 * one flat sheet, which then folds back to it.</li>
 * </ul>
 * The result is a {@link Sheet} like any other fold's, its faces on their planes at their
 * levels, and the motion that folds it.
 */
public final class FoldedForm {
    /** What was folded, and how. */
    public enum Kind {
        GIVEN("its folded state as the file gives it"), ANGLES("its fold angles"), FLAT("folded flat, its layer order found"),
        UNFOLDED("a folded form, unfolded onto one sheet");

        private final String words;

        Kind(String words) {
            this.words = words;
        }

        public String words() {
            return words;
        }
    }

    /**
     * A hinge of the folding motion, in the sheet's face numbers: {@code face} turns about the
     * paper line through (u, v) along (du, dv) by {@code angle} radians from where its parent
     * lies (-1: the face left where the paper lies).
     */
    public record Hinge(int face, int parent, double u, double v, double du, double dv, double angle) {
    }

    /**
     * The folded sheet.
     *
     * @param sheet its faces on their hosts, at their levels
     * @param frames the planes the hosts are
     * @param hinges the motion, parents before children; the first face is the root
     * @param kind how its folded state was found
     * @param creases the mountain and valley edges
     */
    public record Result(Sheet sheet, HostFrame[] frames, List<Hinge> hinges, Kind kind, int creases) {
        /**
         * Each face's motion part way, {@code t} from 0 (flat) to 1 (folded, without thickness):
         * 12 numbers a face, R (3 × 3, rows first) then t, taking paper (u, v, 0) into space.
         */
        public double[][] motionAt(double t) {
            FacePlacement.Rigid[] motion = new FacePlacement.Rigid[sheet.faceCount()];
            double[][] out = new double[motion.length][];
            for (Hinge h : hinges) {
                if (h.parent() < 0) {
                    motion[h.face()] = FacePlacement.Rigid.IDENTITY;
                } else {
                    double length = Math.hypot(h.du(), h.dv());
                    motion[h.face()] = motion[h.parent()].after(FacePlacement.Rigid.turnAbout(new double[] {h.u(), h.v(), 0},
                            new double[] {h.du() / length, h.dv() / length, 0}, t * h.angle()));
                }
                double[] m = new double[12];
                System.arraycopy(motion[h.face()].r(), 0, m, 0, 9);
                System.arraycopy(motion[h.face()].t(), 0, m, 9, 3);
                out[h.face()] = m;
            }
            return out;
        }
    }

    private FoldedForm() {
    }

    /**
     * Folds the file's paper.
     *
     * @throws CreasePattern.Refused naming the vertex, edge or faces where it cannot be folded
     */
    public static Result fold(Map<String, Object> file) throws CreasePattern.Refused {
        FoldInput in = checked(file);
        double[][] vertices = in.vertices();
        int n = vertices.length;
        double size = diagonal(vertices);
        if (!(size > Tolerance.SMALLEST_SIZE) || !(size < Tolerance.LARGEST_SIZE)) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "the sheet is too %s: %s across; iFold folds sheets from %.0e to %.0e"
                    + " across: scale the pattern %s", size > 1 ? "large" : "small", CreasePattern.fmt(size), Tolerance.SMALLEST_SIZE,
                    Tolerance.LARGEST_SIZE, size > 1 ? "down" : "up"));
        }
        // Files hold their numbers to a few digits (Mathematica's square twist, to about seven):
        // points a millionth of the paper apart agree, where the file's data must agree.
        double tolerance = 1e-6 * size;
        Map<Long, Integer> edgeOf = new HashMap<>();
        for (int e = 0; e < in.edges().length; e++) {
            int a = in.edges()[e][0];
            int b = in.edges()[e][1];
            if (a == b) {
                throw new CreasePattern.Refused("edge " + e + ": edges_vertices names vertex " + a + " twice");
            }
            edgeOf.put(FacePlacement.key(a, b), e);
        }
        boolean[] hingeable = new boolean[in.edges().length];
        int[] flatSign = new int[in.edges().length];
        for (int e = 0; e < hingeable.length; e++) {
            char assignment = in.assignments()[e];
            hingeable[e] = assignment != 'B' && assignment != 'C';
            flatSign[e] = assignment == 'M' ? -1 : assignment == 'V' ? 1 : !Double.isNaN(in.angles()[e]) ? (int) Math.signum(in.angles()[e]) : 0;
        }
        double[][] uv;
        int[][] faces;
        FacePlacement.Rigid[] motion;
        List<FacePlacement.Hinge> hinges;
        List<int[]> orders;
        Kind kind;
        int[] bottomUp = null;
        if (in.foldedForm() || !in.flat()) {
            // A folded form: its vertices where the paper lies folded (2D: a flat folded state).
            if (in.faces() == null) {
                for (int v = 0; v < n; v++) {
                    if (vertices[v].length > 2 && vertices[v][2] != 0) {
                        throw new CreasePattern.Refused(String.format(Locale.ROOT, "vertex %d is (%s, %s, %s): a crease pattern lies flat,"
                                + " its vertices 2D points (or with z = 0); a folded form in 3D needs faces_vertices", v,
                                CreasePattern.fmt(vertices[v][0]), CreasePattern.fmt(vertices[v][1]), CreasePattern.fmt(vertices[v][2])));
                    }
                }
                throw new CreasePattern.Refused("a folded form needs faces_vertices to be unfolded");
            }
            double[][] xyz = new double[n][];
            for (int v = 0; v < n; v++) {
                xyz[v] = new double[] {vertices[v][0], vertices[v][1], vertices[v].length > 2 ? vertices[v][2] : 0};
            }
            kind = Kind.UNFOLDED;
            if (in.unfolded() != null) {
                // Where the file says each vertex lies on the paper (fold-convert --flat-fold writes it).
                uv = new double[n][];
                for (int v = 0; v < n; v++) {
                    uv[v] = new double[] {in.unfolded()[v][0], in.unfolded()[v][1]};
                }
                faces = counterClockwise(uv, in.faces());
            } else {
                faces = in.faces();
                // A folded form's faces are as isometric to the sheet as its numbers' digits allow:
                // Mathematica's square twist, to about a millionth of its size.
                uv = FacePlacement.develop(xyz, faces, edgeOf, hingeable, 1e-5 * size);
            }
            motion = FacePlacement.fromPlaces(uv, xyz, faces);
            hinges = FacePlacement.hingesOf(uv, faces, motion, edgeOf, hingeable, flatSign);
            orders = in.faceOrders();
            if (orders.isEmpty() && allFlat(motion)) {
                // Folded flat with no order given: found as a crease pattern's would be.
                double[] angles = new double[in.edges().length];
                for (int e = 0; e < angles.length; e++) {
                    angles[e] = in.assignments()[e] == 'V' ? Math.PI : in.assignments()[e] == 'M' ? -Math.PI : 0;
                }
                bottomUp = flatOrder(uv, faces, motion, in, edgeOf, angles, tolerance);
            }
        } else {
            uv = new double[n][];
            for (int v = 0; v < n; v++) {
                uv[v] = new double[] {vertices[v][0], vertices[v][1]};
            }
            faces = in.faces() != null ? in.faces() : PlanarFaceTracing.faces(uv, in.edges());
            if (faces.length == 0) {
                throw new CreasePattern.Refused("the edges enclose no face: a crease pattern needs its paper's outline");
            }
            faces = counterClockwise(uv, faces);
            if (in.folded() != null) {
                kind = Kind.GIVEN;
                motion = FacePlacement.fromPlaces(uv, in.folded(), faces);
                hinges = FacePlacement.hingesOf(uv, faces, motion, edgeOf, hingeable, flatSign);
                orders = in.foldedOrders();
            } else {
                double[] angles = new double[in.edges().length];
                boolean flat = true;
                for (int e = 0; e < angles.length; e++) {
                    char assignment = in.assignments()[e];
                    double degrees = in.angles()[e];
                    if (Double.isNaN(degrees)) {
                        if (assignment == 'U') {
                            throw new CreasePattern.Refused("edge " + e + " is U: iFold folds mountains and valleys (M, V), not unassigned"
                                    + " creases; give it M, V or F, or a fold angle");
                        }
                        degrees = assignment == 'V' ? 180 : assignment == 'M' ? -180 : 0;
                    }
                    angles[e] = Math.toRadians(degrees);
                    flat &= degrees == 0 || Math.abs(degrees) == 180;
                }
                if (flat) {
                    FlatVertices.check(uv, in.edges(), angles, hingeable);
                }
                // A flat pattern's vertices pass Kawasaki to the file's digits (a thousandth of a
                // radian at worst, in designs of curved creases): its faces meet again to as much.
                FacePlacement.Placed placed = FacePlacement.byAngles(uv, faces, edgeOf, angles, hingeable,
                        flat ? FlatVertices.ANGLE_TOLERANCE * size : tolerance);
                motion = placed.faces();
                hinges = placed.hinges();
                orders = List.of();
                kind = flat ? Kind.FLAT : Kind.ANGLES;
                if (flat) {
                    bottomUp = flatOrder(uv, faces, motion, in, edgeOf, angles, tolerance);
                }
            }
        }
        // The planes the faces lie on, each a host.
        List<HostFrame> frames = new ArrayList<>();
        int[] hostOf = hosts(uv, faces, motion, in.facing(), frames, tolerance);
        if (bottomUp == null) {
            bottomUp = orderFromFile(faces.length, orders, motion, hostOf, frames);
        }
        Isometry2[] poses = new Isometry2[faces.length];
        for (int f = 0; f < faces.length; f++) {
            poses[f] = pose(uv, faces[f], motion[f], frames.get(hostOf[f]));
        }
        double[] flatUv = new double[2 * n];
        for (int v = 0; v < n; v++) {
            if (uv[v] != null) {
                flatUv[2 * v] = uv[v][0];
                flatUv[2 * v + 1] = uv[v][1];
            }
        }
        List<int[]> creases = new ArrayList<>();
        List<Integer> creaseFolds = new ArrayList<>();
        for (int e = 0; e < in.edges().length; e++) {
            char assignment = in.assignments()[e];
            boolean folded = assignment == 'M' || assignment == 'V' || (!Double.isNaN(in.angles()[e]) && in.angles()[e] != 0 && hingeable[e]);
            if (folded) {
                creases.add(in.edges()[e]);
                creaseFolds.add(creases.size() - 1);
            }
        }
        double thickness = !Double.isNaN(in.thickness()) ? in.thickness() : size / 1000;
        // The sheet measures its faces as the folds do, against the folded paper's size: a
        // long strip's crease pattern is thousands of times the wrap it folds into, and overlaps
        // a millionth of that across are real layers.
        double sheetTolerance = Tolerance.ON_PLANE * foldedSize(uv, faces, motion);
        Sheet sheet = FoldedStateSheet.of(flatUv, faces, hostOf, poses, bottomUp, creases.toArray(new int[0][]),
                creaseFolds.stream().mapToInt(Integer::intValue).toArray(), thickness, sheetTolerance);
        int[] number = FoldedStateSheet.faceNumbers(bottomUp);
        List<Hinge> motionHinges = new ArrayList<>();
        motionHinges.add(new Hinge(number[0], -1, 0, 0, 1, 0, 0));
        for (FacePlacement.Hinge h : hinges) {
            if (h.parent() < 0) {
                motionHinges.add(new Hinge(number[h.face()], -1, 0, 0, 1, 0, 0)); // another piece's first face
                continue;
            }
            motionHinges.add(new Hinge(number[h.face()], number[h.parent()], uv[h.a()][0], uv[h.a()][1], uv[h.b()][0] - uv[h.a()][0],
                    uv[h.b()][1] - uv[h.a()][1], h.angle() * FacePlacement.sense(uv, faces[h.face()], h.a(), h.b())));
        }
        return new Result(sheet, frames.toArray(new HostFrame[0]), motionHinges, kind, creases.size());
    }

    /**
     * Checks a FOLD file whichever way it is then folded: every key and index ({@link FoldInput}),
     * no two edges of a crease pattern crossing or touching but at a shared vertex, and every
     * crease a side of a face where faces are given.
     *
     * @throws CreasePattern.Refused naming the key, the edges or the crease
     */
    /**
     * How many levels the file's own folded state stacks its paper in ({@code faces_ifold:level}
     * of its {@code foldedForm} frame, the highest plus one), or -1 where it states none: what a
     * folding of its crease pattern must come back to.
     */
    public static int statedStack(Map<String, Object> file) throws CreasePattern.Refused {
        FoldInput in = FoldInput.read(file);
        if (in.levels() == null) {
            return -1;
        }
        int most = -1;
        for (int level : in.levels()) {
            most = Math.max(most, level);
        }
        return most + 1;
    }

    public static void check(Map<String, Object> file) throws CreasePattern.Refused {
        checked(file);
    }

    private static FoldInput checked(Map<String, Object> file) throws CreasePattern.Refused {
        FoldInput in = FoldInput.read(file);
        if (in.flat() && !in.foldedForm()) {
            EdgeCrossings.refuse(in.vertices(), in.edges(), in.assignments());
        }
        if (in.faces() != null) {
            java.util.Set<Long> sides = new java.util.HashSet<>();
            for (int[] face : in.faces()) {
                for (int i = 0; i < face.length; i++) {
                    sides.add(FacePlacement.key(face[i], face[(i + 1) % face.length]));
                }
            }
            for (int e = 0; e < in.edges().length; e++) {
                char a = in.assignments()[e];
                if ((a == 'M' || a == 'V') && !sides.contains(FacePlacement.key(in.edges()[e][0], in.edges()[e][1]))) {
                    throw new CreasePattern.Refused("edge " + e + " is " + a + ", but no face of faces_vertices has it as a side: the"
                            + " faces must be cut by the creases");
                }
            }
        }
        if (!file.containsKey("edges_assignment") && !file.containsKey("edges_foldAngle") && in.folded() == null && in.flat()
                && !in.foldedForm()) {
            throw new CreasePattern.Refused("no edges_assignment: a crease pattern says which edges are the border (B), mountains (M),"
                    + " valleys (V) or flat (F)");
        }
        return in;
    }

    /** Whether every face lies in the plane z = 0 (a flat folded state). */
    private static boolean allFlat(FacePlacement.Rigid[] motion) {
        for (FacePlacement.Rigid m : motion) {
            if (Math.abs(m.turn(new double[] {0, 0, 1})[2]) < 1 - 1e-9 || Math.abs(m.t()[2]) > 1e-9) {
                return false;
            }
        }
        return true;
    }

    /** The diagonal of the box the folded faces take in space. */
    private static double foldedSize(double[][] uv, int[][] faces, FacePlacement.Rigid[] motion) {
        List<double[]> placed = new ArrayList<>();
        for (int f = 0; f < faces.length; f++) {
            for (int v : faces[f]) {
                placed.add(motion[f].apply(uv[v][0], uv[v][1], 0));
            }
        }
        return diagonal(placed.toArray(new double[0][]));
    }

    /** The diagonal of the box the points take (2D points lie at z = 0). */
    private static double diagonal(double[][] points) {
        double[] min = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] max = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (double[] p : points) {
            for (int k = 0; k < 3; k++) {
                double c = k < p.length ? p[k] : 0;
                min[k] = Math.min(min[k], c);
                max[k] = Math.max(max[k], c);
            }
        }
        return Math.hypot(max[0] - min[0], Math.hypot(max[1] - min[1], max[2] - min[2]));
    }

    private static int[][] counterClockwise(double[][] uv, int[][] faces) throws CreasePattern.Refused {
        int[][] oriented = new int[faces.length][];
        for (int f = 0; f < faces.length; f++) {
            double area = PlanarFaceTracing.area(uv, faces[f]);
            if (area == 0) {
                throw new CreasePattern.Refused("face " + f + " has no area on the paper");
            }
            oriented[f] = faces[f].clone();
            if (area < 0) {
                for (int i = 0, j = oriented[f].length - 1; i < j; i++, j--) {
                    int swap = oriented[f][i];
                    oriented[f][i] = oriented[f][j];
                    oriented[f][j] = swap;
                }
            }
        }
        return oriented;
    }

    /**
     * Each face's host: faces on one plane share it (their normals parallel or opposite, their
     * offsets equal). Planes are found by the point of each nearest the origin, which is the same
     * whichever way a face on it looks, in a grid of cells a thousand tolerances wide, each face
     * compared with the planes in its cell and the cells around.
     */
    private static int[] hosts(double[][] uv, int[][] faces, FacePlacement.Rigid[] motion, int[] facing, List<HostFrame> frames,
            double tolerance) {
        int[] hostOf = new int[faces.length];
        Map<List<Long>, List<Integer>> cells = new HashMap<>();
        double cell = 1000 * tolerance;
        for (int f = 0; f < faces.length; f++) {
            double[] normal = motion[f].turn(new double[] {0, 0, 1});
            // Where the file says which side is out, faces of one plane looking out opposite ways
            // (under an overhang and on a column's top of one height) rest on two hosts, each with
            // its layers on its own side; without, on one, whichever way its first face looks.
            boolean sided = facing != null;
            if (sided && facing[f] < 0) {
                normal = FacePlacement.scale(normal, -1);
            }
            double[] origin = motion[f].apply(uv[faces[f][0]][0], uv[faces[f][0]][1], 0);
            double[] nearest = FacePlacement.scale(normal, FacePlacement.dot(normal, origin));
            long[] at = {(long) Math.floor(nearest[0] / cell), (long) Math.floor(nearest[1] / cell), (long) Math.floor(nearest[2] / cell)};
            int host = -1;
            search:
            for (long dx = -1; dx <= 1; dx++) {
                for (long dy = -1; dy <= 1; dy++) {
                    for (long dz = -1; dz <= 1; dz++) {
                        for (int h : cells.getOrDefault(List.of(at[0] + dx, at[1] + dy, at[2] + dz), List.of())) {
                            HostFrame frame = frames.get(h);
                            double along = FacePlacement.dot(frame.normal(), normal);
                            if ((sided ? along : Math.abs(along)) > 1 - 1e-9
                                    && Math.abs(FacePlacement.dot(frame.normal(), FacePlacement.sub(origin, frame.origin()))) <= tolerance) {
                                host = h;
                                break search;
                            }
                        }
                    }
                }
            }
            if (host < 0) {
                host = frames.size();
                double[] ex = motion[f].turn(new double[] {1, 0, 0});
                frames.add(new HostFrame(origin, ex, FacePlacement.cross(normal, ex), normal, new double[6]));
                cells.computeIfAbsent(List.of(at[0], at[1], at[2]), k -> new ArrayList<>()).add(host);
            }
            hostOf[f] = host;
        }
        return hostOf;
    }

    /** Face f's pose on its host: its paper corner's place and the turn of its axes, in the host's frame. */
    private static Isometry2 pose(double[][] uv, int[] face, FacePlacement.Rigid motion, HostFrame frame) {
        double[] eu = motion.turn(new double[] {1, 0, 0});
        double[] ev = motion.turn(new double[] {0, 1, 0});
        double u0 = uv[face[0]][0];
        double v0 = uv[face[0]][1];
        double[] at = FacePlacement.sub(motion.apply(u0, v0, 0), frame.origin());
        return Isometry2.anchored(FacePlacement.dot(frame.ex(), eu), FacePlacement.dot(frame.ex(), ev), FacePlacement.dot(frame.ey(), eu),
                FacePlacement.dot(frame.ey(), ev), u0, v0, FacePlacement.dot(frame.ex(), at), FacePlacement.dot(frame.ey(), at));
    }

    /**
     * The faces bottom up by the file's face orders ([f, g, s]: f lies on the side of g's normal
     * s says), each order turned into its host's up; faces no order relates, in their numbers'
     * order.
     */
    private static int[] orderFromFile(int count, List<int[]> orders, FacePlacement.Rigid[] motion, int[] hostOf, List<HostFrame> frames)
            throws CreasePattern.Refused {
        List<List<Integer>> over = new ArrayList<>();
        for (int f = 0; f < count; f++) {
            over.add(new ArrayList<>());
        }
        for (int[] order : orders) {
            int f = order[0];
            int g = order[1];
            if (order[2] == 0 || hostOf[f] != hostOf[g] || f == g) {
                continue;
            }
            double[] ng = motion[g].turn(new double[] {0, 0, 1});
            boolean fAbove = order[2] * FacePlacement.dot(ng, frames.get(hostOf[g]).normal()) > 0;
            over.get(fAbove ? g : f).add(fAbove ? f : g);
        }
        int[] bottomUp = LayerSolver.kahn(count, over);
        if (count > 0 && bottomUp[count - 1] < 0) {
            throw new CreasePattern.Refused("faceOrders put faces in a cycle: no stack of layers is so ordered");
        }
        return bottomUp;
    }

    /** A flat folding's layer order: the faces in the plane they fold into, their creases, the solver. */
    private static int[] flatOrder(double[][] uv, int[][] faces, FacePlacement.Rigid[] motion, FoldInput in, Map<Long, Integer> edgeOf,
            double[] angles, double tolerance) throws CreasePattern.Refused {
        double[][] polygons = new double[faces.length][];
        boolean[] faceUp = new boolean[faces.length];
        for (int f = 0; f < faces.length; f++) {
            polygons[f] = new double[2 * faces[f].length];
            for (int i = 0; i < faces[f].length; i++) {
                double[] p = motion[f].apply(uv[faces[f][i]][0], uv[faces[f][i]][1], 0);
                polygons[f][2 * i] = p[0];
                polygons[f][2 * i + 1] = p[1];
            }
            faceUp[f] = motion[f].turn(new double[] {0, 0, 1})[2] > 0;
        }
        Map<Long, int[]> sides = FacePlacement.sides(faces);
        List<LayerSolver.FlatCrease> creases = new ArrayList<>();
        for (Map.Entry<Long, int[]> entry : sides.entrySet()) {
            int[] pair = entry.getValue();
            Integer e = edgeOf.get(entry.getKey());
            if (pair[0] < 0 || pair[1] < 0) {
                continue;
            }
            long key = entry.getKey();
            int a = (int) (key >>> 32);
            int b = (int) key;
            double[] p = motion[pair[0]].apply(uv[a][0], uv[a][1], 0);
            double[] q = motion[pair[0]].apply(uv[b][0], uv[b][1], 0);
            if (e != null && Math.abs(angles[e]) >= 1) {
                creases.add(new LayerSolver.FlatCrease(pair[0], pair[1], angles[e] > 0, p[0], p[1], q[0], q[1]));
            } else {
                creases.add(LayerSolver.FlatCrease.join(pair[0], pair[1], p[0], p[1], q[0], q[1]));
            }
        }
        // Overlaps as the layer-order check counts them (a billionth of the folded paper); lines
        // as the file's digits allow.
        return LayerSolver.order(polygons, faceUp, creases, Tolerance.ON_PLANE * foldedSize(uv, faces, motion), tolerance);
    }
}
