package ifold.wrap;

import ifold.geom.Tolerance;
import ifold.mesh.GridSquares;
import ifold.mesh.PolygonSoup;
import ifold.sheet.FoldException;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Sheet.Placement;
import ifold.wrap.Wrap.Kind;
import ifold.wrap.Wrap.Step;
import ifold.wrap.Wrap.Strip;
import ifold.wrap.Wrap.TailMove;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * The hinge strip's wrap of a grid polyhedron (Benbernou, Demaine, Demaine and Lubiw, "Universal
 * hinge patterns for folding strips efficiently into any grid polyhedron"): a strip of squares
 * as wide as the lattice's, with hinges along the squares' sides and diagonals, folded along
 * the {@link HingeTour}: straight on over flat sides, a fold by the surface's angle over the
 * others, and a flat fold along a square's diagonal where the tour turns. The same engine as
 * the zig-zag's ({@link Sheet}), the same result ({@link Wrap.Result}), so the same placing in
 * space, checks, report, viewer, movie and exports.
 *
 * <p><b>The path.</b> The wrap's mesh is the surface cut into two triangles a square, one
 * triangle a pass of the tour, in the tour's order (the result's triangles "on the path"): a
 * turning pass has the half of its square at its corner, where its paper lies twice; a straight
 * pass one half, the other pass through that square the other (both cover it whole).
 *
 * <p><b>Hosts.</b> The paper rests on its square, a host each: every layer then lies on the
 * surface (rectangles of several squares stacked paper up to 9 levels over 2 layers, floating
 * over squares it did not cover), a stack of at most 2. Over a side to a square of the same
 * plane the strip folds by nothing, over an edge by the surface's angle. Each piece of the strip
 * laid lands over all the paper it overlaps: the tour lays paper only on top.
 */
public final class HingeStrip {
    private HingeStrip() {
    }

    /**
     * Wraps {@code squares}, each component along its tour.
     *
     * @param thickness the paper's thickness, or NaN for {@link Wrap#defaultThickness} of the squares' side
     * @param maxFaces the most faces of paper the wrap may make
     * @throws Wrap.WrapException where the paper would make more faces than {@code maxFaces}
     */
    public static Wrap.Result wrap(GridSquares squares, HingeTour tour, double thickness, int maxFaces, Wrap.Watcher watcher)
            throws Wrap.WrapException {
        double w = squares.spacing();
        double t = Double.isNaN(thickness) ? Wrap.defaultThickness(w) : thickness;
        Layout layout = new Layout(squares, tour);
        // Each fold lays one face, and the end one more: known before any fold.
        long faces = tour.components(); // each strip's end
        for (int c = 0; c < tour.components(); c++) {
            for (int i = tour.componentStart(c); i < tour.componentStart(c + 1); i++) {
                int q = tour.square(i);
                faces += tour.turns(i) ? 1 : 0;
                boolean last = i + 1 == tour.componentStart(c + 1);
                faces += !last && layout.hostOfSquare[squares.across(q, tour.exit(i))] != layout.hostOfSquare[q] ? 1 : 0;
            }
        }
        if (faces > maxFaces) {
            throw new Wrap.FaceLimitException(String.format(Locale.ROOT, "the hinge strip passes %,d times through %,d squares and "
                    + "makes %,d faces of paper, more than the limit of %,d", tour.passes(), squares.count(), faces,
                    maxFaces));
        }
        double tolerance = Tolerance.ON_PLANE * Wrap.modelSize(layout.mesh);
        HostFrame[] frames = BendRoom.of(layout.mesh, layout.hostOf, layout.frames, tolerance);
        List<Strip> strips = new ArrayList<>();
        List<Step> steps = new ArrayList<>();
        for (int c = 0; c < tour.components(); c++) {
            Folding folding = new Folding(squares, tour, layout, frames, c, w, t, tolerance, steps, maxFaces, watcher);
            try {
                strips.add(folding.fold());
            } catch (FoldException e) {
                throw new Wrap.WrapException(folding.where() + ": " + e.getMessage());
            }
        }
        return new Wrap.Result(layout.mesh, frames, layout.hostOf, List.copyOf(strips), List.copyOf(steps), w, t, w, Wrap.Method.HINGE);
    }

    /** What the hinge strip's folds are, as its steps' details say: a step with one of them is a pass's, not a triangle's. */
    static final String TURN_LEFT = "turn left: fold along the square's diagonal";
    static final String TURN_RIGHT = "turn right: fold along the square's diagonal";
    static final String OVER_EDGE = "fold over the edge onto the next square";
    static final String ON_FLAT = "on over the side onto the next piece of the face";
    static final String END = "the strip ends along the side it began by";

