package ifold.wrap;

import ifold.geom.DoubleList;
import ifold.geom.IntList;
import ifold.geom.PackedIntArrays;
import ifold.io.Workers;
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
 * HostFrame#lean}) or a fold facing it stands in front of it ({@link FacingBends}), and those it
 * wraps then less far still. Its rows stop on the line of a bend
 * they would run through where two creases meet at a corner, of its host or of another host in
 * its plane ({@link CoplanarHosts}).
 *
 * <p>Where thick layers stand back from a concave edge (on its mitre, or on the wall of a fold
 * made along it: {@link ConcaveWalls}), a face is cut where the paper begins to stand back, and
 * each piece is placed as it lies: whole, or squashed onto the line where its layer ends.
 *
 * @param xyz x, y, z of each vertex
 * @param uv the paper coordinates of each vertex
 * @param paperFaces the faces of the sheet, as vertex loops (counter-clockwise on the sheet): one
 *     for each face, or the pieces it is cut into where its paper stands back from a concave edge
 * @param paperHosts the triangle each paper face rests on
 * @param caps the cap facets
 * @param capAfter for each cap, the later of the two faces it joins (index in paperFaces): it exists from then on
 * @param creep the paper vertices that stand back from a concave edge, and where they stood
 * @param pieceStart the paper faces of the sheet's face f are {@code pieceStart[f]} to {@code
 *     pieceStart[f + 1] - 1}
 */
