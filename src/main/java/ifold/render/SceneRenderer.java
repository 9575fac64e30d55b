package ifold.render;

import com.jogamp.opengl.GL3;
import ifold.scene.Geometry;
import ifold.scene.Light;
import ifold.scene.Material;
import ifold.scene.Scene;
import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Vector3f;

/**
 * Draws a {@link Scene} with the OpenGL 3.3 core profile. Keeps the GL buffers of each
 * geometry and uploads them again only when the geometry's version moved. Faces are pushed back
 * a little (polygon offset) so that edges drawn over them win the depth test.
 */
public final class SceneRenderer {
    private GlProgram faceProgram;
    private GlProgram edgeProgram;
    private GlProgram indexProgram;
    private final Map<Geometry, GpuMesh> uploaded = new IdentityHashMap<>();
    private final float[] matrix = new float[16];
    private int uploads;

    /** Compiles the shaders; call on the GL thread with the context current. */
    public void init(GL3 gl) {
        faceProgram = new GlProgram(gl, Shaders.FACE_VERTEX, Shaders.FACE_FRAGMENT);
        edgeProgram = new GlProgram(gl, Shaders.EDGE_VERTEX, Shaders.EDGE_FRAGMENT);
        indexProgram = new GlProgram(gl, Shaders.EDGE_VERTEX, Shaders.INDEX_FRAGMENT);
    }

    /** How many meshes have been uploaded so far (a geometry whose version moved counts again). */
    public int uploads() {
        return uploads;
    }

    public void render(GL3 gl, Scene scene, int width, int height) {
        draw(gl, scene, width, height, false);
    }

    /**
     * Draws, instead of colours, the index of the triangle seen at each pixel plus one (0 where
     * there is none), packed into red, green and blue. Read it with one sample per pixel.
     */
    public void renderIndices(GL3 gl, Scene scene, int width, int height) {
        draw(gl, scene, width, height, true);
    }

    private void draw(GL3 gl, Scene scene, int width, int height, boolean indices) {
        int background = indices ? 0 : scene.background();
        gl.glViewport(0, 0, width, height);
        gl.glClearColor(channel(background, 16), channel(background, 8), channel(background, 0), 1f);
        gl.glClear(GL3.GL_COLOR_BUFFER_BIT | GL3.GL_DEPTH_BUFFER_BIT);
        gl.glEnable(GL3.GL_DEPTH_TEST);
        gl.glEnable(GL3.GL_MULTISAMPLE);

        Matrix4d view = scene.camera().viewMatrix(new Matrix4d());
        Matrix4f projection = new Matrix4f(scene.camera().projectionMatrix((double) width / Math.max(1, height), new Matrix4d()));
        List<Geometry> geometries = new ArrayList<>();
        scene.root().visitGeometry(geometries::add);
        // What lies under others is drawn after them, what is seen through everything last, over
        // what is already there.
        geometries.sort(java.util.Comparator.comparing(Geometry::isSeenThrough).thenComparing(Geometry::isUnder));
        for (Geometry geometry : geometries) {
            GpuMesh mesh = uploaded.get(geometry);
            if (mesh == null || mesh.version != geometry.version()) {
                if (mesh != null) {
                    mesh.delete(gl);
                }
                mesh = new GpuMesh(gl, geometry.mesh(), geometry.version());
                uploaded.put(geometry, mesh);
                uploads++;
            }
            Matrix4f modelView = new Matrix4f(new Matrix4d(view).mul(geometry.worldTransform()));
            if (indices) {
                drawIndices(gl, geometry, mesh, modelView, projection, height);
                continue;
            }
            if (geometry.isSeenThrough()) {
                gl.glDisable(GL3.GL_DEPTH_TEST);
            }
            drawFaces(gl, scene, geometry, mesh, modelView, projection, height);
            if (geometry.material().showEdges()) {
                drawEdges(gl, mesh, modelView, projection);
            }
            gl.glEnable(GL3.GL_DEPTH_TEST);
        }
        // Forget geometry that left the scene.
        uploaded.entrySet().removeIf(entry -> {
            if (!geometries.contains(entry.getKey())) {
                entry.getValue().delete(gl);
                return true;
            }
            return false;
        });
        gl.glBindVertexArray(0);
        gl.glUseProgram(0);
    }

