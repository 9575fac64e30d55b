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
import java.util.TreeMap;
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
 * <p>First, each convex pentagon or hexagon whose triangles fan three or more at one of its
 * corners (cut into triangles from that corner, as a file's polygon is) is fanned from its centre
 * instead ({@code PlanarRegion.fanFromCentre}): the refinement cuts every triangle at a corner
 * again, so the shared dodecahedron's pentagons had six thin triangles at one corner, and the
 * turn of each into its last pass lay at that corner, two layers each where they met (17 layers
 * at most, the house 17, the shared hex_prism's hexagons eight triangles and 21); from the
 * centre, two triangles at every corner (13, the house 14, hex_prism 15). A square cut in two is
 * left as it is (from its centre the cube had 14 layers rather than 13; see
 * {@code PlanarRegion.FEWEST_FAN_CORNERS}).
 *
 * <p>The prepared mesh is built and validated like a model read from a file; anything that
 * would not come out as the same closed or open surface (a repair the builder had to make,
 * another topology or area), or come out worse (a smallest angle under the model's, fifty times
 * its triangles), keeps the model's own triangles, and the result says why. A region that is
 * not a polygon with holes (it touches itself at a corner) is left as it is, like a sharp one;
 * a refinement stopped at its limit of points keeps what it made. A region that cannot be
 * triangulated, or whose triangles would have a corner sharper than the model's sharpest (a
 * sliver triangulated with the points its neighbours cut its edges at), keeps its own triangles
 * on its own: the preparation runs again with its edges left uncut, the others prepared, and
 * the result names it ({@link Result#keptRegions}).
 */
public final class FacePreparation {
    /** The smallest angle the preparation aims for, in degrees (Ruppert's algorithm is proven to about 20.7°). */
    public static final int TARGET_ANGLE = 20;

    /** Boundary pieces are at most this many times the region's thickness long. */
    private static final double PIECE_OVER_THICKNESS = 1.5;

    /** Ruppert's algorithm leaves triangles under this fraction of the region's thickness squared. */
    static final double AREA_FLOOR = 0.02;

    /** The most pieces the edges of a model may be cut into before the triangulation, at least: beyond that the model keeps its triangles. */
    private static final long MOST_PIECES = 100_000;

    /** The most pieces one edge is cut into: a split's place on its edge is 24 bits of its key. */
    private static final int MOST_SPLITS_OF_AN_EDGE = 1 << 23;

    /** The prepared triangles may be this many times the model's (and 10,000 more) before the model keeps its own. */
    private static final int MOST_TIMES_TRIANGLES = 50;

    /** The most times the regions may be triangulated, over the regions to prepare: a cascade of splits from region to region stops there. */
    private static final int ROUNDS = 20;

    /**
     * The most runs of the preparation: a run in which regions fail is run again with them kept
     * as they are (the shared capsule's 32 slivers, mpi's 2: one run more each).
     */
    private static final int MOST_RUNS = 8;

    /**
     * The most times one region is refined; after that it is triangulated from its boundary
     * alone. Each refinement starts from the boundary, forgetting which points the last one
     * added at a corner, and may halve the pieces there again: two regions meeting at such a
     * corner gave each other a point a round, until Tinfour merged two (the shared cgal_mpi and
     * trimesh_rabbit). No region of models/ or of the shared polyhedra is refined more than once.
     */
    static final int MOST_REFINEMENTS = 3;

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
     * @param centred the model with the regions fanned from their centre and no other change: its
     *     own triangles, as far as a wrap is concerned (the model itself where none was)
     * @param centredRegions the regions fanned from their centre
     * @param keptRegions the regions kept as they are while the others were prepared, each in
     *     words ("face 72: ..."); empty where none was
     */
    public record Result(HalfedgeMesh mesh, int regions, int prepared, int trianglesBefore, double minAngleBefore,
            double minAngleAfter, String kept, HalfedgeMesh centred, int centredRegions, List<String> keptRegions) {
        public int trianglesAfter() {
            return mesh.faceCount();
        }
    }

    /**
     * Prepares {@code mesh}, a valid triangle mesh: its regions fanned from their centre where
     * their triangles fan at a corner, then those with slivers triangulated again.
     *
     * @throws IllegalArgumentException if a face is not a triangle
     */
    public static Result prepare(HalfedgeMesh mesh) {
        Run centring = new Run(mesh);
        int centredRegions = centring.centreFans();
        if (centredRegions == 0) {
            return centring.run(); // its regions grown once, for both
        }
        HalfedgeMesh centred;
        try {
            centred = centring.assemble();
        } catch (Unprepared e) {
            return new Run(mesh).run(); // not seen: the fans keep each region's boundary and area
        }
        Result result = new Run(centred).run();
        return new Result(result.mesh(), result.regions(), result.prepared(), mesh.faceCount(), RefinementClaims.minAngleDegrees(mesh),
                result.minAngleAfter(), result.kept(), centred, centredRegions, result.keptRegions());
    }

    /** One preparation of one mesh. */
    static final class Run {
        final HalfedgeMesh mesh;
        final double[] xyz;
        /** The unit normal of each face, x, y, z interleaved. */
        final double[] normal;
        /** The region of each face. */
        final int[] regionOf;
        private final List<PlanarRegion> regions = new ArrayList<>();
        /** The points splitting each edge of the mesh, as parameters t in (0, 1) from fromVertex(2e) to toVertex(2e); null for none. */
        final double[][] splits;
        /** The regions kept as they are, by index, and why in words: found by the earlier runs of the same mesh. */
        private final Map<Integer, String> keptRegions;
        /** How many runs of the same mesh came before this one. */
        private final int earlierRuns;

        Run(HalfedgeMesh mesh) {
            this(mesh, Map.of(), 0);
        }

        private Run(HalfedgeMesh mesh, Map<Integer, String> keptRegions, int earlierRuns) {
            this.mesh = mesh;
            this.keptRegions = keptRegions;
            this.earlierRuns = earlierRuns;
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
            if (regions.isEmpty()) {
                growRegions();
            }
            for (Map.Entry<Integer, String> kept : keptRegions.entrySet()) {
                PlanarRegion region = regions.get(kept.getKey());
                region.keptBecause = kept.getValue();
                region.sharp = true; // its edges not cut before the triangulation
            }
            List<PlanarRegion> toPrepare = new ArrayList<>();
            for (PlanarRegion region : regions) {
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
                return new Result(mesh, regions.size(), 0, mesh.faceCount(), before, before, null, mesh, 0, List.of());
            }
            try {
                for (PlanarRegion region : toPrepare) {
                    region.prepare = true;
                }
                splitBoundaries(toPrepare);
                Map<Integer, String> failed = triangulateUntilAgreed();
                failed.putAll(sharperThanTheModel(before));
                if (!failed.isEmpty()) {
                    return again(failed);
                }
                HalfedgeMesh prepared = assemble();
                double after = RefinementClaims.minAngleDegrees(prepared);
                if (sharperThan(after, before)) {
                    throw new Unprepared(String.format(Locale.ROOT, "the prepared triangles' smallest angle, %.3g degrees, is "
                            + "under the model's own %.3g (a feature thinner than its faces)", after, before));
                }
                if (prepared.faceCount() > MOST_TIMES_TRIANGLES * mesh.faceCount() + MOST_PIECES / 10) {
                    throw new Unprepared(String.format(Locale.ROOT, "the prepared faces would be %d triangles, more than %d "
                            + "times the model's %d", prepared.faceCount(), MOST_TIMES_TRIANGLES, mesh.faceCount()));
                }
                int count = 0;
                for (PlanarRegion region : regions) {
                    count += region.prepare ? 1 : 0;
                }
                return new Result(prepared, regions.size(), count, mesh.faceCount(), before, after, null, mesh, 0,
                        List.copyOf(keptRegions.values()));
            } catch (Unprepared e) {
                return new Result(mesh, regions.size(), 0, mesh.faceCount(), before, before, e.getMessage(), mesh, 0, List.of());
            }
        }

        /**
         * The preparation run again from the start with the regions that failed in this run kept
         * as they are, their edges left uncut: a region across from one that failed has already
         * taken the points its refinement put there.
         */
        private Result again(Map<Integer, String> failed) throws Unprepared {
            Map<Integer, String> kept = new TreeMap<>(keptRegions);
            kept.putAll(failed);
            if (earlierRuns + 1 >= MOST_RUNS) {
                throw new Unprepared(kept.size() + " regions could not be prepared in " + MOST_RUNS + " runs, among them "
                        + failed.values().iterator().next());
            }
            return new Run(mesh, kept, earlierRuns + 1).run();
        }

        /**
         * The prepared regions whose triangles have a corner sharper than the model's sharpest
         * ({@code before}, in degrees), and why: those the prepared surface would be worse by (a
         * sliver triangulated again with the points its neighbours cut its edges at).
         */
        private Map<Integer, String> sharperThanTheModel(double before) {
            Map<Integer, String> sharper = new HashMap<>();
            double[] corners = new double[9];
            for (PlanarRegion region : regions) {
                if (!region.prepare || region.keptBecause != null) {
                    continue;
                }
                double sharpest = Math.PI;
                for (int k = 0; k < region.triangles.length; k += 3) {
                    for (int c = 0; c < 3; c++) {
                        System.arraycopy(position(region, region.triangles[k + c]), 0, corners, 3 * c, 3);
                    }
                    sharpest = Math.min(sharpest, Triangles.minAngle(corners, 0, 1, 2));
                }
                if (sharperThan(Math.toDegrees(sharpest), before)) {
                    sharper.put(region.index, region.describe() + String.format(Locale.ROOT, ": triangulated again with the points its "
                            + "neighbours cut its edges at, it would have a corner of %.3g degrees, sharper than the model's sharpest, %.3g",
                            Math.toDegrees(sharpest), before));
                }
            }
            return sharper;
        }

        /** Whether {@code degrees} is sharper than {@code before} by more than rounding: a sliver triangulated again from its own corners is no sharper. */
        private static boolean sharperThan(double degrees, double before) {
            return degrees < before * (1 - Tolerance.RELATIVE_EQUALITY);
        }

        /** The point a corner key of {@code region} names. */
        private double[] position(PlanarRegion region, long key) {
            int kind = (int) (key >>> 56);
            if (kind == CORNER) {
                int v = (int) key;
                return new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
            }
            if (kind == SPLIT) {
                return pointOnEdge(splitEdge(key), splits[splitEdge(key)][splitIndex(key)]);
            }
            int i = (int) (key & 0xFFFFFFFFL);
            return Arrays.copyOfRange(region.interior, 3 * i, 3 * i + 3);
        }

        /** Why region r keeps its triangles while the others are prepared; null where it may be prepared. */
        String keptBecause(int r) {
            return regions.get(r).keptBecause;
        }

        /** Fans from its centre each region that asks for it ({@link PlanarRegion#fanFromCentre}), to be assembled; how many. */
        int centreFans() {
            growRegions();
            int count = 0;
            for (PlanarRegion region : regions) {
                try {
                    region.prepare = region.fanFromCentre();
                } catch (Unprepared e) {
                    region.prepare = false; // not a polygon with holes: left as it is
                }
                count += region.prepare ? 1 : 0;
            }
            return count;
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
                PlanarRegion region = new PlanarRegion(this, regions.size(), seed);
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

        private boolean coplanar(PlanarRegion region, int g) {
            double cos = normal[3 * region.seed] * normal[3 * g] + normal[3 * region.seed + 1] * normal[3 * g + 1]
                    + normal[3 * region.seed + 2] * normal[3 * g + 2];
            if (!(cos > 1 - Tolerance.COPLANAR_COSINE)) {
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
                if (Math.abs(d) > Tolerance.ON_PLANE * region.seedSize) {
                    return false;
                }
                h = mesh.next(h);
            } while (h != h0);
            return true;
        }

        /** Splits every boundary edge of the regions to prepare into pieces no longer than the thinner region beside it asks. */
        private void splitBoundaries(List<PlanarRegion> toPrepare) throws Unprepared {
            long budget = Math.max(MOST_PIECES, 100L * mesh.faceCount());
            long pieces = 0;
            double[] piece = new double[mesh.edgeCount()];
            Arrays.fill(piece, Double.POSITIVE_INFINITY);
            for (PlanarRegion region : toPrepare) {
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
                double n0 = Math.ceil(length / piece[e] - Tolerance.RELATIVE_EQUALITY);
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
        void markAcross(int e) {
            markAcross(e, null);
        }

        /**
         * The regions beside split edge e, but {@code splitter}, whose refinement put the split
         * there, must be triangulated again (with the split): a point from a neighbour.
         */
        void markAcross(int e, PlanarRegion splitter) {
            for (int side = 0; side < 2; side++) {
                int f = mesh.face(HalfedgeMesh.halfedgeOfEdge(e, side));
                if (f >= 0 && regions.get(regionOf[f]) != splitter && regions.get(regionOf[f]).keptBecause == null) {
                    PlanarRegion region = regions.get(regionOf[f]);
                    region.prepare = true;
                    region.dirty = true;
                    region.triangulatedForOwnSplits = false;
                }
            }
        }

        /** Triangulates the regions to prepare until they agree on their shared edges; the regions that could not be triangulated, and why. */
        private Map<Integer, String> triangulateUntilAgreed() throws Unprepared {
            Map<Integer, String> failed = new HashMap<>();
            int prepared = 0;
            for (PlanarRegion region : regions) {
                if (region.prepare) {
                    region.dirty = true;
                    prepared++;
                }
            }
            int budget = ROUNDS * Math.max(1, prepared) + 100;
            boolean changed = true;
            while (changed) {
                changed = false;
                for (PlanarRegion region : regions) {
                    if (!region.prepare || !region.dirty) {
                        continue;
                    }
                    if (budget-- == 0) {
                        throw new Unprepared("the regions' triangulations did not agree on their shared edges after "
                                + (ROUNDS * prepared + 100) + " tries");
                    }
                    region.dirty = false;
                    try {
                        region.triangulate(!region.sharp && region.refinements < MOST_REFINEMENTS);
                    } catch (RuntimeException refinementFailed) {
                        // Tinfour's refiner fails on some small regions (a lone triangle whose
                        // interpolation walk finds no edge): the region is then triangulated
                        // from its boundary alone, which its neighbours agree with.
                        try {
                            region.triangulate(false);
                        } catch (RuntimeException e) {
                            // The refiner's own words name its internals ("Cannot invoke
                            // Vertex.getX() because v is null"), which tell a user nothing.
                            failed.put(region.index, region.describe() + ": " + (e instanceof PlanarRegion.CutsAKeptRegion
                                    ? "its triangles would cut the edge of a face kept as it is beside it"
                                    : "its outline of " + region.outlinePoints() + " points (its corners and those its neighbours cut its "
                                            + "edges at) could not be triangulated"));
                            region.keptBecause = failed.get(region.index); // this run is given up: the others go on, to find more
                            region.prepare = false;
                        }
                    }
                    changed = true;
                }
            }
            return failed;
        }

        /** The prepared mesh: the kept regions' triangles and the new ones, over the vertices they use. */
        HalfedgeMesh assemble() throws Unprepared {
            PolygonSoup soup = new PolygonSoup();
            int[] vertexId = new int[mesh.vertexCount()];
            Arrays.fill(vertexId, -1);
            int[][] splitId = new int[splits.length][];
            for (PlanarRegion region : regions) {
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
                            int e = splitEdge(key);
                            int i = splitIndex(key);
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
            if (Math.abs(areaAfter - areaBefore) > Tolerance.RELATIVE_EQUALITY * areaBefore) {
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
        double[] pointOnEdge(int e, double t) {
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

        static long cornerKey(int v) {
            return v;
        }

        static long splitKey(int e, int i) {
            return ((long) SPLIT << 56) | ((long) e << 24) | i;
        }

        static boolean isSplitKey(long key) {
            return (int) (key >>> 56) == SPLIT;
        }

        static int splitEdge(long key) {
            return (int) ((key >>> 24) & 0xFFFFFFFFL);
        }

        static int splitIndex(long key) {
            return (int) (key & 0xFFFFFF);
        }

        static long insideKey(int i) {
            return ((long) INSIDE << 56) | i;
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
    static final class Unprepared extends Exception {
        private static final long serialVersionUID = 1L;

        Unprepared(String message) {
            super(message);
        }
    }
}
