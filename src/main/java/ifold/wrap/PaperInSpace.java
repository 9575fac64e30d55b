package ifold.wrap;

import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Polygons2;
import ifold.sheet.Sheet;
import java.util.ArrayList;
import java.util.List;

/**
 * Folded paper in space, with its thickness: every face of a sheet (a wrapped strip, or the
 * sheet of a fold script or a demo) placed on its host at its level, with vertices shared
 * where neighbouring faces meet, and caps where they meet at different heights (the paper bent
 * around a fold, or over an edge of the surface).
 *
 * <p>A face at level k lies at height (k + 1/2)·T above its host: its mid-surface, so the
 * paper's lower side touches the surface, or the face below. A cap over an edge of the surface
 * is one quad from the crease on one host's layer to the crease on the other's. A cap at a flat
 * fold on one host is its bend, the paper wrapping the layers between its two, as a book's
 * cover wraps its pages: where it wraps no other fold about its crease line, one wall standing
 * on the crease, so that paper between its layers that reaches the crease from beyond only
 * touches it (a valid layer order keeps such paper from going across). A bend that wraps folds
 * nested about the same line steps out beyond them, a thickness a rank ({@link NestedBends}):
 * from its upper layer it leans out at 45 degrees, from its lower at the slope of the room
 * beyond the host's edge ({@link HostFrame#room}; 45 degrees where nothing limits it), and a
 * wall joins the two; less far where the room beyond a nearby edge is short ({@link
 * HostFrame#lean}), and those it wraps then less far still. Its rows stop on the line of a bend
 * they would run through where two creases meet at a corner.
 *
 * @param xyz x, y, z of each vertex
 * @param uv the paper coordinates of each vertex
 * @param paperFaces the faces of the sheet, as vertex loops (counter-clockwise on the sheet)
 * @param paperHosts the triangle each paper face rests on
 * @param caps the cap facets
 * @param capAfter for each cap, the later of the two faces it joins (index in paperFaces): it exists from then on
 * @param creep the paper vertices that stand back from a concave edge, and where they stood
 */
