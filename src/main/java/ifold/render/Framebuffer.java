package ifold.render;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL3;
import java.nio.ByteBuffer;

/**
 * A multisampled framebuffer to draw into and a plain one to resolve it to, so that frames are
 * antialiased the same way on every driver, whether or not the window or the offscreen
 * drawable was granted multisampling. Also reads back integer pictures (triangle indices).
 */
final class Framebuffer {
    final int width;
    final int height;
    private final int[] framebuffers = new int[2];
    private final int[] renderbuffers = new int[3];
    private final ByteBuffer pixels;

    /**
     * @param samples samples per pixel wanted for antialiasing (0 or 1 for none); the driver's
     *     maximum caps it
     */
    Framebuffer(GL3 gl, int width, int height, int samples) {
        this.width = width;
        this.height = height;
        int[] maxSamples = new int[1];
        gl.glGetIntegerv(GL3.GL_MAX_SAMPLES, maxSamples, 0);
        samples = Math.min(samples, Math.max(0, maxSamples[0]));
        gl.glGenFramebuffers(2, framebuffers, 0);
        gl.glGenRenderbuffers(3, renderbuffers, 0);
        gl.glBindFramebuffer(GL3.GL_FRAMEBUFFER, framebuffers[0]);
        gl.glBindRenderbuffer(GL3.GL_RENDERBUFFER, renderbuffers[0]);
        gl.glRenderbufferStorageMultisample(GL3.GL_RENDERBUFFER, samples, GL3.GL_RGBA8, width, height);
        gl.glFramebufferRenderbuffer(GL3.GL_FRAMEBUFFER, GL3.GL_COLOR_ATTACHMENT0, GL3.GL_RENDERBUFFER, renderbuffers[0]);
        gl.glBindRenderbuffer(GL3.GL_RENDERBUFFER, renderbuffers[1]);
        gl.glRenderbufferStorageMultisample(GL3.GL_RENDERBUFFER, samples, GL3.GL_DEPTH_COMPONENT24, width, height);
        gl.glFramebufferRenderbuffer(GL3.GL_FRAMEBUFFER, GL3.GL_DEPTH_ATTACHMENT, GL3.GL_RENDERBUFFER, renderbuffers[1]);
        check(gl, "multisampled");
        gl.glBindFramebuffer(GL3.GL_FRAMEBUFFER, framebuffers[1]);
        gl.glBindRenderbuffer(GL3.GL_RENDERBUFFER, renderbuffers[2]);
        gl.glRenderbufferStorage(GL3.GL_RENDERBUFFER, GL3.GL_RGBA8, width, height);
        gl.glFramebufferRenderbuffer(GL3.GL_FRAMEBUFFER, GL3.GL_COLOR_ATTACHMENT0, GL3.GL_RENDERBUFFER, renderbuffers[2]);
        check(gl, "resolve");
        gl.glBindFramebuffer(GL3.GL_FRAMEBUFFER, 0);
        pixels = Buffers.newDirectByteBuffer(3 * width * height);
    }

    private static void check(GL3 gl, String which) {
        int status = gl.glCheckFramebufferStatus(GL3.GL_FRAMEBUFFER);
        if (status != GL3.GL_FRAMEBUFFER_COMPLETE) {
            throw new IllegalStateException("the " + which + " framebuffer is incomplete (status 0x" + Integer.toHexString(status) + ")");
        }
    }

    /** Makes this the target of drawing. */
    void bind(GL3 gl) {
        gl.glBindFramebuffer(GL3.GL_FRAMEBUFFER, framebuffers[0]);
    }

    /** Resolves the samples and reads the picture: RGB rows, top first. */
    byte[] read(GL3 gl) {
        return read(gl, new byte[3 * width * height]);
    }

    /** Like {@link #read(GL3)}, into {@code rgb} (3 bytes a pixel). */
    byte[] read(GL3 gl, byte[] rgb) {
        resolveAndRead(gl);
        // GL's rows start at the bottom; pictures start at the top.
        int stride = 3 * width;
        for (int y = 0; y < height; y++) {
            pixels.position((height - 1 - y) * stride);
            pixels.get(rgb, y * stride, stride);
        }
        return rgb;
    }

    /** Copies the drawn picture to the plain framebuffer (resolving samples) and reads it into {@link #pixels}, bottom row first. */
    private void resolveAndRead(GL3 gl) {
        gl.glBindFramebuffer(GL3.GL_READ_FRAMEBUFFER, framebuffers[0]);
        gl.glBindFramebuffer(GL3.GL_DRAW_FRAMEBUFFER, framebuffers[1]);
        gl.glBlitFramebuffer(0, 0, width, height, 0, 0, width, height, GL3.GL_COLOR_BUFFER_BIT, GL3.GL_NEAREST);
        gl.glBindFramebuffer(GL3.GL_READ_FRAMEBUFFER, framebuffers[1]);
        gl.glPixelStorei(GL3.GL_PACK_ALIGNMENT, 1);
        pixels.clear();
        gl.glReadPixels(0, 0, width, height, GL3.GL_RGB, GL3.GL_UNSIGNED_BYTE, pixels);
        gl.glBindFramebuffer(GL3.GL_FRAMEBUFFER, 0);
    }

    /**
     * Reads the plain framebuffer without resolving: for pictures drawn with one sample, whose
     * pixels are data (a triangle index in the red, green and blue bytes) rather than colours.
     * Returns one int per pixel, rows top first.
     */
    int[] readIndices(GL3 gl) {
        resolveAndRead(gl);
        int[] indices = new int[width * height];
        for (int y = 0; y < height; y++) {
            int row = (height - 1 - y) * 3 * width;
            for (int x = 0; x < width; x++) {
                int i = row + 3 * x;
                indices[y * width + x] = (pixels.get(i) & 0xFF) << 16 | (pixels.get(i + 1) & 0xFF) << 8 | (pixels.get(i + 2) & 0xFF);
            }
        }
        return indices;
    }

    void delete(GL3 gl) {
        gl.glDeleteFramebuffers(2, framebuffers, 0);
        gl.glDeleteRenderbuffers(3, renderbuffers, 0);
    }
}
