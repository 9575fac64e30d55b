package ifold.render;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL3;
import ifold.scene.SceneMesh;
import java.nio.ByteBuffer;

/**
 * The GL buffers of one {@link SceneMesh}: faces as unshared, flat-shaded vertices (position,
 * face normal, colour, the triangle's index for the reveal) and edges as line vertices. Floats
 * are made here, at upload, and nowhere else.
 */
final class GpuMesh {
    private static final int FACE_STRIDE = 32; // 3 floats position, 3 floats normal, 4 bytes colour, 1 float order
    private static final int EDGE_STRIDE = 16; // 3 floats position, 4 bytes colour

    final int version;
    private final int[] arrays = new int[2];
    private final int[] buffers = new int[2];
    final int faceVertices;
    final int edgeVertices;

    GpuMesh(GL3 gl, SceneMesh mesh, int version) {
        this.version = version;
        gl.glGenVertexArrays(2, arrays, 0);
        gl.glGenBuffers(2, buffers, 0);
        faceVertices = 3 * mesh.triangleCount();
        edgeVertices = 2 * mesh.edgeCount();

        ByteBuffer faces = Buffers.newDirectByteBuffer(Math.max(1, faceVertices) * FACE_STRIDE);
        double[] xyz = mesh.positions();
        int[] triangles = mesh.triangles();
        int[] colors = mesh.triangleColors();
        for (int t = 0; t < mesh.triangleCount(); t++) {
            int a = 3 * triangles[3 * t];
            int b = 3 * triangles[3 * t + 1];
            int c = 3 * triangles[3 * t + 2];
            double ux = xyz[b] - xyz[a];
            double uy = xyz[b + 1] - xyz[a + 1];
            double uz = xyz[b + 2] - xyz[a + 2];
            double vx = xyz[c] - xyz[a];
            double vy = xyz[c + 1] - xyz[a + 1];
            double vz = xyz[c + 2] - xyz[a + 2];
            double nx = uy * vz - uz * vy;
            double ny = uz * vx - ux * vz;
            double nz = ux * vy - uy * vx;
            double length = Math.sqrt(nx * nx + ny * ny + nz * nz);
            if (length > 0) {
                nx /= length;
                ny /= length;
                nz /= length;
            }
            for (int k = 0; k < 3; k++) {
                int p = 3 * triangles[3 * t + k];
                faces.putFloat((float) xyz[p]).putFloat((float) xyz[p + 1]).putFloat((float) xyz[p + 2]);
                faces.putFloat((float) nx).putFloat((float) ny).putFloat((float) nz);
                putColor(faces, colors[t]);
                faces.putFloat(t);
            }
        }
        faces.flip();
        gl.glBindVertexArray(arrays[0]);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffers[0]);
        gl.glBufferData(GL3.GL_ARRAY_BUFFER, faces.remaining(), faces, GL3.GL_STATIC_DRAW);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(0, 3, GL3.GL_FLOAT, false, FACE_STRIDE, 0);
        gl.glEnableVertexAttribArray(1);
        gl.glVertexAttribPointer(1, 3, GL3.GL_FLOAT, false, FACE_STRIDE, 12);
        gl.glEnableVertexAttribArray(2);
        gl.glVertexAttribPointer(2, 4, GL3.GL_UNSIGNED_BYTE, true, FACE_STRIDE, 24);
        gl.glEnableVertexAttribArray(3);
        gl.glVertexAttribPointer(3, 1, GL3.GL_FLOAT, false, FACE_STRIDE, 28);

        ByteBuffer lines = Buffers.newDirectByteBuffer(Math.max(1, edgeVertices) * EDGE_STRIDE);
        int[] edges = mesh.edges();
        int[] edgeColors = mesh.edgeColors();
        for (int e = 0; e < mesh.edgeCount(); e++) {
            for (int k = 0; k < 2; k++) {
                int p = 3 * edges[2 * e + k];
                lines.putFloat((float) xyz[p]).putFloat((float) xyz[p + 1]).putFloat((float) xyz[p + 2]);
                putColor(lines, edgeColors[e]);
            }
        }
        lines.flip();
        gl.glBindVertexArray(arrays[1]);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffers[1]);
        gl.glBufferData(GL3.GL_ARRAY_BUFFER, lines.remaining(), lines, GL3.GL_STATIC_DRAW);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(0, 3, GL3.GL_FLOAT, false, EDGE_STRIDE, 0);
        gl.glEnableVertexAttribArray(1);
        gl.glVertexAttribPointer(1, 4, GL3.GL_UNSIGNED_BYTE, true, EDGE_STRIDE, 12);
        gl.glBindVertexArray(0);
    }

    private static void putColor(ByteBuffer buffer, int argb) {
        buffer.put((byte) (argb >>> 16)).put((byte) (argb >>> 8)).put((byte) argb).put((byte) (argb >>> 24));
    }

    void drawFaces(GL3 gl) {
        gl.glBindVertexArray(arrays[0]);
        gl.glDrawArrays(GL3.GL_TRIANGLES, 0, faceVertices);
    }

    void drawEdges(GL3 gl) {
        gl.glBindVertexArray(arrays[1]);
        gl.glDrawArrays(GL3.GL_LINES, 0, edgeVertices);
    }

    void delete(GL3 gl) {
        gl.glDeleteVertexArrays(2, arrays, 0);
        gl.glDeleteBuffers(2, buffers, 0);
    }
}
