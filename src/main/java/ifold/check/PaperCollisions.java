package ifold.check;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

/**
 * Where folded paper runs through itself or through the model, found from the exported OBJ
 * alone: an independent check that shares no code with the fold engine.
 *
 * <p>Every face of the file (paper and caps; convex polygons, fanned into triangles from their
 * first corner) is tested against every other whose box it meets, found in a uniform grid
 * ({@link BoxGrid}), by an exact test ({@link TriangleContact}): a pair <em>crosses</em> when the
 * triangles interpenetrate deeper than {@link #TOUCH} thicknesses, where the depth is their
 * penetration depth (the shortest move that frees one from the other; see TriangleContact). So
 * neighbours on the sheet, which share an edge or a corner, and layers that meet within the
 * touching distance do not cross; two layers overlapping in one plane are counted apart, as
 * coplanar, with depth 0. Triangles of one face are never paired (a convex face cannot cross
 * itself).
 *
 * <p>Against a model (its triangles given as numbers): paper triangles that cross a model
 * triangle by the same test, and paper vertices inside the solid its closed components bound
 * ({@link SolidInside}). Correctly folded paper lies half a thickness above the surface at
 * least, so it neither touches the model nor enters it.
 *
 * <p>Faces are numbered as in the file: face k is the k-th {@code f} line (1-based), counting
 * every strip and both groups; vertices as OBJ numbers them; model triangles from 1 in the
 * order given. Depths are in thicknesses T.
 */
public final class PaperCollisions {
    /** Pairs that meet no deeper than this many thicknesses touch: they do not cross. */
    public static final double TOUCH = 1e-3;

    private PaperCollisions() {
    }

    /** What crossed: two paper faces, a cap and paper (or two caps), paper and the model. */
    public enum Kind {
        PAPER, CAP, MODEL
    }

    public record Point(double x, double y, double z) {
        @Override
        public String toString() {
            return "(" + x + ", " + y + ", " + z + ")";
        }
    }

    /**
     * Two triangles that cross.
     *
     * @param faceA the paper face (1-based, file order); the lower-numbered one of two paper faces
     * @param faceB the other paper face, or for {@link Kind#MODEL} the model triangle (1-based)
     * @param coplanar whether they overlap lying in one plane (then depth is 0, and the segment
     *     is the overlap's longest chord)
     * @param depth the penetration depth in thicknesses
     * @param from one end of the segment the two triangles share
     * @param to the other end
     */
    public record Crossing(Kind kind, int faceA, int faceB, boolean coplanar, double depth, Point from, Point to) {
        /** The segment's length, in the file's units. */
        public double length() {
            return Math.sqrt((to.x - from.x) * (to.x - from.x) + (to.y - from.y) * (to.y - from.y) + (to.z - from.z) * (to.z - from.z));
        }
    }

    /** A paper vertex inside the solid: its OBJ number (1-based) and where it is. */
    public record Inside(int vertex, Point point) {
    }

    /**
     * @param listed how many crossings (and points inside) the result lists, in order of their faces
     * @param threads how many threads test the pairs (1 or more)
     */
    public record Options(int listed, int threads) {
        public static final Options DEFAULT = new Options(100, Math.max(1, Math.min(4, Runtime.getRuntime().availableProcessors())));

        public Options {
            if (listed < 0 || threads < 1) {
                throw new IllegalArgumentException("listed " + listed + " must not be negative, threads " + threads + " at least 1");
            }
        }
    }

