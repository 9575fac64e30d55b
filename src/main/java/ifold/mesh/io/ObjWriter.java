package ifold.mesh.io;

import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Writes a Wavefront OBJ file: a comment header, one {@code v x y z} line per vertex, then one
 * {@code f} line per face in the mesh's face order, with 1-based indices. OBJ has no standard
 * per-face colour, so colours are not written; the header says so when the mesh has them.
 */
public final class ObjWriter {
    private ObjWriter() {
    }

    /**
     * Writes {@code mesh} to {@code file} all or nothing (see the class comment of
     * {@link MeshWriters}).
     *
     * @throws IllegalArgumentException when a coordinate is not finite, or a face has fewer than
     *         3 vertices or an index outside the vertices: no reader would accept the file
     * @throws IOException when the file cannot be written; {@code file} is then unchanged
     */
    public static void write(IndexedPolygons mesh, Path file) throws IOException {
        AsciiOutput.writeAtomically(file, out -> writeTo(mesh, out));
    }

    private static void writeTo(IndexedPolygons mesh, AsciiOutput out) throws IOException {
        int vertexCount = mesh.vertexCount();
        int faceCount = mesh.faceCount();
        out.writeAscii("# iFold: ");
        out.writeLong(vertexCount);
        out.writeAscii(" vertices, ");
        out.writeLong(faceCount);
        out.writeAscii(" faces\n");
        if (mesh.hasFaceColors()) {
            out.writeAscii("# face colours not written: OBJ has no standard per-face colour\n");
        }
        out.writeLines(vertexCount, (block, v) -> {
            block.writeAscii("v ");
            MeshWriters.writeVertex(mesh, v, block);
        });
        out.writeLines(faceCount, (block, f) -> {
            int size = MeshWriters.checkedFaceSize(mesh, f);
            block.writeByte('f');
            for (int k = 0; k < size; k++) {
                block.writeByte(' ');
                block.writeLong(MeshWriters.checkedFaceVertex(mesh, f, k) + 1L);
            }
            block.writeByte('\n');
        });
    }
}
