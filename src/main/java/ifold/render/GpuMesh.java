package ifold.render;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL3;
import ifold.scene.SceneMesh;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.util.BitSet;
import org.joml.Matrix4fc;
import org.joml.Vector4f;

/**
 * The GL objects of one {@link SceneMesh}: shared vertex positions, triangle and edge index
 * buffers, and the colours of triangles and edges as buffer textures read by primitive index.
 * Floats are made here, at upload, and nowhere else.
 *
 * <p>A wrap of a million faces is millions of triangles, and Mesa's software renderer draws
 * about three million a second. The triangles come in the order they were folded, each run of
 * them close together: they are drawn in chunks of {@link #CHUNK}, and a chunk whose box lies
 * out of view is not drawn (the camera follows the strip, close to it). Where the mesh has
 * {@linkplain SceneMesh.Layers layers}:
 * <ul>
 * <li>a chunk drawn whole draws only its triangles not yet covered by others (a second index
 * buffer, each chunk's triangles covered last first, so that those are its first);
 * <li>its seams (a fold's caps, closing the gap between layers, most of a wrap's triangles) are
 * drawn only where they are at least {@link #SEAM_PIXELS} wide on screen;
 * <li>a chunk whose patches are settled and whose faces are under {@link #PATCH_PIXELS} on
 * screen is drawn as its patches, a few triangles each;
 * <li>the last chunk is drawn first and in each its last triangle: paper laid later mostly lies
 * higher, and what is drawn in front first spares shading what is behind.
 * </ul>
 */
final class GpuMesh {
    final int version;
    /** Triangles a chunk: its box is tested against the view. */
    static final int CHUNK = 512;
    /** Seams narrower than this on screen are not drawn. */
    static final double SEAM_PIXELS = 1.0;
    /** A settled chunk whose faces are smaller than this on screen is drawn as its patches. */
    static final double PATCH_PIXELS = 1.0;
    /** The edges' vertex array, positions, edge indices, edge colours. */
    private final int[] arrays = new int[1];
    private final int[] buffers = new int[3];
    private final int[] textures = new int[1];
    final int triangleCount;
    final int edgeCount;
    /** min x, y, z, max x, y, z of each chunk's triangles */
    private final float[] chunkBoxes;
    /** The widest seam of each chunk (0 where it has none). */
    private final float[] seamWidths;
    private final BitSet seams;
    /** All triangles, each chunk's seams after its others, as they come (with layers: the last first). */
    private final Order all;
    /** Where the mesh has layers: all triangles, likewise, those covered last first; and the patches. Else null. */
    private final Order byCover;
    private final Order patches;
    private final int[] patchStart;
    /** For each chunk, how many triangles must be drawn for all its patches to be settled. */
    private final int[] settledAt;
    /** For each chunk, its patches: {@code chunkPatches[chunkPatchStart[c]]} to {@code [c + 1]}. */
    private final int[] chunkPatchStart;
    private final int[] chunkPatches;
    /** For each chunk, the side of a square of its other triangles' mean area. */
    private final float[] faceSizes;
    private final int[] patchPositions = new int[1];
    private final Vector4f corner = new Vector4f();

    /**
     * The triangles in one order, by chunk: chunk c's others from {@code start[c]} to
     * {@code seamStart[c]}, its seams on to {@code end[c]}; with its own colours, so that a
     * triangle's place in the order is its index in the shader.
     */
    private static final class Order {
        final int[] objects = new int[4]; // vertex array, index buffer, colour buffer, colour texture
        final int[] start;
        final int[] seamStart;
        final int[] end;
        /** Whether the last chunk comes first, and in each part the last triangle (else all as they come). */
        final boolean lastFirst;
        /** Where the order is by cover: the key of each place, falling within each part of a chunk; else null. */
        final int[] hiddenFrom;

