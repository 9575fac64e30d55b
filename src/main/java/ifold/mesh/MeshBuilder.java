package ifold.mesh;

import ifold.geom.PolygonTriangulator;
import ifold.geom.Polygons;
import ifold.geom.Triangles;
import java.util.Arrays;
import java.util.EnumMap;
import java.util.Map;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.FutureTask;

/**
 * Turns a polygon soup into a valid {@link HalfedgeMesh}, repairing what real models get wrong
 * or, in strict mode, refusing it.
 *
 * <p>The steps, each linear in the size of the input (up to small per-edge sorts):
 * <ol>
 *   <li>clean each face: indices in range, repeated corners removed, faces with fewer than
 *       three distinct vertices or no area dropped; polygons optionally triangulated by
 *       {@link PolygonTriangulator} (ear clipping);</li>
 *   <li>drop faces with the same vertex set as an earlier face;</li>
 *   <li>group corners by undirected edge (a bucket per lower vertex);</li>
 *   <li>orient each component consistently by a breadth-first walk over edges shared by exactly
 *       two faces, turning over the fewer faces; an edge that contradicts the walk (a Moebius
 *       band) is cut; closed components with negative volume are turned outward;</li>
 *   <li>pair each edge's two halfedges; an edge with more than two faces keeps one opposite
 *       pair and the others become boundary, so non-manifold edges are split;</li>
 *   <li>split pinch vertices: each fan of faces around a vertex gets a vertex of its own;</li>
 *   <li>link the boundary loops.</li>
 * </ol>
 * Every repair is counted by {@link Defect} kind in the result. Input vertices keep their order
 * (unreferenced ones are left out) and vertices made by splitting pinches come after them.
 */
public final class MeshBuilder {

    /**
     * @param strict refuse any defect instead of repairing it
     * @param triangulate split polygons into triangles
     */
    public record Options(boolean strict, boolean triangulate) {
        public static final Options REPAIR = new Options(false, false);
        public static final Options REPAIR_TRIANGULATE = new Options(false, true);
    }

    /**
     * What the builder made.
     *
     * @param mesh the valid halfedge mesh
     * @param repairs how many repairs of each kind were made (kinds with none are absent)
     * @param sourceFace for each mesh face, the input face it came from
     * @param sourceVertex for each mesh vertex, the input vertex it came from
     */
    public record Result(HalfedgeMesh mesh, Map<Defect, Integer> repairs, int[] sourceFace, int[] sourceVertex) {
        public int repairCount() {
            return repairs.values().stream().mapToInt(Integer::intValue).sum();
        }
    }

    final IndexedPolygons soup;
    final Options options;
    final double[] xyz;
    final EnumMap<Defect, Integer> repairs = new EnumMap<>(Defect.class);

    // Working faces after cleaning: faceStart(f)..faceStart(f+1) index wVerts; wSource[f] is the
    // input face. While every face is a triangle, wStart is null and face f starts at 3f: that is
    // always so when triangulating, and saves an array as long as the faces of a big model.
    int[] wStart;
    int[] wVerts;
    int[] wSource;
    int wFaceCount;
    int wCornerCount;

    // Corners grouped by undirected edge, alive from grouping to pairing only: for a big model
    // they are a third of the builder's memory, so they are dropped as soon as pairing is done.
    /** The working face of each corner; null when every face is a triangle (then it is c / 3). */
    int[] cornerFace;
    /**
     * The corner across the edge when exactly two corners share it ({@link #BOUNDARY} when
     * none, {@link #NON_MANIFOLD} when more than two do). Orientation and pairing, which touch
     * every corner, need only this: one read instead of a search through the group.
     */
    int[] mate;
    /** Corners sorted by the lower, then the higher vertex of their edge; kept only when some edge is non-manifold. */
    int[] byMin;
    static final int BOUNDARY = -1;
    static final int NON_MANIFOLD = -2;
    /** The number of halfedges, once they are paired. */
    int halfedgeCount;
    /** Steps 5 to 7: the halfedges paired, pinches split, boundaries linked, the mesh assembled. */
    private final MeshAssembly assembly = new MeshAssembly(this);
    /** Step 4: the faces turned alike, closed components outwards. */
    private final MeshOrientation orientation = new MeshOrientation(this);

