package ifold.refine;

import ifold.geom.Polygons;
import ifold.geom.Tolerance;
import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Topology;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.tinfour.common.IConstraint;
import org.tinfour.common.IQuadEdge;
import org.tinfour.common.PolygonConstraint;
import org.tinfour.common.SimpleTriangle;
import org.tinfour.common.Vertex;
import org.tinfour.refinement.RuppertRefiner;
import org.tinfour.standard.IncrementalTin;

/**
 * One planar region of a model being prepared ({@link FacePreparation}): coplanar faces grown
 * from a seed, their boundary loops, and their triangulation again by Tinfour's constrained
 * Delaunay triangulation and Ruppert's refinement, with the points that cut its edges, shared
 * with the regions across them.
 */
final class PlanarRegion {
    private final FacePreparation.Run run;
    private final HalfedgeMesh mesh;
    private final double[] xyz;
    private final double[] normal;
    private final int[] regionOf;
    private final double[][] splits;
    final int index;
    final int seed;
    final List<Integer> faces = new ArrayList<>();
    /** A corner of the seed face, on the region's plane, and the seed's size, for the coplanarity test. */
    final double[] origin = new double[3];
    final double seedSize;
    double minAngle = Math.PI;
    /** Twice the area over the perimeter: the width of a long region, the inradius of a round one. */
    double thickness;
    /**
     * Whether a corner of the region is sharper than the target: no triangulation can
     * widen it, and refining towards it makes triangles too small for any strip. Such a
     * region keeps its triangles, or is triangulated from its boundary alone where a
     * neighbour's refinement cut its edges.
     */
    boolean sharp;
    boolean prepare;
    boolean dirty;
    /**
     * Whether the region was triangulated again for the points its own refinement put on its
     * boundary, since a neighbour last gave it one: once is enough ({@link #triangulate}).
     */
    boolean triangulatedForOwnSplits;
    /** How many times the region was refined ({@link FacePreparation#MOST_REFINEMENTS}). */
    int refinements;
    /** Why the region keeps its triangles while the others are prepared, in words; null where it may be prepared. */
    String keptBecause;
    /** The triangles made, three corner keys each, and the points inside, x, y, z interleaved. */
    long[] triangles = new long[0];
    double[] interior = new double[0];

    PlanarRegion(FacePreparation.Run run, int index, int seed) {
        this.run = run;
        this.mesh = run.mesh;
        this.xyz = run.xyz;
        this.normal = run.normal;
        this.regionOf = run.regionOf;
        this.splits = run.splits;
        this.index = index;
        this.seed = seed;
        int h = mesh.faceHalfedge(seed);
        int a = mesh.fromVertex(h);
        for (int k = 0; k < 3; k++) {
            origin[k] = xyz[3 * a + k];
        }
        seedSize = Math.max(Triangles.distance(xyz, a, mesh.toVertex(h)),
                Math.max(Triangles.distance(xyz, mesh.toVertex(h), mesh.toVertex(mesh.next(h))),
                        Triangles.distance(xyz, mesh.toVertex(mesh.next(h)), a)));
    }

    void measure() {
        double area = 0;
        for (int f : faces) {
            int h = mesh.faceHalfedge(f);
            int a = mesh.fromVertex(h);
            int b = mesh.toVertex(h);
            int c = mesh.toVertex(mesh.next(h));
            minAngle = Math.min(minAngle, Triangles.minAngle(xyz, a, b, c));
            area += Triangles.twiceArea(xyz, a, b, c) / 2;
        }
        Map<Integer, Double> cornerAngle = new HashMap<>();
        for (int f : faces) {
            int h0 = mesh.faceHalfedge(f);
            int h = h0;
            do {
                int v = mesh.fromVertex(h);
                double angle = Triangles.angleAt(xyz, v, mesh.toVertex(h), mesh.fromVertex(mesh.prev(h)));
                cornerAngle.merge(v, angle, Double::sum);
                h = mesh.next(h);
            } while (h != h0);
        }
        double perimeter = 0;
        for (int h : boundary()) {
            sharp |= cornerAngle.get(mesh.fromVertex(h)) < Math.toRadians(FacePreparation.TARGET_ANGLE);
            perimeter += Triangles.distance(xyz, mesh.fromVertex(h), mesh.toVertex(h));
        }
        thickness = perimeter > 0 ? 2 * area / perimeter : Math.sqrt(area);
    }

