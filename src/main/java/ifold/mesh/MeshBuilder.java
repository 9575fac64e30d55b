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

    private final IndexedPolygons soup;
    private final Options options;
    private final double[] xyz;
    private final EnumMap<Defect, Integer> repairs = new EnumMap<>(Defect.class);

    // Working faces after cleaning: faceStart(f)..faceStart(f+1) index wVerts; wSource[f] is the
    // input face. While every face is a triangle, wStart is null and face f starts at 3f: that is
    // always so when triangulating, and saves an array as long as the faces of a big model.
    private int[] wStart;
    private int[] wVerts;
    private int[] wSource;
    private int wFaceCount;
    private int wCornerCount;

    // Corners grouped by undirected edge, alive from grouping to pairing only: for a big model
    // they are a third of the builder's memory, so they are dropped as soon as pairing is done.
    /** The working face of each corner; null when every face is a triangle (then it is c / 3). */
    private int[] cornerFace;
    /**
     * The corner across the edge when exactly two corners share it ({@link #BOUNDARY} when
     * none, {@link #NON_MANIFOLD} when more than two do). Orientation and pairing, which touch
     * every corner, need only this: one read instead of a search through the group.
     */
    private int[] mate;
    /** Corners sorted by the lower, then the higher vertex of their edge; kept only when some edge is non-manifold. */
    private int[] byMin;
    private static final int BOUNDARY = -1;
    private static final int NON_MANIFOLD = -2;
    /** The number of halfedges, once they are paired. */
    private int halfedgeCount;

    private MeshBuilder(IndexedPolygons soup, Options options) {
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
    private static final int PARALLEL_FACES = 50_000;

    private Result run() throws InvalidMeshException {
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
        reverseFlippedFaces(orient());
        return assemble(pairHalfedges());
    }

    private static boolean[] await(FutureTask<boolean[]> task) throws InvalidMeshException {
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

    private void checkCoordinates() throws InvalidMeshException {
        for (int i = 0; i < 3 * soup.vertexCount(); i++) {
            if (!Double.isFinite(xyz[i])) {
                throw new InvalidMeshException(Defect.NON_FINITE_COORDINATE, 0,
                        "vertex " + (i / 3) + " has a non-finite coordinate (" + xyz[i] + ")");
            }
        }
    }

    private void cleanFaces() throws InvalidMeshException {
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

    private static boolean visitsVertexTwice(int[] polygon, int size) {
        for (int i = 0; i < size; i++) {
            for (int j = i + 1; j < size; j++) {
                if (polygon[i] == polygon[j]) {
                    return true;
                }
            }
        }
        return false;
    }

    private void addWorkingFace(int[] vertices, int offset, int size, int source) {
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
    private boolean[] duplicateCandidates() {
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
    private boolean[] findDuplicateFaces(boolean[] candidates) throws InvalidMeshException {
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
    private int faceKeyHash(int f) {
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

    private boolean sameVertexSet(int f, int g) {
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

    private void compactWorkingFaces(boolean[] drop) {
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

    private int faceStart(int f) {
        return wStart == null ? 3 * f : wStart[f];
    }

    private int faceOfCorner(int c) {
        return cornerFace == null ? c / 3 : cornerFace[c];
    }

    private int[] cornerFaces() {
        int[] cornerFace = new int[wCornerCount];
        for (int f = 0; f < wFaceCount; f++) {
            Arrays.fill(cornerFace, faceStart(f), faceStart(f + 1), f);
        }
        return cornerFace;
    }

    /** The vertex the edge of corner {@code c} starts from. */
    private int cornerFrom(int c) {
        return wVerts[c];
    }

    /** The vertex the edge of corner {@code c} points to: the next corner of its face. */
    private int cornerTo(int c) {
        int f = faceOfCorner(c);
        return c + 1 < faceStart(f + 1) ? wVerts[c + 1] : wVerts[faceStart(f)];
    }

    /**
     * Sorts corners by the lower vertex of their edge, then by the higher, so that the corners of
     * one undirected edge are adjacent, and fills {@link #mate} from the runs. Keeps the sorted
     * order in {@link #byMin} only if some edge has more than two corners.
     */
    private void findMates() {
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

    // ---- step 4: orientation ----------------------------------------------------------------

    private boolean[] orient() throws InvalidMeshException {
        boolean[] flip = new boolean[wFaceCount];
        int[] component = new int[wFaceCount];
        Arrays.fill(component, -1);
        // The components one after another, each in the order the walk reached its faces.
        int[] queue = new int[wFaceCount];
        // Per component: turned over as a whole (the minority rule), and closed.
        boolean[] inverted = new boolean[16];
        boolean[] closedComponent = new boolean[16];
        int[] origin = new int[16]; // a vertex of each: volumes are measured from it
        int components = 0;
        int tail = 0;
        for (int seed = 0; seed < wFaceCount; seed++) {
            if (component[seed] >= 0) {
                continue;
            }
            int first = tail;
            int head = tail;
            queue[tail++] = seed;
            component[seed] = components;
            int flipped = 0;
            boolean closed = true;
            while (head < tail) {
                int f = queue[head++];
                for (int c = faceStart(f); c < faceStart(f + 1); c++) {
                    int o = mate[c];
                    if (o < 0) {
                        closed = false;
                        continue;
                    }
                    int of = faceOfCorner(o);
                    if (of == f) {
                        closed = false;
                        continue;
                    }
                    boolean sameDirection = cornerFrom(c) == cornerFrom(o);
                    boolean wanted = flip[f] ^ sameDirection;
                    if (component[of] < 0) {
                        component[of] = components;
                        flip[of] = wanted;
                        if (wanted) {
                            flipped++;
                        }
                        queue[tail++] = of;
                    } else if (flip[of] != wanted) {
                        if (options.strict()) {
                            throw refuse(Defect.NON_ORIENTABLE, wSource[f], "face " + wSource[f]
                                    + ": " + Defect.NON_ORIENTABLE.description());
                        }
                        // Cut the edge: both corners become boundary, so the far side will not
                        // count it again.
                        mate[c] = BOUNDARY;
                        mate[o] = BOUNDARY;
                        closed = false;
                        repairs.merge(Defect.NON_ORIENTABLE, 1, Integer::sum);
                    }
                }
            }
            int size = tail - first;
            // Turn over the minority: the side most faces agree on is taken as meant.
            boolean invert = 2 * flipped > size;
            int turned = invert ? size - flipped : flipped;
            if (turned > 0) {
                if (options.strict()) {
                    int example = firstDisagreeing(queue, first, tail, flip, invert);
                    throw refuse(Defect.INCONSISTENT_ORIENTATION, wSource[example], "face " + wSource[example]
                            + ": " + Defect.INCONSISTENT_ORIENTATION.description());
                }
                repair(Defect.INCONSISTENT_ORIENTATION, wSource[seed], turned);
            }
            if (components == inverted.length) {
                inverted = Arrays.copyOf(inverted, 2 * components);
                closedComponent = Arrays.copyOf(closedComponent, 2 * components);
                origin = Arrays.copyOf(origin, 2 * components);
            }
            inverted[components] = invert;
            closedComponent[components] = closed;
            origin[components] = wVerts[faceStart(seed)];
            components++;
        }
        // Closed components enclosing a negative volume are turned outward. The volumes are
        // summed in face order, one pass over memory for all components together. A volume
        // next to nothing for its surface's area (a flat closed sheet, a pillow: zero but for
        // rounding, whose sign the order of summing decides) has no inside to turn out.
        double[][] volumes = signedVolumes(component, flip, inverted, closedComponent, origin, components);
        for (int k = 0; k < components; k++) {
            if (closedComponent[k] && volumes[0][k] < -1e-9 * Math.pow(volumes[1][k], 1.5)) {
                inverted[k] = !inverted[k];
                repairs.merge(Defect.INWARD_COMPONENT, 1, Integer::sum);
            }
        }
        for (int f = 0; f < wFaceCount; f++) {
            flip[f] ^= inverted[component[f]];
        }
        return flip;
    }

    private static int firstDisagreeing(int[] faces, int from, int to, boolean[] flip, boolean invert) {
        for (int i = from; i < to; i++) {
            if (flip[faces[i]] != invert) {
                return faces[i];
            }
        }
        return faces[from];
    }

    /**
     * Six times the signed volume enclosed by each closed component, with its faces oriented as
     * {@code flip}, then {@code inverted} for the whole component, will orient them, measured
     * from a vertex of its own; and twice its surface's area: {volumes, areas}.
     */
    private double[][] signedVolumes(int[] component, boolean[] flip, boolean[] inverted, boolean[] closed, int[] origin,
            int components) {
        double[] volume = new double[components];
        double[] area = new double[components];
        for (int f = 0; f < wFaceCount; f++) {
            int k = component[f];
            if (!closed[k]) {
                continue;
            }
            int start = faceStart(f);
            int end = faceStart(f + 1);
            int a = wVerts[start];
            double faceVolume = 0;
            for (int c = start + 1; c + 1 < end; c++) {
                faceVolume += tripleProduct(origin[k], a, wVerts[c], wVerts[c + 1]);
                area[k] += Triangles.twiceArea(xyz, a, wVerts[c], wVerts[c + 1]);
            }
            volume[k] += flip[f] ^ inverted[k] ? -faceVolume : faceVolume;
        }
        return new double[][] {volume, area};
    }

    /** The triple product of corners a, b and c taken from vertex o: six times the tetrahedron's signed volume. */
    private double tripleProduct(int o, int a, int b, int c) {
        double ox = xyz[3 * o];
        double oy = xyz[3 * o + 1];
        double oz = xyz[3 * o + 2];
        double ax = xyz[3 * a] - ox;
        double ay = xyz[3 * a + 1] - oy;
        double az = xyz[3 * a + 2] - oz;
        double bx = xyz[3 * b] - ox;
        double by = xyz[3 * b + 1] - oy;
        double bz = xyz[3 * b + 2] - oz;
        double cx = xyz[3 * c] - ox;
        double cy = xyz[3 * c + 1] - oy;
        double cz = xyz[3 * c + 2] - oz;
        return ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx);
    }

    /**
     * Reverses the vertex lists of flipped faces. Corner k of a reversed face of n corners is
     * the edge that was corner n - 2 - k (and the other way round), so each corner's mate, and
     * its place in {@code byMin}, move with it.
     */
    private void reverseFlippedFaces(boolean[] flip) {
        boolean any = false;
        for (int c = 0; c < wCornerCount; c++) {
            if (mate[c] >= 0) {
                mate[c] = reversedIndex(mate[c], flip);
            }
            any |= flip[faceOfCorner(c)];
        }
        if (!any) {
            return;
        }
        if (byMin != null) {
            for (int i = 0; i < byMin.length; i++) {
                byMin[i] = reversedIndex(byMin[i], flip);
            }
        }
        int[] mates = new int[16];
        for (int f = 0; f < wFaceCount; f++) {
            if (!flip[f]) {
                continue;
            }
            int start = faceStart(f);
            int n = faceStart(f + 1) - start;
            if (mates.length < n) {
                mates = new int[2 * n];
            }
            for (int k = 0; k < n; k++) {
                mates[k] = mate[start + Math.floorMod(n - 2 - k, n)];
            }
            System.arraycopy(mates, 0, mate, start, n);
            for (int i = 0, j = n - 1; i < j; i++, j--) {
                int swap = wVerts[start + i];
                wVerts[start + i] = wVerts[start + j];
                wVerts[start + j] = swap;
            }
        }
    }

    /** Where corner {@code c} will be once flipped faces are reversed. */
    private int reversedIndex(int c, boolean[] flip) {
        int f = faceOfCorner(c);
        if (!flip[f]) {
            return c;
        }
        int start = faceStart(f);
        int n = faceStart(f + 1) - start;
        return start + Math.floorMod(n - 2 - (c - start), n);
    }

    // ---- steps 5 to 7: pair, split pinches, link boundaries ----------------------------------

    /**
     * Pairs each edge's halfedges and numbers the halfedges: returns the halfedge of each
     * corner. Paired corners share an edge (halfedges 2e and 2e + 1); a corner left unpaired
     * gets an edge of its own whose twin is a boundary halfedge.
     */
    private int[] pairHalfedges() throws InvalidMeshException {
        // First pass: the partner of each corner, encoded as -(partner + 2); -1 for none.
        int[] cornerHalfedge = new int[wCornerCount];
        Arrays.fill(cornerHalfedge, -1);
        for (int c = 0; c < wCornerCount; c++) {
            int d = mate[c];
            // Orientation made the mates run in opposite directions, unless the edge lies twice
            // in one face: such corners stay boundary.
            if (d > c && cornerFrom(c) != cornerFrom(d) && faceOfCorner(c) != faceOfCorner(d)) {
                cornerHalfedge[c] = -(d + 2);
                cornerHalfedge[d] = -(c + 2);
            }
        }
        if (byMin != null) {
            pairNonManifoldEdges(cornerHalfedge);
        }
        // Second pass: number the halfedges in corner order.
        int h = 0;
        for (int c = 0; c < wCornerCount; c++) {
            int partner = cornerHalfedge[c];
            if (partner >= 0) {
                continue; // numbered with its partner
            }
            cornerHalfedge[c] = h;
            if (partner <= -2) {
                cornerHalfedge[-partner - 2] = h + 1;
            }
            h += 2;
        }
        halfedgeCount = h;
        byMin = null;
        mate = null;
        return cornerHalfedge;
    }

    /**
     * Splits each edge that more than two corners share: joins the first two corners of
     * opposite direction in different faces and leaves the rest boundary.
     */
    private void pairNonManifoldEdges(int[] cornerHalfedge) throws InvalidMeshException {
        for (int i = 0; i < byMin.length; ) {
            int first = byMin[i];
            int low = Math.min(cornerFrom(first), cornerTo(first));
            int high = Math.max(cornerFrom(first), cornerTo(first));
            int end = i + 1;
            while (end < byMin.length && Math.min(cornerFrom(byMin[end]), cornerTo(byMin[end])) == low
                    && Math.max(cornerFrom(byMin[end]), cornerTo(byMin[end])) == high) {
                end++;
            }
            if (mate[first] == NON_MANIFOLD) {
                int f = wSource[faceOfCorner(first)];
                if (options.strict()) {
                    throw refuse(Defect.NON_MANIFOLD_EDGE, f, "face " + f + ": edge " + cornerFrom(first) + "-"
                            + cornerTo(first) + " is shared by " + (end - i) + " faces");
                }
                repair(Defect.NON_MANIFOLD_EDGE, f, 1);
                search:
                for (int j = i; j < end; j++) {
                    for (int k = j + 1; k < end; k++) {
                        int c = byMin[j];
                        int d = byMin[k];
                        if (cornerFrom(c) != cornerFrom(d) && faceOfCorner(c) != faceOfCorner(d)) {
                            cornerHalfedge[c] = -(d + 2);
                            cornerHalfedge[d] = -(c + 2);
                            break search;
                        }
                    }
                }
            }
            i = end;
        }
    }

    private Result assemble(int[] cornerHalfedge) throws InvalidMeshException {
        int[] toVertex = new int[halfedgeCount];
        int[] face = new int[halfedgeCount];
        int[] next = new int[halfedgeCount];
        int[] prev = new int[halfedgeCount];
        // Boundary halfedges have no corner: they are the twins not set below, and point back
        // to where their interior twin starts.
        Arrays.fill(face, -1);
        int[] faceHalfedge = new int[wFaceCount];
        for (int f = 0; f < wFaceCount; f++) {
            int start = faceStart(f);
            int end = faceStart(f + 1);
            faceHalfedge[f] = cornerHalfedge[start];
            for (int c = start; c < end; c++) {
                int hc = cornerHalfedge[c];
                int hn = cornerHalfedge[c + 1 < end ? c + 1 : start];
                // The twin ends where this corner starts: a boundary twin gets its vertex only
                // here; an interior twin is written again, the same, from its own corner.
                toVertex[hc ^ 1] = wVerts[c];
                toVertex[hc] = wVerts[c + 1 < end ? c + 1 : start];
                face[hc] = f;
                next[hc] = hn;
                prev[hn] = hc;
            }
        }
        cornerHalfedge = null; // as big as a halfedge array: let it go before the next ones

        // Vertices: referenced input vertices keep their order; pinch splits come after.
        int inputVertices = soup.vertexCount();
        int[] meshVertex = new int[inputVertices];
        Arrays.fill(meshVertex, -1);
        int vertexCount = 0;
        for (int c = 0; c < wCornerCount; c++) {
            meshVertex[wVerts[c]] = 0;
        }
        int unreferenced = 0;
        int firstUnreferenced = -1;
        for (int v = 0; v < inputVertices; v++) {
            if (meshVertex[v] == 0) {
                meshVertex[v] = vertexCount++;
            } else {
                unreferenced++;
                if (firstUnreferenced < 0) {
                    firstUnreferenced = v;
                }
            }
        }
        if (unreferenced > 0) {
            if (options.strict()) {
                throw new InvalidMeshException(Defect.UNREFERENCED_VERTEX, 0,
                        "vertex " + firstUnreferenced + ": " + Defect.UNREFERENCED_VERTEX.description());
            }
            repairs.merge(Defect.UNREFERENCED_VERTEX, unreferenced, Integer::sum);
        }
        if (unreferenced > 0) { // otherwise every vertex keeps its number
            for (int i = 0; i < halfedgeCount; i++) {
                toVertex[i] = meshVertex[toVertex[i]];
            }
        }
        int[] sourceVertex = new int[Math.max(4, vertexCount + vertexCount / 8)];
        for (int v = 0; v < inputVertices; v++) {
            if (meshVertex[v] >= 0) {
                sourceVertex[meshVertex[v]] = v;
            }
        }

        // Split pinches: walk each fan of faces around a vertex once; a vertex already claimed
        // by an earlier fan gets a copy for this one.
        int[] vertexHalfedge = new int[sourceVertex.length];
        Arrays.fill(vertexHalfedge, -1);
        boolean[] visited = new boolean[halfedgeCount];
        boolean[] pinched = new boolean[vertexCount];
        int pinchCount = 0;
        for (int start = 0; start < halfedgeCount; start++) {
            if (face[start] < 0 || visited[start]) {
                continue;
            }
            // Counter-clockwise from start to the boundary, or all the way round; an open fan
            // is then walked clockwise from start to its other end.
            int boundaryOut = -1;
            int h = start;
            while (true) {
                visited[h] = true;
                int ccw = prev[h] ^ 1;
                if (face[ccw] < 0) {
                    boundaryOut = ccw; // the boundary halfedge leaving this fan
                    break;
                }
                if (ccw == start) {
                    break;
                }
                h = ccw;
            }
            if (boundaryOut >= 0) {
                for (h = start; face[h ^ 1] >= 0; ) {
                    h = next[h ^ 1];
                    visited[h] = true;
                }
            }
            int v = toVertex[prev[start]];
            if (vertexHalfedge[v] >= 0) {
                if (options.strict()) {
                    throw new InvalidMeshException(Defect.NON_MANIFOLD_VERTEX, 0, "vertex "
                            + sourceVertex[v] + ": " + Defect.NON_MANIFOLD_VERTEX.description());
                }
                if (!pinched[v]) {
                    pinched[v] = true;
                    pinchCount++;
                }
                if (vertexCount == sourceVertex.length) {
                    sourceVertex = Arrays.copyOf(sourceVertex, 2 * vertexCount);
                    vertexHalfedge = Arrays.copyOf(vertexHalfedge, 2 * vertexCount);
                }
                sourceVertex[vertexCount] = sourceVertex[v];
                v = vertexCount++;
                moveFan(start, v, toVertex, next, prev, face);
            }
            // A closed fan starts one step counter-clockwise of where the walk began.
            vertexHalfedge[v] = boundaryOut >= 0 ? boundaryOut : prev[start] ^ 1;
        }
        if (pinchCount > 0) {
            repairs.merge(Defect.NON_MANIFOLD_VERTEX, pinchCount, Integer::sum);
        }

        // Boundary loops: each vertex now has at most one boundary halfedge leaving it.
        for (int b = 0; b < halfedgeCount; b++) {
            if (face[b] < 0) {
                int out = vertexHalfedge[toVertex[b]];
                next[b] = out;
                prev[out] = b;
            }
        }

        double[] positions = new double[3 * sourceVertex.length];
        for (int v = 0; v < vertexCount; v++) {
            System.arraycopy(xyz, 3 * sourceVertex[v], positions, 3 * v, 3);
        }
        int[] faceColor = null;
        if (soup.hasFaceColors()) {
            faceColor = new int[wFaceCount];
            for (int f = 0; f < wFaceCount; f++) {
                faceColor[f] = soup.faceColor(wSource[f]);
            }
        }
        HalfedgeMesh mesh = HalfedgeMesh.adopt(positions, vertexHalfedge, vertexCount, next, prev, toVertex,
                face, halfedgeCount, faceHalfedge, faceColor, wFaceCount);
        int[] sourceFace = Arrays.copyOf(wSource, wFaceCount);
        return new Result(mesh, Map.copyOf(repairs), sourceFace, Arrays.copyOf(sourceVertex, vertexCount));
    }

    /**
     * Points the fan of halfedge {@code start} (its outgoing halfedges, and the incoming ones
     * before them and across from them) at vertex {@code v}, the copy made for a pinch.
     */
    private static void moveFan(int start, int v, int[] toVertex, int[] next, int[] prev, int[] face) {
        int h = start;
        while (true) {
            toVertex[prev[h]] = v;
            toVertex[h ^ 1] = v;
            int ccw = prev[h] ^ 1;
            if (ccw == start) {
                return; // closed: all of it done
            }
            if (face[ccw] < 0) {
                break;
            }
            h = ccw;
        }
        for (h = start; face[h ^ 1] >= 0; ) {
            h = next[h ^ 1];
            toVertex[prev[h]] = v;
            toVertex[h ^ 1] = v;
        }
    }

    // ---- reporting --------------------------------------------------------------------------

    private void repair(Defect defect, int inputFace, int count) throws InvalidMeshException {
        if (options.strict()) {
            throw refuse(defect, inputFace, "face " + inputFace + ": " + defect.description());
        }
        repairs.merge(defect, count, Integer::sum);
    }

    private InvalidMeshException refuse(Defect defect, int inputFace, String message) {
        int line = soup instanceof PolygonSoup polygons ? polygons.faceLine(inputFace) : 0;
        return new InvalidMeshException(defect, line, message);
    }
}