    MeshBuilder(IndexedPolygons soup, Options options) {
        this.soup = soup;
        this.options = options;
        if (soup instanceof PolygonSoup polygons) {
            xyz = polygons.coordinateArray(); // read only: saves a copy of every position
        } else {
            int n = soup.vertexCount();
            xyz = new double[3 * n];
            for (int v = 0; v < n; v++) {
                xyz[3 * v] = soup.coordinate(v, 0);
                xyz[3 * v + 1] = soup.coordinate(v, 1);
                xyz[3 * v + 2] = soup.coordinate(v, 2);
            }
        }
    }

    /** Builds a mesh from {@code soup}; see the class documentation for what is repaired. */
    public static Result build(IndexedPolygons soup, Options options) throws InvalidMeshException {
        return new MeshBuilder(soup, options).run();
    }

    /** Builds with repairs and no triangulation. */
    public static Result build(IndexedPolygons soup) throws InvalidMeshException {
        return build(soup, Options.REPAIR);
    }

    /** Below this many faces a second thread costs more than it saves. */
    static final int PARALLEL_FACES = 50_000;

    Result run() throws InvalidMeshException {
        checkCoordinates();
        cleanFaces();
        boolean[] drop;
        if (wStart == null) {
            // Triangles: the mates rule out almost every face at once (duplicateCandidates).
            findMates();
            drop = findDuplicateFaces(duplicateCandidates());
        } else {
            // Polygons: duplicates are rare, and looking for them is a pass of random look-ups:
            // do it on a second core while the corners are grouped.
            FutureTask<boolean[]> duplicates = new FutureTask<>(() -> findDuplicateFaces(null));
            if (wFaceCount >= PARALLEL_FACES) {
                Thread thread = new Thread(duplicates, "duplicate-faces");
                thread.setDaemon(true);
                thread.start();
            } else {
                duplicates.run();
            }
            cornerFace = cornerFaces();
            findMates();
            drop = await(duplicates);
        }
        if (drop != null) { // group again without them
            compactWorkingFaces(drop);
            cornerFace = wStart == null ? null : cornerFaces();
            findMates();
        }
        orientation.reverseFlippedFaces(orientation.orient());
        return assembly.assemble(assembly.pairHalfedges());
    }

    static boolean[] await(FutureTask<boolean[]> task) throws InvalidMeshException {
        try {
            return task.get();
        } catch (ExecutionException e) {
            if (e.getCause() instanceof InvalidMeshException invalid) {
                throw invalid;
            }
            throw new IllegalStateException(e.getCause());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while building the mesh", e);
        }
    }

    // ---- step 1: clean faces ----------------------------------------------------------------

    void checkCoordinates() throws InvalidMeshException {
        for (int i = 0; i < 3 * soup.vertexCount(); i++) {
            if (!Double.isFinite(xyz[i])) {
                throw new InvalidMeshException(Defect.NON_FINITE_COORDINATE, 0,
                        "vertex " + (i / 3) + " has a non-finite coordinate (" + xyz[i] + ")");
            }
        }
    }