public record PaperInSpace(double[] xyz, double[] uv, List<int[]> paperFaces, int[] paperHosts, List<int[]> caps, int[] capAfter,
        Creep creep, int[] pieceStart) {

    /** Paper that stands where it was laid: nothing creeps, every face whole. */
    public PaperInSpace(double[] xyz, double[] uv, List<int[]> paperFaces, int[] paperHosts, List<int[]> caps, int[] capAfter) {
        this(xyz, uv, paperFaces, paperHosts, caps, capAfter, Creep.NONE, wholeFaces(paperFaces.size()));
    }

    private static int[] wholeFaces(int count) {
        int[] start = new int[count + 1];
        for (int f = 0; f <= count; f++) {
            start[f] = f;
        }
        return start;
    }

    /** The sheet's faces. */
    public int sheetFaceCount() {
        return pieceStart.length - 1;
    }

    /** The sheet face that paper face (piece) {@code piece} is of. */
    public int sheetFace(int piece) {
        int k = java.util.Arrays.binarySearch(pieceStart, piece);
        if (k < 0) {
            return -k - 2;
        }
        while (k + 1 < pieceStart.length && pieceStart[k + 1] == piece) {
            k++; // past faces of no piece
        }
        return k;
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
        // The builder's working lists are garbage once it is done, and its points are copied out
        // one list at a time, each let go as it is copied: on the 5,000-triangle torus the lists,
        // the points and their copies held at once were the run's peak.
        Built built = new Builder(sheet, frames).build();
        double[] xyz = built.xyz().drain();
        double[] uv = built.uv().drain();
        return new PaperInSpace(xyz, uv, built.paper(), built.hosts(), built.caps(), built.capAfter(), built.creep(), built.pieceStart());
    }

    /** What the builder made, its vertices still in lists. */
    private record Built(DoubleList xyz, DoubleList uv, List<int[]> paper, int[] hosts, List<int[]> caps, int[] capAfter, Creep creep,
            int[] pieceStart) {
    }

    /**
     * Flat folds whose creases lie within this many thicknesses of one line share it: their
     * bends would stand within touching distance of each other there ({@link NestedBends}).
     */
    static final double NEST_TOLERANCE = 0.01;

    private static final class Builder {
        private final Sheet sheet;
        private HostFrame[] frames;
        private final int[] levels;
        private final DoubleList xyz = new DoubleList();
        private final DoubleList uv = new DoubleList();
        /**
         * For each paper vertex, the first space vertex made for it (-1: none); the others (one
         * per layer it is on) follow it by {@link #nextCopy}. Chains through one array rather than
         * an array a point: a big wrap makes millions of points, and the collector walked them all.
         */
        private int[] firstCopy;
        /**
         * For each space vertex made for a paper vertex or a cut point, the next made for the same
         * point (-1: none); null once the faces are placed, as {@link #firstCopy} and {@link
         * #copyLevel} then are: the caps share no vertex by them ({@link #doneWithFaces}).
         */
        private IntList nextCopy = new IntList();
        private final double merge;
        private final double exact;
        /** The triangle and level each space vertex was made for (caps' middle rows: -1). */
        private final IntList copyHost = new IntList();
        private IntList copyLevel = new IntList();
        /** Each face's corners as placed whole (null for a face placed in pieces). */
        private int[][] corners;
        /**
         * For a face placed in pieces, where its sides begin in {@link #sideStarts} (-1 for a face
         * placed whole): there, for each side of its loop and one past the last, where that side's
         * edges of pieces begin in {@link #sideEdges}.
         */
        private int[] sidesOf;
        /**
         * Faces placed whole that lie wholly in a region where their layer creeps, pressed onto the
         * region's line with no area: along their sides they count as squashed, as such pieces do,
         * so that a bend between two layers both pressed there is left out. Counted as unsquashed,
         * a fold of levels 0 and 1 from the far end of a wall's crease at square_frame's outer
         * corners (its crease 2 T long, wholly within the wall's reach) drew its bend on the wall's
         * line, in the wall's plane: 2 pairs in one plane at each of five corners.
         */
        private boolean[] pressedWhole;
        /**
         * The layers' points made on a crease that a bend's facet pressed flat onto a mitre left
         * out ({@link #addPressed}), since the stretch being drawn began.
         */
        private IntList leftOut = new IntList();
        private final IntList sideStarts = new IntList();
        /**
         * The pieces' edges along the sides of their faces, {@link #SIDE_EDGE} numbers each: from,
         * to (along the side), their two vertices, 1 where squashed, and at each end the unit
         * normal (x, y on the host's frame) of the line across its region that cut it there (where
         * a wall or a concave stretch ends; NaN where none did).
         */
        private final DoubleList sideEdges = new DoubleList();
        private static final int SIDE_EDGE = 9;
        /** The pieces of face f are paper faces pieceStart[f] to pieceStart[f + 1] - 1. */
        private int[] pieceStart;
        /** Where paper ends at the concave edges of its host. */
        private ConcaveWalls walls;
        /** The bends standing out beyond the edges the strip crosses, known before the caps over those edges. */
        private CrossingOverBends crossings;
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
            this.firstCopy = new int[sheet.vertexCount()];
            java.util.Arrays.fill(firstCopy, -1);
        }

        Built build() {
            int faces = sheet.faceCount();
            // Flat folds first, from the sheet alone (two faces across a paper edge on one host at
            // two levels): how far each bend stands out depends on the folds nested about its
            // crease line (NestedBends), and where one lies along a concave edge of its host, the
            // paper of its layers ends on its wall (ConcaveWalls), which places the vertices.
            List<NestedBends.Bend> bends = new ArrayList<>();
            IntList bendEdges = new IntList(); // f, i, g, a, b each
            // The joins that are not bends, for the caps once the faces are placed: which sides of
            // the faces' loops (in order) join a later face, and that face. The face across a side
            // is a hash lookup, and looked up again there it was half of the joins' time.
            java.util.BitSet flatSides = new java.util.BitSet();
            IntList flatAcross = new IntList();
            for (int f = 0, here = 0; f < faces; f++) {
                int n = sheet.loopLength(f);
                for (int i = 0; i < n; i++, here++) {
                    int a = sheet.loopVertex(f, i);
                    int b = sheet.loopVertex(f, (i + 1) % n);
                    int g = sheet.faceAcross(a, b);
                    if (g <= f) {
                        continue; // joined once, from the earlier face
                    }
                    if (!isBend(f, g)) {
                        flatSides.set(here);
                        flatAcross.add(g);
                        continue;
                    }
                    bends.add(bend(f, g, a, b));
                    bendEdges.add(f);
                    bendEdges.add(i);
                    bendEdges.add(g);
                    bendEdges.add(a);
                    bendEdges.add(b);
                }
            }
            NestedBends nested = NestedBends.of(bends, sheet.thickness() * NEST_TOLERANCE);
            int[] ranks = nested.ranks();
            int[] backToBack = nested.backToBack();
            double[] stackTop = new double[frames.length];
            for (int f = 0; f < faces; f++) {
                stackTop[sheet.host(f)] = Math.max(stackTop[sheet.host(f)], (levels[f] + 1) * sheet.thickness());
            }
            // Which folds stand out at all, before any wall is known: a fold along a cut or a
            // concave edge has no room there and stands out 0 either way, so the others' outs
            // are the same as once the walls are known.
            double[] outsBeforeWalls = standOut(bends, ranks, nested, new boolean[bends.size()], new double[bends.size()]);
            walls = ConcaveWalls.of(bends, ranks, backToBack, frames, sheet.thickness(), sheet.tolerance(), stackTop, outsBeforeWalls);
            // Where a concave edge runs on as a convex one, the paper is mitred on past the corner as
            // far as the stop there keeps paper going over the edge (BendRoom.mitredOnPastStops).
            // The walls are found on the frames as they were: folds along the convex stretch are no
            // walls, they still stand out beyond it (walls standing back there met the layers
            // mitred on in their own plane: 1,233 pairs rather than 150 on 50 random cubes).
            frames = BendRoom.mitredOnPastStops(frames, stackTop, sheet.tolerance());
            boolean[] onWall = walls.along();

            List<int[]> paper = new PackedIntArrays();
            IntList hostList = new IntList();
            List<int[]> caps = new PackedIntArrays();
            IntList capAfter = new IntList();
            corners = new int[faces][];
            sidesOf = new int[faces];
            pressedWhole = new boolean[faces];
            pieceStart = new int[faces + 1];
            try (PiecesAhead ahead = new PiecesAhead(faces)) {
                for (int f = 0; f < faces; f++) {
                    FacePieces pieces = ahead.next();
                    sidesOf[f] = -1;
                    if (pieces == null || pieces.pieces().size() == 1) {
                        int[] loop = sheet.loop(f);
                        int[] placed = new int[loop.length];
                        for (int i = 0; i < loop.length; i++) {
                            placed[i] = vertex(f, loop[i]);
                        }
                        corners[f] = placed;
                        pressedWhole[f] = pieces != null && spaceArea(placed) <= 1e-6 * sheetArea(pieces.pieces().get(0));
                        paper.add(placed);
                        hostList.add(sheet.host(f));
                    } else {
                        placePieces(f, pieces, paper, hostList, caps, capAfter);
                    }
                    pieceStart[f + 1] = paper.size();
                }
            }
            doneWithFaces();
            int[] hosts = hostList.toArray();
            // How far each bend stands out, for the caps over edges (CrossingOverBends) and the bends.
            double[] slopes = new double[bends.size()];
            double[] outs = standOut(bends, ranks, nested, onWall, slopes);
            double[] past = nested.mitres(outs, CoplanarHosts.of(frames, sheet.tolerance()));
            stopRowsOnPaper(bends, outs, past);
            crossings = new CrossingOverBends(bends, outs, frames, sheet.thickness(),
                    Math.max(sheet.tolerance(), sheet.thickness() * NEST_TOLERANCE));
            // The bends below, once every bend is known.
            int next = 0;
            for (int f = 0, here = 0; f < faces; f++) {
                int n = sheet.loopLength(f);
                for (int i = 0; i < n; i++, here++) {
                    if (!flatSides.get(here)) {
                        continue;
                    }
                    int g = flatAcross.get(next++);
                    int a = sheet.loopVertex(f, i);
                    int b = sheet.loopVertex(f, (i + 1) % n);
                    // the paper runs on flat, or bends over an edge with no thickness where the two sides meet
                    if (sheet.host(f) != sheet.host(g) && sheet.thickness() > 0) {
                        addCrossingCap(f, g, chain(f, i, a, b), chain(g, side(g, a, b), a, b), a, b, pieceStart[g + 1] - 1, caps, capAfter);
                    } else {
                        addCap(chain(f, i, a, b), chain(g, side(g, a, b), a, b), a, b, pieceStart[g + 1] - 1, -1, false, caps, capAfter);
                    }
                }
            }
            // Each bend's faces f and g, its crease a, b, and where each face's paper begins and ends along it.
            int[][] bendCorners = new int[bends.size()][];
            for (int k = 0; k < bends.size(); k++) {
                int f = bendEdges.get(5 * k);
                int i = bendEdges.get(5 * k + 1);
                int g = bendEdges.get(5 * k + 2);
                int a = bendEdges.get(5 * k + 3);
                int b = bendEdges.get(5 * k + 4);
                double[][] fChain = chain(f, i, a, b);
                double[][] gChain = chain(g, side(g, a, b), a, b);
                bendCorners[k] = new int[] {f, g, a, b, (int) fChain[0][2], (int) fChain[fChain.length - 1][3], (int) gChain[0][2],
                    (int) gChain[gChain.length - 1][3]};
            }

            for (int k = 0; k < bends.size(); k++) {
                int[] c = bendCorners[k];
                int f = c[0];
                int g = c[1];
                NestedBends.Bend bend = bends.get(k);
                double out = outs[k];
                if ((c[4] == c[6] || samePlace(c[4], c[6])) && (c[5] == c[7] || samePlace(c[5], c[7]))) {
                    continue; // paper of no thickness folded flat: nothing to bridge
                }
                int after = pieceStart[g + 1] - 1;
                // The two layers' chains along the crease, made again rather than kept for every bend.
                double[][] fChain = chain(f, bendEdges.get(5 * k + 1), c[2], c[3]);
                double[][] gChain = chain(g, side(g, c[2], c[3]), c[2], c[3]);
                if (out == 0 && !ConcaveWalls.standsBack(backToBack, onWall, k) && !walls.stepsBack(k)) {
                    addCap(fChain, gChain, c[2], c[3], after, bend.host(), !onWall[k], caps, capAfter);
                    continue;
                }
                if (fChain.length == 1 && gChain.length == 1) {
                    wholeBend(k, c, bend, out, out == 0 ? apexHeight(bends, backToBack, k) : 0, slopes[k], past, after, caps, capAfter);
                    continue;
                }
                // Where its faces are placed in pieces, the bend goes from piece to piece as they meet the crease.
                boolean backs = out == 0;
                double middle = backs ? apexHeight(bends, backToBack, k) : (height(f) + height(g)) / 2;
                boolean fLower = height(f) < height(g);
                double lower = Math.min(height(f), height(g)) + (backs ? 0 : out / slopes[k]);
                double upper = Math.max(height(f), height(g)) - out;
                double[] cuts = backs ? cutsAlong(fChain, gChain) : withRowCuts(cutsAlong(fChain, gChain), bend, out, lower, upper);
                // Where a row's end is mitred short (past < 0), the crease runs on beyond the
                // mitre's start: a stretch there has its rows on the mitre, standing out the less
                // the nearer the crease's end, and no wall (it would lie in the mitre's plane).
                // At the full row, cut stretches beyond the mitre crossed the bends across it
                // (t_prism's stem, whose layers are cut where they stand back from its cut). Only
                // rows stopped on another host's bends (at a reflex corner of their face), and not
                // at a crease's end on a concave edge, whose layers are pressed onto its mitres.
                double span = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
                double zoneA = backs || !nested.mitredAcrossHosts(2 * k) || onConcaveEdge(bend.host(), bend.ax(), bend.ay()) ? 0
                        : -past[2 * k] / span;
                double zoneB = backs || !nested.mitredAcrossHosts(2 * k + 1) || onConcaveEdge(bend.host(), bend.bx(), bend.by()) ? 1
                        : 1 + past[2 * k + 1] / span;
                boolean zoned = false;
                for (int j = 1; j + 1 < cuts.length; j++) {
                    zoned |= cuts[j] < zoneA - SAME_CUT || cuts[j] > zoneB + SAME_CUT;
                }
                if (zoned) {
                    cuts = withCuts(cuts, zoneA, zoneB);
                }
                int a = c[2];
                int b = c[3];
                // Stretch by stretch between the points where either layer's pieces meet the crease.
                // Where a wall ends, the pieces on its two sides put one point of the crease in two
                // places (on the wall, and out on the mitre): each stretch takes its ends from the
                // pieces that run along it, and places its rows as it lies, beside the walls and
                // mitres that its middle is. Taken from whichever piece came first along the chain,
                // a stretch beyond a wall's end got a corner on the wall at one end, and its rows
                // beside the wall there, while the layers it joined stood off it: on the torus the
                // bend, and the bend it wraps, twisted through each other and through the walls.
                int[] rowFrom = null;
                // The points a facet of the stretch before pressed flat left out (joinSquashedStretch).
                int[] leftOutBefore = new int[0];
                leftOut = new IntList();
                for (int j = 1; j < cuts.length; j++) {
                    Stretch stretch = stretch(fChain, gChain, a, b, cuts[j - 1], cuts[j]);
                    double t0 = stretch.from();
                    double t1 = stretch.to();
                    double between = stretch.middle();
                    double u0 = stretch.u0();
                    double v0 = stretch.v0();
                    double u1 = stretch.u1();
                    double v1 = stretch.v1();
                    double uMid = along(sheet.u(a), sheet.u(b), between);
                    double vMid = along(sheet.v(a), sheet.v(b), between);
                    int fFrom = stretch.fFrom();
                    int fAt = stretch.fTo();
                    int gFrom = stretch.gFrom();
                    int gAt = stretch.gTo();
                    int[] rowAt;
                    int[] rowStart;
                    if (backs) {
                        rowStart = rowFrom != null ? new int[] {rowFrom[0]} : new int[] {apex(k, f, a, middle)};
                        rowAt = new int[] {j == cuts.length - 1 ? apex(k, f, b, middle) : apex(k, f, u1, v1, middle)};
                    } else {
                        double beyond0 = j == 1 ? -past[2 * k] : onCut(bend, out, fChain, gChain, t0, between);
                        double beyond1 = j == cuts.length - 1 ? past[2 * k + 1] : onCut(bend, out, fChain, gChain, t1, between);
                        double out0 = zoned ? out * zoneScale(t0, zoneA, zoneB) : out;
                        double out1 = zoned ? out * zoneScale(t1, zoneA, zoneB) : out;
                        beyond0 = out0 < out ? 0 : beyond0;
                        beyond1 = out1 < out ? 0 : beyond1;
                        double lowRow0 = rowHeight(f, g, out0, slopes[k], fLower);
                        double highRow0 = rowHeight(f, g, out0, slopes[k], !fLower);
                        double lowRow1 = rowHeight(f, g, out1, slopes[k], fLower);
                        double highRow1 = rowHeight(f, g, out1, slopes[k], !fLower);
                        // Each row leans from its own layer's crease as that layer is placed (f's row from f's).
                        double[] fCrept0 = crept(f, fFrom, u0, v0);
                        double[] gCrept0 = crept(f, gFrom, u0, v0);
                        double[] fCrept1 = crept(f, fAt, u1, v1);
                        double[] gCrept1 = crept(f, gAt, u1, v1);
                        boolean short0 = j == 1 && past[2 * k] < 0;
                        boolean short1 = j == cuts.length - 1 && past[2 * k + 1] < 0;
                        rowStart = new int[] {row(f, bend, u0, v0, out0, shortOrCrept(bend, beyond0, short0, fCrept0), lowRow0, uMid, vMid,
                                rowFrom == null ? -1 : rowFrom[0], fCrept0),
                            row(f, bend, u0, v0, out0, shortOrCrept(bend, beyond0, short0, gCrept0), highRow0, uMid, vMid,
                                rowFrom == null ? -1 : rowFrom[1], gCrept0)};
                        rowAt = new int[] {row(f, bend, u1, v1, out1, shortOrCrept(bend, beyond1, short1, fCrept1), lowRow1, uMid, vMid, -1, fCrept1),
                            row(f, bend, u1, v1, out1, shortOrCrept(bend, beyond1, short1, gCrept1), highRow1, uMid, vMid, -1, gCrept1)};
                    }
                    boolean inZone = zoned && (t0 >= zoneB - SAME_CUT || t1 <= zoneA + SAME_CUT);
                    boolean squashed = !backs && !onWall[k] && insideAt(fChain, between) && insideAt(gChain, between);
                    if (!squashed && inZone) {
                        addBendCap(bend.host(), new int[] {fFrom, fAt, rowAt[0], rowStart[0]}, after, caps, capAfter);
                        addBendCap(bend.host(), new int[] {rowStart[1], rowAt[1], gAt, gFrom}, after, caps, capAfter);
                        // The two layers' rows stand apart on the mitre: a line between them at each
                        // point where the stretches meet, so that the bend joins its layers there.
                        if (t0 <= SAME_CUT) {
                            joinSquashed(rowStart[0], rowStart[1], after, caps, capAfter);
                        }
                        joinSquashed(rowAt[0], rowAt[1], after, caps, capAfter);
                    } else if (!squashed) {
                        int fm0 = rowStart[0];
                        int fm1 = rowAt[0];
                        int gm0 = rowStart[rowStart.length - 1];
                        int gm1 = rowAt[rowAt.length - 1];
                        addBendCap(bend.host(), new int[] {fFrom, fAt, fm1, fm0}, after, caps, capAfter);
                        if (!backs) {
                            addBendCap(bend.host(), new int[] {fm0, fm1, gm1, gm0}, after, caps, capAfter);
                        }
                        addBendCap(bend.host(), new int[] {gm0, gm1, gAt, gFrom}, after, caps, capAfter);
                    } else {
                        joinSquashedStretch(fChain, gChain, stretch, leftOutBefore, after, caps, capAfter);
                    }
                    leftOutBefore = leftOut.toArray();
                    leftOut = new IntList();
                    rowFrom = rowAt;
                }
            }
            Creep creep = creptCount == 0 ? Creep.NONE
                    : new Creep(java.util.Arrays.copyOf(creptVertices, creptCount), java.util.Arrays.copyOf(creptFrom, 3 * creptCount));
            return new Built(xyz, uv, paper, hosts, caps, capAfter.toArray(), creep, pieceStart);
        }

        /**
         * How far each bend stands out from its crease ({@code slopes}: the room beyond the
         * host's edge it leans at, filled in): none for a fold on a wall ({@code onWall}).
         */
        private double[] standOut(List<NestedBends.Bend> bends, int[] ranks, NestedBends nested, boolean[] onWall, double[] slopes) {
            double[] outs = new double[bends.size()];
            for (int k = 0; k < bends.size(); k++) {
                NestedBends.Bend bend = bends.get(k);
                // Each rank steps out by a thickness, less where the room beyond the host's edge
                // is narrow: the lower side then leans out at the room's slope s, and a bend of
                // rank r (its layers at least 2r + 1 apart) keeps a wall between its two sides:
                // r·step·(1/s + 1) <= 2r·T.
                if (ranks[k] == 0 || onWall[k]) {
                    continue; // on its crease whatever the room, or on its wall at a concave edge
                }
                HostFrame frame = frames[bend.host()];
                slopes[k] = frame.roomBeyond(bend.ax(), bend.ay(), bend.bx(), bend.by(), sheet.tolerance());
                double out = ranks[k] * sheet.thickness() * Math.min(1, 2 * slopes[k] / (1 + slopes[k]));
                double low = (bend.low() + 0.5) * sheet.thickness();
                out = frame.lean(bend.ax(), bend.ay(), bend.nx(), bend.ny(), low, slopes[k], out, sheet.tolerance());
                outs[k] = frame.lean(bend.bx(), bend.by(), bend.nx(), bend.ny(), low, slopes[k], out, sheet.tolerance());
            }
            FacingBends.keepApart(bends, outs, sheet.thickness() * NEST_TOLERANCE);
            nested.keepNested(outs);
            return outs;
        }

        /**
         * Lets go of what only placing the faces needed (the copies' chains and levels, the cut
         * points): on the 5,000-triangle torus about 180 MB, held till the caps were done too.
         */
        private void doneWithFaces() {
            firstCopy = null;
            nextCopy = null;
            copyLevel = null;
            cutPoints = null;
            cutCopies = null;
            cutCells = null;
            cutNext = null;
            holding.clear();
            inside.clear();
        }

        /** A face's pieces ({@link #pieces}), and which of them lie in a region where paper creeps. */
        private record FacePieces(List<List<Corner>> pieces, boolean[] inside) {
        }

        /**
         * Each face's pieces in turn, cut on a thread of their own ahead of the placing where there
         * are two threads: on two cores cutting was a quarter of placing the 5,000-triangle torus's
         * paper, placing the faces cut before it another quarter, one after the other. The cutting
         * reads only what does not change while faces are placed (the sheet, the frames, the
         * walls) and writes only the cut points, which the placing does not read: each corner on
         * a cut carries what the placing needs of its point ({@link CutPoint}), as it was once
         * the face was cut. So the faces are placed exactly as when cut and placed one by one.
         */
        private final class PiecesAhead implements AutoCloseable {
            /** Faces cut at a time, and batches cut ahead at most: the thread hands over a batch, not a face. */
            private static final int BATCH = 512;
            private static final int AHEAD = 8;
            private final int faces;
            private final java.util.concurrent.BlockingQueue<Object> cut;
            private final Thread cutting;
            private volatile boolean stopped;
            private FacePieces[] batch = new FacePieces[0];
            private int inBatch;
            private int next;

            PiecesAhead(int faces) {
                this.faces = faces;
                if (Workers.threads() < 2 || faces <= BATCH) {
                    cut = null;
                    cutting = null;
                    return;
                }
                cut = new java.util.concurrent.ArrayBlockingQueue<>(AHEAD);
                cutting = new Thread(this::cutAll, "ifold-pieces");
                cutting.setDaemon(true);
                cutting.start();
            }

            /** The next face's pieces: null where it is placed whole. */
            FacePieces next() {
                if (cut == null) {
                    return pieces(next++);
                }
                if (inBatch == batch.length) {
                    Object taken;
                    try {
                        taken = cut.take();
                    } catch (InterruptedException e) {
                        Thread.currentThread().interrupt();
                        throw new java.util.concurrent.CancellationException("interrupted");
                    }
                    if (taken instanceof RuntimeException failed) {
                        throw failed;
                    }
                    if (taken instanceof Error failed) {
                        throw failed;
                    }
                    batch = (FacePieces[]) taken;
                    inBatch = 0;
                }
                next++;
                return batch[inBatch++];
            }

            private void cutAll() {
                try {
                    for (int from = 0; from < faces && !stopped; from += BATCH) {
                        FacePieces[] faceBatch = new FacePieces[Math.min(BATCH, faces - from)];
                        for (int k = 0; k < faceBatch.length; k++) {
                            faceBatch[k] = pieces(from + k);
                        }
                        handOver(faceBatch);
                    }
                } catch (RuntimeException | Error failed) {
                    handOver(failed);
                }
            }

            private void handOver(Object item) {
                try {
                    while (!stopped && !cut.offer(item, 100, java.util.concurrent.TimeUnit.MILLISECONDS)) {
                        // the placing is behind: wait, unless it has stopped
                    }
                } catch (InterruptedException e) {
                    stopped = true;
                }
            }

            /** Stops the cutting where the placing ends early (it failed): the thread lets go of what it holds. */
            @Override
            public void close() {
                if (cutting != null) {
                    stopped = true;
                    cut.clear();
                }
            }
        }

        /**
         * Stops the rows of bends standing out where flat paper between their layers leaves their
         * crease's end at an angle ({@link RowsOnPaper}): every face's corners are offered.
         */
        private void stopRowsOnPaper(List<NestedBends.Bend> bends, double[] outs, double[] past) {
            RowsOnPaper rows = new RowsOnPaper(bends, outs, past, sheet.thickness() * NEST_TOLERANCE);
            if (!rows.any()) {
                return;
            }
            // Most corners have no bend's end standing out at them: their sides are placed only
            // where one has (every corner's were a sixth of the placing). Which faces have such a
            // corner is asked on every thread (the rows are only read), the rows stopped in order.
            boolean[] atAnEnd = new boolean[sheet.faceCount()];
            Workers.forChunks(sheet.faceCount(), 8192, () -> null, (from, to, none) -> {
                for (int f = from; f < to; f++) {
                    Isometry2 pose = sheet.pose(f);
                    for (int i = 0; i < sheet.loopLength(f) && !atAnEnd[f]; i++) {
                        int v = sheet.loopVertex(f, i);
                        atAnEnd[f] = rows.near(sheet.host(f), levels[f], pose.x(sheet.u(v), sheet.v(v)), pose.y(sheet.u(v), sheet.v(v)));
                    }
                }
            });
            for (int f = 0; f < sheet.faceCount(); f++) {
                if (!atAnEnd[f]) {
                    continue;
                }
                Isometry2 pose = sheet.pose(f);
                int n = sheet.loopLength(f);
                int host = sheet.host(f);
                for (int i = 0; i < n; i++) {
                    int v = sheet.loopVertex(f, i);
                    double x = pose.x(sheet.u(v), sheet.v(v));
                    double y = pose.y(sheet.u(v), sheet.v(v));
                    if (!rows.near(host, levels[f], x, y)) {
                        continue;
                    }
                    int p = sheet.loopVertex(f, (i + n - 1) % n);
                    int q = sheet.loopVertex(f, (i + 1) % n);
                    rows.corner(host, levels[f], x, y, pose.x(sheet.u(p), sheet.v(p)), pose.y(sheet.u(p), sheet.v(p)),
                            pose.x(sheet.u(q), sheet.v(q)), pose.y(sheet.u(q), sheet.v(q)));
                }
            }
        }

        /**
         * How high bend k's apex stands where it stands back from its crease, back to back with
         * another ({@link ConcaveWalls#standsBack}): halfway up the levels the two share, so that
         * the two bends meet on one segment of the crease, as their standing back half a thickness
         * each assumes. Halfway between its own layers, two such bends of different levels (15
         * and 16 against 15 and 17, by a top corner of a hexagonal prism 4 high whose hexagons are
         * fanned from their centre) met the crease at heights half a thickness apart: nowhere
         * did the two meet, and the truths (which let a fold's corners stand back where two
         * bends meet on one segment) found three faces there shortened, by up to a thickness.
         */
        private double apexHeight(List<NestedBends.Bend> bends, int[] backToBack, int k) {
            NestedBends.Bend bend = bends.get(k);
            // One stepping back into its layers, nested on one line (no fold back to back): halfway between them.
            NestedBends.Bend other = backToBack[k] < 0 ? bend : bends.get(backToBack[k]);
            int low = Math.max(bend.low(), other.low());
            int high = Math.min(bend.high(), other.high());
            // As height() places the two levels, so that two bends of the same levels (a hinge strip's
            // turns) have their apexes where each had them.
            return ((low + 0.5) * sheet.thickness() + (high + 0.5) * sheet.thickness()) / 2;
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
            return vertex(f, p, Double.NaN, Double.NaN);
        }

        /**
         * {@link #vertex(int, int)} for a corner of a piece of face f ({@link Pieces}) that lies
         * wholly beside the same walls and mitres as its point (bx, by).
         */
        private int vertex(int f, int p, double bx, double by) {
            Isometry2 pose = sheet.pose(f);
            HostFrame frame = frames[sheet.host(f)];
            double x = pose.x(sheet.u(p), sheet.v(p));
            double y = pose.y(sheet.u(p), sheet.v(p));
            int v = placed(f, x, y, sheet.u(p), sheet.v(p), frame.stops() == null ? null : over(f, p, pose), bx, by, firstCopy[p]);
            firstCopy[p] = linked(firstCopy[p], v);
            return v;
        }

        /** The chain of copies that begins at {@code first} (-1: none) with v at its end, where it is not in it already: its first. */
        private int linked(int first, int v) {
            if (first < 0) {
                return v;
            }
            int last = first;
            while (true) {
                if (last == v) {
                    return first;
                }
                if (nextCopy.get(last) < 0) {
                    break;
                }
                last = nextCopy.get(last);
            }
            nextCopy.set(last, v);
            return first;
        }

        /**
         * The space vertex of face f's paper at frame point (x, y), sheet point (u, v), as the
         * walls and mitres place it (for a corner of a piece, as the piece's point (bx, by) lies;
         * NaN: as the point itself does): one of the copies already made of that point (the chain
         * from {@code first}, {@link #nextCopy}) where it lands on it at the same level of the same
         * host, or a new one.
         */
        private int placed(int f, double x, double y, double u, double v, double[] over, double bx, double by, int first) {
            HostFrame frame = frames[sheet.host(f)];
            double[] point = placedPoint;
            double[] xy = placedXy;
            int host = sheet.host(f);
            if (middleFace != f) {
                middleFace = f;
                middleOfFace = middle(f);
            }
            walls.place(host, frame, x, y, height(f), middleOfFace[0], middleOfFace[1], over, bx, by, xy);
            boolean crept = xy[0] != x || xy[1] != y;
            frame.toSpace(xy[0], xy[1], height(f), point, 0);
            for (int copy = first; copy >= 0; copy = nextCopy.get(copy)) {
                if (copyHost.get(copy) == host && copyLevel.get(copy) == levels[f] && closer(copy, point, exact)) {
                    return copy;
                }
            }
            if (sheet.thickness() == 0) {
                for (int copy = first; copy >= 0; copy = nextCopy.get(copy)) {
                    if (closer(copy, point, merge)) {
                        return copy;
                    }
                }
            }
            int made = add(point, u, v);
            copyHost.set(made, host);
            copyLevel.set(made, levels[f]);
            if (crept) {
                if (creptCount == creptVertices.length) {
                    creptVertices = java.util.Arrays.copyOf(creptVertices, 2 * creptCount + 8);
                    creptFrom = java.util.Arrays.copyOf(creptFrom, 3 * creptVertices.length);
                }
                creptVertices[creptCount] = made;
                frame.toSpace(x, y, height(f), creptFrom, 3 * creptCount);
                creptCount++;
            }
            return made;
        }

        /**
         * {@link #placed}'s working point in space and on the frame, and the middle of the face it
         * last placed a point of ({@link #middleFace}): it places 4.6M points on the
         * 5,000-triangle torus, a face's corners one after another, and made three arrays each.
         */
        private final double[] placedPoint = new double[3];
        private final double[] placedXy = new double[2];
        private int middleFace = -1;
        private double[] middleOfFace;

        /** The middle of face f's polygon on its host's frame, as laid. */
        private double[] middle(int f) {
            Isometry2 pose = sheet.pose(f);
            int n = sheet.loopLength(f);
            double cx = 0;
            double cy = 0;
            for (int i = 0; i < n; i++) {
                int q = sheet.loopVertex(f, i);
                cx += pose.x(sheet.u(q), sheet.v(q)) / n;
                cy += pose.y(sheet.u(q), sheet.v(q)) / n;
            }
            return new double[] {cx, cy};
        }

        /**
         * Where face f's paper goes on from paper vertex p over an edge to another host: the other
         * ends of its sheet edges at p whose face across lies on another host, in f's host frame
         * (x, y pairs); null where none does.
         */
        private double[] over(int f, int p, Isometry2 pose) {
            int n = sheet.loopLength(f);
            double[] over = null;
            for (int i = 0; i < n; i++) {
                if (sheet.loopVertex(f, i) != p) {
                    continue;
                }
                int next = sheet.loopVertex(f, (i + 1) % n);
                int previous = sheet.loopVertex(f, (i + n - 1) % n);
                for (int j = 0; j < 2; j++) {
                    int q = j == 0 ? next : previous;
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
            return row(f, bend, sheet.u(p), sheet.v(p), out, along, height);
        }

        /** {@link #row(int, NestedBends.Bend, int, double, double, double)} at paper point (u, v) of the crease. */
        private int row(int f, NestedBends.Bend bend, double u, double v, double out, double along, double height) {
            return row(f, bend, u, v, out, along, height, Double.NaN, Double.NaN, -1, NOT_CREPT);
        }

        /**
         * How far along its crease (from a towards b) a row moves at an end of the crease where it
         * stops short ({@code isShort}: {@code along} from that end inwards, a mitre against
         * another's bends), given that its layer's point there crept by {@code creep} (x, y on the
         * host's frame): the row stops as far in as the farther of the two, not their sum. A layer
         * standing back from a cut's wall at a reflex corner crept back along the crease, and the
         * row, stopped short by the mitre as well, lay back over the stretch before (on t_prism's
         * stem, a rank-1 bend's row at its end 1 T behind where its stretch began, its wall folded
         * back over its own wall in its plane: 10 pairs in one plane).
         */
        private static double shortOrCrept(NestedBends.Bend bend, double along, boolean isShort, double[] creep) {
            double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
            double crept = (creep[0] * (bend.bx() - bend.ax()) + creep[1] * (bend.by() - bend.ay())) / length;
            if (!isShort || along * crept <= 0) {
                return along;
            }
            return Math.abs(along) > Math.abs(crept) ? along - crept : 0;
        }

        /** No creep: a crease point where its paper lays it. */
        private static final double[] NOT_CREPT = {0, 0};

        /**
         * {@link #row(int, NestedBends.Bend, int, double, double, double)} at paper point (u, v)
         * of the crease, for the stretch of the bend whose middle is at paper point (uMid, vMid)
         * of the crease (NaN: the row point's own place): placed beside the walls and mitres that
         * the stretch's row is, and moved as far as the crease point of the layer it leans from
         * crept ({@code creep}, x and y on the host's frame; {@link #crept}). Where it lands where
         * vertex {@code same} (-1: none) lies, that vertex: the stretch before ends there too.
         */
        private int row(int f, NestedBends.Bend bend, double u, double v, double out, double along, double height, double uMid,
                double vMid, int same, double[] creep) {
            Isometry2 pose = sheet.pose(f);
            double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
            double px = pose.x(u, v) + creep[0] + bend.nx() * out + (bend.bx() - bend.ax()) / length * along;
            double py = pose.y(u, v) + creep[1] + bend.ny() * out + (bend.by() - bend.ay()) / length * along;
            double bx = Double.isNaN(uMid) ? Double.NaN : pose.x(uMid, vMid) + bend.nx() * out;
            double by = Double.isNaN(uMid) ? Double.NaN : pose.y(uMid, vMid) + bend.ny() * out;
            double[] point = new double[3];
            double[] xy = new double[2];
            walls.place(sheet.host(f), frames[sheet.host(f)], px, py, height, Double.NaN, Double.NaN, null, bx, by, xy);
            frames[sheet.host(f)].toSpace(xy[0], xy[1], height, point, 0);
            if (same >= 0 && closer(same, point, exact)) {
                return same;
            }
            return capVertex(point, u, v);
        }

        /**
         * How far space vertex {@code placed}, a layer's point of a crease at paper point (u, v),
         * stands from where face f (on its host) lays that point: x and y on the host's frame, 0
         * where it did not creep. A bend's row leans from its layer's crease where that layer is
         * placed: where the layer stands back from a concave edge (on its mitre, or on a fold's
         * wall), the row stands back with it. Stepped out from the crease as laid, the row lay
         * nearer the edge than the wall its own layer ended on: at a corner of the torus where a
         * concave edge's walls meet a convex edge, a bend whose crease ran into the corner stood
         * out over the convex edge, its layer on the wall and its row beyond the wall's end, and
         * the facet between ran through that end (0.059 T); and rows pushed back onto a wall in
         * its plane overlapped it there (the torus's pairs in one plane 990 -> 790).
         */
        private double[] crept(int f, int placed, double u, double v) {
            Isometry2 pose = sheet.pose(f);
            HostFrame frame = frames[sheet.host(f)];
            double[] point = {xyz.get(3 * placed), xyz.get(3 * placed + 1), xyz.get(3 * placed + 2)};
            return new double[] {frame.localX(point) - pose.x(u, v), frame.localY(point) - pose.y(u, v)};
        }

        /**
         * A corner of a piece of a face: where it lies on the host's frame and on the sheet, which
         * point it is (a paper vertex, at least 0, or a point where a line cut an edge, -1 - its
         * index in {@link #cutPoints}), and the side of the face's loop that the piece's edge from
         * it to the next corner lies along (-1: along a cut).
         */
        private static final class Corner {
            final double x;
            final double y;
            final double u;
            final double v;
            final int id;
            final int side;
            /** For a corner on a cut, its point as the face's cutting left it ({@link #pieces}); null for a paper vertex. */
            CutPoint point;

            Corner(double x, double y, double u, double v, int id, int side) {
                this.x = x;
                this.y = y;
                this.u = u;
                this.v = v;
                this.id = id;
                this.side = side;
            }
        }

        /**
         * What placing a corner on a cut reads of its point: the two paper vertices of the sheet
         * edge it lies on (-1 where none), and the unit normal of a line across a region that cut
         * there (NaN: none did).
         */
        private record CutPoint(int one, int two, double lineA, double lineB) {
        }

        /** A piece cut in two: the part on the line's positive side and on its negative side (null where none). */
        private record Parts(List<Corner> plus, List<Corner> minus) {
        }

        /**
         * A line where a face is cut: a·x + b·y = c on its host's frame; {@code across} where it
         * runs across its region, where the region begins or ends along its edge.
         */
        private record Cut(double a, double b, double c, boolean across) {
            double value(Corner p) {
                return a * p.x + b * p.y - c;
            }
        }

        /**
         * For each piece of the face last cut that lies in a region, the region it was cut to (by
         * identity). This, {@link #inside} and the cut points ({@link #cutPoints}, {@link #cutCells},
         * {@link #cutNext}) are the cutting's own: on the thread that cuts ahead ({@link PiecesAhead}).
         */
        private final java.util.Map<List<Corner>, double[]> holding = new java.util.IdentityHashMap<>();

        /**
         * Whether paper within region {@code outer} lies within region {@code region} only where
         * {@code outer} holds it anyway: both along one line, {@code outer} reaching as far in or
         * farther, from no later and to no sooner.
         */
        private static boolean covers(double[] outer, double[] region) {
            return outer != null && outer[0] == region[0] && outer[1] == region[1] && outer[2] == region[2] && outer[3] == region[3]
                    && outer[4] >= region[4] && outer[5] <= region[5] && outer[6] >= region[6];
        }

        /** The pieces of the face last cut ({@link #pieces}) that lie in a region where paper creeps: placed on its line. */
        private final java.util.Set<List<Corner>> inside = java.util.Collections.newSetFromMap(new java.util.IdentityHashMap<>());
        /**
         * Where lines cut edges, {@link #CUT_POINT} numbers each: x, y, u, v, the two paper
         * vertices of the sheet edge it lies on (-1 where it lies on none), its host and level,
         * and the unit normal (x, y) of a line across a region that cut there (NaN: none did).
         */
        private DoubleList cutPoints = new DoubleList();
        private static final int CUT_POINT = 10;
        /**
         * The first space vertex made of each cut point (-1: none; the others by {@link #nextCopy}):
         * the placing's own, not the cutting's, which runs ahead of it ({@link PiecesAhead}).
         */
        private IntList cutCopies = new IntList();

        /**
         * Where face f's paper creeps (is placed elsewhere than it lies), along the concave edges
         * of its host that it comes near: by each concave stretch, nearer the edge than its mitre;
         * by each wall holding its level, nearer than the wall, beside it ({@link #edgeRegion}).
         */
        private List<double[]> regions(int f, List<Corner> face, double tiny) {
            int host = sheet.host(f);
            HostFrame frame = frames[host];
            List<double[]> regions = new ArrayList<>();
            if (frame.mitre() == null) {
                return regions;
            }
            double height = height(f);
            for (int k = 0; k < frame.mitre().length; k++) {
                double[] stretches = frame.mitre()[k];
                if (stretches == null) {
                    continue;
                }
                double[] edge = frame.edge(k);
                double most = walls.farthestWall(host, k);
                for (int i = 0; i + 2 < stretches.length; i += 3) {
                    most = Math.max(most, height * stretches[i + 2]);
                }
                if (!nearLine(face, edgeRegion(edge, 0, 0, 0), most, tiny)) {
                    continue; // the face comes nowhere near this edge's mitres and walls
                }
                double near = ifold.geom.Tolerance.ON_PLANE * edge[4];
                for (int i = 0; i + 2 < stretches.length; i += 3) {
                    if (stretches[i + 2] > HostFrame.CUT_TAN) {
                        // A stretch that runs to an end of the edge holds paper beyond it too (HostFrame.mitreAt).
                        regions.add(edgeRegion(edge, height * stretches[i + 2], stretches[i] <= near ? Double.NEGATIVE_INFINITY : stretches[i],
                                stretches[i + 1] >= edge[4] - near ? Double.POSITIVE_INFINITY : stretches[i + 1]));
                    }
                }
                List<double[]> wallsHere = new ArrayList<>();
                walls.wallsAt(host, k, levels[f], wallsHere);
                for (double[] wall : wallsHere) {
                    regions.add(edgeRegion(edge, wall[0], wall[1], wall[2]));
                }
            }
            return regions;
        }

        /** Whether some corner of the face lies nearer the region's line than {@code reach} (on its inner side, or beyond it). */
        private static boolean nearLine(List<Corner> face, double[] region, double reach, double tiny) {
            for (Corner c : face) {
                if (-region[3] * (c.x - region[0]) + region[2] * (c.y - region[1]) < reach - tiny) {
                    return true;
                }
            }
            return false;
        }

        /**
         * A region along edge {@code edge} of a host's polygon ({@link HostFrame#edge}): nearer it
         * than {@code keep}, from {@code from} to {@code to} along it; as a line (x, y of a point,
         * the unit direction, the host inside on its left), how far in, from and to.
         */
        private static double[] edgeRegion(double[] edge, double keep, double from, double to) {
            return new double[] {edge[0], edge[1], edge[2] / edge[4], edge[3] / edge[4], keep, from, to};
        }

        /**
         * Face f cut into pieces each of which lies wholly in or wholly out of each region where
         * its paper creeps ({@link #regions}); null where the face meets none, and the face alone
         * where it lies wholly in one (both placed whole).
         *
         * <p>Paper in such a region is placed on the region's line (a mitre, a fold's wall): it
         * ends there. A face placed by its corners alone, some crept and some not, is drawn as if
         * the creep ran straight between them: an edge from a corner that stays to one that crept
         * turns about the first and sweeps across the paper and bends beside it (the long edge of a
         * face nearly along a crease crossing that crease's bend), and a face that runs past the
         * end of a wall keeps the corners beyond the end where they were and runs through the wall.
         * Cut where the regions begin and end, each piece is placed as it lies: whole, or squashed
         * onto its region's line (where the paper ends, it has no area).
         */
        private FacePieces pieces(int f) {
            int host = sheet.host(f);
            if (!(sheet.thickness() > 0) || walls == null) {
                return null;
            }
            if (frames[host].mitre() == null) {
                return null;
            }
            // A face a fold back to back holds (the hinge strip's turning squares) is placed whole: its
            // corners by the crease stand back half a thickness, where the mitre's pieces would not
            // meet them (cut there too, pieces of the two overlapped at the corners of concave edges).
            double[] middle = middle(f);
            if (walls.holdsBack(host, levels[f], middle[0], middle[1])) {
                return null;
            }
            Isometry2 pose = sheet.pose(f);
            int[] loop = sheet.loop(f);
            List<Corner> whole = new ArrayList<>(loop.length);
            for (int i = 0; i < loop.length; i++) {
                double u = sheet.u(loop[i]);
                double v = sheet.v(loop[i]);
                whole.add(new Corner(pose.x(u, v), pose.y(u, v), u, v, loop[i], i));
            }
            // A corner this near a line lies on it: no piece thinner than a millionth of the face.
            double size = 0;
            for (Corner p : whole) {
                for (Corner q : whole) {
                    size = Math.max(size, Math.abs(p.x - q.x) + Math.abs(p.y - q.y));
                }
            }
            double tiny = Math.max(sheet.tolerance() * 1e-3, 1e-6 * size);
            List<double[]> regions = regions(f, whole, tiny);
            if (regions.isEmpty()) {
                return null;
            }
            List<List<Corner>> pieces = new ArrayList<>();
            pieces.add(whole);
            inside.clear();
            holding.clear();
            // Outermost first along each line: a piece already squashed onto a wall farther in is
            // not cut again by the walls nearer the edge that it lies within.
            regions.sort((p, q) -> Double.compare(q[4], p[4]));
            for (int r = 0; r < regions.size(); r++) {
                double[] region = regions.get(r);
                double px = region[0];
                double py = region[1];
                double tx = region[2];
                double ty = region[3];
                // Inwards: left of the line.
                Cut band = new Cut(-ty, tx, -ty * px + tx * py + region[4], false);
                Cut from = Double.isFinite(region[5]) ? new Cut(tx, ty, tx * px + ty * py + region[5], true) : null;
                Cut to = Double.isFinite(region[6]) ? new Cut(tx, ty, tx * px + ty * py + region[6], true) : null;
                List<List<Corner>> next = new ArrayList<>();
                for (List<Corner> piece : pieces) {
                    double[] within = holding.get(piece);
                    if (!meets(piece, band, from, to, tiny) || covers(within, region)) {
                        next.add(piece);
                        continue;
                    }
                    boolean wasInside = inside.remove(piece);
                    holding.remove(piece);
                    int before = next.size();
                    Parts byBand = cut(f, piece, band, tiny);
                    add(next, byBand.plus());
                    List<Corner> near = byBand.minus();
                    if (near != null && from != null) {
                        Parts byFrom = cut(f, near, from, tiny);
                        add(next, byFrom.minus());
                        near = byFrom.plus();
                    }
                    if (near != null && to != null) {
                        Parts byTo = cut(f, near, to, tiny);
                        add(next, byTo.plus());
                        near = byTo.minus();
                    }
                    add(next, near);
                    if (near != null) {
                        inside.add(near);
                        holding.put(near, region);
                    }
                    for (int k = before; wasInside && k < next.size(); k++) {
                        inside.add(next.get(k));
                        if (within != null) {
                            holding.putIfAbsent(next.get(k), within);
                        }
                    }
                }
                pieces = next;
            }
            if (pieces.size() > 1) {
                mergeNearCuts(pieces, tiny);
            }
            if (pieces.size() <= 1) {
                // Whole: met by no region, or lying wholly in one (placed whole, pressed onto its line).
                return pieces.size() == 1 && inside.contains(pieces.get(0)) ? new FacePieces(pieces, new boolean[] {true}) : null;
            }
            joinCuts(pieces, tiny);
            boolean[] inRegion = new boolean[pieces.size()];
            for (int p = 0; p < pieces.size(); p++) {
                inRegion[p] = inside.contains(pieces.get(p));
                for (Corner c : pieces.get(p)) {
                    if (c.id < 0) {
                        int at = CUT_POINT * (-1 - c.id);
                        c.point = new CutPoint((int) cutPoints.get(at + 4), (int) cutPoints.get(at + 5), cutPoints.get(at + 8), cutPoints.get(at + 9));
                    }
                }
            }
            return new FacePieces(pieces, inRegion);
        }

        /**
         * Gives each piece's edge along a cut the corners that the piece across it got there (a
         * line that cut one of two pieces but not the other put a corner on one side only): so
         * that the two are joined corner to corner, where a cap closes any gap between them.
         */
        private static void joinCuts(List<List<Corner>> pieces, double tiny) {
            List<Corner> cuts = new ArrayList<>(cutCorners(pieces).values());
            for (int p = 0; p < pieces.size(); p++) {
                List<Corner> piece = pieces.get(p);
                List<Corner> joined = new ArrayList<>(piece.size());
                for (int k = 0; k < piece.size(); k++) {
                    Corner here = piece.get(k);
                    Corner there = piece.get((k + 1) % piece.size());
                    joined.add(here);
                    if (here.side >= 0) {
                        continue; // along the face's own side: the caps there pair the pieces by where they meet it
                    }
                    double dx = there.x - here.x;
                    double dy = there.y - here.y;
                    double length2 = dx * dx + dy * dy;
                    // A corner on the edge lies in its box: one more than tiny outside is either
                    // off its line or past an end by more than tiny, as the tests below find too
                    // (half the corners of the 5,000-triangle torus's faces were tested against all
                    // their face's cuts: 49 million tests).
                    double left = Math.min(here.x, there.x) - tiny;
                    double right = Math.max(here.x, there.x) + tiny;
                    double bottom = Math.min(here.y, there.y) - tiny;
                    double top = Math.max(here.y, there.y) + tiny;
                    List<double[]> between = null;
                    for (int i = 0; i < cuts.size(); i++) {
                        Corner c = cuts.get(i);
                        if (!(c.x >= left && c.x <= right && c.y >= bottom && c.y <= top)) {
                            continue;
                        }
                        if (c.id == here.id || c.id == there.id || !(length2 > 0)) {
                            continue;
                        }
                        double t = ((c.x - here.x) * dx + (c.y - here.y) * dy) / length2;
                        double off = Math.abs((c.x - here.x) * dy - (c.y - here.y) * dx) / Math.sqrt(length2);
                        // On the edge to rounding (a crossing of it), not merely near it.
                        if (off <= 1e-6 * tiny && t * Math.sqrt(length2) > tiny && (1 - t) * Math.sqrt(length2) > tiny) {
                            if (between == null) {
                                between = new ArrayList<>();
                            }
                            between.add(new double[] {t, i});
                        }
                    }
                    if (between == null) {
                        continue;
                    }
                    between.sort((a, b) -> Double.compare(a[0], b[0]));
                    for (double[] at : between) {
                        Corner c = cuts.get((int) at[1]);
                        joined.add(new Corner(c.x, c.y, c.u, c.v, c.id, -1));
                    }
                }
                piece.clear(); // the same list: which pieces lie in a region is known by the list
                piece.addAll(joined);
            }
        }

        /**
         * Makes two cut points one where they lie on one cut closer than {@code tiny}: a line that
         * cut the pieces on one side of a cut but not those on the other (a region nearer the edge
         * that they already lay in) left a point beside the other side's, too near to be put on
         * its edge ({@link #joinCuts}), and the pieces either side met at different points, placed
         * on different walls with no cap between (a thickness apart on a bumpy sphere, where the
         * bands of two walls 2·10⁻⁷ apart crossed the start of a region). The point kept is one on
         * a side of the face (shared with the face across it), else the one made first. Two points
         * are not joined where that would leave a piece fewer than three corners or take the length
         * from a side of the face: the side's paper would be lost to its bend (a sliver between a
         * crease and a cut 5·10⁻⁸ off it).
         */
        private void mergeNearCuts(List<List<Corner>> pieces, double tiny) {
            java.util.Map<Integer, Corner> byId = cutCorners(pieces);
            if (byId.size() < 2) {
                return;
            }
            List<Corner> cuts = new ArrayList<>(byId.values());
            java.util.Map<Integer, Integer> kept = new java.util.HashMap<>();
            for (List<Corner> piece : pieces) {
                for (int k = 0; k < piece.size(); k++) {
                    Corner here = piece.get(k);
                    Corner there = piece.get((k + 1) % piece.size());
                    double dx = there.x - here.x;
                    double dy = there.y - here.y;
                    double length = Math.hypot(dx, dy);
                    if (here.side >= 0 || !(length > 0)) {
                        continue; // along the face's own side, or of no length
                    }
                    for (Corner c : cuts) {
                        if (c.id == here.id || c.id == there.id) {
                            continue;
                        }
                        double off = Math.abs((c.x - here.x) * dy - (c.y - here.y) * dx) / length;
                        if (!(off <= 1e-6 * tiny)) {
                            continue; // not a crossing of this cut's line
                        }
                        for (Corner end : new Corner[] {here, there}) {
                            if (end.id < 0 && Math.hypot(c.x - end.x, c.y - end.y) <= tiny) {
                                join(kept, c.id, end.id, pieces);
                            }
                        }
                    }
                }
            }
            if (kept.isEmpty()) {
                return;
            }
            for (List<Corner> piece : pieces) {
                List<Corner> merged = new ArrayList<>(piece.size());
                for (Corner c : piece) {
                    int id = c.id < 0 ? keptOf(kept, c.id) : c.id;
                    Corner k = id == c.id ? c : byId.get(id);
                    merged.add(k == c ? c : new Corner(k.x, k.y, k.u, k.v, k.id, c.side));
                }
                for (int k = merged.size() - 1; k >= 0 && merged.size() > 1; k--) {
                    if (merged.get(k).id == merged.get((k + 1) % merged.size()).id) {
                        merged.remove(k); // a cut of no length: the next corner starts the edge after it
                    }
                }
                piece.clear(); // the same list: which pieces lie in a region is known by the list
                piece.addAll(merged);
            }
        }

        /**
         * Joins cut points a and b in {@code kept} (each point to the one kept for it), keeping one
         * on a side of the face, else the one made first; not where both lie on sides, or where a
         * piece would lose its area or a side its length ({@link #mergeNearCuts}).
         */
        private void join(java.util.Map<Integer, Integer> kept, int a, int b, List<List<Corner>> pieces) {
            a = keptOf(kept, a);
            b = keptOf(kept, b);
            if (a == b) {
                return;
            }
            boolean aOnSide = cutPoints.get(CUT_POINT * (-1 - a) + 4) >= 0;
            boolean bOnSide = cutPoints.get(CUT_POINT * (-1 - b) + 4) >= 0;
            if (aOnSide && bOnSide) {
                return; // both shared with faces across: neither may move
            }
            boolean keepA = aOnSide || !bOnSide && a > b; // made first: the nearer zero
            int gone = keepA ? b : a;
            int stays = keepA ? a : b;
            kept.put(gone, stays);
            for (List<Corner> piece : pieces) {
                int corners = 0;
                for (int k = 0; k < piece.size(); k++) {
                    Corner here = piece.get(k);
                    Corner there = piece.get((k + 1) % piece.size());
                    boolean noLength = here.id < 0 && there.id < 0 && keptOf(kept, here.id) == keptOf(kept, there.id);
                    if (noLength && here.side >= 0) {
                        corners = -1;
                        break;
                    }
                    corners += noLength ? 0 : 1;
                }
                if (corners < 3) {
                    kept.remove(gone);
                    return;
                }
            }
        }

        /** The pieces' corners on cuts, each point once (the first corner made of it), in the order met. */
        private static java.util.Map<Integer, Corner> cutCorners(List<List<Corner>> pieces) {
            java.util.Map<Integer, Corner> byId = new java.util.LinkedHashMap<>();
            for (List<Corner> piece : pieces) {
                for (Corner c : piece) {
                    if (c.id < 0) {
                        byId.putIfAbsent(c.id, c);
                    }
                }
            }
            return byId;
        }

        /** The cut point kept for {@code id} ({@link #join}). */
        private static int keptOf(java.util.Map<Integer, Integer> kept, int id) {
            Integer next;
            while ((next = kept.get(id)) != null) {
                id = next;
            }
            return id;
        }

        private static void add(List<List<Corner>> pieces, List<Corner> piece) {
            if (piece != null && piece.size() >= 3) {
                pieces.add(piece);
            }
        }

        /** Whether a piece reaches into the region nearer the edge than {@code band} and between {@code from} and {@code to}. */
        private static boolean meets(List<Corner> piece, Cut band, Cut from, Cut to, double tiny) {
            boolean nearer = false;
            boolean after = from == null;
            boolean before = to == null;
            for (Corner p : piece) {
                nearer |= band.value(p) < -tiny;
                after |= from != null && from.value(p) > tiny;
                before |= to != null && to.value(p) < -tiny;
            }
            return nearer && after && before;
        }

        /**
         * The piece cut by the line: the part on its positive side and the part on its negative
         * side (null where there is none); the corners where the line crosses an edge are the same
         * for every face of the layer along that edge.
         */
        private Parts cut(int f, List<Corner> piece, Cut line, double tiny) {
            int n = piece.size();
            double[] values = new double[n];
            double most = 0;
            double least = 0;
            for (int i = 0; i < n; i++) {
                values[i] = line.value(piece.get(i));
                most = Math.max(most, values[i]);
                least = Math.min(least, values[i]);
            }
            // A part reaching less than ten times the least cut past the line is not cut off:
            // the piece goes whole to the side it reaches farther into (its corners that far past
            // the line are placed as the rest of it, a ten-thousandth of a thickness from where they lie).
            if (!(most > 10 * tiny) || !(least < -10 * tiny)) {
                return most >= -least ? new Parts(piece, null) : new Parts(null, piece);
            }
            // Each corner of the two parts, with the input edge it starts (a corner) or lies on (a cut, -1 - edge).
            List<Corner> plus = new ArrayList<>();
            List<Corner> minus = new ArrayList<>();
            List<Integer> plusAt = new ArrayList<>();
            List<Integer> minusAt = new ArrayList<>();
            Corner firstCrossing = null;
            for (int i = 0; i < n; i++) {
                Corner here = piece.get(i);
                Corner there = piece.get((i + 1) % n);
                double a = values[i];
                double b = values[(i + 1) % n];
                if (a >= -tiny) {
                    plus.add(here);
                    plusAt.add(i);
                }
                if (a <= tiny) {
                    minus.add(here);
                    minusAt.add(i);
                }
                if (a > tiny && b < -tiny || a < -tiny && b > tiny) {
                    Corner crossing = crossing(f, here, there, a / (a - b), line);
                    // Across a sliver thinner than a thousandth of tiny (a billionth of the face),
                    // the line's two crossings are one point: apart, the part of its sharp corner
                    // keeps a side shorter than rounding can tell from none (the CGAL elephant at
                    // the defaults: 13 paper faces that turned the wrong way round at such a side).
                    if (firstCrossing == null) {
                        firstCrossing = crossing;
                    } else if (Math.hypot(crossing.x - firstCrossing.x, crossing.y - firstCrossing.y) <= 1e-3 * tiny) {
                        crossing = firstCrossing;
                    }
                    plus.add(crossing);
                    plusAt.add(-1 - i);
                    minus.add(crossing);
                    minusAt.add(-1 - i);
                }
            }
            return new Parts(withoutRepeats(sided(piece, plus, plusAt)), withoutRepeats(sided(piece, minus, minusAt)));
        }

        /**
         * The part without a corner that the next repeats (both crossings one point, or a
         * crossing that took the point of an end of its edge: a second line crossing an edge
         * within {@link #SAME_POINT} of it, where the face is that small), the later kept, whose
         * side runs on; null where fewer than three corners are left (the tip of a sliver, of no
         * area to tell). Kept, the cow ({@code common3d_spot.obj}) at the defaults, its strip
         * 0.0022 wide, had 3 paper faces of a corner twice.
         */
        private static List<Corner> withoutRepeats(List<Corner> part) {
            for (int k = part.size() - 1; k >= 0 && part.size() > 1; k--) {
                if (part.get(k).id == part.get((k + 1) % part.size()).id) {
                    part.remove(k);
                }
            }
            return part.size() >= 3 ? part : null;
        }

        /** The part's corners with the side each edge lies along: a side of the input where it runs along one of its edges, else the cut. */
        private static List<Corner> sided(List<Corner> piece, List<Corner> part, List<Integer> at) {
            int n = piece.size();
            List<Corner> sided = new ArrayList<>(part.size());
            for (int k = 0; k < part.size(); k++) {
                int here = at.get(k);
                int there = at.get((k + 1) % part.size());
                int edge = -1;
                if (here >= 0 && (there == (here + 1) % n || there == -1 - here)) {
                    edge = here; // along the input's edge from this corner
                } else if (here < 0 && there == (-1 - here + 1) % n) {
                    edge = -1 - here; // from a cut on an input edge to that edge's end
                }
                Corner c = part.get(k);
                sided.add(new Corner(c.x, c.y, c.u, c.v, c.id, edge >= 0 ? piece.get(edge).side : -1));
            }
            return sided;
        }

        /**
         * Where {@code line} crosses the edge from {@code a} to {@code b} of a piece of face f, at
         * {@code t} along it: one point for every face of the layer that cuts that edge there.
         */
        private Corner crossing(int f, Corner a, Corner b, double t, Cut line) {
            // The side of the face the edge lies along, as its two paper vertices (none for a cut).
            int one = a.side >= 0 ? sheet.loopVertex(f, a.side) : -1;
            int two = a.side >= 0 ? sheet.loopVertex(f, (a.side + 1) % sheet.loopLength(f)) : -1;
            double u = a.u + t * (b.u - a.u);
            double v = a.v + t * (b.v - a.v);
            // One point for every face of the layer whose edge the line crosses there (and for two
            // lines crossing an edge at one point, where a wall ends on a mitre).
            int known = cutAt(sheet.host(f), levels[f], u, v, one, two);
            if (known < 0) {
                known = cutPoints.size() / CUT_POINT;
                // And the sheet edge it lies on (its two paper vertices), where it lies on one.
                for (double value : new double[] {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y), u, v, one, two, sheet.host(f), levels[f],
                    Double.NaN, Double.NaN}) {
                    cutPoints.add(value);
                }
                long cell = cell(sheet.host(f), levels[f], Math.floorDiv(Math.round(u / SAME_POINT), CELL_POINTS),
                        Math.floorDiv(Math.round(v / SAME_POINT), CELL_POINTS));
                if (known >= cutNext.length) {
                    cutNext = java.util.Arrays.copyOf(cutNext, 2 * known + 16);
                }
                cutNext[known] = cutCells.get(cell, -1);
                cutCells.put(cell, known);
            }
            int p = CUT_POINT * known;
            if (line.across() && Double.isNaN(cutPoints.get(p + 8))) {
                cutPoints.set(p + 8, line.a());
                cutPoints.set(p + 9, line.b());
            }
            return new Corner(cutPoints.get(p), cutPoints.get(p + 1), cutPoints.get(p + 2), cutPoints.get(p + 3), -1 - known, -1);
        }

        /** Cut points closer than this on the sheet are one. */
        private static final double SAME_POINT = 1e-9;
        /**
         * A cell holds this many {@link #SAME_POINT}s a side. The points within {@link #SAME_POINT}
         * of a point lie in the 3 x 3 squares {@link #SAME_POINT} across about it, and with cells
         * that small each cut point looked in nine of them: nine hash lookups, a tenth of placing
         * the 5,000-triangle torus's paper. Those squares lie in one cell but where they meet its
         * border (about a point in 32 along each axis).
         */
        private static final long CELL_POINTS = 64;
        /** The last cut point made in each cell of the sheet {@link #CELL_POINTS} across, by host and level ({@link #cell}). */
        private ifold.sheet.LongIntMap cutCells = new ifold.sheet.LongIntMap();
        /** For each cut point, the one made before it in its cell (-1: none). */
        private int[] cutNext = new int[16];

        /** A cell's key: its host, level and place, mixed (cells that share a key are told apart by their points). */
        private static long cell(int host, int level, long cu, long cv) {
            long h = host * 0x9E3779B97F4A7C15L + level;
            h = h * 0xC2B2AE3D27D4EB4FL + cu;
            h = h * 0x165667B19E3779F9L + cv;
            return (h ^ (h >>> 29)) & Long.MAX_VALUE; // the map takes keys of no sign
        }

        /**
         * The cut point made on {@code host} at {@code level} at sheet point (u, v), within {@link
         * #SAME_POINT}, on the same edge: the sheet edge from paper vertex {@code one} to {@code two}
         * (either way round), or a cut (-1, -1); -1 if none. Of two there, the one in the first of
         * the squares {@link #SAME_POINT} across about the point (the square below and left first,
         * then up, then right), the later made in one square.
         *
         * <p>A line cutting a sliver near its sharp corner crosses both sides of the corner within
         * {@link #SAME_POINT} of each other: taken as one point, the two parts each had it twice
         * (a triangle of two corners, a quadrilateral of three). On the CGAL elephant's strip at
         * the defaults, 0.001 wide and 1,689 long, 1,062 of its 1.28 million paper faces were such.
         */
        private int cutAt(int host, int level, double u, double v, int one, int two) {
            long cu = Math.round(u / SAME_POINT);
            long cv = Math.round(v / SAME_POINT);
            int found = -1;
            long foundSquare = Long.MAX_VALUE;
            for (long cellU = Math.floorDiv(cu - 1, CELL_POINTS); cellU <= Math.floorDiv(cu + 1, CELL_POINTS); cellU++) {
                for (long cellV = Math.floorDiv(cv - 1, CELL_POINTS); cellV <= Math.floorDiv(cv + 1, CELL_POINTS); cellV++) {
                    for (int k = cutCells.get(cell(host, level, cellU, cellV), -1); k >= 0; k = cutNext[k]) {
                        int p = CUT_POINT * k;
                        if (cutPoints.get(p + 6) != host || cutPoints.get(p + 7) != level || !(Math.abs(cutPoints.get(p + 2) - u) <= SAME_POINT)
                                || !(Math.abs(cutPoints.get(p + 3) - v) <= SAME_POINT) || !sameEdge(p, one, two)) {
                            continue;
                        }
                        long du = Math.round(cutPoints.get(p + 2) / SAME_POINT) - cu;
                        long dv = Math.round(cutPoints.get(p + 3) / SAME_POINT) - cv;
                        long square = 3 * (du + 1) + dv + 1;
                        // The chain runs from the latest made: the first found in a square is the later.
                        if (Math.abs(du) <= 1 && Math.abs(dv) <= 1 && (square < foundSquare || square == foundSquare && k > found)) {
                            found = k;
                            foundSquare = square;
                        }
                    }
                }
            }
            return found;
        }

        /** Whether the cut point numbered from {@code p} in {@link #cutPoints} lies on the edge from {@code one} to {@code two}, either way round. */
        private boolean sameEdge(int p, int one, int two) {
            int a = (int) cutPoints.get(p + 4);
            int b = (int) cutPoints.get(p + 5);
            return a == one && b == two || a == two && b == one;
        }

        /** The space vertex of a piece's corner, as the piece's point (bx, by) is placed. */
        private int vertexOf(int f, Corner c, double bx, double by) {
            if (c.id >= 0) {
                return vertex(f, c.id, bx, by);
            }
            int index = -1 - c.id;
            // On a sheet edge that goes over an edge of the surface to another host, it is kept from
            // the end of that edge as the edge's ends are (HostFrame.Stop).
            double[] over = null;
            if (c.point.one() >= 0 && frames[sheet.host(f)].stops() != null) {
                int g = sheet.faceAcross(c.point.one(), c.point.two());
                if (g < 0) {
                    g = sheet.faceAcross(c.point.two(), c.point.one());
                }
                if (g >= 0 && sheet.host(g) != sheet.host(f)) {
                    Isometry2 pose = sheet.pose(f);
                    int p = c.point.one();
                    int q = c.point.two();
                    over = new double[] {pose.x(sheet.u(p), sheet.v(p)), pose.y(sheet.u(p), sheet.v(p)), pose.x(sheet.u(q), sheet.v(q)),
                        pose.y(sheet.u(q), sheet.v(q))};
                }
            }
            while (cutCopies.size() <= index) {
                cutCopies.add(-1);
            }
            int v = placed(f, c.x, c.y, c.u, c.v, over, bx, by, cutCopies.get(index));
            cutCopies.set(index, linked(cutCopies.get(index), v));
            return v;
        }


        /**
         * Places face f's pieces: each corner as its piece lies ({@link #pieces}), the pieces'
         * edges along the face's sides recorded for the caps, and where two pieces of the face
         * are placed apart along the cut between them (the end of a wall, where the paper on one
         * side ends on the wall and on the other runs on to its mitre) a cap across, of no area.
         */
        private void placePieces(int f, FacePieces facePieces, List<int[]> paper, IntList hostList, List<int[]> caps,
                IntList capAfter) {
            List<List<Corner>> pieces = facePieces.pieces();
            int[] loop = sheet.loop(f);
            List<List<double[]>> along = new ArrayList<>();
            for (int i = 0; i < loop.length; i++) {
                along.add(new ArrayList<>());
            }
            java.util.Map<List<Integer>, int[]> cuts = new java.util.HashMap<>();
            List<int[]> tears = new ArrayList<>();
            for (int p = 0; p < pieces.size(); p++) {
                List<Corner> piece = pieces.get(p);
                double bx = 0;
                double by = 0;
                for (Corner c : piece) {
                    bx += c.x / piece.size();
                    by += c.y / piece.size();
                }
                int n = piece.size();
                int[] placed = new int[n];
                for (int k = 0; k < n; k++) {
                    placed[k] = vertexOf(f, piece.get(k), bx, by);
                }
                paper.add(placed);
                hostList.add(sheet.host(f));
                // A piece in a region where paper creeps, pressed onto the line where its layer ends.
                boolean squashed = facePieces.inside()[p] && spaceArea(placed) <= 1e-6 * sheetArea(piece);
                for (int k = 0; k < n; k++) {
                    Corner here = piece.get(k);
                    Corner there = piece.get((k + 1) % n);
                    if (here.side >= 0) {
                        double from = alongSide(f, here.side, here);
                        double to = alongSide(f, here.side, there);
                        double in = squashed ? 1 : 0;
                        double[] lineHere = lineAcross(here);
                        double[] lineThere = lineAcross(there);
                        along.get(here.side).add(from <= to
                                ? new double[] {from, to, placed[k], placed[(k + 1) % n], in, lineHere[0], lineHere[1], lineThere[0], lineThere[1]}
                                : new double[] {to, from, placed[(k + 1) % n], placed[k], in, lineThere[0], lineThere[1], lineHere[0], lineHere[1]});
                    } else {
                        List<Integer> key = List.of(Math.min(here.id, there.id), Math.max(here.id, there.id));
                        int[] ends = here.id < there.id ? new int[] {placed[k], placed[(k + 1) % n]} : new int[] {placed[(k + 1) % n], placed[k]};
                        int[] other = cuts.putIfAbsent(key, ends);
                        if (other != null && !(sameOrAt(other[0], ends[0]) && sameOrAt(other[1], ends[1]))) {
                            tears.add(new int[] {other[0], other[1], ends[1], ends[0]});
                        }
                    }
                }
            }
            for (int[] tear : tears) {
                caps.add(tear);
                capAfter.add(paper.size() - 1); // after the face's last piece
            }
            sidesOf[f] = sideStarts.size();
            for (List<double[]> segments : along) {
                segments.sort((p, q) -> Double.compare(p[0], q[0]));
                sideStarts.add(sideEdges.size() / SIDE_EDGE);
                for (double[] segment : segments) {
                    for (double value : segment) {
                        sideEdges.add(value);
                    }
                }
            }
            sideStarts.add(sideEdges.size() / SIDE_EDGE);
        }

        /** The unit normal of the line across a region that cut a piece at corner c (NaN, NaN: none did). */
        private double[] lineAcross(Corner c) {
            if (c.id >= 0) {
                return new double[] {Double.NaN, Double.NaN};
            }
            return new double[] {c.point.lineA(), c.point.lineB()};
        }

        /** The area of a polygon of space vertices. */
        private double spaceArea(int[] polygon) {
            double[] n = new double[3];
            for (int k = 0; k < polygon.length; k++) {
                int i = 3 * polygon[k];
                int j = 3 * polygon[(k + 1) % polygon.length];
                n[0] += (xyz.get(i + 1) - xyz.get(j + 1)) * (xyz.get(i + 2) + xyz.get(j + 2));
                n[1] += (xyz.get(i + 2) - xyz.get(j + 2)) * (xyz.get(i) + xyz.get(j));
                n[2] += (xyz.get(i) - xyz.get(j)) * (xyz.get(i + 1) + xyz.get(j + 1));
            }
            return Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]) / 2;
        }

        /** The area of a piece on the sheet. */
        private static double sheetArea(List<Corner> piece) {
            double twice = 0;
            Corner first = piece.get(0);
            for (int k = 0; k < piece.size(); k++) {
                Corner a = piece.get(k);
                Corner b = piece.get((k + 1) % piece.size());
                twice += (a.u - first.u) * (b.v - first.v) - (b.u - first.u) * (a.v - first.v);
            }
            return Math.abs(twice) / 2;
        }

        private boolean sameOrAt(int a, int b) {
            return a == b || samePlace(a, b);
        }

        /** How far along side {@code side} of face f's loop (0 at its first corner, 1 at its second) the piece corner lies. */
        private double alongSide(int f, int side, Corner c) {
            int[] loop = sheet.loop(f);
            int a = loop[side];
            int b = loop[(side + 1) % loop.length];
            double du = sheet.u(b) - sheet.u(a);
            double dv = sheet.v(b) - sheet.v(a);
            return ((c.u - sheet.u(a)) * du + (c.v - sheet.v(a)) * dv) / (du * du + dv * dv);
        }

        /** The side of face g's loop from paper vertex a to b, or b to a. */
        private int side(int g, int a, int b) {
            int n = sheet.loopLength(g);
            for (int j = 0; j < n; j++) {
                int here = sheet.loopVertex(g, j);
                int next = sheet.loopVertex(g, (j + 1) % n);
                if (here == a && next == b || here == b && next == a) {
                    return j;
                }
            }
            throw new IllegalStateException("faces across an edge do not share its vertices");
        }

        /**
         * Face f's paper along side i of its loop, which joins paper vertices a and b, from a to
         * b: the edges of its pieces there in order, each as how far along from a it runs from
         * and to (0 at a, 1 at b) and its vertex towards a and towards b.
         */
        private double[][] chain(int f, int i, int a, int b) {
            boolean forward = sheet.loopVertex(f, i) == a;
            if (sidesOf[f] < 0) {
                int first = corners[f][i];
                int second = corners[f][(i + 1) % sheet.loopLength(f)];
                double none = Double.NaN;
                double in = pressedWhole[f] ? 1 : 0;
                return new double[][] {forward ? new double[] {0, 1, first, second, in, none, none, none, none}
                        : new double[] {0, 1, second, first, in, none, none, none, none}};
            }
            int from = sideStarts.get(sidesOf[f] + i);
            int to = sideStarts.get(sidesOf[f] + i + 1);
            double[][] chain = new double[to - from][];
            for (int k = 0; k < chain.length; k++) {
                double[] segment = new double[SIDE_EDGE];
                for (int d = 0; d < SIDE_EDGE; d++) {
                    segment[d] = sideEdges.get(SIDE_EDGE * (forward ? from + k : to - 1 - k) + d);
                }
                chain[k] = forward ? segment
                        : new double[] {1 - segment[1], 1 - segment[0], segment[3], segment[2], segment[4], segment[7], segment[8], segment[5],
                            segment[6]};
            }
            return chain;
        }

        /**
         * One stretch of a crease from a to b, between two points where either layer's pieces meet
         * it ({@code from} and {@code to} along it): its middle, its ends on the sheet, and the
         * vertices each layer's chain has at its ends, taken from the pieces that run along it
         * ({@link #pointAt}).
         */
        private record Stretch(double from, double to, double middle, double u0, double v0, double u1, double v1, int fFrom, int fTo,
                int gFrom, int gTo) {
        }

        /** The stretch of crease a, b from {@code from} to {@code to} along it, between the layers' chains f and g. */
        private Stretch stretch(double[][] f, double[][] g, int a, int b, double from, double to) {
            double middle = (from + to) / 2;
            double u0 = along(sheet.u(a), sheet.u(b), from);
            double v0 = along(sheet.v(a), sheet.v(b), from);
            double u1 = along(sheet.u(a), sheet.u(b), to);
            double v1 = along(sheet.v(a), sheet.v(b), to);
            return new Stretch(from, to, middle, u0, v0, u1, v1, pointAt(f, from, u0, v0, middle), pointAt(f, to, u1, v1, middle),
                    pointAt(g, from, u0, v0, middle), pointAt(g, to, u1, v1, middle));
        }

        /**
         * The cap between two layers' paper along one crease (or edge), each given as its chain
         * from a to b ({@link #chain}): a quad between the two for each stretch where neither is
         * cut (where one is cut and the other not, a point on the other's edge there, as it
         * lies). For paper running on flat or over an edge ({@code bendHost} -1), none where the
         * two lie on each other; for a bend, its facets as {@link #addBendCap} makes them on its
         * host {@code bendHost}.
         */
        private void addCap(double[][] f, double[][] g, int a, int b, int after, int bendHost, boolean dropSquashed, List<int[]> caps,
                IntList capAfter) {
            boolean flat = bendHost < 0;
            double[] cuts = cutsAlong(f, g);
            // Stretch by stretch, each with its ends from the pieces that run along it (see the bends in pieces).
            for (int k = 1; k < cuts.length; k++) {
                Stretch s = stretch(f, g, a, b, cuts[k - 1], cuts[k]);
                int[] quad = {s.fFrom(), s.fTo(), s.gTo(), s.gFrom()};
                // Paper of both layers squashed where it ends (a fold inside a wall's, or running
                // into a mitre): the bend is not there, where the paper across has the room.
                boolean squashed = dropSquashed && insideAt(f, s.middle()) && insideAt(g, s.middle());
                // A stretch of no length (both layers' ends at one place each) is a line from layer
                // to layer, joined as squashed paper is: drawn as a quad, it was a sliver to the
                // collision check, in the plane of the wall beside it (the 5,000-triangle torus
                // along its own triangles, 2 of its pairs in one plane, by walls of levels 13 to 16).
                boolean noLength = sameOrAt(s.fFrom(), s.fTo()) && sameOrAt(s.gFrom(), s.gTo());
                if (flat && !(sameOrAt(s.fFrom(), s.gFrom()) && sameOrAt(s.fTo(), s.gTo()))) {
                    caps.add(quad);
                    capAfter.add(after);
                } else if (!flat && !squashed && !noLength) {
                    addBendCap(bendHost, quad, after, caps, capAfter);
                } else if (!flat) {
                    joinSquashed(cornerNear(f, s.middle(), s.from()), cornerNear(g, s.middle(), s.from()), after, caps, capAfter);
                }
            }
        }

        /**
         * The cap where the strip crosses an edge from face f on one host to face g on another
         * (their chains along the crease a, b, as {@link #addCap} takes them): a quad for each
         * stretch, as there; but where it would run through a bend of the host of the higher
         * layer standing out beyond the edge ({@link CrossingOverBends}), each stretch goes over
         * it, out from the higher layer to the mitre and down from there to the lower.
         */
        private void addCrossingCap(int f, int g, double[][] fChain, double[][] gChain, int a, int b, int after, List<int[]> caps,
                IntList capAfter) {
            double[] cuts = cutsAlong(fChain, gChain);
            Stretch[] stretches = new Stretch[cuts.length - 1];
            for (int k = 1; k < cuts.length; k++) {
                stretches[k - 1] = stretch(fChain, gChain, a, b, cuts[k - 1], cuts[k]);
            }
            int high = -1; // the face whose host's bends the cap goes over: f or g
            double[] crease = null;
            for (int face : new int[] {f, g}) {
                double[] line = creaseOn(face, a, b);
                for (Stretch s : stretches) {
                    boolean isF = face == f;
                    if (crossings.runsThrough(sheet.host(face), line, s.from(), s.to(), point(isF ? s.fFrom() : s.gFrom()),
                            point(isF ? s.fTo() : s.gTo()), point(isF ? s.gFrom() : s.fFrom()), point(isF ? s.gTo() : s.fTo()))) {
                        high = face;
                        crease = line;
                        break;
                    }
                }
                if (high >= 0) {
                    break;
                }
            }
            double slope = high < 0 ? 0 : crossings.mitre(sheet.host(high), sheet.host(high == f ? g : f), crease);
            if (slope <= HostFrame.CUT_TAN) {
                high = -1; // not over a convex edge: no mitre to go out to
            }
            for (Stretch s : stretches) {
                if (sameOrAt(s.fFrom(), s.gFrom()) && sameOrAt(s.fTo(), s.gTo())) {
                    continue;
                }
                if (high < 0) {
                    caps.add(new int[] {s.fFrom(), s.fTo(), s.gTo(), s.gFrom()});
                    capAfter.add(after);
                    continue;
                }
                int host = sheet.host(high);
                int over0 = capVertex(crossings.overMitre(host, crease, point(high == f ? s.fFrom() : s.gFrom()), slope), s.u0(), s.v0());
                int over1 = capVertex(crossings.overMitre(host, crease, point(high == f ? s.fTo() : s.gTo()), slope), s.u1(), s.v1());
                caps.add(new int[] {s.fFrom(), s.fTo(), over1, over0});
                capAfter.add(after);
                caps.add(new int[] {over0, over1, s.gTo(), s.gFrom()});
                capAfter.add(after);
            }
        }

        /** Crease a, b on face f's host's frame as f lies (ax, ay, bx, by), and the middle of f there (x, y). */
        private double[] creaseOn(int f, int a, int b) {
            Isometry2 pose = sheet.pose(f);
            double[] middle = middle(f);
            return new double[] {pose.x(sheet.u(a), sheet.v(a)), pose.y(sheet.u(a), sheet.v(a)), pose.x(sheet.u(b), sheet.v(b)),
                pose.y(sheet.u(b), sheet.v(b)), middle[0], middle[1]};
        }

        /** Space vertex v's point. */
        private double[] point(int v) {
            return new double[] {xyz.get(3 * v), xyz.get(3 * v + 1), xyz.get(3 * v + 2)};
        }

        /**
         * Adds a facet of a bend on {@code host} (a quad, its corners in order), drawn so that no
         * part of it with area lies on the mitre of a concave edge of the host: there a layer's
         * paper ends (pressed onto the mitre's line where it would reach nearer the edge, no area),
         * and the paper going over the edge, or the paper of the host across ending from the other
         * side, lies in that plane too. A facet wholly on the mitre is pressed flat there, as the
         * layer's paper is ({@link #addPressed}); one with a layer's side pressed onto the mitre's
         * line has that side pressed flat and the rest drawn as one triangle ({@link #addPressedSide}).
         */
        private void addBendCap(int host, int[] quad, int after, List<int[]> caps, IntList capAfter) {
            HostFrame frame = frames[host];
            if (frame.mitre() != null && sheet.thickness() > 0 && quad.length == 4) {
                boolean[] on = new boolean[4];
                for (int k = 0; k < frame.mitre().length; k++) {
                    if (frame.mitre()[k] == null) {
                        continue;
                    }
                    for (int c = 0; c < 4; c++) {
                        on[c] = onMitre(frame, k, quad[c]);
                    }
                    if (on[0] && on[1] && on[2] && on[3]) {
                        addPressed(quad, after, caps, capAfter);
                        return;
                    }
                    // One layer's side (corners 0 to 1, or 2 to 3) pressed onto the mitre's line.
                    int p = on[0] && on[1] ? 0 : on[2] && on[3] ? 2 : -1;
                    if (p >= 0) {
                        addPressedSide(frame, quad, p, after, caps, capAfter);
                        return;
                    }
                }
            }
            caps.add(quad);
            capAfter.add(after);
        }

        /**
         * A bend's facet whose side from corner p to p + 1 (a layer's, or a row's) is pressed onto
         * the mitre's line: that side is drawn with no area, as the paper pressed there is (a cap
         * along it, which keeps its corners joined to the bend), and the rest of the facet as the
         * triangle from the other side to the pressed side's corner nearer that side, in the host's
         * plane.
         *
         * <p>The mitre moves a layer's paper straight in from its concave edge. A crease not square
         * to that edge (along a convex edge of the host that meets the concave one at an obtuse
         * corner, or a turn's crease running nearly along it) has its pressed corners moved across
         * its line, to the side of the layers it joins, where paper lying between them reaches the
         * crease; the farther one as far as the stretch reaches into the creep. Drawn with area
         * (as triangles from the corner off the mitre, or whole), the facet leant from the other
         * layer's crease to that corner, through such paper: the 16 × 8 torus crossed itself so in
         * 29 pairs, 0.004 to 0.09 T deep, by its inner vertices. The triangle to the nearer corner
         * stays on the crease's side of it: where the stretch ends at the mitre's line, that corner
         * is on the crease, and the triangle is the bend's wall where it stands beyond the mitre.
         * Neither the triangle (one corner off the mitre) nor the pressed side lies with area in the
         * mitre's plane, where the paper going over the edge lies.
         */
        private void addPressedSide(HostFrame frame, int[] quad, int p, int after, List<int[]> caps, IntList capAfter) {
            int o0 = quad[(p + 2) % 4];
            int o1 = quad[(p + 3) % 4];
            double ox = spaceX(frame, o0);
            double oy = spaceY(frame, o0);
            double dx = spaceX(frame, o1) - ox;
            double dy = spaceY(frame, o1) - oy;
            double length = Math.hypot(dx, dy);
            int far = p + 1;
            if (length > 0) {
                // Distances from the other side's line, times its length.
                double off0 = Math.abs((spaceX(frame, quad[p]) - ox) * dy - (spaceY(frame, quad[p]) - oy) * dx);
                double off1 = Math.abs((spaceX(frame, quad[p + 1]) - ox) * dy - (spaceY(frame, quad[p + 1]) - oy) * dx);
                far = off0 > off1 ? p : p + 1;
            }
            caps.add(new int[] {quad[(far + 1) % 4], quad[(far + 2) % 4], quad[(far + 3) % 4]});
            capAfter.add(after);
            addLineCap(quad[p], quad[p + 1], after, caps, capAfter);
        }

        /** The frame x of space vertex {@code vertex}. */
        private double spaceX(HostFrame frame, int vertex) {
            return frame.localX(new double[] {xyz.get(3 * vertex), xyz.get(3 * vertex + 1), xyz.get(3 * vertex + 2)});
        }

        /** The frame y of space vertex {@code vertex}. */
        private double spaceY(HostFrame frame, int vertex) {
            return frame.localY(new double[] {xyz.get(3 * vertex), xyz.get(3 * vertex + 1), xyz.get(3 * vertex + 2)});
        }

        /**
         * A bend's facet whose every corner is pressed onto the mitre of a concave edge, drawn as
         * the paper pressed there is, with no area: along each of its sides that runs on a layer's
         * crease (corners 0 to 1, or 2 to 3, one of them made for a layer's paper), a cap of no
         * area, which keeps that layer's corner joined to the bend; nothing for a side between the
         * bend's rows. Drawn whole, such facets lay in the mitre's plane, where the host across
         * presses its own paper from the other side: where a crease over a convex edge runs into a
         * concave one, the upper layer of its bend and the rows leaning from it are pressed onto
         * the mitre, and on the torus the bends of the two hosts beside each inner meridian edge,
         * their creases over the one parallel through its end, overlapped there (228 of its 249
         * pairs in one plane). Left out without these caps, the pressed layer's corner had no cap
         * and was torn from the paper beside it on the sheet.
         */
        private void addPressed(int[] quad, int after, List<int[]> caps, IntList capAfter) {
            for (int side = 0; side < 4; side += 2) {
                int a = quad[side];
                int b = quad[side + 1];
                if (copyHost.get(a) < 0 && copyHost.get(b) < 0) {
                    leftOut.add(a);
                    leftOut.add(b);
                    continue; // between the bend's rows, or points made on a crease between a layer's corners
                }
                addLineCap(a, b, after, caps, capAfter);
            }
            // Its side from the layer's crease to the rows, or from row to row, where not one point:
            // the two layers' facets were otherwise joined only where their rows met their creases,
            // and two corners of turns pressed with their neighbours fell off the strip (50
            // random cubes, seed 1, mitred on past the corners of its faces: five pieces in space).
            joinSquashed(quad[0], quad[3], after, caps, capAfter);
        }

        /**
         * A cap of no area from space vertex a to b, through a vertex made halfway along the
         * paper and at a's place in space: paper pressed or squashed to a line, which still joins
         * the paper at its two ends (the collision checker passes over shapes of no area; the
         * truths see the join). Made halfway in space, the middle lay off the line by rounding,
         * and a line shorter than about a millionth of the model had area to the checker, and a
         * plane of its own: on the 5,000-triangle torus along its own triangles, 29 lines 2e-7
         * long, from layers pressed onto a mitre at inner vertices, lay in the plane of the cap
         * over the edge there, pairs in one plane.
         */
        private void addLineCap(int a, int b, int after, List<int[]> caps, IntList capAfter) {
            int m = capVertex(point(a), (uv.get(2 * a) + uv.get(2 * b)) / 2, (uv.get(2 * a + 1) + uv.get(2 * b + 1)) / 2);
            caps.add(new int[] {a, m, b});
            capAfter.add(after);
        }

        /**
         * The corner of a piece that the chain's edge along the stretch whose middle is
         * {@code middle} ends at, the end nearer {@code t}: a point of the paper as placed, where
         * a point made between its ends ({@link #pointAt}) would belong to no piece.
         */
        private static int cornerNear(double[][] chain, double middle, double t) {
            for (double[] edge : chain) {
                if (edge[0] <= middle && middle <= edge[1]) {
                    return (int) (Math.abs(edge[0] - t) <= Math.abs(edge[1] - t) ? edge[2] : edge[3]);
                }
            }
            return (int) chain[0][2];
        }

        /**
         * Joins the two layers of a bend's stretch that are both squashed where they end (a fold
         * inside a wall's, or running into a mitre), with a cap of no area from a corner of one
         * layer's piece along the stretch to a corner of the other's ({@link #cornerNear}). The
         * bend itself is left out there (drawn, it would lie on the wall or the mitre, where the
         * paper across has the room); but a face squashed whole whose every neighbour on the sheet
         * is squashed with it was then joined to nothing: on a random polycube of 20 cubes (seed
         * 4), two turns' corners folded under beside a tall wall by the corner of a hole in a face
         * fell off the strip (truth 1: three pieces in space).
         */
        private void joinSquashed(int f, int g, int after, List<int[]> caps, IntList capAfter) {
            if (f == g || closer(f, new double[] {xyz.get(3 * g), xyz.get(3 * g + 1), xyz.get(3 * g + 2)}, exact)) {
                return;
            }
            addLineCap(f, g, after, caps, capAfter);
        }

        /**
         * Joins the two layers of a squashed stretch of a bend placed in pieces: from a corner of
         * each layer's piece along it ({@link #joinSquashed}), and at the point where it meets the
         * stretch before, where a facet of that one pressed flat onto a mitre left a layer's point
         * there out ({@code leftOutBefore}) and either layer's point is not the corner joined. A
         * facet pressed flat ({@link #addPressed}) joins the bend's layers where its stretch
         * begins, and leaves out a layer's side whose two ends are points made on the crease
         * (between that layer's corners): the stretch after joins them where it begins. Squashed,
         * that stretch joined the corners of its pieces only, and where one layer's side pressed
         * onto the mitre's line runs on past the point (one piece of that layer along both
         * stretches, the other layer's pieces meeting the crease between its corners), its point
         * there was joined to nothing, a few thicknesses from the other layer's. The strip along
         * the model's own triangles lays each triangle's last pass along its exit edge, concave on
         * a torus's inner half, and tucks the pass's ends under along the triangle's sides, whose
         * creases run into that edge's mitre: the 16 x 8 torus tore so at 29 places, the 60 x 7
         * torus at 117, all at whole triangles (WrapTruths, not torn). The refinement's wraps are
         * as they were.
         */
        private void joinSquashedStretch(double[][] f, double[][] g, Stretch s, int[] leftOutBefore, int after, List<int[]> caps,
                IntList capAfter) {
            int fCorner = cornerNear(f, s.middle(), s.from());
            int gCorner = cornerNear(g, s.middle(), s.from());
            joinSquashed(fCorner, gCorner, after, caps, capAfter);
            if (!(sameOrAt(s.fFrom(), fCorner) && sameOrAt(s.gFrom(), gCorner))
                    && (atAny(leftOutBefore, s.fFrom()) || atAny(leftOutBefore, s.gFrom()))) {
                joinSquashed(s.fFrom(), s.gFrom(), after, caps, capAfter);
            }
        }

        /** Whether space vertex {@code vertex} is one of {@code vertices}, or at the same place. */
        private boolean atAny(int[] vertices, int vertex) {
            for (int v : vertices) {
                if (sameOrAt(v, vertex)) {
                    return true;
                }
            }
            return false;
        }

        /** Whether space vertex {@code vertex} lies on the mitre of concave edge k of the frame's host, within {@link #ON_MITRE}. */
        private boolean onMitre(HostFrame frame, int k, int vertex) {
            double[] point = {xyz.get(3 * vertex), xyz.get(3 * vertex + 1), xyz.get(3 * vertex + 2)};
            double x = frame.localX(point);
            double y = frame.localY(point);
            double tan = frame.mitreAt(k, x, y);
            if (!(tan > HostFrame.CUT_TAN)) {
                return false; // no mitre, or a cut's (its wall on the cut's own line is no mitre)
            }
            double[] edge = frame.edge(k);
            double in = ((x - edge[0]) * -edge[3] + (y - edge[1]) * edge[2]) / edge[4];
            return Math.abs(in - frame.height(point) * tan) <= ON_MITRE * sheet.thickness();
        }

        /**
         * A point this near a mitre's plane, in thicknesses, lies on it: half a thousandth, half
         * the depth from which the collision check counts contact (as {@link NestedBends} takes
         * bends to overlap), so that a triangle whose corners all lie this near the plane is one
         * the check finds in it.
         */
        private static final double ON_MITRE = 5e-4;

        /** Where either chain's edges begin or end along the crease (0 to 1), in order, each once. */
        private static double[] cutsAlong(double[][] f, double[][] g) {
            double[] all = new double[2 * (f.length + g.length)];
            int n = 0;
            for (double[][] chain : List.of(f, g)) {
                for (double[] edge : chain) {
                    all[n++] = edge[0];
                    all[n++] = edge[1];
                }
            }
            java.util.Arrays.sort(all, 0, n);
            double[] cuts = new double[n];
            int count = 0;
            for (int k = 0; k < n; k++) {
                if (count == 0 || all[k] - cuts[count - 1] > SAME_CUT) {
                    cuts[count++] = all[k];
                }
            }
            cuts[0] = 0;
            cuts[count - 1] = 1;
            return java.util.Arrays.copyOf(cuts, count);
        }

        /**
         * The cuts along a bend's crease ({@link #cutsAlong}), with those where its rows,
         * {@code out} beyond it at heights {@code lower} and {@code upper}, pass the end of a wall
         * that holds their height and that they come nearer the edge than somewhere. The rows
         * stand between the bend's layers, where walls may hold them that hold neither layer, and
         * no piece of either layer is cut there: a stretch whose middle lay beyond such a wall's
         * end and whose end lay beside it placed its row at that end on the edge's side of the
         * wall, and the bend ran through it (on the torus, a sliver of a pass folded between a
         * concave edge and a crease 11 degrees off it, 0.012 T). Cut there, each stretch's rows lie
         * wholly beside the wall or wholly beyond its end.
         */
        private double[] withRowCuts(double[] cuts, NestedBends.Bend bend, double out, double lower, double upper) {
            HostFrame frame = frames[bend.host()];
            if (frame.mitre() == null) {
                return cuts;
            }
            double[] all = java.util.Arrays.copyOf(cuts, cuts.length + 4);
            int n = cuts.length;
            List<double[]> held = new ArrayList<>();
            for (double height : new double[] {lower, upper}) {
                held.clear();
                walls.wallsHolding(bend.host(), height / sheet.thickness() - 0.5, held);
                for (double[] wall : held) {
                    // The row from the crease's end a to its end b: how far along the wall's edge and in from it.
                    double[] edge = frame.edge((int) wall[0]);
                    double ax = bend.ax() + bend.nx() * out - edge[0];
                    double ay = bend.ay() + bend.ny() * out - edge[1];
                    double bx = bend.bx() + bend.nx() * out - edge[0];
                    double by = bend.by() + bend.ny() * out - edge[1];
                    double alongA = (ax * edge[2] + ay * edge[3]) / edge[4];
                    double alongB = (bx * edge[2] + by * edge[3]) / edge[4];
                    double inA = (ay * edge[2] - ax * edge[3]) / edge[4];
                    double inB = (by * edge[2] - bx * edge[3]) / edge[4];
                    if (!(Math.min(inA, inB) < wall[3]) || alongA == alongB) {
                        continue; // the row keeps beyond the wall's line, or runs square to its edge
                    }
                    for (double end : new double[] {wall[1], wall[2]}) {
                        double t = (end - alongA) / (alongB - alongA);
                        if (t > SAME_CUT && t < 1 - SAME_CUT) {
                            if (n == all.length) {
                                all = java.util.Arrays.copyOf(all, 2 * n);
                            }
                            all[n++] = t;
                        }
                    }
                }
            }
            if (n == cuts.length) {
                return cuts;
            }
            java.util.Arrays.sort(all, 0, n);
            double[] merged = new double[n];
            int count = 0;
            for (int k = 0; k < n; k++) {
                if (count == 0 || all[k] - merged[count - 1] > SAME_CUT) {
                    merged[count++] = all[k];
                }
            }
            return java.util.Arrays.copyOf(merged, count);
        }

        /** From a to b, t of the way (a and b themselves at the ends). */
        private static double along(double a, double b, double t) {
            return t == 0 ? a : t == 1 ? b : a + t * (b - a);
        }

        /**
         * The bend of flat fold k (its corners c, as {@code bendCorners}) between two faces placed
         * whole: back to back with another fold, its layers stand back half a thickness, and its
         * bend reaches the crease halfway up, where the other's meets it; else out beyond the
         * crease from each layer, and straight across between.
         */
        private void wholeBend(int k, int[] c, NestedBends.Bend bend, double out, double middle, double slope, double[] past, int after,
                List<int[]> caps, IntList capAfter) {
            int f = c[0];
            int g = c[1];
            if (out == 0) {
                int apexA = apex(k, f, c[2], middle);
                int apexB = apex(k, f, c[3], middle);
                caps.add(new int[] {c[4], c[5], apexB, apexA});
                caps.add(new int[] {apexA, apexB, c[7], c[6]});
                capAfter.add(after);
                capAfter.add(after);
                return;
            }
            boolean fLower = height(f) < height(g);
            double lower = Math.min(height(f), height(g)) + out / slope;
            double upper = Math.max(height(f), height(g)) - out;
            int fma = row(f, bend, c[2], out, -past[2 * k], fLower ? lower : upper);
            int fmb = row(f, bend, c[3], out, past[2 * k + 1], fLower ? lower : upper);
            int gma = row(f, bend, c[2], out, -past[2 * k], fLower ? upper : lower);
            int gmb = row(f, bend, c[3], out, past[2 * k + 1], fLower ? upper : lower);
            caps.add(new int[] {c[4], c[5], fmb, fma});
            caps.add(new int[] {fma, fmb, gmb, gma});
            caps.add(new int[] {gma, gmb, c[7], c[6]});
            capAfter.add(after);
            capAfter.add(after);
            capAfter.add(after);
        }

        /** Cuts along a crease closer than this (of its length) are one. */
        private static final double SAME_CUT = 1e-9;

        /**
         * Whether frame point (x, y) of host h lies on a concave edge of it (not a cut's): a crease
         * ending there has its layers pressed onto the edge's mitres, and its rows on a mitre
         * between stretches tore the bend from its layers (the coarse tori 10 × 6 and 14 × 6, by
         * their inner equators).
         */
        private boolean onConcaveEdge(int h, double x, double y) {
            HostFrame frame = frames[h];
            if (frame.mitre() == null) {
                return false;
            }
            for (int k = 0; k < frame.corners().length / 2; k++) {
                if (frame.mitre()[k] != null && frame.along(k, x, y, x, y, sheet.tolerance()) && frame.mitreAt(k, x, y) > HostFrame.CUT_TAN) {
                    return true;
                }
            }
            return false;
        }

        /** The height of the lower row (lower: the one leaning out at {@code slope}) or the upper of the bend between f and g standing {@code out}. */
        private double rowHeight(int f, int g, double out, double slope, boolean lower) {
            return lower ? Math.min(height(f), height(g)) + out / slope : Math.max(height(f), height(g)) - out;
        }

        /** How far out, as a share of the row's, a bend stands at t along its crease where its row's end is mitred short ({@code zoneA}, {@code zoneB}). */
        private static double zoneScale(double t, double zoneA, double zoneB) {
            if (t < zoneA - SAME_CUT) {
                return Math.max(0, t / zoneA);
            }
            if (t > zoneB + SAME_CUT) {
                return Math.max(0, (1 - t) / (1 - zoneB));
            }
            return 1;
        }

        /** The cuts with those at {@code from} and {@code to} added (where inside and not already there). */
        private static double[] withCuts(double[] cuts, double from, double to) {
            double[] all = java.util.Arrays.copyOf(cuts, cuts.length + 2);
            int n = cuts.length;
            for (double t : new double[] {from, to}) {
                boolean there = false;
                for (double c : cuts) {
                    there |= Math.abs(c - t) <= SAME_CUT;
                }
                if (!there && t > SAME_CUT && t < 1 - SAME_CUT) {
                    all[n++] = t;
                }
            }
            all = java.util.Arrays.copyOf(all, n);
            java.util.Arrays.sort(all);
            return all;
        }

        /**
         * How far along its crease (from its end a towards b) a bend's row, {@code out} beyond
         * the crease, moves at {@code t} to lie on the line that cut its layers' pieces there
         * across a region (where a wall or a concave stretch of an edge ends: square to the edge),
         * for the stretch whose middle is {@code middle}; 0 where no such line did, or where it
         * runs within 45 degrees of the crease. Stepped out square to a crease that meets the edge
         * at a slant, the row at the end of a stretch beyond a wall's end lay back beside the wall,
         * and the bend there ran through it (on the torus, by up to 0.18 T, where a sliver of a
         * pass folded inside walls at a concave corner).
         */
        private static double onCut(NestedBends.Bend bend, double out, double[][] f, double[][] g, double t, double middle) {
            double[] normal = lineAcrossAt(f, t, middle);
            if (normal == null) {
                normal = lineAcrossAt(g, t, middle);
            }
            if (normal == null) {
                return 0;
            }
            double length = Polygons2.length(bend.bx() - bend.ax(), bend.by() - bend.ay());
            double along = ((bend.bx() - bend.ax()) * normal[0] + (bend.by() - bend.ay()) * normal[1]) / length;
            double off = bend.nx() * normal[0] + bend.ny() * normal[1];
            if (Math.abs(along) < Math.sqrt(0.5)) {
                return 0;
            }
            // (out·n + s·d)·m = 0 for the line's normal m.
            return -out * off / along;
        }

        /** The normal of the line across a region that cut the chain's edge along the stretch at {@code middle}, at its end {@code t}; null if none. */
        private static double[] lineAcrossAt(double[][] chain, double t, double middle) {
            for (double[] edge : chain) {
                if (edge[0] <= middle && middle <= edge[1]) {
                    if (Math.abs(edge[0] - t) <= SAME_CUT && !Double.isNaN(edge[5])) {
                        return new double[] {edge[5], edge[6]};
                    }
                    if (Math.abs(edge[1] - t) <= SAME_CUT && !Double.isNaN(edge[7])) {
                        return new double[] {edge[7], edge[8]};
                    }
                    return null;
                }
            }
            return null;
        }

        /** Whether the chain's paper at {@code t} along it lies in a region where it creeps ({@link #pieces}). */
        private static boolean insideAt(double[][] chain, double t) {
            for (double[] edge : chain) {
                if (edge[0] <= t && t <= edge[1]) {
                    return edge[4] > 0;
                }
            }
            return false;
        }

        /**
         * The vertex of a chain at {@code t} along it for the stretch of the crease whose middle is
         * {@code middle}: the end, or a point made between the ends, of the chain's edge that runs
         * along that stretch. Where a wall ends the pieces on its two sides end at one point of the
         * crease in two places, and each stretch takes the one its own piece put there.
         */
        private int pointAt(double[][] chain, double t, double u, double v, double middle) {
            // The chain's edge that runs along the stretch, where one does and reaches t.
            for (double[] edge : chain) {
                if (edge[0] <= middle && middle <= edge[1] && edge[0] - SAME_CUT <= t && t <= edge[1] + SAME_CUT) {
                    return pointAt(new double[][] {edge}, t, u, v);
                }
            }
            return pointAt(chain, t, u, v);
        }

        /**
         * The vertex of a chain at {@code t} along it, the crease's paper point (u, v) there: an
         * edge's end (of the first edge of the chain that reaches it), or a point made on the edge
         * that runs past it, between its two ends as they lie.
         */
        private int pointAt(double[][] chain, double t, double u, double v) {
            double[] nearest = chain[0];
            for (double[] edge : chain) {
                if (Math.abs(edge[0] - t) <= SAME_CUT) {
                    return (int) edge[2];
                }
                if (Math.abs(edge[1] - t) <= SAME_CUT) {
                    return (int) edge[3];
                }
                if (edge[0] < t && t < edge[1]) {
                    double w = (t - edge[0]) / (edge[1] - edge[0]);
                    int a = (int) edge[2];
                    int b = (int) edge[3];
                    double[] point = new double[3];
                    for (int d = 0; d < 3; d++) {
                        point[d] = xyz.get(3 * a + d) + w * (xyz.get(3 * b + d) - xyz.get(3 * a + d));
                    }
                    return capVertex(point, u, v);
                }
                if (Math.min(Math.abs(edge[0] - t), Math.abs(edge[1] - t)) < Math.min(Math.abs(nearest[0] - t), Math.abs(nearest[1] - t))) {
                    nearest = edge;
                }
            }
            return (int) (Math.abs(nearest[0] - t) < Math.abs(nearest[1] - t) ? nearest[2] : nearest[3]);
        }

        /** A vertex of a cap's middle rows, made for no face's layer: shared with none. */
        private int capVertex(double[] point, double u, double v) {
            int made = add(point, u, v);
            copyHost.set(made, -1);
            return made;
        }


        /**
         * The crease's point at paper vertex p (of face f's pose) at {@code height}: bend k's apex,
         * on the crease line where no fold back to back moves it, mitred by a concave edge; where
         * bend k steps back into its layers ({@link ConcaveWalls#stepsBack}), on its wall.
         */
        private int apex(int k, int f, int p, double height) {
            return apex(k, f, sheet.u(p), sheet.v(p), height);
        }

        /** {@link #apex(int, int, int, double)} at paper point (u, v) of the crease. */
        private int apex(int k, int f, double u, double v, double height) {
            Isometry2 pose = sheet.pose(f);
            double[] point = new double[3];
            double[] xy = new double[2];
            walls.apex(k, sheet.host(f), frames[sheet.host(f)], pose.x(u, v), pose.y(u, v), height, xy);
            frames[sheet.host(f)].toSpace(xy[0], xy[1], height, point, 0);
            return capVertex(point, u, v);
        }

        private boolean closer(int copy, double[] point, double distance) {
            double dx = xyz.get(3 * copy) - point[0];
            double dy = xyz.get(3 * copy + 1) - point[1];
            double dz = xyz.get(3 * copy + 2) - point[2];
            return dx * dx + dy * dy + dz * dz <= distance * distance;
        }

        private boolean samePlace(int a, int b) {
            return closer(a, new double[] {xyz.get(3 * b), xyz.get(3 * b + 1), xyz.get(3 * b + 2)}, merge);
        }

        private int add(double[] point, double u, double v) {
            int made = copyHost.size();
            copyHost.add(-1);
            if (nextCopy != null) {
                copyLevel.add(-1);
                nextCopy.add(-1);
            }
            xyz.add(point[0]);
            xyz.add(point[1]);
            xyz.add(point[2]);
            uv.add(u);
            uv.add(v);
            return made;
        }
    }
}
