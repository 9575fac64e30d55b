package ifold.mesh.io;

import ifold.io.AtomicFile;
import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Path;

/**
 * Writes PLY: binary little-endian by default (what scanners' tools and libraries read
 * fastest), ASCII on request. Vertices as doubles, so that {@link PlyReader} reads back the
 * same coordinates bit for bit; faces as a list of {@code int} indices with a {@code uchar}
 * count ({@code int} where a face has more than 255 corners); face colours, where the mesh has
 * them, as {@code uchar} red, green and blue, as the OFF writer writes them.
 */
public final class PlyWriter {
    private PlyWriter() {
    }

    /**
     * Writes {@code mesh} to {@code file} all or nothing (see {@link MeshWriters}).
     *
     * @param ascii text rather than binary
     * @throws IllegalArgumentException when a coordinate is not finite, or a face has fewer than
     *         3 vertices or an index outside the vertices
     */
    public static void write(IndexedPolygons mesh, Path file, boolean ascii) throws IOException {
        int faceCount = mesh.faceCount();
        int most = 0;
        for (int f = 0; f < faceCount; f++) {
            most = Math.max(most, MeshWriters.checkedFaceSize(mesh, f));
        }
        boolean byteCounts = most <= 255;
        String countType = byteCounts ? "uchar" : "int";
        boolean colors = mesh.hasFaceColors();
        StringBuilder header = new StringBuilder("ply\nformat ").append(ascii ? "ascii" : "binary_little_endian").append(" 1.0\n")
                .append("comment written by iFold\n")
                .append("element vertex ").append(mesh.vertexCount()).append('\n')
                .append("property double x\nproperty double y\nproperty double z\n")
                .append("element face ").append(faceCount).append('\n')
                .append("property list ").append(countType).append(" int vertex_indices\n");
        if (colors) {
            header.append("property uchar red\nproperty uchar green\nproperty uchar blue\n");
        }
        header.append("end_header\n");
        if (ascii) {
            AsciiOutput.writeAtomically(file, out -> {
                out.writeAscii(header.toString());
                out.writeLines(mesh.vertexCount(), (block, v) -> MeshWriters.writeVertex(mesh, v, block));
                out.writeLines(faceCount, (block, f) -> OffWriter.writeFace(mesh, f, colors, block));
            });
            return;
        }
        AtomicFile.write(file, stream -> {
            BinaryOutput out = new BinaryOutput(stream, ByteOrder.LITTLE_ENDIAN);
            out.writeAscii(header.toString());
            for (int v = 0; v < mesh.vertexCount(); v++) {
                for (int axis = 0; axis < 3; axis++) {
                    out.writeDouble(MeshWriters.finiteCoordinate(mesh, v, axis));
                }
            }
            for (int f = 0; f < faceCount; f++) {
                int size = mesh.faceSize(f);
                if (byteCounts) {
                    out.writeByte(size);
                } else {
                    out.writeInt(size);
                }
                for (int k = 0; k < size; k++) {
                    out.writeInt(MeshWriters.checkedFaceVertex(mesh, f, k));
                }
                if (colors) {
                    int argb = mesh.faceColor(f);
                    out.writeByte(argb >>> 16);
                    out.writeByte(argb >>> 8);
                    out.writeByte(argb);
                }
            }
            out.flush();
        }, true);
    }
}