    void cleanFaces() throws InvalidMeshException {
        int faceCount = soup.faceCount();
        int vertexCount = soup.vertexCount();
        wStart = null;
        wVerts = new int[Math.max(16, 3 * faceCount)];
        wSource = new int[Math.max(16, faceCount)];
        int[] polygon = new int[16];
        int[] triangles = new int[3 * 16];
        for (int f = 0; f < faceCount; f++) {
            int size = soup.faceSize(f);
            if (size == 3 && wStart == null && wCornerCount + 3 <= wVerts.length && wFaceCount < wSource.length) {
                // The common case, a proper triangle, without the copies of the general path
                // below (which treats it the same way: nothing repeated, no area or kept).
                int a = soup.faceVertex(f, 0);
                int b = soup.faceVertex(f, 1);
                int c = soup.faceVertex(f, 2);
                if (a >= 0 && a < vertexCount && b >= 0 && b < vertexCount && c >= 0 && c < vertexCount
                        && a != b && b != c && c != a) {
                    if (Triangles.isDegenerate(xyz, a, b, c)) {
                        repair(Defect.ZERO_AREA_FACE, f, 1);
                    } else {
                        wVerts[wCornerCount] = a;
                        wVerts[wCornerCount + 1] = b;
                        wVerts[wCornerCount + 2] = c;
                        wCornerCount += 3;
                        wSource[wFaceCount++] = f;
                    }
                    continue;
                }
            }
            if (size > polygon.length) {
                polygon = new int[2 * size];
                triangles = new int[6 * size];
            }
            int kept = 0;
            for (int k = 0; k < size; k++) {
                int v = soup.faceVertex(f, k);
                if (v < 0 || v >= vertexCount) {
                    throw refuse(Defect.INDEX_OUT_OF_RANGE, f, "face " + f + " refers to vertex " + v
                            + " but there are " + vertexCount + " vertices");
                }
                if (kept == 0 || polygon[kept - 1] != v) {
                    polygon[kept++] = v;
                }
            }
            while (kept > 1 && polygon[kept - 1] == polygon[0]) {
                kept--;
            }
            if (kept < size) {
                repair(Defect.REPEATED_VERTEX, f, 1);
            }
            if (kept < 3 || visitsVertexTwice(polygon, kept)) {
                repair(Defect.DEGENERATE_FACE, f, 1);
                continue;
            }
            if (kept == 3 || options.triangulate()) {
                int count = PolygonTriangulator.triangulate(xyz, polygon, kept, triangles);
                if (count == 0) {
                    repair(Defect.ZERO_AREA_FACE, f, 1);
                    continue;
                }
                for (int t = 0; t < count; t++) {
                    int a = triangles[3 * t];
                    int b = triangles[3 * t + 1];
                    int c = triangles[3 * t + 2];
                    if (Triangles.isDegenerate(xyz, a, b, c)) {
                        repair(Defect.ZERO_AREA_FACE, f, 1);
                    } else {
                        addWorkingFace(triangles, 3 * t, 3, f);
                    }
                }
            } else if (!Polygons.hasArea(xyz, polygon, kept)) {
                repair(Defect.ZERO_AREA_FACE, f, 1);
            } else {
                addWorkingFace(polygon, 0, kept, f);
            }
        }
    }

    static boolean visitsVertexTwice(int[] polygon, int size) {
        for (int i = 0; i < size; i++) {
            for (int j = i + 1; j < size; j++) {
                if (polygon[i] == polygon[j]) {
                    return true;
                }
            }
        }
        return false;
    }

    void addWorkingFace(int[] vertices, int offset, int size, int source) {
        if (wCornerCount + size > wVerts.length) {
            wVerts = Arrays.copyOf(wVerts, Math.max(2 * wVerts.length, wCornerCount + size));
        }
        if (wStart == null && size != 3) {
            wStart = new int[Math.max(16, wSource.length + 1)];
            for (int f = 0; f <= wFaceCount; f++) {
                wStart[f] = 3 * f;
            }
        }
        if (wStart != null && wFaceCount + 2 > wStart.length) {
            wStart = Arrays.copyOf(wStart, 2 * wStart.length);
        }
        if (wFaceCount + 1 > wSource.length) {
            wSource = Arrays.copyOf(wSource, 2 * wSource.length);
        }
        System.arraycopy(vertices, offset, wVerts, wCornerCount, size);
        wCornerCount += size;
        wSource[wFaceCount++] = source;
        if (wStart != null) {
            wStart[wFaceCount] = wCornerCount;
        }
    }

    // ---- step 2: duplicate faces ------------------------------------------------------------

