package ifold.render;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL3;
import ifold.scene.SceneMesh;
import java.nio.ByteBuffer;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;

/**
 * The GL objects of one {@link SceneMesh}: shared vertex positions, triangle and edge index
 * buffers, and the colours of triangles and edges as buffer textures read by primitive index.
 * Floats are made here, at upload, and nowhere else.
 */
final class GpuMesh {
    final int version;
    private final int[] arrays = new int[2];
    /** positions, triangle indices, edge indices, triangle colours, edge colours */
    private final int[] buffers = new int[5];
    /** triangle colours, edge colours */
    private final int[] textures = new int[2];
    final int triangleCount;
    final int edgeCount;

    GpuMesh(GL3 gl, SceneMesh mesh, int version) {
        this.version = version;
        triangleCount = mesh.triangleCount();
        edgeCount = mesh.edgeCount();
        gl.glGenVertexArrays(2, arrays, 0);
        gl.glGenBuffers(5, buffers, 0);
        gl.glGenTextures(2, textures, 0);

        double[] xyz = mesh.positions();
        FloatBuffer positions = Buffers.newDirectFloatBuffer(Math.max(3, xyz.length));
        for (double coordinate : xyz) {
            positions.put((float) coordinate);
        }
        positions.flip();
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffers[0]);
        gl.glBufferData(GL3.GL_ARRAY_BUFFER, 4L * positions.remaining(), positions, GL3.GL_STATIC_DRAW);

        bindArray(gl, 0, buffers[1], mesh.triangles());
        bindArray(gl, 1, buffers[2], mesh.edges());
        colorTexture(gl, 0, buffers[3], mesh.triangleColors());
        colorTexture(gl, 1, buffers[4], mesh.edgeColors());
        gl.glBindVertexArray(0);
    }

    /** A vertex array reading the shared positions through {@code indices}. */
    private void bindArray(GL3 gl, int which, int indexBuffer, int[] indices) {
        gl.glBindVertexArray(arrays[which]);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffers[0]);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(0, 3, GL3.GL_FLOAT, false, 12, 0);
        gl.glBindBuffer(GL3.GL_ELEMENT_ARRAY_BUFFER, indexBuffer);
        IntBuffer data = Buffers.newDirectIntBuffer(Math.max(1, indices.length));
        data.put(indices).flip();
        gl.glBufferData(GL3.GL_ELEMENT_ARRAY_BUFFER, 4L * Math.max(1, indices.length), data, GL3.GL_STATIC_DRAW);
    }

    private void colorTexture(GL3 gl, int which, int buffer, int[] argb) {
        ByteBuffer rgba = Buffers.newDirectByteBuffer(4 * Math.max(1, argb.length));
        for (int color : argb) {
            rgba.put((byte) (color >>> 16)).put((byte) (color >>> 8)).put((byte) color).put((byte) (color >>> 24));
        }
        rgba.rewind();
        gl.glBindBuffer(GL3.GL_TEXTURE_BUFFER, buffer);
        gl.glBufferData(GL3.GL_TEXTURE_BUFFER, rgba.capacity(), rgba, GL3.GL_STATIC_DRAW);
        gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, textures[which]);
        gl.glTexBuffer(GL3.GL_TEXTURE_BUFFER, GL3.GL_RGBA8, buffer);
        gl.glBindBuffer(GL3.GL_TEXTURE_BUFFER, 0);
    }

    /** Draws the triangles with their colours bound to texture unit 0. */
    void drawFaces(GL3 gl) {
        drawFaces(gl, triangleCount);
    }

    /** Draws the first {@code count} triangles (at most all of them). */
    void drawFaces(GL3 gl, int count) {
        gl.glActiveTexture(GL3.GL_TEXTURE0);
        gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, textures[0]);
        gl.glBindVertexArray(arrays[0]);
        gl.glDrawElements(GL3.GL_TRIANGLES, 3 * Math.max(0, Math.min(count, triangleCount)), GL3.GL_UNSIGNED_INT, 0);
    }

    /** Draws the edges with their colours bound to texture unit 0. */
    void drawEdges(GL3 gl) {
        gl.glActiveTexture(GL3.GL_TEXTURE0);
        gl.glBindTexture(GL3.GL_TEXTURE_BUFFER, textures[1]);
        gl.glBindVertexArray(arrays[1]);
        gl.glDrawElements(GL3.GL_LINES, 2 * edgeCount, GL3.GL_UNSIGNED_INT, 0);
    }

    void delete(GL3 gl) {
        gl.glDeleteVertexArrays(2, arrays, 0);
        gl.glDeleteBuffers(5, buffers, 0);
        gl.glDeleteTextures(2, textures, 0);
    }
}