        /**
         * The triangles in chunks, each chunk's others before its seams; {@code lastFirst}, the
         * last chunk first and each part the last triangle first or, given {@code hiddenFrom},
         * the latest covered first: the triangles still seen when n are drawn are then the first
         * of each part. Paper laid later mostly lies higher, and a software renderer that draws
         * what is in front first skips shading what is behind. Else as they come, so that a
         * triangle's place is its index.
         */
        Order(GL3 gl, int positions, SceneMesh mesh, BitSet seams, int[] hiddenFrom, int chunks, boolean lastFirst) {
            this.lastFirst = lastFirst;
            int[] triangles = mesh.triangles();
            int[] colors = mesh.triangleColors();
            int count = triangles.length / 3;
            start = new int[chunks];
            seamStart = new int[chunks];
            end = new int[chunks];
            this.hiddenFrom = hiddenFrom == null ? null : new int[count];
            int[] indices = new int[3 * count];
            int[] orderedColors = new int[count];
            long[] part = new long[CHUNK];
            int k = 0;
            for (int step = 0; step < chunks; step++) {
                int c = lastFirst ? chunks - 1 - step : step;
                start[c] = k;
                int from = c * CHUNK;
                int to = Math.min(count, from + CHUNK);
                for (int pass = 0; pass < 2; pass++) {
                    if (pass == 1) {
                        seamStart[c] = k;
                    }
                    int n = 0;
                    for (int t = from; t < to; t++) {
                        boolean seam = seams != null && seams.get(t);
                        if (seam == (pass == 1)) {
                            // Latest covered first, then the last first.
                            long key = hiddenFrom == null ? 0 : Integer.MAX_VALUE - (long) hiddenFrom[t];
                            part[n++] = key << 32 | (lastFirst ? Integer.MAX_VALUE - t : t);
                        }
                    }
                    java.util.Arrays.sort(part, 0, n);
                    for (int i = 0; i < n; i++) {
                        int t = lastFirst ? Integer.MAX_VALUE - (int) part[i] : (int) part[i];
                        System.arraycopy(triangles, 3 * t, indices, 3 * k, 3);
                        orderedColors[k] = colors[t];
                        if (hiddenFrom != null) {
                            this.hiddenFrom[k] = hiddenFrom[t];
                        }
                        k++;
                    }
                }
                end[c] = k;
            }
            gl.glGenVertexArrays(1, objects, 0);
            gl.glGenBuffers(2, objects, 1);
            gl.glGenTextures(1, objects, 3);
            bindArray(gl, objects[0], positions, objects[1], indices);
            colorTexture(gl, objects[2], objects[3], orderedColors);
        }

        /** The triangles in the mesh's own order, in one part. */
        Order(GL3 gl, int positions, SceneMesh mesh) {
            lastFirst = false;
            start = new int[] {0};
            seamStart = new int[] {mesh.triangleCount()};
            end = new int[] {mesh.triangleCount()};
            hiddenFrom = null;
            gl.glGenVertexArrays(1, objects, 0);
            gl.glGenBuffers(2, objects, 1);
            gl.glGenTextures(1, objects, 3);
            bindArray(gl, objects[0], positions, objects[1], mesh.triangles());
            colorTexture(gl, objects[2], objects[3], mesh.triangleColors());
        }

        /** Where the {@code n} first triangles of the part from {@code first} to {@code end} lie (from there to n on). */
        int firstOf(int first, int end, int n) {
            return lastFirst ? end - n : first;
        }

        /** How many of the places from {@code first} to {@code end} (one part of a chunk) are still seen when {@code drawn} are drawn. */
        int seen(int first, int end, int drawn) {
            if (hiddenFrom == null) {
                return end - first;
            }
            int low = first;
            int high = end; // the first place hidden by then
            while (low < high) {
                int middle = (low + high) >>> 1;
                if (hiddenFrom[middle] > drawn) {
                    low = middle + 1;
                } else {
                    high = middle;
                }
            }
            return low - first;
        }

        void delete(GL3 gl) {
            gl.glDeleteVertexArrays(1, objects, 0);
            gl.glDeleteBuffers(2, objects, 1);
            gl.glDeleteTextures(1, objects, 3);
        }
    }