    /**
     * For triangles, once the mates are known: the faces that may have a duplicate. Two
     * triangles on the same three vertices share all three edges, so a triangle with a
     * duplicate has no edge of its own (a boundary mate), and no edge shared with exactly one
     * other triangle on other vertices; most are ruled out by their first corner.
     */
    boolean[] duplicateCandidates() {
        boolean[] candidate = new boolean[wFaceCount];
        for (int f = 0; f < wFaceCount; f++) {
            boolean may = true;
            for (int c = 3 * f; c < 3 * f + 3 && may; c++) {
                int m = mate[c];
                may = m != BOUNDARY && (m == NON_MANIFOLD || sameVertexSet(m / 3, f));
            }
            candidate[f] = may;
        }
        return candidate;
    }

    /**
     * Marks each face with the same vertex set as an earlier one, and counts it as repaired
     * (strict mode throws at the first); looks only at the faces of {@code candidates} (null for
     * all): a face that is not one has no duplicate either way.
     *
     * @return which faces to drop, or null if none
     */
    boolean[] findDuplicateFaces(boolean[] candidates) throws InvalidMeshException {
        int count = wFaceCount;
        if (candidates != null) {
            count = 0;
            for (boolean candidate : candidates) {
                count += candidate ? 1 : 0;
            }
            if (count == 0) {
                return null;
            }
        }
        // Open addressing at a load of at most 0.7.
        int capacity = Integer.highestOneBit(Math.max(4, (int) (count / 0.7))) << 1;
        int[] table = new int[capacity]; // face + 1, 0 for empty
        boolean[] drop = new boolean[wFaceCount];
        int dropped = 0;
        for (int f = 0; f < wFaceCount; f++) {
            if (candidates != null && !candidates[f]) {
                continue;
            }
            int slot = faceKeyHash(f) & (capacity - 1);
            while (table[slot] != 0) {
                if (sameVertexSet(table[slot] - 1, f)) {
                    drop[f] = true;
                    break;
                }
                slot = (slot + 1) & (capacity - 1);
            }
            if (drop[f]) {
                repair(Defect.DUPLICATE_FACE, wSource[f], 1);
                dropped++;
            } else {
                table[slot] = f + 1;
            }
        }
        return dropped > 0 ? drop : null;
    }

    /** A hash of the face's vertex set that does not depend on order or orientation. */
    int faceKeyHash(int f) {
        long sum = 0;
        long xor = 0;
        for (int c = faceStart(f); c < faceStart(f + 1); c++) {
            long mixed = (wVerts[c] + 1L) * 0x9E3779B97F4A7C15L;
            mixed ^= mixed >>> 29;
            sum += mixed;
            xor ^= mixed * 0xBF58476D1CE4E5B9L;
        }
        long h = sum * 31 + xor;
        return (int) (h ^ (h >>> 32));
    }

    boolean sameVertexSet(int f, int g) {
        int size = faceStart(f + 1) - faceStart(f);
        if (size != faceStart(g + 1) - faceStart(g)) {
            return false;
        }
        for (int c = faceStart(f); c < faceStart(f + 1); c++) {
            boolean found = false;
            for (int d = faceStart(g); d < faceStart(g + 1) && !found; d++) {
                found = wVerts[c] == wVerts[d];
            }
            if (!found) {
                return false;
            }
        }
        return true;
    }

    void compactWorkingFaces(boolean[] drop) {
        int faces = 0;
        int corners = 0;
        for (int f = 0; f < wFaceCount; f++) {
            if (drop[f]) {
                continue;
            }
            int start = faceStart(f);
            int size = faceStart(f + 1) - start;
            System.arraycopy(wVerts, start, wVerts, corners, size);
            wSource[faces] = wSource[f];
            if (wStart != null) {
                wStart[faces] = corners;
            }
            corners += size;
            faces++;
        }
        if (wStart != null) {
            wStart[faces] = corners;
        }
        wFaceCount = faces;
        wCornerCount = corners;
    }

    // ---- step 3: group corners by undirected edge -------------------------------------------

    int faceStart(int f) {
        return wStart == null ? 3 * f : wStart[f];
    }