    /**
     * What the check found.
     *
     * @param faces the faces of the file, paper and caps
     * @param capFaces of which caps
     * @param triangles the triangles they fan into
     * @param crossingPairs pairs of paper triangles (caps included) that cross, coplanar ones not counted
     * @param capPairs of those, the pairs with a cap in them
     * @param coplanarPairs pairs of paper triangles that overlap in one plane
     * @param facePairs pairs of faces with a crossing or coplanar pair of their triangles
     * @param modelCrossings pairs of a paper triangle and a model triangle that cross (or overlap in one plane)
     * @param pointsInside paper vertices inside the solid
     * @param deepest the deepest crossing of paper with paper, null when none
     * @param deepestIntoModel the deepest crossing of paper with the model (not in its plane), null when none
     * @param crossings the first crossings of paper with paper (coplanar ones too) in order of their faces
     * @param intoModel the first crossings of paper with the model in order of their faces
     * @param inside the first paper vertices inside the solid
     */
    public record Result(int faces, int capFaces, int triangles, int crossingPairs, int capPairs, int coplanarPairs,
            int facePairs, int modelCrossings, int pointsInside, Crossing deepest, Crossing deepestIntoModel,
            List<Crossing> crossings, List<Crossing> intoModel, List<Inside> inside) {
        /** Whether nothing collides: no crossing, no coplanar overlap, nothing into the model. */
        public boolean isClean() {
            return crossingPairs == 0 && coplanarPairs == 0 && modelCrossings == 0 && pointsInside == 0;
        }

        /**
         * One line for people, the cube's wrap as it was for one: "collisions: 8014 crossing pairs
         * (8014 with caps), deepest 4.000 T (faces 3 and 8643), 0 pairs overlapping in one plane,
         * 0 paper-model crossings, 0 paper points inside the solid" (depths to four digits; the
         * record holds them exactly).
         */
        public String summary() {
            // Pairs that cross and pairs that overlap in one plane are counted apart, and said apart.
            StringBuilder line = new StringBuilder("collisions: ").append(crossingPairs)
                    .append(crossingPairs == 1 ? " crossing pair" : " crossing pairs").append(" (").append(capPairs).append(" with caps)");
            if (deepest != null) {
                line.append(String.format(Locale.ROOT, ", deepest %.4g T (faces %d and %d)", deepest.depth(), deepest.faceA(), deepest.faceB()));
            }
            line.append(", ").append(coplanarPairs).append(coplanarPairs == 1 ? " pair" : " pairs").append(" overlapping in one plane");
            line.append(", ").append(modelCrossings).append(modelCrossings == 1 ? " paper-model crossing" : " paper-model crossings");
            if (deepestIntoModel != null) {
                line.append(String.format(Locale.ROOT, " (deepest %.4g T, face %d into model triangle %d)",
                        deepestIntoModel.depth(), deepestIntoModel.faceA(), deepestIntoModel.faceB()));
            }
            line.append(", ").append(pointsInside).append(pointsInside == 1 ? " paper point" : " paper points").append(" inside the solid");
            return line.toString();
        }
    }

    /** Checks the paper of an OBJ against itself; see {@link #check(CharSequence, double, double[], Options)}. */
    public static Result check(CharSequence objText, double thickness) {
        return check(objText, thickness, new double[0], Options.DEFAULT);
    }

    /** Checks the paper of an OBJ against itself and the model; see {@link #check(CharSequence, double, double[], Options)}. */
    public static Result check(CharSequence objText, double thickness, double[] modelTriangles) {
        return check(objText, thickness, modelTriangles, Options.DEFAULT);
    }

    /**
     * Checks the paper of an OBJ against itself and against a model.
     *
     * @param objText the OBJ that {@code ifold wrap --export-obj} writes (strips, groups paper and cap)
     * @param thickness the paper's thickness T, more than 0: depths are in T, and the touching distance is {@link #TOUCH} T
     * @param modelTriangles the model's triangles, 9 numbers each (corners x y z); empty for none
     * @throws IllegalArgumentException for a thickness that is not positive and finite, a model
     *     array whose length is not a multiple of 9 or holding a number that is not finite, and
     *     for OBJ text that is not the format (naming the line)
     */
    public static Result check(CharSequence objText, double thickness, double[] modelTriangles, Options options) {
        if (!(thickness > 0) || Double.isInfinite(thickness)) {
            throw new IllegalArgumentException("the thickness must be positive and finite (depths are measured in it), not " + thickness);
        }
        if (modelTriangles.length % 9 != 0) {
            throw new IllegalArgumentException("model triangles are 9 numbers each, not " + modelTriangles.length + " numbers");
        }
        for (double c : modelTriangles) {
            if (!Double.isFinite(c)) {
                throw new IllegalArgumentException("a model coordinate is not finite: " + c);
            }
        }
        PaperObj paper = PaperObj.read(objText);
        return new Run(paper, thickness, modelTriangles, options).result();
    }

    /** One check: the triangles, the grid, the sweeps' findings made a result. */
    private static final class Run {
        private final TriangleSet set;
        private final PaperObj paper;
        private final double thickness;
        private final double[] model;
        private final Options options;
        private final int paperTriangles;
        private final int modelTriangles;

