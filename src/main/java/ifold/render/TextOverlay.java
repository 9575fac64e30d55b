package ifold.render;

import com.jogamp.common.nio.Buffers;
import com.jogamp.opengl.GL3;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.nio.ByteBuffer;
import java.util.List;

/**
 * Lines of text drawn over the picture (the status line, the help): rasterised by Java2D into
 * a texture, redrawn only when the text changes, and blended onto a screen-aligned quad.
 */
final class TextOverlay {
    private final GlProgram program;
    private final int[] texture = new int[1];
    private final int[] array = new int[1];
    private final int[] buffer = new int[1];
    private final Font font = new Font(Font.MONOSPACED, Font.PLAIN, 14);
    private List<String> lines = List.of();
    private int textureWidth;
    private int textureHeight;

    TextOverlay(GL3 gl) {
        program = new GlProgram(gl, Shaders.OVERLAY_VERTEX, Shaders.OVERLAY_FRAGMENT);
        gl.glGenTextures(1, texture, 0);
        gl.glGenVertexArrays(1, array, 0);
        gl.glGenBuffers(1, buffer, 0);
    }

    /**
     * Draws {@code text} in a dark box at the bottom-left ({@code atTop} false) or top-left of a
     * view {@code width} by {@code height}.
     */
    void draw(GL3 gl, List<String> text, boolean atTop, int width, int height) {
        if (text.isEmpty()) {
            return;
        }
        if (!text.equals(lines)) {
            upload(gl, text);
            lines = List.copyOf(text);
        }
        float x0 = -1 + 2f * 8 / width;
        float x1 = x0 + 2f * textureWidth / width;
        float y0 = atTop ? 1 - 2f * (8 + textureHeight) / height : -1 + 2f * 8 / height;
        float y1 = y0 + 2f * textureHeight / height;
        float[] quad = {x0, y0, 0, 1, x1, y0, 1, 1, x1, y1, 1, 0, x0, y0, 0, 1, x1, y1, 1, 0, x0, y1, 0, 0};
        gl.glBindVertexArray(array[0]);
        gl.glBindBuffer(GL3.GL_ARRAY_BUFFER, buffer[0]);
        gl.glBufferData(GL3.GL_ARRAY_BUFFER, 4L * quad.length, Buffers.newDirectFloatBuffer(quad), GL3.GL_STREAM_DRAW);
        gl.glEnableVertexAttribArray(0);
        gl.glVertexAttribPointer(0, 2, GL3.GL_FLOAT, false, 16, 0);
        gl.glEnableVertexAttribArray(1);
        gl.glVertexAttribPointer(1, 2, GL3.GL_FLOAT, false, 16, 8);
        gl.glUseProgram(program.id);
        gl.glActiveTexture(GL3.GL_TEXTURE0);
        gl.glBindTexture(GL3.GL_TEXTURE_2D, texture[0]);
        gl.glUniform1i(program.uniform(gl, "image"), 0);
        gl.glDisable(GL3.GL_DEPTH_TEST);
        gl.glEnable(GL3.GL_BLEND);
        gl.glBlendFunc(GL3.GL_SRC_ALPHA, GL3.GL_ONE_MINUS_SRC_ALPHA);
        gl.glDrawArrays(GL3.GL_TRIANGLES, 0, 6);
        gl.glDisable(GL3.GL_BLEND);
        gl.glEnable(GL3.GL_DEPTH_TEST);
        gl.glBindVertexArray(0);
        gl.glUseProgram(0);
    }

    private void upload(GL3 gl, List<String> text) {
        BufferedImage probe = new BufferedImage(1, 1, BufferedImage.TYPE_INT_ARGB);
        Graphics2D g = probe.createGraphics();
        FontMetrics metrics = g.getFontMetrics(font);
        g.dispose();
        int lineHeight = metrics.getHeight();
        int widest = 1;
        for (String line : text) {
            widest = Math.max(widest, metrics.stringWidth(line));
        }
        textureWidth = widest + 16;
        textureHeight = lineHeight * text.size() + 10;
        BufferedImage image = new BufferedImage(textureWidth, textureHeight, BufferedImage.TYPE_INT_ARGB);
        g = image.createGraphics();
        g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
        g.setColor(new Color(0, 0, 0, 170));
        g.fillRoundRect(0, 0, textureWidth, textureHeight, 10, 10);
        g.setColor(Color.WHITE);
        g.setFont(font);
        for (int i = 0; i < text.size(); i++) {
            g.drawString(text.get(i), 8, 5 + metrics.getAscent() + i * lineHeight);
        }
        g.dispose();
        int[] argb = image.getRGB(0, 0, textureWidth, textureHeight, null, 0, textureWidth);
        ByteBuffer rgba = Buffers.newDirectByteBuffer(4 * argb.length);
        for (int pixel : argb) {
            rgba.put((byte) (pixel >>> 16)).put((byte) (pixel >>> 8)).put((byte) pixel).put((byte) (pixel >>> 24));
        }
        rgba.flip();
        gl.glBindTexture(GL3.GL_TEXTURE_2D, texture[0]);
        gl.glPixelStorei(GL3.GL_UNPACK_ALIGNMENT, 1);
        gl.glTexImage2D(GL3.GL_TEXTURE_2D, 0, GL3.GL_RGBA8, textureWidth, textureHeight, 0, GL3.GL_RGBA, GL3.GL_UNSIGNED_BYTE, rgba);
        gl.glTexParameteri(GL3.GL_TEXTURE_2D, GL3.GL_TEXTURE_MIN_FILTER, GL3.GL_NEAREST);
        gl.glTexParameteri(GL3.GL_TEXTURE_2D, GL3.GL_TEXTURE_MAG_FILTER, GL3.GL_NEAREST);
    }

    void delete(GL3 gl) {
        gl.glDeleteTextures(1, texture, 0);
        gl.glDeleteVertexArrays(1, array, 0);
        gl.glDeleteBuffers(1, buffer, 0);
        program.delete(gl);
    }
}