    GpuMesh(GL3 gl, SceneMesh mesh, int version) {
        this.version = version;
        triangleCount = mesh.triangleCount();
        edgeCount = mesh.edgeCount();
        gl.glGenVertexArrays(1, arrays, 0);
        gl.glGenBuffers(3, buffers, 0);
        gl.glGenTextures(1, textures, 0);

        double[] xyz = mesh.positions();
        uploadPositions(gl, buffers[0], xyz);

        bindArray(gl, arrays[0], buffers[0], buffers[1], mesh.edges());
        colorTexture(gl, buffers[2], textures[0], mesh.edgeColors());
        int chunks = (triangleCount + CHUNK - 1) / CHUNK;
        SceneMesh.Layers layers = mesh.layers();
        seams = layers == null ? null : layers.seams();
        chunkBoxes = new float[6 * chunks];
        seamWidths = new float[chunks];
        faceSizes = new float[chunks];
        measureChunks(xyz, mesh.triangles());
        all = new Order(gl, buffers[0], mesh, seams, null, chunks, layers != null);
        if (layers != null) {
            byCover = new Order(gl, buffers[0], mesh, seams, layers.hiddenFrom(), chunks, true);
            SceneMesh patchMesh = layers.patches();
            gl.glGenBuffers(1, patchPositions, 0);
            uploadPositions(gl, patchPositions[0], patchMesh.positions());
            patches = new Order(gl, patchPositions[0], patchMesh);
            patchStart = layers.patchStart();
            settledAt = new int[chunks];
            chunkPatchStart = new int[chunks + 1];
            int[] found = new int[16];
            int foundCount = 0;
            int[] seen = new int[layers.patchSettled().length];
            java.util.Arrays.fill(seen, -1);
            for (int c = 0; c < chunks; c++) {
                for (int t = c * CHUNK; t < Math.min(triangleCount, (c + 1) * CHUNK); t++) {
                    int p = layers.patchOf()[t];
                    settledAt[c] = Math.max(settledAt[c], layers.patchSettled()[p]);
                    if (seen[p] != c) {
                        seen[p] = c;
                        if (foundCount == found.length) {
                            found = java.util.Arrays.copyOf(found, 2 * found.length);
                        }
                        found[foundCount++] = p;
                    }
                }
                chunkPatchStart[c + 1] = foundCount;
            }
            chunkPatches = java.util.Arrays.copyOf(found, foundCount);
        } else {
            byCover = null;
            patches = null;
            patchStart = null;
            settledAt = null;
            chunkPatchStart = null;
            chunkPatches = null;
        }
        gl.glBindVertexArray(0);
    }