        Run(PaperObj paper, double thickness, double[] model, Options options) {
            this.set = new TriangleSet(paper, model, TOUCH * thickness);
            this.paper = paper;
            this.thickness = thickness;
            this.model = model;
            this.options = options;
            paperTriangles = set.paperTriangles;
            modelTriangles = set.modelTriangles;
        }

        Result result() {
            BoxGrid grid = new BoxGrid(set.boxes, set.count());
            long[] entries = grid.entries;
            // Chunks of whole cells, several a thread, taken in turn so that a crowded cell does not hold one thread up.
            int chunks = Math.max(1, Math.min(entries.length / 1024, 16 * options.threads()));
            int[] chunkStart = new int[chunks + 1];
            int at = 0;
            for (int c = 1; c <= chunks; c++) {
                int target = (int) ((long) entries.length * c / chunks);
                while (at < target) {
                    at = grid.runEnd(at);
                }
                chunkStart[c] = at;
            }
            AtomicInteger nextChunk = new AtomicInteger();
            AtomicReference<RuntimeException> failure = new AtomicReference<>();
            CellSweep[] workers = new CellSweep[options.threads()];
            Thread[] threads = new Thread[workers.length];
            for (int w = 0; w < workers.length; w++) {
                CellSweep worker = new CellSweep(grid, set, thickness);
                workers[w] = worker;
                threads[w] = new Thread(() -> {
                    try {
                        for (int c = nextChunk.getAndIncrement(); c < chunks; c = nextChunk.getAndIncrement()) {
                            worker.cells(chunkStart[c], chunkStart[c + 1]);
                        }
                    } catch (RuntimeException e) {
                        failure.compareAndSet(null, e);
                        // The other threads stop at their next chunk.
                        nextChunk.set(chunks);
                    }
                }, "paper-collisions-" + w);
                threads[w].start();
            }
            for (Thread thread : threads) {
                try {
                    thread.join();
                } catch (InterruptedException e) {
                    nextChunk.set(chunks);
                    Thread.currentThread().interrupt();
                    throw new IllegalStateException("interrupted while checking collisions", e);
                }
            }
            if (failure.get() != null) {
                throw failure.get();
            }
            return summarise(workers);
        }

