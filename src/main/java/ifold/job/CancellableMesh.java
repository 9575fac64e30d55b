package ifold.job;

import ifold.mesh.IndexedPolygons;
import java.util.concurrent.atomic.AtomicInteger;

/**
 * A mesh as a writer reads it, which looks at its job's {@link JobWatcher} every
 * {@link #BLOCK} vertices and faces: Cancel then throws out of the writer, which discards its
 * temporary file, and the progress bar moves meanwhile. The writers format blocks of lines on
 * several threads, so the count is shared and the bar may step back by a block or two.
 */
public final class CancellableMesh implements IndexedPolygons {
    /** How often the progress is looked at: a few microseconds a time, against milliseconds of formatting. */
    public static final int BLOCK = 1 << 14;

    private final IndexedPolygons mesh;
    private final JobWatcher watcher;
    /** Blocks of vertices and faces begun. */
    private final AtomicInteger blocks = new AtomicInteger();
    private final int totalBlocks;

    public CancellableMesh(IndexedPolygons mesh, JobWatcher watcher) {
        this.mesh = mesh;
        this.watcher = watcher;
        totalBlocks = (mesh.vertexCount() + BLOCK - 1) / BLOCK + (mesh.faceCount() + BLOCK - 1) / BLOCK;
    }

    private void blockBegins() {
        watcher.stopIfAsked();
        watcher.done(Math.min(blocks.incrementAndGet(), totalBlocks), totalBlocks);
    }

    @Override
    public int vertexCount() {
        return mesh.vertexCount();
    }

    @Override
    public double coordinate(int v, int axis) {
        if (axis == 0 && v % BLOCK == 0) {
            blockBegins();
        }
        return mesh.coordinate(v, axis);
    }

    @Override
    public int faceCount() {
        return mesh.faceCount();
    }

    @Override
    public int faceSize(int f) {
        if (f % BLOCK == 0) {
            blockBegins();
        }
        return mesh.faceSize(f);
    }

    @Override
    public int faceVertex(int f, int k) {
        return mesh.faceVertex(f, k);
    }

    @Override
    public boolean hasFaceColors() {
        return mesh.hasFaceColors();
    }

    @Override
    public int faceColor(int f) {
        return mesh.faceColor(f);
    }
}
