package ifold.mesh.io;

import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.file.Path;

/**
 * Writes an ASCII OFF file: header {@code OFF}, the counts, one {@code x y z} line per vertex,
 * then one {@code n i0 .. i(n-1)} line per face in the mesh's face order, with 0-based indices.
 * When the mesh has face colours each face line ends in {@code r g b}, integers 0..255 (alpha
 * is not written). {@link OffReader} reads the file back to the same doubles, faces and colours.
 */
public final class OffWriter {
    private OffWriter() {
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
        boolean colors = mesh.hasFaceColors();
        out.writeAscii("OFF\n");
        out.writeLong(vertexCount);
        out.writeByte(' ');
        out.writeLong(faceCount);
        out.writeAscii(" 0\n");
        out.writeLines(vertexCount, (block, v) -> MeshWriters.writeVertex(mesh, v, block));
        out.writeLines(faceCount, (block, f) -> writeFace(mesh, f, colors, block));
    }

    /** "n i0 .. i(n-1) [r g b]\n": OFF's face line, and an ASCII PLY face with uchar colours alike. */
    static void writeFace(IndexedPolygons mesh, int f, boolean colors, AsciiOutput out) throws IOException {
        int size = MeshWriters.checkedFaceSize(mesh, f);
        out.writeLong(size);
        for (int k = 0; k < size; k++) {
            out.writeByte(' ');
            out.writeLong(MeshWriters.checkedFaceVertex(mesh, f, k));
        }
        if (colors) {
            int argb = mesh.faceColor(f);
            out.writeByte(' ');
            out.writeLong(argb >>> 16 & 0xFF);
            out.writeByte(' ');
            out.writeLong(argb >>> 8 & 0xFF);
            out.writeByte(' ');
            out.writeLong(argb & 0xFF);
        }
        out.writeByte('\n');
    }
}