        /** The counts and the crossings worth naming, from the workers' findings (all of them kept only as numbers). */
        private Result summarise(CellSweep[] workers) {
            int found = 0;
            for (CellSweep worker : workers) {
                found += worker.size();
            }
            // The findings' keys, face A << 32 | face B (a model triangle's face B offset past the faces), each with its finding.
            long[] keys = new long[found];
            int k = 0;
            int crossing = 0;
            int caps = 0;
            int coplanar = 0;
            int intoModel = 0;
            Crossing deepest = null;
            Crossing deepestIntoModel = null;
            long deepestKey = 0;
            long deepestModelKey = 0;
            long faceCount = paper.faceCount();
            for (CellSweep worker : workers) {
                for (int f = 0; f < worker.size(); f++) {
                    int i = worker.paperTriangle(f);
                    int j = worker.otherTriangle(f);
                    long faceA = paper.triFace[i];
                    boolean model = j >= paperTriangles;
                    long faceB = model ? faceCount + j - paperTriangles : paper.triFace[j];
                    keys[k++] = faceA << 32 | faceB;
                    // Ties are broken by the triangles (in file order), not by which thread came first.
                    long key = (long) i << 32 | j;
                    double depth = worker.depth(f);
                    // The deepest, and of equal depths the one of the first triangles.
                    if (model) {
                        intoModel++;
                        boolean deeper = deepestIntoModel == null || depth > deepestIntoModel.depth() || depth == deepestIntoModel.depth() && key < deepestModelKey;
                        if (!worker.coplanar(f) && deeper) {
                            deepestIntoModel = crossing(worker, f);
                            deepestModelKey = key;
                        }
                    } else if (worker.coplanar(f)) {
                        coplanar++;
                    } else {
                        crossing++;
                        caps += paper.cap[(int) faceA] || paper.cap[(int) faceB] ? 1 : 0;
                        if (deepest == null || depth > deepest.depth() || depth == deepest.depth() && key < deepestKey) {
                            deepest = crossing(worker, f);
                            deepestKey = key;
                        }
                    }
                }
            }
            long[] sorted = keys.clone();
            Arrays.sort(sorted);
            int facePairs = 0;
            for (int p = 0; p < sorted.length && (sorted[p] & 0xFFFFFFFFL) < faceCount; p++) {
                facePairs += p == 0 || sorted[p] != sorted[p - 1] ? 1 : 0;
            }
            // The first listed of each list, in order of faces: those with keys up to the listed-th key of the list.
            int listed = options.listed();
            List<Crossing> paperList = new ArrayList<>();
            List<Crossing> modelList = new ArrayList<>();
            long paperLast = Long.MIN_VALUE;
            long modelLast = Long.MIN_VALUE;
            int paperSeen = 0;
            int modelSeen = 0;
            for (long key : sorted) {
                boolean model = (key & 0xFFFFFFFFL) >= faceCount;
                if (model && modelSeen++ < listed) {
                    modelLast = key;
                } else if (!model && paperSeen++ < listed) {
                    paperLast = key;
                }
            }
            k = 0;
            for (CellSweep worker : workers) {
                for (int f = 0; f < worker.size(); f++) {
                    long key = keys[k++];
                    boolean model = (key & 0xFFFFFFFFL) >= faceCount;
                    if (model ? key <= modelLast : key <= paperLast) {
                        (model ? modelList : paperList).add(crossing(worker, f));
                    }
                }
            }
            Comparator<Crossing> byFaces = Comparator.comparingInt(Crossing::faceA).thenComparingInt(Crossing::faceB)
                    .thenComparing(Crossing::depth, Comparator.reverseOrder());
            paperList.sort(byFaces);
            modelList.sort(byFaces);
            List<Inside> inside = new ArrayList<>();
            int pointsInside = modelTriangles == 0 ? 0 : pointsInside(inside, listed);
            return new Result(paper.faceCount(), capFaces(), paperTriangles, crossing, caps, coplanar, facePairs, intoModel,
                    pointsInside, deepest, deepestIntoModel,
                    List.copyOf(paperList.subList(0, Math.min(listed, paperList.size()))),
                    List.copyOf(modelList.subList(0, Math.min(listed, modelList.size()))), List.copyOf(inside));
        }

        private int capFaces() {
            int caps = 0;
            for (boolean cap : paper.cap) {
                caps += cap ? 1 : 0;
            }
            return caps;
        }

        /** The paper vertices (those of faces) inside the model's solid: counted, the first listed into out. */
        private int pointsInside(List<Inside> out, int listed) {
            SolidInside solid = new SolidInside(model, modelTriangles);
            if (solid.closedTriangleCount() == 0) {
                return 0;
            }
            boolean[] used = new boolean[paper.vertexCount()];
            for (int v : paper.corner) {
                used[v] = true;
            }
            int count = 0;
            for (int v = 0; v < used.length; v++) {
                double x = paper.xyz[3 * v];
                double y = paper.xyz[3 * v + 1];
                double z = paper.xyz[3 * v + 2];
                if (used[v] && solid.inside(x, y, z)) {
                    count++;
                    if (out.size() < listed) {
                        out.add(new Inside(v + 1, new Point(x, y, z)));
                    }
                }
            }
            return count;
        }

        /** Finding f of a sweep as a crossing. */
        private Crossing crossing(CellSweep sweep, int f) {
            int i = sweep.paperTriangle(f);
            int j = sweep.otherTriangle(f);
            Point from = new Point(sweep.segment(f, 0), sweep.segment(f, 1), sweep.segment(f, 2));
            Point to = new Point(sweep.segment(f, 3), sweep.segment(f, 4), sweep.segment(f, 5));
            int faceA = paper.triFace[i];
            if (set.isModel(j)) {
                return new Crossing(Kind.MODEL, faceA + 1, j - paperTriangles + 1, sweep.coplanar(f), sweep.depth(f), from, to);
            }
            int faceB = paper.triFace[j];
            Kind kind = paper.cap[faceA] || paper.cap[faceB] ? Kind.CAP : Kind.PAPER;
            return new Crossing(kind, faceA + 1, faceB + 1, sweep.coplanar(f), sweep.depth(f), from, to);
        }
    }
}
