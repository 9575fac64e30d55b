package ifold.render;

import com.jogamp.opengl.GL3;
import com.jogamp.opengl.GLAutoDrawable;
import com.jogamp.opengl.GLCapabilities;
import com.jogamp.opengl.GLContext;
import com.jogamp.opengl.GLDrawableFactory;
import com.jogamp.opengl.GLException;
import ifold.scene.Scene;

/**
 * Renders scenes into pictures without a window, on the calling thread. Needs an X display
 * (Xvfb will do) because JOGL reaches Mesa through GLX.
 */
public final class OffscreenRenderer implements AutoCloseable {
    private final GLAutoDrawable drawable;
    private final SceneRenderer renderer = new SceneRenderer();
    private final Framebuffer framebuffer;
    private Framebuffer indexFramebuffer;
    private final int width;
    private final int height;

    /**
     * @param samples samples per pixel for antialiasing: 4 looks best; 0 costs a software
     *     renderer a half or less of the time, and big meshes have pixel-sized triangles anyway
     */
    public OffscreenRenderer(int width, int height, int samples) throws RenderUnavailableException {
        this.width = width;
        this.height = height;
        GLCapabilities caps = GlContexts.capabilities();
        caps.setOnscreen(false);
        caps.setFBO(true);
        try {
            // The drawable only provides the context; frames go to our own framebuffer.
            drawable = GLDrawableFactory.getFactory(caps.getGLProfile()).createOffscreenAutoDrawable(null, caps, null, 16, 16);
            drawable.display();
        } catch (GLException e) {
            throw new RenderUnavailableException("cannot create an offscreen OpenGL context: " + GlContexts.firstLine(e), e);
        }
        GL3 gl = makeCurrent();
        try {
            renderer.init(gl);
            framebuffer = new Framebuffer(gl, width, height, samples);
        } finally {
            drawable.getContext().release();
        }
    }

    private GL3 makeCurrent() {
        if (drawable.getContext().makeCurrent() == GLContext.CONTEXT_NOT_CURRENT) {
            throw new IllegalStateException("cannot make the offscreen OpenGL context current");
        }
        return drawable.getGL().getGL3();
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }

    /** Renders {@code scene} and returns its picture: RGB rows, top first. */
    public byte[] render(Scene scene) {
        return render(scene, new byte[3 * width * height]);
    }

    /** Renders {@code scene} into {@code rgb} (3 bytes a pixel, rows top first) and returns it. */
    public byte[] render(Scene scene, byte[] rgb) {
        GL3 gl = makeCurrent();
        try {
            framebuffer.bind(gl);
            renderer.render(gl, scene, width, height);
            gl.glFinish();
            return framebuffer.read(gl, rgb);
        } finally {
            drawable.getContext().release();
        }
    }

    /**
     * Renders the index of the triangle seen at each pixel plus one, 0 for the background: one
     * int per pixel, rows top first.
     */
    public int[] renderIndices(Scene scene) {
        GL3 gl = makeCurrent();
        try {
            if (indexFramebuffer == null) {
                indexFramebuffer = new Framebuffer(gl, width, height, 0);
            }
            indexFramebuffer.bind(gl);
            renderer.renderIndices(gl, scene, width, height);
            gl.glFinish();
            return indexFramebuffer.readIndices(gl);
        } finally {
            drawable.getContext().release();
        }
    }

    /** The OpenGL version and renderer, for reports. */
    public String describe() {
        GL3 gl = makeCurrent();
        try {
            return gl.glGetString(GL3.GL_VERSION) + ", " + gl.glGetString(GL3.GL_RENDERER);
        } finally {
            drawable.getContext().release();
        }
    }

    @Override
    public void close() {
        GL3 gl = makeCurrent();
        try {
            framebuffer.delete(gl);
            if (indexFramebuffer != null) {
                indexFramebuffer.delete(gl);
            }
            renderer.dispose(gl);
        } finally {
            drawable.getContext().release();
        }
        drawable.destroy();
    }
}