    private void drawFaces(GL3 gl, Scene scene, Geometry geometry, GpuMesh mesh, Matrix4f modelView, Matrix4f projection, int height) {
        Material material = geometry.material();
        gl.glUseProgram(faceProgram.id);
        gl.glUniformMatrix4fv(faceProgram.uniform(gl, "modelView"), 1, false, modelView.get(matrix), 0);
        gl.glUniformMatrix4fv(faceProgram.uniform(gl, "projection"), 1, false, projection.get(matrix), 0);
        List<Light> lights = scene.lights();
        float[] directions = new float[6];
        float[] intensities = new float[2];
        for (int i = 0; i < Math.min(2, lights.size()); i++) {
            Vector3f d = new Vector3f(lights.get(i).direction());
            directions[3 * i] = d.x;
            directions[3 * i + 1] = d.y;
            directions[3 * i + 2] = d.z;
            intensities[i] = (float) lights.get(i).intensity();
        }
        gl.glUniform3fv(faceProgram.uniform(gl, "lightDirection"), 2, directions, 0);
        gl.glUniform1fv(faceProgram.uniform(gl, "lightIntensity"), 2, intensities, 0);
        gl.glUniform1f(faceProgram.uniform(gl, "ambient"), (float) scene.ambient());
        setColor(gl, faceProgram.uniform(gl, "frontColor"), material.front());
        setColor(gl, faceProgram.uniform(gl, "backColor"), material.back());
        setColor(gl, faceProgram.uniform(gl, "hiddenColor"), geometry.hiddenColor());
        gl.glUniform1i(faceProgram.uniform(gl, "useFaceColors"), material.useFaceColors() ? 1 : 0);
        // A clear hidden colour: the triangles not yet revealed are not there, and are not drawn.
        boolean hiddenNotThere = (geometry.hiddenColor() >>> 24) == 0;
        gl.glUniform1i(faceProgram.uniform(gl, "revealed"), hiddenNotThere ? Integer.MAX_VALUE : geometry.revealed());
        gl.glUniform1i(faceProgram.uniform(gl, "triangleColors"), 0);
        gl.glEnable(GL3.GL_POLYGON_OFFSET_FILL);
        gl.glPolygonOffset(1f, 1f);
        if (geometry.isClosed()) {
            gl.glEnable(GL3.GL_CULL_FACE);
            gl.glCullFace(GL3.GL_BACK);
        }
        mesh.drawFaces(gl, hiddenNotThere ? geometry.revealed() : Integer.MAX_VALUE, new Matrix4f(projection).mul(modelView),
                0.5 * height * projection.m11(), faceProgram.uniform(gl, "primitiveBase"), hiddenNotThere);
        gl.glDisable(GL3.GL_CULL_FACE); // paper is seen from both sides
        gl.glDisable(GL3.GL_POLYGON_OFFSET_FILL);
    }

    private void drawIndices(GL3 gl, Geometry geometry, GpuMesh mesh, Matrix4f modelView, Matrix4f projection, int height) {
        gl.glUseProgram(indexProgram.id);
        gl.glUniformMatrix4fv(indexProgram.uniform(gl, "modelView"), 1, false, modelView.get(matrix), 0);
        gl.glUniformMatrix4fv(indexProgram.uniform(gl, "projection"), 1, false, projection.get(matrix), 0);
        if (geometry.isClosed()) {
            gl.glEnable(GL3.GL_CULL_FACE);
            gl.glCullFace(GL3.GL_BACK);
        }
        gl.glDisable(GL3.GL_MULTISAMPLE);
        mesh.drawFaces(gl, Integer.MAX_VALUE, new Matrix4f(projection).mul(modelView), 0.5 * height * projection.m11(),
                indexProgram.uniform(gl, "primitiveBase"), false);
        gl.glEnable(GL3.GL_MULTISAMPLE);
        gl.glDisable(GL3.GL_CULL_FACE);
    }

    private void drawEdges(GL3 gl, GpuMesh mesh, Matrix4f modelView, Matrix4f projection) {
        gl.glUseProgram(edgeProgram.id);
        gl.glUniformMatrix4fv(edgeProgram.uniform(gl, "modelView"), 1, false, modelView.get(matrix), 0);
        gl.glUniformMatrix4fv(edgeProgram.uniform(gl, "projection"), 1, false, projection.get(matrix), 0);
        gl.glUniform1i(edgeProgram.uniform(gl, "edgeColors"), 0);
        mesh.drawEdges(gl);
    }

    private static void setColor(GL3 gl, int location, int argb) {
        gl.glUniform4f(location, channel(argb, 16), channel(argb, 8), channel(argb, 0), channel(argb, 24));
    }

    private static float channel(int argb, int shift) {
        return ((argb >>> shift) & 0xFF) / 255f;
    }

    public void dispose(GL3 gl) {
        for (GpuMesh mesh : uploaded.values()) {
            mesh.delete(gl);
        }
        uploaded.clear();
        if (faceProgram != null) {
            faceProgram.delete(gl);
            edgeProgram.delete(gl);
            indexProgram.delete(gl);
        }
    }
}