    int faceOfCorner(int c) {
        return cornerFace == null ? c / 3 : cornerFace[c];
    }

    int[] cornerFaces() {
        int[] cornerFace = new int[wCornerCount];
        for (int f = 0; f < wFaceCount; f++) {
            Arrays.fill(cornerFace, faceStart(f), faceStart(f + 1), f);
        }
        return cornerFace;
    }

    /** The vertex the edge of corner {@code c} starts from. */
    int cornerFrom(int c) {
        return wVerts[c];
    }

    /** The vertex the edge of corner {@code c} points to: the next corner of its face. */
    int cornerTo(int c) {
        int f = faceOfCorner(c);
        return c + 1 < faceStart(f + 1) ? wVerts[c + 1] : wVerts[faceStart(f)];
    }

    /**
     * Sorts corners by the lower vertex of their edge, then by the higher, so that the corners of
     * one undirected edge are adjacent, and fills {@link #mate} from the runs. Keeps the sorted
     * order in {@link #byMin} only if some edge has more than two corners.
     */
    void findMates() {
        int vertexCount = soup.vertexCount();
        byMin = new int[wCornerCount];
        mate = new int[wCornerCount];
        int[] bucketStart = new int[vertexCount + 1];
        // Borrowed until the mates are known: the higher vertex of each corner's edge. A run's
        // slots are all read before its mates overwrite them.
        int[] high = mate;
        for (int c = 0; c < wCornerCount; c++) {
            int a = cornerFrom(c);
            int b = cornerTo(c);
            high[c] = Math.max(a, b);
            bucketStart[Math.min(a, b) + 1]++;
        }
        for (int v = 0; v < vertexCount; v++) {
            bucketStart[v + 1] += bucketStart[v];
        }
        int[] fill = Arrays.copyOf(bucketStart, vertexCount);
        for (int c = 0; c < wCornerCount; c++) {
            byMin[fill[Math.min(cornerFrom(c), cornerTo(c))]++] = c;
        }
        fill = null;
        boolean nonManifold = false;
        for (int v = 0; v < vertexCount; v++) {
            int start = bucketStart[v];
            int end = bucketStart[v + 1];
            // A bucket holds the few edges of one vertex: insertion sort by the higher vertex.
            for (int i = start + 1; i < end; i++) {
                int c = byMin[i];
                int key = high[c];
                int j = i - 1;
                while (j >= start && high[byMin[j]] > key) {
                    byMin[j + 1] = byMin[j];
                    j--;
                }
                byMin[j + 1] = c;
            }
            for (int i = start; i < end; ) {
                int runEnd = i + 1;
                while (runEnd < end && high[byMin[runEnd]] == high[byMin[i]]) {
                    runEnd++;
                }
                if (runEnd - i == 1) {
                    mate[byMin[i]] = BOUNDARY;
                } else if (runEnd - i == 2) {
                    mate[byMin[i]] = byMin[i + 1];
                    mate[byMin[i + 1]] = byMin[i];
                } else {
                    nonManifold = true;
                    for (int k = i; k < runEnd; k++) {
                        mate[byMin[k]] = NON_MANIFOLD;
                    }
                }
                i = runEnd;
            }
        }
        if (!nonManifold) {
            byMin = null;
        }
    }

    // ---- step 4, orientation: MeshOrientation; steps 5 to 7, pair, split pinches, link
    // boundaries: MeshAssembly -----------------------------------------------------------------

    // ---- reporting --------------------------------------------------------------------------

    void repair(Defect defect, int inputFace, int count) throws InvalidMeshException {
        if (options.strict()) {
            throw refuse(defect, inputFace, "face " + inputFace + ": " + defect.description());
        }
        repairs.merge(defect, count, Integer::sum);
    }

    InvalidMeshException refuse(Defect defect, int inputFace, String message) {
        int line = soup instanceof PolygonSoup polygons ? polygons.faceLine(inputFace) : 0;
        return new InvalidMeshException(defect, line, message);
    }
}