    /**
     * The fewest corners of a region fanned from its centre: a pentagon. A square has no corner
     * where three triangles fan, and fanned from its centre took the cube from 13 layers to 14.
     */
    static final int FEWEST_FAN_CORNERS = 5;

    /**
     * The most corners of a region fanned from its centre: a hexagon. The shared hex_prism's
     * hexagons, cut from one corner, had eight thin triangles there, each turning into its last
     * pass at it (21 layers at most); fanned from their centre, 15 in every start and 27 % fewer
     * faces. They crossed by their corners (4 pairs, 1 T: a bend on the line from a corner to the
     * centre standing out into flat paper tucked between its layers, which leaves the corner 30
     * degrees off that line), and so did a lone hexagon and an irregular hexagonal prism (2 and
     * 4 pairs, 0.24 and 0.93 T), until such a bend's row stopped on that paper
     * ({@code ifold.wrap.RowsOnPaper}; docs/wrap.md, Faces prepared where they help).
     */
    static final int MOST_FAN_CORNERS = 6;

    /**
     * Fans the region from its centre where its triangles fan three or more at one of its corners
     * ({@link FacePreparation}): a convex pentagon or hexagon, one loop with no point inside,
     * none of its corners sharper than the target, and no triangle of the fan either. Sets its
     * triangles (a corner key and the centre's each) and its one point inside; false, and nothing
     * set, where the region is not such a polygon or needs no fan.
     */
    boolean fanFromCentre() throws FacePreparation.Unprepared {
        double target = Math.toRadians(FacePreparation.TARGET_ANGLE);
        if (sharp || faces.size() < 3 || minAngle < target) {
            return false;
        }
        Map<Integer, Integer> around = new HashMap<>();
        int most = 0;
        for (int f : faces) {
            int h0 = mesh.faceHalfedge(f);
            int h = h0;
            do {
                most = Math.max(most, around.merge(mesh.fromVertex(h), 1, Integer::sum));
                h = mesh.next(h);
            } while (h != h0);
        }
        if (most < 3) {
            return false;
        }
        List<List<Integer>> loops = loops();
        List<Integer> loop = loops.get(0);
        if (loops.size() != 1 || faces.size() != loop.size() - 2) {
            return false; // a hole, or a point inside: no fan from one centre
        }
        // The centre of area: inside any convex polygon.
        double[] centre = new double[3];
        double area = 0;
        for (int f : faces) {
            int h = mesh.faceHalfedge(f);
            int a = mesh.fromVertex(h);
            int b = mesh.toVertex(h);
            int c = mesh.toVertex(mesh.next(h));
            double weight = Triangles.twiceArea(xyz, a, b, c);
            area += weight;
            for (int k = 0; k < 3; k++) {
                centre[k] += weight * (xyz[3 * a + k] + xyz[3 * b + k] + xyz[3 * c + k]) / 3;
            }
        }
        for (int k = 0; k < 3; k++) {
            centre[k] /= area;
        }
        double[] n = {normal[3 * seed], normal[3 * seed + 1], normal[3 * seed + 2]};
        double[] fan = new double[9];
        long[] made = new long[3 * loop.size()];
        int corners = 0;
        for (int i = 0; i < loop.size(); i++) {
            int a = mesh.fromVertex(loop.get(i));
            int b = mesh.toVertex(loop.get(i));
            int c = mesh.toVertex(loop.get((i + 1) % loop.size()));
            // Convex: the boundary turns left about the normal at every corner, or runs straight on.
            double turn = 0;
            for (int k = 0; k < 3; k++) {
                int k1 = (k + 1) % 3;
                int k2 = (k + 2) % 3;
                turn += n[k] * ((xyz[3 * b + k1] - xyz[3 * a + k1]) * (xyz[3 * c + k2] - xyz[3 * b + k2])
                        - (xyz[3 * b + k2] - xyz[3 * a + k2]) * (xyz[3 * c + k1] - xyz[3 * b + k1]));
            }
            double straight = Tolerance.RELATIVE_EQUALITY * Triangles.distance(xyz, a, b) * Triangles.distance(xyz, b, c);
            if (turn < -straight) {
                return false;
            }
            corners += turn > straight ? 1 : 0;
            for (int k = 0; k < 3; k++) {
                fan[k] = xyz[3 * a + k];
                fan[3 + k] = xyz[3 * b + k];
                fan[6 + k] = centre[k];
            }
            if (Triangles.minAngle(fan, 0, 1, 2) < target) {
                return false;
            }
            made[3 * i] = FacePreparation.Run.cornerKey(a);
            made[3 * i + 1] = FacePreparation.Run.cornerKey(b);
            made[3 * i + 2] = FacePreparation.Run.insideKey(0);
        }
        if (corners < FEWEST_FAN_CORNERS || corners > MOST_FAN_CORNERS) {
            return false;
        }
        triangles = made;
        interior = centre;
        return true;
    }

