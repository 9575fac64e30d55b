package ifold.mesh.io;

import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Writes a model file by the extension of its name: {@code .off}, {@code .obj}, {@code .ply} or
 * {@code .stl}, in any case; PLY and STL binary unless asked for text.
 *
 * <p>Every writer writes all or nothing: the bytes go to a temporary file beside the target,
 * which is forced to disk and then renamed over the target (atomically where the file system
 * allows). A failed write deletes the temporary file and leaves an existing target as it was.
 */
public final class MeshWriters {
    private MeshWriters() {
    }

    /** The extensions of the files {@link #write} writes, without their dot. */
    public static final java.util.List<String> EXTENSIONS = java.util.List.of("off", "obj", "ply", "stl");

    /** As {@link #write(IndexedPolygons, Path, boolean)}, PLY and STL binary. */
    public static void write(IndexedPolygons mesh, Path file) throws IOException {
        write(mesh, file, false);
    }

    /**
     * Writes {@code mesh} to {@code file} with {@link OffWriter}, {@link ObjWriter},
     * {@link PlyWriter} or {@link StlWriter}.
     *
     * @param ascii PLY and STL as text rather than binary (OFF and OBJ are text)
     * @throws IllegalArgumentException for a name that ends in none of the extensions, and for a
     *         mesh that no reader would accept (see the writers)
     * @throws IOException when the file cannot be written; {@code file} is then unchanged
     */
    public static void write(IndexedPolygons mesh, Path file, boolean ascii) throws IOException {
        String name = MeshReaders.lowerCaseName(file);
        if (name.endsWith(".off")) {
            OffWriter.write(mesh, file);
        } else if (name.endsWith(".obj")) {
            ObjWriter.write(mesh, file);
        } else if (name.endsWith(".ply")) {
            PlyWriter.write(mesh, file, ascii);
        } else if (name.endsWith(".stl")) {
            StlWriter.write(mesh, file, ascii);
        } else {
            throw new IllegalArgumentException("cannot write " + file + ": expected a name ending in .off, .obj, .ply or .stl");
        }
    }

    /** Whether {@link #write} writes a file of this name: .off, .obj, .ply or .stl, in any case. */
    public static boolean writes(Path file) {
        String name = MeshReaders.lowerCaseName(file);
        return EXTENSIONS.stream().anyMatch(extension -> name.endsWith("." + extension));
    }

    /** Coordinate {@code axis} of vertex {@code v}, refused where it is not finite: no reader would take it. */
    static double finiteCoordinate(IndexedPolygons mesh, int v, int axis) {
        double c = mesh.coordinate(v, axis);
        if (!Double.isFinite(c)) {
            throw new IllegalArgumentException("vertex " + v + " has a non-finite coordinate " + c);
        }
        return c;
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