    /** Whether a step's detail is one of the hinge strip's. */
    static boolean hinge(String detail) {
        return TURN_LEFT.equals(detail) || TURN_RIGHT.equals(detail) || OVER_EDGE.equals(detail) || ON_FLAT.equals(detail)
                || END.equals(detail);
    }

    /** The path's triangles, a pass each, and the hosts: a square each. */
    static final class Layout {
        final PolygonSoup mesh = new PolygonSoup();
        /** Per triangle (pass): its host. */
        final int[] hostOf;
        /** Per square: its host. */
        final int[] hostOfSquare;
        final HostFrame[] frames;
        private final GridSquares squares;
        private final Map<Long, Integer> vertexAt = new HashMap<>();

        Layout(GridSquares squares, HingeTour tour) {
            this.squares = squares;
            hostOfSquare = new int[squares.count()];
            List<HostFrame> hosts = squareHosts();
            frames = hosts.toArray(new HostFrame[0]);
            hostOf = new int[tour.passes()];
            boolean[] halfTaken = new boolean[squares.count()];
            for (int i = 0; i < tour.passes(); i++) {
                int q = tour.square(i);
                int a = tour.entry(i);
                int first;
                if (!tour.turns(i)) {
                    first = halfTaken[q] ? 2 : 0; // the two straight passes of a square, a half each
                    halfTaken[q] = true;
                } else {
                    // The half at the corner the pass turns about: the corner its two sides share.
                    first = tour.turnsLeft(i) ? a + 3 : a;
                }
                mesh.addTriangle(vertex(q, first), vertex(q, first + 1), vertex(q, first + 2));
                hostOf[i] = hostOfSquare[q];
            }
        }

        private int vertex(int q, int k) {
            int corner = k % 4;
            long key = ((long) squares.latticeCorner(q, corner, 0) << 40) | ((long) squares.latticeCorner(q, corner, 1) << 20)
                    | squares.latticeCorner(q, corner, 2);
            return vertexAt.computeIfAbsent(key, x -> mesh.addVertex(squares.corner(q, corner, 0), squares.corner(q, corner, 1),
                    squares.corner(q, corner, 2)));
        }

        double[] point(int q, int k) {
            int corner = k % 4;
            return new double[] {squares.corner(q, corner, 0), squares.corner(q, corner, 1), squares.corner(q, corner, 2)};
        }

        /** A host a square, framed on its corners 0, 1, 2, its four corners counter-clockwise from outside. */
        private List<HostFrame> squareHosts() {
            List<HostFrame> hosts = new ArrayList<>();
            for (int q = 0; q < squares.count(); q++) {
                hostOfSquare[q] = q;
                HostFrame onEdge = HostFrame.onEdge(point(q, 0), point(q, 1), point(q, 2));
                double[] xy = new double[8];
                for (int k = 0; k < 4; k++) {
                    xy[2 * k] = onEdge.localX(point(q, k));
                    xy[2 * k + 1] = onEdge.localY(point(q, k));
                }
                hosts.add(new HostFrame(onEdge.origin(), onEdge.ex(), onEdge.ey(), onEdge.normal(), xy));
            }
            return hosts;
        }
    }

    /** The folding of one component's strip along its passes. */
    private static final class Folding {
        private final GridSquares squares;
        private final HingeTour tour;
        private final Layout layout;
        private final HostFrame[] frames;
        private final int strip;
        private final double w;
        private final double thickness;
        private final double tolerance;
        private final List<Step> steps;
        private final int maxFaces;
        private final Wrap.Watcher watcher;
        private final int first;
        private final int end;
        private Sheet sheet;
        private int pass;

        Folding(GridSquares squares, HingeTour tour, Layout layout, HostFrame[] frames, int strip, double w, double thickness,
                double tolerance, List<Step> steps, int maxFaces, Wrap.Watcher watcher) {
            this.squares = squares;
            this.tour = tour;
            this.layout = layout;
            this.frames = frames;
            this.strip = strip;
            this.w = w;
            this.thickness = thickness;
            this.tolerance = tolerance;
            this.steps = steps;
            this.maxFaces = maxFaces;
            this.watcher = watcher;
            this.first = tour.componentStart(strip);
            this.end = tour.componentStart(strip + 1);
        }