    /** The halfedges of the region's faces whose twin lies outside it (on another region, or no face). */
    List<Integer> boundary() {
        List<Integer> boundary = new ArrayList<>();
        for (int f : faces) {
            int h0 = mesh.faceHalfedge(f);
            int h = h0;
            do {
                int g = mesh.face(HalfedgeMesh.twin(h));
                if (g < 0 || regionOf[g] != index) {
                    boundary.add(h);
                }
                h = mesh.next(h);
            } while (h != h0);
        }
        return boundary;
    }

    /** The boundary halfedges as closed loops, each in order (the outer loop counter-clockwise about the normal, holes clockwise). */
    List<List<Integer>> loops() throws FacePreparation.Unprepared {
        List<Integer> boundary = boundary();
        Map<Integer, Integer> place = new HashMap<>();
        for (int i = 0; i < boundary.size(); i++) {
            place.put(boundary.get(i), i);
        }
        // A region that touches itself at a corner passes that corner twice: no polygon with holes.
        Set<Integer> corners = new HashSet<>();
        for (int h : boundary) {
            if (!corners.add(mesh.fromVertex(h))) {
                throw new FacePreparation.Unprepared("region " + index + "'s boundary touches itself at a corner");
            }
        }
        boolean[] used = new boolean[boundary.size()];
        List<List<Integer>> loops = new ArrayList<>();
        for (int i = 0; i < boundary.size(); i++) {
            if (used[i]) {
                continue;
            }
            List<Integer> loop = new ArrayList<>();
            int h = boundary.get(i);
            while (true) {
                Integer at = place.get(h);
                if (at == null) {
                    throw new FacePreparation.Unprepared("region " + index + "'s boundary is not a loop");
                }
                if (used[at]) {
                    break; // back at its start: each corner is passed once
                }
                used[at] = true;
                loop.add(h);
                // The next boundary halfedge: turn about h's end inside the region.
                int next = mesh.next(h);
                int guard = 0;
                while (true) {
                    int g = mesh.face(HalfedgeMesh.twin(next));
                    if (g < 0 || regionOf[g] != index) {
                        break;
                    }
                    next = mesh.next(HalfedgeMesh.twin(next));
                    if (++guard > 1 << 20) {
                        throw new FacePreparation.Unprepared("region " + index + "'s boundary cannot be followed");
                    }
                }
                h = next;
            }
            loops.add(loop);
        }
        return loops;
    }

