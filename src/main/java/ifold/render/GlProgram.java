package ifold.render;

import com.jogamp.opengl.GL3;
import java.nio.IntBuffer;
import java.util.HashMap;
import java.util.Map;

/** A linked GLSL program with its uniform locations looked up once. */
final class GlProgram {
    final int id;
    private final Map<String, Integer> uniforms = new HashMap<>();

    GlProgram(GL3 gl, String vertexSource, String fragmentSource) {
        int vertex = compile(gl, GL3.GL_VERTEX_SHADER, vertexSource);
        int fragment = compile(gl, GL3.GL_FRAGMENT_SHADER, fragmentSource);
        id = gl.glCreateProgram();
        gl.glAttachShader(id, vertex);
        gl.glAttachShader(id, fragment);
        gl.glLinkProgram(id);
        IntBuffer status = IntBuffer.allocate(1);
        gl.glGetProgramiv(id, GL3.GL_LINK_STATUS, status);
        if (status.get(0) == 0) {
            throw new IllegalStateException("GLSL program does not link: " + programLog(gl, id));
        }
        gl.glDeleteShader(vertex);
        gl.glDeleteShader(fragment);
    }

    int uniform(GL3 gl, String name) {
        return uniforms.computeIfAbsent(name, n -> gl.glGetUniformLocation(id, n));
    }

    private static int compile(GL3 gl, int type, String source) {
        int shader = gl.glCreateShader(type);
        gl.glShaderSource(shader, 1, new String[] {source}, null);
        gl.glCompileShader(shader);
        IntBuffer status = IntBuffer.allocate(1);
        gl.glGetShaderiv(shader, GL3.GL_COMPILE_STATUS, status);
        if (status.get(0) == 0) {
            IntBuffer length = IntBuffer.allocate(1);
            gl.glGetShaderiv(shader, GL3.GL_INFO_LOG_LENGTH, length);
            byte[] log = new byte[Math.max(1, length.get(0))];
            gl.glGetShaderInfoLog(shader, log.length, null, 0, log, 0);
            throw new IllegalStateException("GLSL shader does not compile: " + new String(log).trim());
        }
        return shader;
    }

    private static String programLog(GL3 gl, int program) {
        IntBuffer length = IntBuffer.allocate(1);
        gl.glGetProgramiv(program, GL3.GL_INFO_LOG_LENGTH, length);
        byte[] log = new byte[Math.max(1, length.get(0))];
        gl.glGetProgramInfoLog(program, log.length, null, 0, log, 0);
        return new String(log).trim();
    }

    void delete(GL3 gl) {
        gl.glDeleteProgram(id);
    }
}
