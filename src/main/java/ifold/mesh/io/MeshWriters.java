package ifold.mesh.io;

import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Writes a model file by the extension of its name: {@code .off} or {@code .obj}, in any case.
 *
 * <p>Every writer writes all or nothing: the text goes to a temporary file beside the target,
 * which is forced to disk and then renamed over the target (atomically where the file system
 * allows). A failed write deletes the temporary file and leaves an existing target as it was.
 */
public final class MeshWriters {
    private MeshWriters() {
    }

    /**
     * Writes {@code mesh} to {@code file} with {@link OffWriter} or {@link ObjWriter}.
     *
     * @throws IllegalArgumentException for a name that ends in neither extension, and for a mesh
     *         that no reader would accept (see the writers)
     * @throws IOException when the file cannot be written; {@code file} is then unchanged
     */
    public static void write(IndexedPolygons mesh, Path file) throws IOException {
        String name = MeshReaders.lowerCaseName(file);
        if (name.endsWith(".off")) {
            OffWriter.write(mesh, file);
        } else if (name.endsWith(".obj")) {
            ObjWriter.write(mesh, file);
        } else {
            throw new IllegalArgumentException("cannot write " + file + ": expected a name ending in .off or .obj");
        }
    }

    /** Whether {@link #write} writes a file of this name: .off or .obj, in any case (STL is read, not yet written). */
    public static boolean writes(Path file) {
        String name = MeshReaders.lowerCaseName(file);
        return name.endsWith(".off") || name.endsWith(".obj");
    }

    /** Writes "x y z\n" for vertex {@code v}. */
    static void writeVertex(IndexedPolygons mesh, int v, AsciiOutput out) throws IOException {
        for (int axis = 0; axis < 3; axis++) {
            double c = mesh.coordinate(v, axis);
            if (!Double.isFinite(c)) {
                throw new IllegalArgumentException("vertex " + v + " has a non-finite coordinate " + c);
            }
            if (axis > 0) {
                out.writeByte(' ');
            }
            out.writeDouble(c);
        }
        out.writeByte('\n');
    }

    static int checkedFaceSize(IndexedPolygons mesh, int f) {
        int size = mesh.faceSize(f);
        if (size < 3) {
            throw new IllegalArgumentException("face " + f + " has " + size + " vertices, need at least 3");
        }
        return size;
    }

    static int checkedFaceVertex(IndexedPolygons mesh, int f, int k) {
        int v = mesh.faceVertex(f, k);
        if (v < 0 || v >= mesh.vertexCount()) {
            throw new IllegalArgumentException("face " + f + " has vertex index " + v + ", outside 0 to "
                    + (mesh.vertexCount() - 1));
        }
        return v;
    }
}
