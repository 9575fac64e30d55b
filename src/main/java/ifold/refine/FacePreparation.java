package ifold.refine;

import ifold.geom.Polygons;
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
 * Prepares a surface for wrapping: every planar region (a face, or coplanar neighbours) whose
 * triangles have an angle under {@link #TARGET_ANGLE} is triangulated again into well-shaped
 * triangles, keeping the model's edges and its shape. The strip may crease anywhere inside a
 * face, so a long thin face is no sharp corner of the solid: a 100 × 1 rectangle cut into two
 * triangles of 0.57° corners becomes a row of triangles about as wide as it is high, and the
 * box it belongs to wraps like a row of cubes.
 *
 * <p><b>How.</b> Regions are grown over edges between coplanar triangles. A region to prepare
 * has its boundary edges split first into pieces about as long as the region is thick (twice its
 * area over its perimeter), the same pieces on both sides of an edge; then a constrained
 * Delaunay triangulation of its boundary is refined by Ruppert's algorithm (Tinfour's
 * {@code RuppertRefiner}) to the target angle, with a floor on the area of the triangles it
 * refines, so that a corner of the region sharper than the target (a spike's apex) keeps a few
 * thin triangles rather than a cascade of ever smaller ones: a strip has one width, which the
 * smallest triangle would set. Where the refinement splits an edge of the region, the region
 * across the edge gets the point too and is triangulated again, until no region has a point its
 * neighbour lacks.
 *
 * <p>The prepared mesh is built and validated like a model read from a file; anything that
 * would not come out as the same closed or open surface (a repair the builder had to make,
 * another topology or area), or come out worse (a smallest angle under the model's, fifty times
 * its triangles), keeps the model's own triangles, and the result says why. A region that is
 * not a polygon with holes (it touches itself at a corner) is left as it is, like a sharp one;
 * a refinement stopped at its limit of points keeps what it made.
 */
public final class FacePreparation {
    /** The smallest angle the preparation aims for, in degrees (Ruppert's algorithm is proven to about 20.7°). */
    public static final int TARGET_ANGLE = 20;

    /** Normals of coplanar neighbours agree to this (1 - cos of the angle between them). */
    private static final double COPLANAR_COSINE = 1e-12;

    /** A point this far from a region's plane, over the size of the region's first face, is off it. */
    private static final double OFF_PLANE = 1e-9;

    /** Boundary pieces are at most this many times the region's thickness long. */
    private static final double PIECE_OVER_THICKNESS = 1.5;

    /** Ruppert's algorithm leaves triangles under this fraction of the region's thickness squared. */
    private static final double AREA_FLOOR = 0.02;

    /** The most pieces the edges of a model may be cut into before the triangulation, at least: beyond that the model keeps its triangles. */
    private static final long MOST_PIECES = 100_000;

    /** The most pieces one edge is cut into: a split's place on its edge is 24 bits of its key. */
    private static final int MOST_SPLITS_OF_AN_EDGE = 1 << 23;

    /** The prepared triangles may be this many times the model's (and 10,000 more) before the model keeps its own. */
    private static final int MOST_TIMES_TRIANGLES = 50;

    /** The most times the regions may be triangulated, over the regions to prepare: a cascade of splits from region to region stops there. */
    private static final int ROUNDS = 20;

    private FacePreparation() {
    }

    /**
     * What the preparation made.
     *
     * @param mesh the prepared surface (the model itself where nothing needed preparing, or it was kept)
     * @param regions the planar regions of the model
     * @param prepared the regions triangulated again
     * @param trianglesBefore the model's triangles
     * @param minAngleBefore the model's smallest angle, in degrees
     * @param minAngleAfter the prepared surface's smallest angle, in degrees
     * @param kept why the model's own triangles were kept although some region needed preparing, or null
     */
    public record Result(HalfedgeMesh mesh, int regions, int prepared, int trianglesBefore, double minAngleBefore,
            double minAngleAfter, String kept) {
        public int trianglesAfter() {
            return mesh.faceCount();
        }
    }

    /**
     * Prepares {@code mesh}, a valid triangle mesh.
     *
     * @throws IllegalArgumentException if a face is not a triangle
     */
    public static Result prepare(HalfedgeMesh mesh) {
        return new FacePreparation.Run(mesh).run();
    }

    /** One preparation of one mesh. */
    private static final class Run {
        private final HalfedgeMesh mesh;
        private final double[] xyz;
        /** The unit normal of each face, x, y, z interleaved. */
        private final double[] normal;
        /** The region of each face. */
        private final int[] regionOf;
        private final List<Region> regions = new ArrayList<>();
        /** The points splitting each edge of the mesh, as parameters t in (0, 1) from fromVertex(2e) to toVertex(2e); null for none. */
        private final double[][] splits;

        Run(HalfedgeMesh mesh) {
            this.mesh = mesh;
            this.xyz = mesh.positionArray();
            int faces = mesh.faceCount();
            normal = new double[3 * faces];
            regionOf = new int[faces];
            splits = new double[mesh.edgeCount()][];
            int[] corners = new int[3];
            double[] n = new double[3];
            for (int f = 0; f < faces; f++) {
                int h = mesh.faceHalfedge(f);
                if (mesh.next(mesh.next(mesh.next(h))) != h) {
                    throw new IllegalArgumentException("face preparation needs triangles, but face " + f + " has " + mesh.faceSize(f) + " sides");
                }
                corners[0] = mesh.fromVertex(h);
                corners[1] = mesh.toVertex(h);
                corners[2] = mesh.toVertex(mesh.next(h));
                Polygons.newellNormal(xyz, corners, 3, n);
                double length = Math.sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
                for (int k = 0; k < 3; k++) {
                    normal[3 * f + k] = length > 0 ? n[k] / length : 0;
                }
            }
        }

        Result run() {
            double before = RefinementClaims.minAngleDegrees(mesh);
            growRegions();
            List<Region> toPrepare = new ArrayList<>();
            for (Region region : regions) {
                if (region.minAngle < Math.toRadians(TARGET_ANGLE) && !region.sharp) {
                    try {
                        region.loops();
                        toPrepare.add(region);
                    } catch (Unprepared e) {
                        region.sharp = true; // not a polygon with holes: left as it is, its edges not cut
                    }
                }
            }
            if (toPrepare.isEmpty()) {
                return new Result(mesh, regions.size(), 0, mesh.faceCount(), before, before, null);
            }
            try {
                for (Region region : toPrepare) {
                    region.prepare = true;
                }
                splitBoundaries(toPrepare);
                triangulateUntilAgreed();
                HalfedgeMesh prepared = assemble();
                double after = RefinementClaims.minAngleDegrees(prepared);
                if (after < before) {
                    throw new Unprepared(String.format(Locale.ROOT, "the prepared triangles' smallest angle, %.3g degrees, is "
                            + "under the model's own %.3g (a feature thinner than its faces)", after, before));
                }
                if (prepared.faceCount() > MOST_TIMES_TRIANGLES * mesh.faceCount() + MOST_PIECES / 10) {
                    throw new Unprepared(String.format(Locale.ROOT, "the prepared faces would be %d triangles, more than %d "
                            + "times the model's %d", prepared.faceCount(), MOST_TIMES_TRIANGLES, mesh.faceCount()));
                }
                int count = 0;
                for (Region region : regions) {
                    count += region.prepare ? 1 : 0;
                }
                return new Result(prepared, regions.size(), count, mesh.faceCount(), before, after, null);
            } catch (Unprepared e) {
                return new Result(mesh, regions.size(), 0, mesh.faceCount(), before, before, e.getMessage());
            }
        }

        // ------------------------------------------------------------ regions

        /** Grows regions over edges between coplanar faces, each within its first face's plane. */
        private void growRegions() {
            Arrays.fill(regionOf, -1);
            Deque<Integer> queue = new ArrayDeque<>();
            for (int seed = 0; seed < mesh.faceCount(); seed++) {
                if (regionOf[seed] >= 0) {
                    continue;
                }
                Region region = new Region(regions.size(), seed);
                regions.add(region);
                regionOf[seed] = region.index;
                queue.add(seed);
                while (!queue.isEmpty()) {
                    int f = queue.poll();
                    region.faces.add(f);
                    int h0 = mesh.faceHalfedge(f);
                    int h = h0;
                    do {
                        int g = mesh.face(HalfedgeMesh.twin(h));
                        if (g >= 0 && regionOf[g] < 0 && coplanar(region, g)) {
                            regionOf[g] = region.index;
                            queue.add(g);
                        }
                        h = mesh.next(h);
                    } while (h != h0);
                }
                region.measure();
            }
        }

        private boolean coplanar(Region region, int g) {
            double cos = normal[3 * region.seed] * normal[3 * g] + normal[3 * region.seed + 1] * normal[3 * g + 1]
                    + normal[3 * region.seed + 2] * normal[3 * g + 2];
            if (!(cos > 1 - COPLANAR_COSINE)) {
                return false;
            }
            int h0 = mesh.faceHalfedge(g);
            int h = h0;
            do {
                int v = mesh.toVertex(h);
                double d = 0;
                for (int k = 0; k < 3; k++) {
                    d += normal[3 * region.seed + k] * (xyz[3 * v + k] - region.origin[k]);
                }
                if (Math.abs(d) > OFF_PLANE * region.seedSize) {
                    return false;
                }
                h = mesh.next(h);
            } while (h != h0);
            return true;
        }

        /** Splits every boundary edge of the regions to prepare into pieces no longer than the thinner region beside it asks. */
        private void splitBoundaries(List<Region> toPrepare) throws Unprepared {
            long budget = Math.max(MOST_PIECES, 100L * mesh.faceCount());
            long pieces = 0;
            double[] piece = new double[mesh.edgeCount()];
            Arrays.fill(piece, Double.POSITIVE_INFINITY);
            for (Region region : toPrepare) {
                for (int h : region.boundary()) {
                    int e = HalfedgeMesh.edge(h);
                    int across = mesh.face(HalfedgeMesh.twin(h));
                    if (across >= 0 && regions.get(regionOf[across]).sharp) {
                        continue; // a sharp region's edges are cut only where the refinement beside it must
                    }
                    piece[e] = Math.min(piece[e], PIECE_OVER_THICKNESS * region.thickness);
                }
            }
            for (int e = 0; e < piece.length; e++) {
                if (piece[e] == Double.POSITIVE_INFINITY) {
                    continue;
                }
                int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
                double length = Triangles.distance(xyz, mesh.fromVertex(h), mesh.toVertex(h));
                double n0 = Math.ceil(length / piece[e] - 1e-9);
                pieces += (long) Math.min(n0, budget + 1);
                if (pieces > budget) {
                    throw new Unprepared(String.format(Locale.ROOT, "a face is too thin to prepare: its edges would be cut "
                            + "into more than %d pieces (an edge %.4g long beside a face %.4g thick)", budget, length, piece[e] / PIECE_OVER_THICKNESS));
                }
                int n = (int) n0;
                if (n > MOST_SPLITS_OF_AN_EDGE) {
                    throw new Unprepared(String.format(Locale.ROOT, "a face is too thin to prepare: an edge %.4g long would be cut "
                            + "into %d pieces, more than %d", length, n, MOST_SPLITS_OF_AN_EDGE));
                }
                if (n > 1) {
                    double[] t = new double[n - 1];
                    for (int k = 1; k < n; k++) {
                        t[k - 1] = (double) k / n;
                    }
                    splits[e] = t;
                    markAcross(e);
                }
            }
        }

        /** The regions on both sides of split edge e must be triangulated again (with the split). */
        private void markAcross(int e) {
            for (int side = 0; side < 2; side++) {
                int f = mesh.face(HalfedgeMesh.halfedgeOfEdge(e, side));
                if (f >= 0) {
                    Region region = regions.get(regionOf[f]);
                    region.prepare = true;
                    region.dirty = true;
                }
            }
        }

        private void triangulateUntilAgreed() throws Unprepared {
            int prepared = 0;
            for (Region region : regions) {
                if (region.prepare) {
                    region.dirty = true;
                    prepared++;
                }
            }
            int budget = ROUNDS * Math.max(1, prepared) + 100;
            boolean changed = true;
            while (changed) {
                changed = false;
                for (Region region : regions) {
                    if (!region.prepare || !region.dirty) {
                        continue;
                    }
                    if (budget-- == 0) {
                        throw new Unprepared("the regions' triangulations did not agree on their shared edges after "
                                + (ROUNDS * prepared + 100) + " tries");
                    }
                    region.dirty = false;
                    try {
                        region.triangulate(!region.sharp);
                    } catch (RuntimeException refinementFailed) {
                        // Tinfour's refiner fails on some small regions (a lone triangle whose
                        // interpolation walk finds no edge): the region is then triangulated
                        // from its boundary alone, which its neighbours agree with.
                        try {
                            region.triangulate(false);
                        } catch (RuntimeException e) {
                            throw new Unprepared("region " + region.index + " (face " + region.seed + ") could not be triangulated: " + e);
                        }
                    }
                    changed = true;
                }
            }
        }

        /** The prepared mesh: the kept regions' triangles and the new ones, over the vertices they use. */
        private HalfedgeMesh assemble() throws Unprepared {
            PolygonSoup soup = new PolygonSoup();
            int[] vertexId = new int[mesh.vertexCount()];
            Arrays.fill(vertexId, -1);
            int[][] splitId = new int[splits.length][];
            for (Region region : regions) {
                if (!region.prepare) {
                    for (int f : region.faces) {
                        int h = mesh.faceHalfedge(f);
                        soup.addTriangle(corner(soup, vertexId, mesh.fromVertex(h)), corner(soup, vertexId, mesh.toVertex(h)),
                                corner(soup, vertexId, mesh.toVertex(mesh.next(h))));
                    }
                    continue;
                }
                int[] interiorId = new int[region.interior.length / 3];
                for (int k = 0; k < interiorId.length; k++) {
                    interiorId[k] = soup.addVertex(region.interior[3 * k], region.interior[3 * k + 1], region.interior[3 * k + 2]);
                }
                int[] ids = new int[3];
                for (int k = 0; k < region.triangles.length; k += 3) {
                    for (int c = 0; c < 3; c++) {
                        long key = region.triangles[k + c];
                        int kind = (int) (key >>> 56);
                        if (kind == CORNER) {
                            ids[c] = corner(soup, vertexId, (int) key);
                        } else if (kind == SPLIT) {
                            int e = (int) ((key >>> 24) & 0xFFFFFFFFL);
                            int i = (int) (key & 0xFFFFFF);
                            if (splitId[e] == null) {
                                splitId[e] = new int[splits[e].length];
                                Arrays.fill(splitId[e], -1);
                            }
                            if (splitId[e][i] < 0) {
                                double[] p = pointOnEdge(e, splits[e][i]);
                                splitId[e][i] = soup.addVertex(p[0], p[1], p[2]);
                            }
                            ids[c] = splitId[e][i];
                        } else {
                            ids[c] = interiorId[(int) (key & 0xFFFFFFFFL)];
                        }
                    }
                    soup.addTriangle(ids[0], ids[1], ids[2]);
                }
            }
            MeshBuilder.Result built;
            try {
                built = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR);
            } catch (InvalidMeshException e) {
                throw new Unprepared("the prepared triangles do not make a surface: " + e.getMessage());
            }
            if (built.repairCount() > 0) {
                throw new Unprepared("the prepared triangles needed repairs: " + built.repairs());
            }
            HalfedgeMesh prepared = built.mesh();
            if (!MeshValidator.isValid(prepared)) {
                throw new Unprepared("the prepared mesh is not valid: " + MeshValidator.validate(prepared).get(0));
            }
            Topology before = Topology.of(mesh);
            Topology after = Topology.of(prepared);
            if (after.eulerCharacteristic() != before.eulerCharacteristic() || after.boundaryLoops() != before.boundaryLoops()
                    || after.components() != before.components()) {
                throw new Unprepared("the prepared surface has another topology than the model's");
            }
            double areaBefore = area(mesh);
            double areaAfter = area(prepared);
            if (Math.abs(areaAfter - areaBefore) > 1e-9 * areaBefore) {
                throw new Unprepared("the prepared surface's area " + areaAfter + " is not the model's " + areaBefore);
            }
            return prepared;
        }

        private int corner(PolygonSoup soup, int[] vertexId, int v) {
            if (vertexId[v] < 0) {
                vertexId[v] = soup.addVertex(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
            }
            return vertexId[v];
        }

        /** The point at t along edge e, from its first halfedge's start: the same doubles from either region beside it. */
        private double[] pointOnEdge(int e, double t) {
            int h = HalfedgeMesh.halfedgeOfEdge(e, 0);
            int a = mesh.fromVertex(h);
            int b = mesh.toVertex(h);
            double[] p = new double[3];
            for (int k = 0; k < 3; k++) {
                p[k] = xyz[3 * a + k] + t * (xyz[3 * b + k] - xyz[3 * a + k]);
            }
            return p;
        }

        /** The keys of a region's triangle corners: a vertex of the model, a split of an edge, a point inside. */
        private static final int CORNER = 0;
        private static final int SPLIT = 1;
        private static final int INSIDE = 2;

        private static long cornerKey(int v) {
            return v;
        }

        private static long splitKey(int e, int i) {
            return ((long) SPLIT << 56) | ((long) e << 24) | i;
        }

        private static long insideKey(int i) {
            return ((long) INSIDE << 56) | i;
        }

        /** One planar region of the model. */
        private final class Region {
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
            /** The triangles made, three corner keys each, and the points inside, x, y, z interleaved. */
            long[] triangles = new long[0];
            double[] interior = new double[0];

            Region(int index, int seed) {
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
                    sharp |= cornerAngle.get(mesh.fromVertex(h)) < Math.toRadians(TARGET_ANGLE);
                    perimeter += Triangles.distance(xyz, mesh.fromVertex(h), mesh.toVertex(h));
                }
                thickness = perimeter > 0 ? 2 * area / perimeter : Math.sqrt(area);
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
            List<List<Integer>> loops() throws Unprepared {
                List<Integer> boundary = boundary();
                Map<Integer, Integer> place = new HashMap<>();
                for (int i = 0; i < boundary.size(); i++) {
                    place.put(boundary.get(i), i);
                }
                // A region that touches itself at a corner passes that corner twice: no polygon with holes.
                Set<Integer> corners = new HashSet<>();
                for (int h : boundary) {
                    if (!corners.add(mesh.fromVertex(h))) {
                        throw new Unprepared("region " + index + "'s boundary touches itself at a corner");
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
                            throw new Unprepared("region " + index + "'s boundary is not a loop");
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
                                throw new Unprepared("region " + index + "'s boundary cannot be followed");
                            }
                        }
                        h = next;
                    }
                    loops.add(loop);
                }
                return loops;
            }

            /** Triangulates the region from its boundary (with every split of its edges), refined to the target angle if {@code refine}. */
            void triangulate(boolean refine) throws Unprepared {
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
                        addPoint(mesh.fromVertex(h), cornerKey(mesh.fromVertex(h)), o, e1, e2, scale, keys, points, polygon, known);
                        double[] t = taken.get(e);
                        for (int k = 0; k < t.length; k++) {
                            int i = forward ? k : t.length - 1 - k;
                            double[] p = pointOnEdge(e, t[i]);
                            addPoint(p, splitKey(e, i), o, e1, e2, scale, keys, points, polygon, known);
                        }
                    }
                    PolygonConstraint constraint = new PolygonConstraint(polygon);
                    constraint.complete();
                    constraints.add(constraint);
                }
                IncrementalTin tin = new IncrementalTin(1);
                tin.addConstraints(constraints, true);
                if (!tin.isBootstrapped()) {
                    throw new Unprepared("region " + index + " has no area to triangulate");
                }
                if (refine) {
                    RuppertRefiner refiner = new RuppertRefiner(tin, TARGET_ANGLE, AREA_FLOOR);
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
                            triangleKeys.add(keys.get(at));
                            continue;
                        }
                        Long key = made.get(corner);
                        if (key == null) {
                            key = newPoint(corner, onBorder.containsKey(corner), loops, loop2d, taken, inside, o, e1, e2, scale);
                            made.put(corner, key);
                        }
                        triangleKeys.add(key);
                    }
                }
                triangles = triangleKeys.stream().mapToLong(Long::longValue).toArray();
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
                    double[] o, double[] e1, double[] e2, double scale) throws Unprepared {
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
                return insideKey(inside.size() - 1);
            }

            /** A split of the edge of halfedge h, at fraction s of its k-th piece along h between the splits t this run took. */
            private long addSplit(int h, int k, double[] t, double s) {
                int e = HalfedgeMesh.edge(h);
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
                markAcross(e);
                dirty = true; // its keys of this edge's splits moved: triangulated again with the split as a point of its own
                return splitKey(e, Arrays.binarySearch(grown, at));
            }
        }
    }

    private static double area(HalfedgeMesh mesh) {
        double[] xyz = mesh.positionArray();
        double area = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            area += Triangles.twiceArea(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h))) / 2;
        }
        return area;
    }

    /** Why the model's own triangles are kept. */
    private static final class Unprepared extends Exception {
        private static final long serialVersionUID = 1L;

        Unprepared(String message) {
            super(message);
        }
    }
}
