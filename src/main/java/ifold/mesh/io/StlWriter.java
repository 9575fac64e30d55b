package ifold.mesh.io;

import ifold.io.AtomicFile;
import ifold.mesh.IndexedPolygons;
import java.io.IOException;
import java.nio.ByteOrder;
import java.nio.file.Path;
import java.util.Locale;

/**
 * Writes STL, for printers and slicers: binary by default, ASCII on request. STL holds
 * triangles of single-precision corners, each with its own copy of the corners and a unit
 * normal (by the right-hand rule over the corners' order: outwards for a mesh oriented as iFold
 * keeps them); a face of more than three corners is fanned from its first, which is right for
 * the convex faces iFold writes. Colours are not written: STL has no standard place for them.
 * {@link StlReader} welds the corners back into the same vertices.
 */
public final class StlWriter {
    private static final int HEADER = 80;

    private StlWriter() {
    }

    /**
     * Writes {@code mesh} to {@code file} all or nothing (see {@link MeshWriters}).
     *
     * @param ascii text rather than binary
     * @throws IllegalArgumentException when a coordinate is not finite, or a face has fewer than
     *         3 vertices or an index outside the vertices
     */
    public static void write(IndexedPolygons mesh, Path file, boolean ascii) throws IOException {
        long triangles = 0;
        for (int f = 0; f < mesh.faceCount(); f++) {
            triangles += MeshWriters.checkedFaceSize(mesh, f) - 2;
        }
        if (triangles > 0xFFFFFFFFL) {
            throw new IllegalArgumentException(triangles + " triangles: more than a binary STL's count holds");
        }
        long count = triangles;
        AtomicFile.write(file, stream -> {
            BinaryOutput out = new BinaryOutput(stream, ByteOrder.LITTLE_ENDIAN);
            if (ascii) {
                out.writeAscii("solid ifold\n");
            } else {
                // A header that does not begin with "solid", so that no reader takes it for text.
                String text = "binary STL written by iFold";
                out.writeAscii(text);
                for (int i = text.length(); i < HEADER; i++) {
                    out.writeByte(' ');
                }
                out.writeInt((int) count);
            }
            float[] corner = new float[9];
            for (int f = 0; f < mesh.faceCount(); f++) {
                int size = mesh.faceSize(f);
                for (int k = 1; k + 1 < size; k++) {
                    int[] vertices = {MeshWriters.checkedFaceVertex(mesh, f, 0), MeshWriters.checkedFaceVertex(mesh, f, k),
                            MeshWriters.checkedFaceVertex(mesh, f, k + 1)};
                    for (int c = 0; c < 3; c++) {
                        for (int axis = 0; axis < 3; axis++) {
                            corner[3 * c + axis] = (float) MeshWriters.finiteCoordinate(mesh, vertices[c], axis);
                        }
                    }
                    float[] normal = normal(corner);
                    if (ascii) {
                        out.writeAscii(String.format(Locale.ROOT, "facet normal %s %s %s\nouter loop\n", normal[0], normal[1], normal[2]));
                        for (int c = 0; c < 3; c++) {
                            // Float.toString reads back to the same float.
                            out.writeAscii("vertex " + corner[3 * c] + " " + corner[3 * c + 1] + " " + corner[3 * c + 2] + "\n");
                        }
                        out.writeAscii("endloop\nendfacet\n");
                    } else {
                        for (float n : normal) {
                            out.writeFloat(n);
                        }
                        for (float x : corner) {
                            out.writeFloat(x);
                        }
                        out.writeShort(0);
                    }
                }
            }
            if (ascii) {
                out.writeAscii("endsolid ifold\n");
            }
            out.flush();
        }, true);
    }

    /** The unit normal of a triangle's corners (x, y, z thrice), in doubles; zero for a degenerate one. */
    private static float[] normal(float[] c) {
        double ux = c[3] - c[0];
        double uy = c[4] - c[1];
        double uz = c[5] - c[2];
        double vx = c[6] - c[0];
        double vy = c[7] - c[1];
        double vz = c[8] - c[2];
        double nx = uy * vz - uz * vy;
        double ny = uz * vx - ux * vz;
        double nz = ux * vy - uy * vx;
        double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
        return length == 0 || !Double.isFinite(length) ? new float[3]
                : new float[] {(float) (nx / length), (float) (ny / length), (float) (nz / length)};
    }
}
