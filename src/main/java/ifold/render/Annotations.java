package ifold.render;

import ifold.scene.Scene;
import java.awt.AlphaComposite;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;
import org.joml.Matrix4d;
import org.joml.Vector4d;

/**
 * What a frame says besides its caption: the legend of the scene's colours in the top right
 * corner (a swatch and its meaning a line), and the scene's labels written at the points they
 * name. Drawn into the frame's pixels (rows top first, 3 bytes a pixel) after it is rendered;
 * only the rectangles written on are copied out and back.
 */
final class Annotations {
    private final int width;
    private final int height;
    private final Font font;
    private final Font labelFont;

    Annotations(int width, int height) {
        this.width = width;
        this.height = height;
        // A little smaller than the caption: it is read once, not at every step.
        this.font = new Font(Font.SANS_SERIF, Font.PLAIN, Math.max(11, height / 32));
        this.labelFont = new Font(Font.SANS_SERIF, Font.BOLD, Math.max(13, height / 22));
    }

    /** The legend's box, in pixels: x, y, width, height; empty for no entries. */
    int[] legendBox(List<Scene.Swatch> legend) {
        if (legend.isEmpty()) {
            return new int[4];
        }
        FontMetrics metrics = metrics(font);
        int line = metrics.getHeight();
        int widest = 0;
        for (Scene.Swatch swatch : legend) {
            widest = Math.max(widest, metrics.stringWidth(swatch.meaning()));
        }
        int pad = line / 2;
        int boxWidth = Math.min(width, pad + line + pad + widest + pad);
        int boxHeight = Math.min(height, pad + legend.size() * line + pad / 2);
        return new int[] {width - boxWidth - pad, pad, boxWidth, boxHeight};
    }

    void drawLegend(byte[] rgb, List<Scene.Swatch> legend) {
        if (legend.isEmpty()) {
            return;
        }
        int[] box = legendBox(legend);
        paint(rgb, box[0], box[1], box[2], box[3], g -> {
            FontMetrics metrics = g.getFontMetrics(font);
            int line = metrics.getHeight();
            int pad = line / 2;
            g.setComposite(AlphaComposite.getInstance(AlphaComposite.SRC_OVER, 0.8f));
            g.setColor(Color.WHITE);
            g.fillRoundRect(0, 0, box[2], box[3], pad, pad);
            g.setComposite(AlphaComposite.SrcOver);
            g.setFont(font);
            for (int i = 0; i < legend.size(); i++) {
                Scene.Swatch swatch = legend.get(i);
                int top = pad / 2 + i * line;
                int side = line - 4;
                g.setColor(new Color(swatch.color() & 0xFFFFFF));
                g.fillRect(pad, top + 2, side, side);
                g.setColor(new Color(0x60, 0x68, 0x70));
                g.drawRect(pad, top + 2, side, side); // a cream swatch on white still shows
                g.setColor(new Color(0x20, 0x26, 0x2E));
                g.drawString(swatch.meaning(), pad + line + pad / 2, top + metrics.getAscent());
            }
        });
    }

    /**
     * Writes each label beside its point as the camera sees it in a frame of this size, pushed
     * away from the labels' centre so that a corner's letter sits outside its triangle.
     */
    void drawLabels(byte[] rgb, Scene scene, List<Scene.Label> labels) {
        if (labels.isEmpty()) {
            return;
        }
        double[][] at = project(scene, labels, width, height);
        double cx = 0;
        double cy = 0;
        int seen = 0;
        for (double[] p : at) {
            if (p != null) {
                cx += p[0];
                cy += p[1];
                seen++;
            }
        }
        if (seen == 0) {
            return;
        }
        cx /= seen;
        cy /= seen;
        FontMetrics metrics = metrics(labelFont);
        int size = metrics.getHeight();
        for (int i = 0; i < labels.size(); i++) {
            if (at[i] == null) {
                continue;
            }
            double dx = at[i][0] - cx;
            double dy = at[i][1] - cy;
            double length = Math.hypot(dx, dy);
            double push = 0.9 * size;
            double x = at[i][0] + (length > 0 ? push * dx / length : 0);
            double y = at[i][1] + (length > 0 ? push * dy / length : -push);
            String text = labels.get(i).text();
            int boxWidth = metrics.stringWidth(text) + size / 2;
            int left = (int) Math.round(x - boxWidth / 2.0);
            int top = (int) Math.round(y - size / 2.0);
            paint(rgb, left, top, boxWidth, size, g -> {
                g.setComposite(AlphaComposite.getInstance(AlphaComposite.SRC_OVER, 0.75f));
                g.setColor(Color.WHITE);
                g.fillRoundRect(0, 0, boxWidth, size, size / 2, size / 2);
                g.setComposite(AlphaComposite.SrcOver);
                g.setFont(labelFont);
                g.setColor(new Color(0x1E, 0x8C, 0x3A)); // the triangle's outline green: the letters name its corners
                g.drawString(text, size / 4, metrics.getAscent());
            });
        }
    }

    /** Where each label's point falls in a frame, in pixels from the top left; null where it is behind the camera. */
    static double[][] project(Scene scene, List<Scene.Label> labels, int width, int height) {
        Matrix4d m = scene.camera().projectionMatrix((double) width / height, new Matrix4d())
                .mul(scene.camera().viewMatrix(new Matrix4d()));
        double[][] at = new double[labels.size()][];
        for (int i = 0; i < labels.size(); i++) {
            Scene.Label label = labels.get(i);
            Vector4d p = m.transform(new Vector4d(label.x(), label.y(), label.z(), 1));
            if (p.w > 0) {
                at[i] = new double[] {(p.x / p.w + 1) / 2 * width, (1 - p.y / p.w) / 2 * height};
            }
        }
        return at;
    }

    private static FontMetrics metrics(Font font) {
        BufferedImage probe = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB);
        Graphics2D g = probe.createGraphics();
        try {
            return g.getFontMetrics(font);
        } finally {
            g.dispose();
        }
    }

    /** Paints into the rectangle (clipped to the frame) of the picture, through an image of just that rectangle. */
    private void paint(byte[] rgb, int left, int top, int w, int h, java.util.function.Consumer<Graphics2D> painter) {
        int x0 = Math.max(0, left);
        int y0 = Math.max(0, top);
        int x1 = Math.min(width, left + w);
        int y1 = Math.min(height, top + h);
        if (x1 <= x0 || y1 <= y0) {
            return;
        }
        BufferedImage image = new BufferedImage(w, h, BufferedImage.TYPE_INT_RGB);
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int b = 3 * (y * width + x);
                image.setRGB(x - left, y - top, (rgb[b] & 0xff) << 16 | (rgb[b + 1] & 0xff) << 8 | (rgb[b + 2] & 0xff));
            }
        }
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setRenderingHint(RenderingHints.KEY_ANTIALIASING, RenderingHints.VALUE_ANTIALIAS_ON);
            painter.accept(g);
        } finally {
            g.dispose();
        }
        for (int y = y0; y < y1; y++) {
            for (int x = x0; x < x1; x++) {
                int b = 3 * (y * width + x);
                int pixel = image.getRGB(x - left, y - top);
                rgb[b] = (byte) (pixel >>> 16);
                rgb[b + 1] = (byte) (pixel >>> 8);
                rgb[b + 2] = (byte) pixel;
            }
        }
    }
}