public record PaperInSpace(double[] xyz, double[] uv, List<int[]> paperFaces, int[] paperHosts, List<int[]> caps, int[] capAfter,
        Creep creep) {

    /** Paper that stands where it was laid: nothing creeps. */
    public PaperInSpace(double[] xyz, double[] uv, List<int[]> paperFaces, int[] paperHosts, List<int[]> caps, int[] capAfter) {
        this(xyz, uv, paperFaces, paperHosts, caps, capAfter, Creep.NONE);
    }

    public int vertexCount() {
        return uv.length / 2;
    }

    /**
     * Paper vertices moved in from a concave edge of their host ({@link ConcaveWalls}): thick
     * layers that ran up to the edge would run into the layers of the host across. The sheet is
     * folded without thickness; these are where the layers' creases creep once it has some.
     *
     * @param vertices the vertices moved, in increasing order
     * @param from x, y, z of each where the paper of no creep puts it: on its layer over the
     *     sheet's crease
     */
    public record Creep(int[] vertices, double[] from) {
        public static final Creep NONE = new Creep(new int[0], new double[0]);

        /** Where {@code geometry}'s vertex v lies without creep, into {@code out}: its own place, or where it was before it crept. */
        public double[] laid(PaperInSpace geometry, int v, double[] out) {
            int k = vertices.length == 0 ? -1 : java.util.Arrays.binarySearch(vertices, v);
            System.arraycopy(k >= 0 ? from : geometry.xyz(), 3 * (k >= 0 ? k : v), out, 0, 3);
            return out;
        }

        /** The farthest any vertex of {@code geometry} crept. */
        public double most(PaperInSpace geometry) {
            double most = 0;
            double[] xyz = geometry.xyz();
            for (int k = 0; k < vertices.length; k++) {
                int v = vertices[k];
                most = Math.max(most, Math.sqrt(Math.pow(xyz[3 * v] - from[3 * k], 2) + Math.pow(xyz[3 * v + 1] - from[3 * k + 1], 2)
                        + Math.pow(xyz[3 * v + 2] - from[3 * k + 2], 2)));
            }
            return most;
        }
    }

    /** The strip placed in space. */
    public static PaperInSpace of(Sheet sheet, HostFrame[] frames) {
        Builder builder = new Builder(sheet, frames);
        return builder.build();
    }

    /**
     * Flat folds whose creases lie within this many thicknesses of one line share it: their
     * bends would stand within touching distance of each other there ({@link NestedBends}).
     */
    static final double NEST_TOLERANCE = 0.01;

    private static final class Builder {
        private final Sheet sheet;
        private final HostFrame[] frames;
        private final int[] levels;
        private double[] xyz = new double[3 * 64];
        private double[] uv = new double[2 * 64];
        private int vertices;
        /** For each paper vertex, the space vertices made for it (a short list: one per layer it is on). */
        private final List<int[]> copies = new ArrayList<>();
        private final double merge;
        private final double exact;
        /** The triangle and level each space vertex was made for (caps' middle rows: -1). */
        private int[] copyHost = new int[64];
        private int[] copyLevel = new int[64];
        /** Where paper ends at the concave edges of its host. */
        private ConcaveWalls walls;
        /** The vertices made moved in from a concave edge (in the order made, so increasing), and where the paper put them. */
        private int[] creptVertices = new int[0];
        private double[] creptFrom = new double[0];
        private int creptCount;

        Builder(Sheet sheet, HostFrame[] frames) {
            this.sheet = sheet;
            this.frames = frames;
            this.levels = sheet.levels();
            // Without thickness, copies closer than this are the same point: rounding apart.
            this.merge = sheet.tolerance();
            // Faces on one layer share a vertex where their poses agree to rounding; a crease
            // vertex computed a little off its crease makes the two sides differ by more, and each
            // then keeps its own copy, so that no face is bent by a neighbour's rounding.
            this.exact = Math.min(sheet.tolerance() * 1e-3, sheet.width() * 1e-11);
            for (int v = 0; v < sheet.vertexCount(); v++) {
                copies.add(new int[0]);
            }
        }

        PaperInSpace build() {
            int faces = sheet.faceCount();
            // Flat folds first, from the sheet alone (two faces across a paper edge on one host at
            // two levels): how far each bend stands out depends on the folds nested about its
            // crease line (NestedBends), and where one lies along a concave edge of its host, the
            // paper of its layers ends on its wall (ConcaveWalls), which places the vertices.
            List<NestedBends.Bend> bends = new ArrayList<>();
            List<int[]> bendEdges = new ArrayList<>();
            forEachJoin((f, i, g, a, b) -> {
                if (isBend(f, g)) {
                    bends.add(bend(f, g, a, b));
                    bendEdges.add(new int[] {f, i, g, a, b});
                }
            });
            NestedBends nested = NestedBends.of(bends, sheet.thickness() * NEST_TOLERANCE);
            int[] ranks = nested.ranks();
            int[] backToBack = nested.backToBack();
            double[] stackTop = new double[frames.length];
            for (int f = 0; f < faces; f++) {
                stackTop[sheet.host(f)] = Math.max(stackTop[sheet.host(f)], (levels[f] + 1) * sheet.thickness());
            }
            walls = ConcaveWalls.of(bends, ranks, backToBack, frames, sheet.thickness(), sheet.tolerance(), stackTop);
            boolean[] onWall = walls.along();

            List<int[]> paper = new ArrayList<>(faces);
            int[] hosts = new int[faces];
            int[][] corners = new int[faces][];
            for (int f = 0; f < faces; f++) {
                int[] loop = sheet.loop(f);
                int[] placed = new int[loop.length];
                for (int i = 0; i < loop.length; i++) {
                    placed[i] = vertex(f, loop[i]);
                }
                corners[f] = placed;
                paper.add(placed);
                hosts[f] = sheet.host(f);
            }
            List<int[]> caps = new ArrayList<>();
            List<Integer> capAfter = new ArrayList<>();
            forEachJoin((f, i, g, a, b) -> {
                if (isBend(f, g)) {
                    return; // below, once every bend is known
                }
                int fa = corners[f][i];
                int fb = corners[f][(i + 1) % corners[f].length];
                int ga = cornerOf(g, a, corners[g]);
                int gb = cornerOf(g, b, corners[g]);
                if ((fa == ga || samePlace(fa, ga)) && (fb == gb || samePlace(fb, gb))) {
                    return; // the paper runs on flat, or bends over an edge with no thickness
                }
                caps.add(new int[] {fa, fb, gb, ga});
                capAfter.add(g);
            });
            List<int[]> bendCorners = new ArrayList<>();
            for (int[] edge : bendEdges) {
                int f = edge[0];
                int i = edge[1];
                int g = edge[2];
                int a = edge[3];
                int b = edge[4];
                int length = sheet.loop(f).length;
                bendCorners.add(new int[] {f, g, a, b, corners[f][i], corners[f][(i + 1) % length], cornerOf(g, a, corners[g]),
                        cornerOf(g, b, corners[g])});
            }
            double[] outs = new double[bends.size()];
            double[] slopes = new double[bends.size()];
            for (int k = 0; k < bends.size(); k++) {
                NestedBends.Bend bend = bends.get(k);
                // Each rank steps out by a thickness, less where the room beyond the host's edge
                // is narrow: the lower side then leans out at the room's slope s, and a bend of
                // rank r (its layers at least 2r + 1 apart) keeps a wall between its two sides:
                // r·step·(1/s + 1) <= 2r·T.
                if (ranks[k] == 0 || walls.along(k)) {
                    continue; // on its crease whatever the room, or on its wall at a concave edge
                }
                HostFrame frame = frames[bend.host()];
                slopes[k] = frame.roomBeyond(bend.ax(), bend.ay(), bend.bx(), bend.by(), sheet.tolerance());
                double out = ranks[k] * sheet.thickness() * Math.min(1, 2 * slopes[k] / (1 + slopes[k]));
                double low = (bend.low() + 0.5) * sheet.thickness();
                out = frame.lean(bend.ax(), bend.ay(), bend.nx(), bend.ny(), low, slopes[k], out);
                outs[k] = frame.lean(bend.bx(), bend.by(), bend.nx(), bend.ny(), low, slopes[k], out);
            }
            nested.keepNested(outs);
            double[] past = nested.mitres(outs);

            for (int k = 0; k < bends.size(); k++) {
                int[] c = bendCorners.get(k);
                int f = c[0];
                int g = c[1];
                NestedBends.Bend bend = bends.get(k);
                double out = outs[k];
                if ((c[4] == c[6] || samePlace(c[4], c[6])) && (c[5] == c[7] || samePlace(c[5], c[7]))) {
                    continue; // paper of no thickness folded flat: nothing to bridge
                }
                if (out == 0 && ConcaveWalls.standsBack(backToBack, onWall, k)) {
                    // Back to back with another fold: its layers stand back half a thickness, and its
                    // bend reaches the crease halfway up, where the other's meets it.
                    double middle = (height(f) + height(g)) / 2;
                    int apexA = apex(f, c[2], middle);
                    int apexB = apex(f, c[3], middle);
                    caps.add(new int[] {c[4], c[5], apexB, apexA});
                    caps.add(new int[] {apexA, apexB, c[7], c[6]});
                    capAfter.add(g);
                    capAfter.add(g);
                    continue;
                }
                if (out == 0) {
                    caps.add(new int[] {c[4], c[5], c[7], c[6]});
                    capAfter.add(g);
                    continue;
                }
                // Out beyond the crease from each layer, and straight across between.
                boolean fLower = height(f) < height(g);
                double lower = Math.min(height(f), height(g)) + out / slopes[k];
                double upper = Math.max(height(f), height(g)) - out;
                int fma = row(f, bend, c[2], out, -past[2 * k], fLower ? lower : upper);
                int fmb = row(f, bend, c[3], out, past[2 * k + 1], fLower ? lower : upper);
                int gma = row(f, bend, c[2], out, -past[2 * k], fLower ? upper : lower);
                int gmb = row(f, bend, c[3], out, past[2 * k + 1], fLower ? upper : lower);
                caps.add(new int[] {c[4], c[5], fmb, fma});
                caps.add(new int[] {fma, fmb, gmb, gma});
                caps.add(new int[] {gma, gmb, c[7], c[6]});
                capAfter.add(g);
                capAfter.add(g);
                capAfter.add(g);
            }
            Creep creep = creptCount == 0 ? Creep.NONE
                    : new Creep(java.util.Arrays.copyOf(creptVertices, creptCount), java.util.Arrays.copyOf(creptFrom, 3 * creptCount));
            return new PaperInSpace(java.util.Arrays.copyOf(xyz, 3 * vertices), java.util.Arrays.copyOf(uv, 2 * vertices), paper,
                    hosts, caps, capAfter.stream().mapToInt(Integer::intValue).toArray(), creep);
        }

        /** What is done with two faces f and g (g > f) joined along paper edge a → b, edge i of f. */
        private interface Join {
            void of(int f, int i, int g, int a, int b);
        }

        /** Each pair of faces joined on the sheet, once. */
        private void forEachJoin(Join join) {
            for (int f = 0; f < sheet.faceCount(); f++) {
                int[] loop = sheet.loop(f);
                for (int i = 0; i < loop.length; i++) {
                    int a = loop[i];
                    int b = loop[(i + 1) % loop.length];
                    int g = sheet.faceAcross(a, b);
                    if (g > f) {
                        join.of(f, i, g, a, b);
                    }
                }
            }
        }

        /** Whether faces f and g, joined on the sheet, are folded flat onto each other: one host, two levels. */
        private boolean isBend(int f, int g) {
            return sheet.host(f) == sheet.host(g) && levels[f] != levels[g];
        }

        private int cornerOf(int g, int paperVertex, int[] placed) {
            int[] loop = sheet.loop(g);
            for (int i = 0; i < loop.length; i++) {
                if (loop[i] == paperVertex) {
                    return placed[i];
                }
            }
            throw new IllegalStateException("faces across an edge do not share its vertices");
        }

        private double height(int f) {
            return (levels[f] + 0.5) * sheet.thickness();
        }

        /**
         * The space vertex of paper vertex p as face f places it, shared with the faces that
         * place it at the same level of the same triangle (they agree to rounding: their poses
         * differ by the reflections of the creases between them, which fix the crease), and,
         * without thickness, with faces on the next triangle over an edge where the point lies.
         */
        private int vertex(int f, int p) {
            Isometry2 pose = sheet.pose(f);
            HostFrame frame = frames[sheet.host(f)];
            double[] point = new double[3];
            double[] xy = new double[2];
            int host = sheet.host(f);
            double x = pose.x(sheet.u(p), sheet.v(p));
            double y = pose.y(sheet.u(p), sheet.v(p));
            int[] loop = sheet.loop(f);
            double cx = 0;
            double cy = 0;
            for (int q : loop) {
                cx += pose.x(sheet.u(q), sheet.v(q)) / loop.length;
                cy += pose.y(sheet.u(q), sheet.v(q)) / loop.length;
            }
            walls.place(host, frame, x, y, height(f), cx, cy, frame.stops() == null ? null : over(f, p, pose), xy);
            boolean crept = xy[0] != x || xy[1] != y;
            frame.toSpace(xy[0], xy[1], height(f), point, 0);
            for (int copy : copies.get(p)) {
                if (copyHost[copy] == host && copyLevel[copy] == levels[f] && closer(copy, point, exact)) {
                    return copy;
                }
            }
            if (sheet.thickness() == 0) {
                for (int copy : copies.get(p)) {
                    if (closer(copy, point, merge)) {
                        return copy;
                    }
                }
            }
            int v = add(point, sheet.u(p), sheet.v(p));
            if (v >= copyHost.length) {
                copyHost = java.util.Arrays.copyOf(copyHost, 2 * v + 2);
                copyLevel = java.util.Arrays.copyOf(copyLevel, 2 * v + 2);
            }
            copyHost[v] = host;
            copyLevel[v] = levels[f];
            if (crept) {
                if (creptCount == creptVertices.length) {
                    creptVertices = java.util.Arrays.copyOf(creptVertices, 2 * creptCount + 8);
                    creptFrom = java.util.Arrays.copyOf(creptFrom, 3 * creptVertices.length);
                }
                creptVertices[creptCount] = v;
                frame.toSpace(x, y, height(f), creptFrom, 3 * creptCount);
                creptCount++;
            }
            int[] list = copies.get(p);
            int[] longer = java.util.Arrays.copyOf(list, list.length + 1);
            longer[list.length] = v;
            copies.set(p, longer);
            return v;
        }

        /**
         * Where face f's paper goes on from paper vertex p over an edge to another host: the other
         * ends of its sheet edges at p whose face across lies on another host, in f's host frame
         * (x, y pairs); null where none does.
         */
        private double[] over(int f, int p, Isometry2 pose) {
            int[] loop = sheet.loop(f);
            double[] over = null;
            for (int i = 0; i < loop.length; i++) {
                if (loop[i] != p) {
                    continue;
                }
                int next = loop[(i + 1) % loop.length];
                int previous = loop[(i + loop.length - 1) % loop.length];
                for (int q : new int[] {next, previous}) {
                    int g = q == next ? sheet.faceAcross(p, next) : sheet.faceAcross(previous, p);
                    if (g >= 0 && sheet.host(g) != sheet.host(f)) {
                        double[] longer = over == null ? new double[2] : java.util.Arrays.copyOf(over, over.length + 2);
                        longer[longer.length - 2] = pose.x(sheet.u(q), sheet.v(q));
                        longer[longer.length - 1] = pose.y(sheet.u(q), sheet.v(q));
                        over = longer;
                    }
                }
            }
            return over;
        }

        /**
         * The flat fold between faces f and g on one host about the crease (a, b), in the host's
         * plane: the bend stands out on the side away from both faces (a flat fold lays them on
         * the same side).
         */
        private NestedBends.Bend bend(int f, int g, int a, int b) {
            Isometry2 pose = sheet.pose(f);
            double ax = pose.x(sheet.u(a), sheet.v(a));
            double ay = pose.y(sheet.u(a), sheet.v(a));
            double bx = pose.x(sheet.u(b), sheet.v(b));
            double by = pose.y(sheet.u(b), sheet.v(b));
            double length = Polygons2.length(bx - ax, by - ay);
            // Face f runs counter-clockwise on the sheet; placed mirrored it runs clockwise, and
            // its inside is to the right of a -> b instead of the left.
            double nx = (by - ay) / length;
            double ny = -(bx - ax) / length;
            if (pose.mirrors()) {
                nx = -nx;
                ny = -ny;
            }
            return new NestedBends.Bend(sheet.host(f), ax, ay, bx, by, nx, ny, Math.min(levels[f], levels[g]),
                    Math.max(levels[f], levels[g]));
        }

        /**
         * A row of a bend's cap at paper vertex p of its crease: {@code out} beyond the crease,
         * moved {@code along} it (from its end a towards b), at {@code height}.
         */
        private int row(int f, NestedBends.Bend bend, int p, double out, double along, double height) {
            Isometry2 pose = sheet.pose(f);
            double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
            double px = pose.x(sheet.u(p), sheet.v(p)) + bend.nx() * out + (bend.bx() - bend.ax()) / length * along;
            double py = pose.y(sheet.u(p), sheet.v(p)) + bend.ny() * out + (bend.by() - bend.ay()) / length * along;
            double[] point = new double[3];
            double[] xy = new double[2];
            walls.place(sheet.host(f), frames[sheet.host(f)], px, py, height, xy);
            frames[sheet.host(f)].toSpace(xy[0], xy[1], height, point, 0);
            return capVertex(point, sheet.u(p), sheet.v(p));
        }

        /** A vertex of a cap's middle rows, made for no face's layer: shared with none. */
        private int capVertex(double[] point, double u, double v) {
            int made = add(point, u, v);
            if (made >= copyHost.length) {
                copyHost = java.util.Arrays.copyOf(copyHost, 2 * made + 2);
                copyLevel = java.util.Arrays.copyOf(copyLevel, 2 * made + 2);
            }
            copyHost[made] = -1;
            return made;
        }


        /**
         * The crease's point at paper vertex p (of face f's pose) at {@code height}: a bend's apex,
         * on the crease line where no fold back to back moves it, mitred by a concave edge.
         */
        private int apex(int f, int p, double height) {
            Isometry2 pose = sheet.pose(f);
            double[] point = new double[3];
            double[] xy = new double[2];
            walls.apex(sheet.host(f), frames[sheet.host(f)], pose.x(sheet.u(p), sheet.v(p)), pose.y(sheet.u(p), sheet.v(p)), height, xy);
            frames[sheet.host(f)].toSpace(xy[0], xy[1], height, point, 0);
            return capVertex(point, sheet.u(p), sheet.v(p));
        }

        private boolean closer(int copy, double[] point, double distance) {
            double dx = xyz[3 * copy] - point[0];
            double dy = xyz[3 * copy + 1] - point[1];
            double dz = xyz[3 * copy + 2] - point[2];
            return dx * dx + dy * dy + dz * dz <= distance * distance;
        }

        private boolean samePlace(int a, int b) {
            return closer(a, new double[] {xyz[3 * b], xyz[3 * b + 1], xyz[3 * b + 2]}, merge);
        }

        private int add(double[] point, double u, double v) {
            if (3 * vertices + 3 > xyz.length) {
                xyz = java.util.Arrays.copyOf(xyz, 2 * xyz.length);
                uv = java.util.Arrays.copyOf(uv, 2 * uv.length);
            }
            xyz[3 * vertices] = point[0];
            xyz[3 * vertices + 1] = point[1];
            xyz[3 * vertices + 2] = point[2];
            uv[2 * vertices] = u;
            uv[2 * vertices + 1] = v;
            return vertices++;
        }
    }
}