        Strip fold() throws FoldException, Wrap.WrapException {
            int[] after = new int[end - first];
            for (pass = first; pass < end; pass++) {
                int q = tour.square(pass);
                int host = layout.hostOfSquare[q];
                int in = tour.entry(pass);
                int out = tour.exit(pass);
                if (pass == first) {
                    // The strip's start along the side it enters by, v = 0 at that side's end, running in.
                    double[] a = local(host, q, in + 1);
                    double[] b = local(host, q, in + 2);
                    sheet = new Sheet(w, thickness, tolerance, host, Isometry2.placement(a[0], a[1], Math.atan2(b[1] - a[1], b[0] - a[0]), false));
                }
                if (tour.turns(pass)) {
                    // The diagonal away from the corner it turns about: the square's paper beyond it
                    // folds flat onto the half at that corner, and the strip runs out by the other side.
                    int from = tour.turnsLeft(pass) ? in + 1 : in;
                    double[] p = local(host, q, from);
                    double[] d = local(host, q, from + 2);
                    int before = sheet.faceCount();
                    int hostBefore = sheet.tailHost();
                    Isometry2 poseBefore = sheet.tailPose();
                    int face = sheet.foldTail(p[0], p[1], d[0] - p[0], d[1] - p[1], Placement.OVER, Kind.DIAGONAL_TURN.crease());
                    record(Kind.DIAGONAL_TURN, face, hostBefore, poseBefore, true,
                            tour.turnsLeft(pass) ? TURN_LEFT : TURN_RIGHT);
                    sheet.liftTail();
                    check(before);
                }
                if (pass + 1 == end) {
                    double[] p = local(host, q, out);
                    double[] d = local(host, q, out + 1);
                    int face = sheet.endTail(p[0], p[1], d[0] - p[0], d[1] - p[1]);
                    steps.add(new Step(Kind.END, strip, pass, pass - first, end - first, face, null, sheet.faceCount(), null, END));
                } else {
                    int next = squares.across(q, out);
                    int nextHost = layout.hostOfSquare[next];
                    if (nextHost == host) {
                        sheet.liftTail(); // on over the side, over all the paper the next square has
                    } else {
                        cross(host, q, out, nextHost, next, squares.acrossSide(q, out));
                    }
                }
                after[pass - first] = sheet.faceCount();
                watcher.wrapped(pass + 1, tour.passes());
            }
            return new Strip(sheet, first, end - first, after);
        }

        /** Over side {@code out} of square q onto the next host, by the surface's angle there. */
        private void cross(int host, int q, int out, int nextHost, int next, int nextSide) throws FoldException, Wrap.WrapException {
            double[] a = local(host, q, out);
            double[] b = local(host, q, out + 1);
            // The same two corners in the next host's frame: the side runs the other way round there.
            double[] a2 = local(nextHost, next, nextSide + 1);
            double[] b2 = local(nextHost, next, nextSide);
            Isometry2 development = Isometry2.taking(a[0], a[1], b[0], b[1], a2[0], a2[1], b2[0], b2[1]);
            int hostBefore = sheet.tailHost();
            Isometry2 poseBefore = sheet.tailPose();
            int face = sheet.crossTail(a[0], a[1], b[0] - a[0], b[1] - a[1], nextHost, development);
            record(Kind.EDGE_CROSSING, face, hostBefore, poseBefore, true, squares.flatAcross(q, out) ? ON_FLAT : OVER_EDGE);
        }

        /** Corner k of square q in host h's frame. */
        private double[] local(int h, int q, int k) {
            double[] p = layout.point(q, k);
            return new double[] {frames[h].localX(p), frames[h].localY(p)};
        }

        private void record(Kind kind, int face, int hostBefore, Isometry2 before, boolean over, String detail)
                throws Wrap.FaceLimitException {
            if (watcher.stopped()) {
                throw new java.util.concurrent.CancellationException("the wrap was stopped");
            }
            if (sheet.faceCount() > maxFaces) {
                throw new Wrap.FaceLimitException(String.format(Locale.ROOT, "the strip has %d faces of paper at pass %d of %d, more "
                        + "than the limit of %,d faces", sheet.faceCount(), pass - first + 1, end - first, maxFaces));
            }
            TailMove move = new TailMove(hostBefore, before, sheet.tailHost(), sheet.tailPose(), sheet.tailStart(false),
                    sheet.tailStart(true), over);
            steps.add(new Step(kind, strip, pass, pass - first, end - first, face, null, sheet.faceCount(), move, detail));
        }

        private void check(int before) {
            if (sheet.faceCount() <= before) {
                throw new IllegalStateException("a turn laid no paper at pass " + (pass - first + 1));
            }
        }

        String where() {
            return String.format(Locale.ROOT, "square %d, pass %d of %d of the hinge strip", tour.square(pass) + 1, pass - first + 1,
                    end - first);
        }
    }
}