    /** Triangulates the region from its boundary (with every split of its edges), refined to the target angle if {@code refine}. */
    void triangulate(boolean refine) throws FacePreparation.Unprepared {
        double[] n = {normal[3 * seed], normal[3 * seed + 1], normal[3 * seed + 2]};
        List<List<Integer>> loops = loops();
        // The splits as this run takes them: a split the refinement adds is for the next run.
        Map<Integer, double[]> taken = new HashMap<>();
        for (List<Integer> loop : loops) {
            for (int h : loop) {
                int e = HalfedgeMesh.edge(h);
                taken.put(e, splits[e] == null ? new double[0] : splits[e].clone());
            }
        }
        // The frame: the first boundary edge's direction and the normal's cross with it, scaled to the region.
        int h0 = loops.get(0).get(0);
        int a0 = mesh.fromVertex(h0);
        int b0 = mesh.toVertex(h0);
        double[] e1 = new double[3];
        double length = Triangles.distance(xyz, a0, b0);
        for (int k = 0; k < 3; k++) {
            e1[k] = (xyz[3 * b0 + k] - xyz[3 * a0 + k]) / length;
        }
        double[] e2 = {n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2], n[0] * e1[1] - n[1] * e1[0]};
        double[] o = {xyz[3 * a0], xyz[3 * a0 + 1], xyz[3 * a0 + 2]};
        double scale = 1 / Math.max(thickness, 1e-300);
        List<Long> keys = new ArrayList<>();
        List<double[]> points = new ArrayList<>();
        List<IConstraint> constraints = new ArrayList<>();
        Map<Vertex, Integer> known = new IdentityHashMap<>();
        for (List<Integer> loop : loops) {
            List<Vertex> polygon = new ArrayList<>();
            for (int h : loop) {
                int e = HalfedgeMesh.edge(h);
                boolean forward = h == HalfedgeMesh.halfedgeOfEdge(e, 0);
                addPoint(mesh.fromVertex(h), FacePreparation.Run.cornerKey(mesh.fromVertex(h)), o, e1, e2, scale, keys, points, polygon, known);
                double[] t = taken.get(e);
                for (int k = 0; k < t.length; k++) {
                    int i = forward ? k : t.length - 1 - k;
                    double[] p = run.pointOnEdge(e, t[i]);
                    addPoint(p, FacePreparation.Run.splitKey(e, i), o, e1, e2, scale, keys, points, polygon, known);
                }
            }
            PolygonConstraint constraint = new PolygonConstraint(polygon);
            constraint.complete();
            constraints.add(constraint);
        }
        IncrementalTin tin = new IncrementalTin(1);
        tin.addConstraints(constraints, true);
        if (!tin.isBootstrapped()) {
            throw new FacePreparation.Unprepared("region " + index + " has no area to triangulate");
        }
        if (refine) {
            refinements++;
            RuppertRefiner refiner = new RuppertRefiner(tin, FacePreparation.TARGET_ANGLE, FacePreparation.AREA_FLOOR);
            int boundaryPoints = points.size();
            // Each step inserts a point; counting steps, not the TIN's vertices, which Tinfour counts by a walk.
            int limit = 50 * boundaryPoints + 1000;
            for (int steps = 0; steps < limit && refiner.refineOnce() != null; steps++) {
                // enough at the limit: the rest of the region's thin triangles stay
            }
        }
        List<double[]> inside = new ArrayList<>();
        Map<Vertex, Long> made = new IdentityHashMap<>();
        List<Long> triangleKeys = new ArrayList<>();
        int splitsBefore = splitCount(taken.keySet());
        // Each corner's place along its edge where it splits one (NaN where not), for renumberSplits.
        List<Double> splitPlaces = new ArrayList<>();
        Map<Vertex, Double> madePlace = new IdentityHashMap<>();
        double[][] loop2d = loops2d(loops, points, taken);
        // Points the refinement put on the boundary end constrained edges: only those are looked for along it.
        Map<Vertex, Boolean> onBorder = new IdentityHashMap<>();
        for (IQuadEdge edge : tin.edges()) {
            if (edge.isConstrained()) {
                onBorder.put(edge.getA(), true);
                onBorder.put(edge.getB(), true);
            }
        }
        for (SimpleTriangle t : tin.triangles()) {
            if (t.isGhost()) {
                continue;
            }
            Vertex[] corners = {t.getVertexA(), t.getVertexB(), t.getVertexC()};
            IConstraint containing = t.getContainingRegion();
            if (containing == null || !containing.definesConstrainedRegion()) {
                continue; // in a hole, or outside a region that is not convex
            }
            double twice = (corners[1].getX() - corners[0].getX()) * (corners[2].getY() - corners[0].getY())
                    - (corners[1].getY() - corners[0].getY()) * (corners[2].getX() - corners[0].getX());
            if (twice < 0) {
                Vertex swap = corners[1];
                corners[1] = corners[2];
                corners[2] = swap;
            }
            for (Vertex corner : corners) {
                Integer at = known.get(corner);
                if (at != null) {
                    long key = keys.get(at);
                    triangleKeys.add(key);
                    splitPlaces.add(placeOnEdge(key, taken));
                    continue;
                }
                Long key = made.get(corner);
                if (key == null) {
                    key = newPoint(corner, onBorder.containsKey(corner), loops, loop2d, taken, inside, o, e1, e2, scale);
                    made.put(corner, key);
                    madePlace.put(corner, placeOnEdge(key, null));
                }
                triangleKeys.add(key);
                splitPlaces.add(madePlace.get(corner));
            }
        }
        triangles = triangleKeys.stream().mapToLong(Long::longValue).toArray();
        if (splitCount(taken.keySet()) > splitsBefore) {
            renumberSplits(splitPlaces);
            // Triangulated again once, with the new points as its own: the refinement then fits
            // them. Not again for the points that run puts there: refined from its boundary, it
            // has forgotten which points it added at a corner near the target angle, and halves
            // the pieces there again every time (the shared capsule's 20.4° corners: two points a
            // run, the pieces a millionth of the region, until Tinfour merged two of them).
            dirty |= !triangulatedForOwnSplits;
            triangulatedForOwnSplits = true;
        }
        dropFlatTriangles(taken.keySet());
        interior = new double[3 * inside.size()];
        for (int i = 0; i < inside.size(); i++) {
            System.arraycopy(inside.get(i), 0, interior, 3 * i, 3);
        }
    }

    private void addPoint(int v, long key, double[] o, double[] e1, double[] e2, double scale, List<Long> keys,
            List<double[]> points, List<Vertex> polygon, Map<Vertex, Integer> known) {
        addPoint(new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}, key, o, e1, e2, scale, keys, points, polygon, known);
    }

    private void addPoint(double[] p, long key, double[] o, double[] e1, double[] e2, double scale, List<Long> keys,
            List<double[]> points, List<Vertex> polygon, Map<Vertex, Integer> known) {
        double x = 0;
        double y = 0;
        for (int k = 0; k < 3; k++) {
            x += (p[k] - o[k]) * e1[k];
            y += (p[k] - o[k]) * e2[k];
        }
        Vertex vertex = new Vertex(x * scale, y * scale, 0, keys.size());
        known.put(vertex, keys.size());
        keys.add(key);
        points.add(new double[] {x * scale, y * scale});
        polygon.add(vertex);
    }

    /** Each loop's points in the plane, x and y interleaved. */
    private double[][] loops2d(List<List<Integer>> loops, List<double[]> points, Map<Integer, double[]> taken) {
        double[][] result = new double[loops.size()][];
        int at = 0;
        for (int l = 0; l < loops.size(); l++) {
            int count = 0;
            for (int h : loops.get(l)) {
                count += 1 + taken.get(HalfedgeMesh.edge(h)).length;
            }
            result[l] = new double[2 * count];
            for (int i = 0; i < count; i++) {
                result[l][2 * i] = points.get(at + i)[0];
                result[l][2 * i + 1] = points.get(at + i)[1];
            }
            at += count;
        }
        return result;
    }

    /**
     * A point the refinement made: on the region's boundary, a new split of the edge it
     * lies on (the region across is marked to be triangulated again); else a point inside.
     */
    private long newPoint(Vertex vertex, boolean onBorder, List<List<Integer>> loops, double[][] loop2d, Map<Integer, double[]> taken, List<double[]> inside,
            double[] o, double[] e1, double[] e2, double scale) throws FacePreparation.Unprepared {
        double x = vertex.getX();
        double y = vertex.getY();
        for (int l = 0; onBorder && l < loops.size(); l++) {
            double[] ring = loop2d[l];
            int count = ring.length / 2;
            int at = 0;
            for (int h : loops.get(l)) {
                double[] t = taken.get(HalfedgeMesh.edge(h));
                int pieces = 1 + t.length;
                for (int k = 0; k < pieces; k++) {
                    int i = at + k;
                    int j = (i + 1) % count;
                    double ax = ring[2 * i];
                    double ay = ring[2 * i + 1];
                    double bx = ring[2 * j];
                    double by = ring[2 * j + 1];
                    double dx = bx - ax;
                    double dy = by - ay;
                    double len2 = dx * dx + dy * dy;
                    double s = ((x - ax) * dx + (y - ay) * dy) / len2;
                    double off = Math.abs((x - ax) * dy - (y - ay) * dx) / Math.sqrt(len2);
                    if (s > 0 && s < 1 && off <= 1e-9 * Math.sqrt(len2) + 1e-12) {
                        return addSplit(h, k, t, s);
                    }
                }
                at += pieces;
            }
        }
        double[] p = new double[3];
        for (int k = 0; k < 3; k++) {
            p[k] = o[k] + (x * e1[k] + y * e2[k]) / scale;
        }
        inside.add(p);
        return FacePreparation.Run.insideKey(inside.size() - 1);
    }

    /** A split of the edge of halfedge h, at fraction s of its k-th piece along h between the splits t this run took. */
    private long addSplit(int h, int k, double[] t, double s) {
        int e = HalfedgeMesh.edge(h);
        int across = mesh.face(HalfedgeMesh.twin(h));
        if (across >= 0 && run.keptBecause(regionOf[across]) != null) {
            throw new CutsAKeptRegion();
        }
        boolean forward = h == HalfedgeMesh.halfedgeOfEdge(e, 0);
        int pieces = t.length + 1;
        // The piece's ends as parameters along the edge's first halfedge.
        double from;
        double to;
        if (forward) {
            from = k == 0 ? 0 : t[k - 1];
            to = k == pieces - 1 ? 1 : t[k];
        } else {
            from = k == 0 ? 1 : t[t.length - k];
            to = k == pieces - 1 ? 0 : t[t.length - 1 - k];
        }
        double at = from + s * (to - from);
        double[] now = splits[e] == null ? new double[0] : splits[e];
        double[] grown = Arrays.copyOf(now, now.length + 1);
        grown[now.length] = at;
        Arrays.sort(grown);
        splits[e] = grown;
        run.markAcross(e, this);
        return FacePreparation.Run.splitKey(e, Arrays.binarySearch(grown, at));
    }

    /**
     * The refinement put a point on the edge of a region kept as it is, whose triangles cannot
     * take it: the region is then triangulated from its boundary alone.
     */
    static final class CutsAKeptRegion extends RuntimeException {
        private static final long serialVersionUID = 1L;

        CutsAKeptRegion() {
            super(null, null, false, false);
        }
    }

    /** The region in words, for a user: its seed face, and how many coplanar faces with it. */
    String describe() {
        return "face " + seed + (faces.size() > 1 ? " (with " + (faces.size() - 1) + " coplanar neighbour" + (faces.size() > 2 ? "s" : "") + ")" : "");
    }

    /** How many points its outline has: its boundary's corners and the splits of its edges. */
    int outlinePoints() {
        int count = 0;
        for (int h : boundary()) {
            int e = HalfedgeMesh.edge(h);
            count += 1 + (splits[e] == null ? 0 : splits[e].length);
        }
        return count;
    }

    /**
     * Drops the triangles whose three corners lie on one edge of the region's boundary, and fans
     * each triangle whose side then runs along such an edge past points of it from its far
     * corner to those points. Such a triangle is flat in space but not quite in the plane: the
     * points of an edge, projected into the region's frame, stray from their line by a rounding,
     * and Tinfour triangulated the slivers between them (the shared rabbit's face 1168: three
     * on one edge, so that the whole region was kept as it is).
     *
     * @param edges the edges of the region's boundary
     */
    private void dropFlatTriangles(Iterable<Integer> edges) {
        List<long[]> kept = new ArrayList<>();
        for (int k = 0; k < triangles.length; k += 3) {
            long[] triangle = {triangles[k], triangles[k + 1], triangles[k + 2]};
            int e = edgeUnder(triangle[0], triangle[1], edges);
            if (e < 0 || Double.isNaN(placeOn(e, triangle[2]))) {
                kept.add(triangle);
            }
        }
        if (kept.size() == triangles.length / 3) {
            return;
        }
        List<long[]> fanned = new ArrayList<>();
        while (!kept.isEmpty()) {
            long[] triangle = kept.remove(kept.size() - 1);
            boolean split = false;
            for (int c = 0; c < 3 && !split; c++) {
                long from = triangle[c];
                long to = triangle[(c + 1) % 3];
                long apex = triangle[(c + 2) % 3];
                int e = edgeUnder(from, to, edges);
                if (e < 0) {
                    continue;
                }
                double a = placeOn(e, from);
                double b = placeOn(e, to);
                List<Long> between = new ArrayList<>();
                double[] t = splits[e] == null ? new double[0] : splits[e];
                for (int i = 0; i < t.length; i++) {
                    if (t[i] > Math.min(a, b) && t[i] < Math.max(a, b)) {
                        between.add(FacePreparation.Run.splitKey(e, i));
                    }
                }
                if (between.isEmpty()) {
                    continue;
                }
                if (a > b) {
                    java.util.Collections.reverse(between);
                }
                // The points lie on the side between its ends: each piece keeps the triangle's orientation.
                long previous = from;
                for (long point : between) {
                    kept.add(new long[] {previous, point, apex});
                    previous = point;
                }
                kept.add(new long[] {previous, to, apex});
                split = true;
            }
            if (!split) {
                fanned.add(triangle);
            }
        }
        triangles = new long[3 * fanned.size()];
        for (int k = 0; k < fanned.size(); k++) {
            System.arraycopy(fanned.get(k), 0, triangles, 3 * k, 3);
        }
    }

    /** The edge of {@code edges} both corner keys lie on (a split of it, or one of its ends), or -1. */
    private int edgeUnder(long a, long b, Iterable<Integer> edges) {
        for (int e : edges) {
            if (!Double.isNaN(placeOn(e, a)) && !Double.isNaN(placeOn(e, b))) {
                return e;
            }
        }
        return -1;
    }

    /** The parameter along edge e of the point a corner key names, from its first halfedge's start; NaN where it is not on e. */
    private double placeOn(int e, long key) {
        if (FacePreparation.Run.isSplitKey(key)) {
            return FacePreparation.Run.splitEdge(key) == e ? splits[e][FacePreparation.Run.splitIndex(key)] : Double.NaN;
        }
        int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
        if (key == FacePreparation.Run.cornerKey(mesh.fromVertex(h))) {
            return 0;
        }
        return key == FacePreparation.Run.cornerKey(mesh.toVertex(h)) ? 1 : Double.NaN;
    }

    /** How many splits the edges hold now. */
    private int splitCount(Iterable<Integer> edges) {
        int count = 0;
        for (int e : edges) {
            count += splits[e] == null ? 0 : splits[e].length;
        }
        return count;
    }

    /**
     * The parameter along its edge of the split a corner key names, as the key was made: from the
     * splits this run took ({@code taken}), or from the edge's splits now where null; NaN where
     * the key names no split.
     */
    private double placeOnEdge(long key, Map<Integer, double[]> taken) {
        if (!FacePreparation.Run.isSplitKey(key)) {
            return Double.NaN;
        }
        int e = FacePreparation.Run.splitEdge(key);
        return (taken != null ? taken.get(e) : splits[e])[FacePreparation.Run.splitIndex(key)];
    }

    /**
     * Renumbers the split corners of the triangles made, from their places along their edges
     * ({@code places}, one a corner): a split this run added to an edge moved the numbers of
     * those after it.
     */
    private void renumberSplits(List<Double> places) {
        for (int k = 0; k < triangles.length; k++) {
            double place = places.get(k);
            if (!Double.isNaN(place)) {
                int e = FacePreparation.Run.splitEdge(triangles[k]);
                triangles[k] = FacePreparation.Run.splitKey(e, Arrays.binarySearch(splits[e], place));
            }
        }
    }
}