    private static void uploadPositions(GL3 gl, int buffer, double[] xyz) {
        float[] floats = new float[Math.max(3, xyz.length)];
        for (int i = 0; i < xyz.length; i++) {
            floats[i] = (float) xyz[i];
        }
        FloatBuffer positions = Buffers.newDirectFloatBuffer(floats);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffer);
        gl.glBufferData(GL3.GL_ARRAY_BUFFER, 4L * positions.remaining(), positions, GL3.GL_STATIC_DRAW);
    }

    /** A vertex array reading {@code positions} through {@code indices}, uploaded to {@code indexBuffer}. */
    private static void bindArray(GL3 gl, int array, int positions, int indexBuffer, int[] indices) {
        gl.glBindVertexArray(array);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, positions);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(0, 3, GL3.GL_FLOAT, false, 12, 0);
        gl.glBindBuffer(GL3.GL_ELEMENT_ARRAY_BUFFER, indexBuffer);
        IntBuffer data = Buffers.newDirectIntBuffer(Math.max(1, indices.length));
        data.put(indices).flip();
        gl.glBufferData(GL3.GL_ELEMENT_ARRAY_BUFFER, 4L * Math.max(1, indices.length), data, GL3.GL_STATIC_DRAW);
    }

    private static void colorTexture(GL3 gl, int buffer, int texture, int[] argb) {
        // RGBA8 in memory order: red first. As little-endian ints, red is the low byte.
        int[] packed = new int[Math.max(1, argb.length)];
        for (int i = 0; i < argb.length; i++) {
            int color = argb[i];
            packed[i] = (color & 0xFF000000) | (color & 0xFF) << 16 | (color & 0xFF00) | (color >>> 16 & 0xFF);
        }
        ByteBuffer rgba = Buffers.newDirectByteBuffer(4 * packed.length).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        rgba.asIntBuffer().put(packed);
        rgba.rewind();
        gl.glBindBuffer(GL3.GL_TEXTURE_BUFFER, buffer);
        gl.glBufferData(GL3.GL_TEXTURE_BUFFER, rgba.capacity(), rgba, GL3.GL_STATIC_DRAW);
        gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, texture);
        gl.glTexBuffer(GL3.GL_TEXTURE_BUFFER, GL3.GL_RGBA8, buffer);
        gl.glBindBuffer(GL3.GL_TEXTURE_BUFFER, 0);
    }

    /** Each chunk's box, and the width of its widest seam (a triangle's width: twice its area over its longest side). */
    private void measureChunks(double[] xyz, int[] triangles) {
        int chunks = seamWidths.length;
        for (int c = 0; c < chunks; c++) {
            float[] box = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
            double widest = 0;
            double area = 0;
            int others = 0;
            for (int t = c * CHUNK; t < Math.min(triangleCount, (c + 1) * CHUNK); t++) {
                for (int k = 0; k < 3; k++) {
                    int v = triangles[3 * t + k];
                    for (int axis = 0; axis < 3; axis++) {
                        float x = (float) xyz[3 * v + axis];
                        box[axis] = Math.min(box[axis], x);
                        box[3 + axis] = Math.max(box[3 + axis], x);
                    }
                }
                double[] shape = shape(xyz, triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
                if (seams != null && seams.get(t)) {
                    widest = Math.max(widest, shape[1] > 0 ? shape[0] / shape[1] : 0);
                } else {
                    area += shape[0] / 2;
                    others++;
                }
            }
            System.arraycopy(box, 0, chunkBoxes, 6 * c, 6);
            seamWidths[c] = (float) widest;
            faceSizes[c] = others == 0 ? 0 : (float) Math.sqrt(area / others);
        }
    }

    /** Twice the area of triangle (a, b, c) of {@code xyz}, and its longest side. */
    private static double[] shape(double[] xyz, int a, int b, int c) {
        double[] side = new double[9]; // b - a, c - a, c - b
        for (int axis = 0; axis < 3; axis++) {
            side[axis] = xyz[3 * b + axis] - xyz[3 * a + axis];
            side[3 + axis] = xyz[3 * c + axis] - xyz[3 * a + axis];
            side[6 + axis] = xyz[3 * c + axis] - xyz[3 * b + axis];
        }
        double x = side[1] * side[5] - side[2] * side[4];
        double y = side[2] * side[3] - side[0] * side[5];
        double z = side[0] * side[4] - side[1] * side[3];
        double longest = 0;
        for (int k = 0; k < 9; k += 3) {
            longest = Math.max(longest, Math.sqrt(side[k] * side[k] + side[k + 1] * side[k + 1] + side[k + 2] * side[k + 2]));
        }
        return new double[] {Math.sqrt(x * x + y * y + z * z), longest};
    }

    /**
     * The least clip-space w of chunk {@code c}'s box corners (its nearest distance along the
     * view; where a corner is behind the eye, 0), or -1 where the box lies wholly outside one
     * plane of the view volume of {@code clip}.
     */
    private float nearestInView(int c, Matrix4fc clip) {
        int left = 0b111111; // one bit per plane (-x, +x, -y, +y, near, far), cleared once a corner is inside it
        float nearest = Float.MAX_VALUE;
        for (int k = 0; k < 8; k++) {
            float x = chunkBoxes[6 * c + ((k & 1) == 0 ? 0 : 3)];
            float y = chunkBoxes[6 * c + 1 + ((k & 2) == 0 ? 0 : 3)];
            float z = chunkBoxes[6 * c + 2 + ((k & 4) == 0 ? 0 : 3)];
            clip.transform(corner.set(x, y, z, 1f));
            nearest = Math.min(nearest, Math.max(0f, corner.w));
            int outside = 0;
            if (corner.x < -corner.w) {
                outside |= 1;
            }
            if (corner.x > corner.w) {
                outside |= 2;
            }
            if (corner.y < -corner.w) {
                outside |= 4;
            }
            if (corner.y > corner.w) {
                outside |= 8;
            }
            if (corner.z < -corner.w) {
                outside |= 16;
            }
            if (corner.z > corner.w) {
                outside |= 32;
            }
            left &= outside;
        }
        return left != 0 ? -1 : nearest;
    }

    /**
     * Draws the first {@code count} triangles (at most all of them), leaving out the chunks out
     * of the view of {@code clip} (projection × model-view) and the seams of those
     * where they would be narrower than {@link #SEAM_PIXELS} ({@code pixelScale}: pixels a unit
     * at clip w = 1, half the viewport's height times the projection's y scale). Where
     * {@code layered} and the mesh has layers, a chunk drawn whole draws only the triangles not
     * yet covered, and one whose patches are settled and whose faces would be under
     * {@link #PATCH_PIXELS}, its patches instead. Each run drawn sets the uniform {@code base}
     * (-1: none) to the place of its first triangle in the order drawn, so that the shader's
     * triangle is gl_PrimitiveID + base.
     */
    void drawFaces(GL3 gl, int count, Matrix4fc clip, double pixelScale, int base, boolean layered) {
        count = Math.max(0, Math.min(count, triangleCount));
        layered &= byCover != null;
        int chunks = (count + CHUNK - 1) / CHUNK;
        Runs allRuns = new Runs();
        Runs coverRuns = new Runs();
        Runs patchRuns = new Runs();
        BitSet patchesDrawn = layered ? new BitSet() : null;
        for (int step = 0; step < chunks; step++) {
            int c = all.lastFirst ? chunks - 1 - step : step; // in the order of the buffers, for runs to join
            float nearest = nearestInView(c, clip);
            if (nearest < 0) {
                continue;
            }
            double scale = nearest > 0 ? pixelScale / nearest : Double.POSITIVE_INFINITY;
            boolean whole = count >= Math.min(triangleCount, (c + 1) * CHUNK);
            // A chunk in part is never settled: its patches end after it.
            if (layered && count >= settledAt[c] && faceSizes[c] * scale < PATCH_PIXELS) {
                for (int k = chunkPatchStart[c]; k < chunkPatchStart[c + 1]; k++) {
                    patchesDrawn.set(chunkPatches[k]);
                }
                continue;
            }
            boolean withSeams = seamWidths[c] * scale >= SEAM_PIXELS;
            if (layered && whole) {
                coverRuns.add(byCover.start[c], byCover.start[c] + byCover.seen(byCover.start[c], byCover.seamStart[c], count));
                if (withSeams) {
                    coverRuns.add(byCover.seamStart[c], byCover.seamStart[c] + byCover.seen(byCover.seamStart[c], byCover.end[c], count));
                }
                continue;
            }
            int others = all.seamStart[c] - all.start[c];
            int seamCount = all.end[c] - all.seamStart[c];
            if (!whole) { // the last chunk, in part: the first of its others and of its seams
                int seamsBefore = seams == null ? 0 : seams.get(c * CHUNK, count).cardinality();
                others = count - c * CHUNK - seamsBefore;
                seamCount = seamsBefore;
            }
            int first = all.firstOf(all.start[c], all.seamStart[c], others);
            allRuns.add(first, first + others);
            if (withSeams) {
                first = all.firstOf(all.seamStart[c], all.end[c], seamCount);
                allRuns.add(first, first + seamCount);
            }
        }
        if (patchesDrawn != null) {
            for (int p = patchesDrawn.nextSetBit(0); p >= 0; p = patchesDrawn.nextSetBit(p + 1)) {
                patchRuns.add(patchStart[p], patchStart[p + 1]);
            }
        }
        allRuns.draw(gl, all, base);
        coverRuns.draw(gl, byCover, base);
        patchRuns.draw(gl, patches, base);
    }

    /** Ranges of an order to draw, each joined to the one before where they meet. */
    private static final class Runs {
        private int[] ranges = new int[16];
        private int size;

        void add(int first, int end) {
            if (end <= first) {
                return;
            }
            if (size > 0 && ranges[size - 1] == first) {
                ranges[size - 1] = end;
                return;
            }
            if (size + 2 > ranges.length) {
                ranges = java.util.Arrays.copyOf(ranges, 2 * ranges.length);
            }
            ranges[size++] = first;
            ranges[size++] = end;
        }

        void draw(GL3 gl, Order order, int base) {
            if (size == 0) {
                return;
            }
            gl.glActiveTexture(GL3.GL_TEXTURE0);
            gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, order.objects[3]);
            gl.glBindVertexArray(order.objects[0]);
            for (int i = 0; i < size; i += 2) {
                GpuMesh.draw(gl, ranges[i], ranges[i + 1], base);
            }
        }
    }

    private static void draw(GL3 gl, int first, int end, int base) {
        if (end <= first) {
            return;
        }
        if (base >= 0) {
            gl.glUniform1i(base, first);
        }
        gl.glDrawElements(GL3.GL_TRIANGLES, 3 * (end - first), GL3.GL_UNSIGNED_INT, 12L * first);
    }

    /** Draws the edges with their colours bound to texture unit 0. */
    void drawEdges(GL3 gl) {
        gl.glActiveTexture(GL3.GL_TEXTURE0);
        gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, textures[0]);
        gl.glBindVertexArray(arrays[0]);
        gl.glDrawElements(GL3.GL_LINES, 2 * edgeCount, GL3.GL_UNSIGNED_INT, 0);
    }

    void delete(GL3 gl) {
        gl.glDeleteVertexArrays(1, arrays, 0);
        gl.glDeleteBuffers(3, buffers, 0);
        gl.glDeleteTextures(1, textures, 0);
        all.delete(gl);
        if (byCover != null) {
            byCover.delete(gl);
            patches.delete(gl);
            gl.glDeleteBuffers(1, patchPositions, 0);
        }
    }
}
