package ifold.render;

import java.awt.AlphaComposite;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;

/**
 * A caption along the bottom of a frame: the step shown, in white on a dark translucent band,
 * large enough to read at 640×360 (a twenty-fourth of the frame's height, 13 pixels at least).
 * Drawn into the frame's pixels (rows top first, 3 bytes a pixel) after it is rendered.
 */
final class Captions {
    private final int width;
    private final int height;
    private final int band;
    private final Font font;
    private final BufferedImage strip;

    Captions(int width, int height) {
        this.width = width;
        this.height = height;
        int size = Math.max(13, height / 24);
        this.font = new Font(Font.SANS_SERIF, Font.BOLD, size);
        this.band = Math.min(height, (int) Math.ceil(size * 1.7));
        this.strip = new BufferedImage(width, band, BufferedImage.TYPE_INT_RGB);
    }

    /** The rows the caption covers, from the bottom: what stays background without one. */
    int band() {
        return band;
    }

    void draw(byte[] rgb, String text) {
        if (text == null || text.isBlank()) {
            return;
        }
        int top = height - band;
        int[] row = new int[width];
        for (int y = 0; y < band; y++) {
            int base = 3 * (top + y) * width;
            for (int x = 0; x < width; x++) {
                int b = base + 3 * x;
                row[x] = (rgb[b] & 0xff) << 16 | (rgb[b + 1] & 0xff) << 8 | (rgb[b + 2] & 0xff);
            }
            strip.setRGB(0, y, width, 1, row, 0, width);
        }
        Graphics2D g = strip.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setComposite(AlphaComposite.getInstance(AlphaComposite.SRC_OVER, 0.62f));
            g.setColor(new Color(0x20, 0x26, 0x2E));
            g.fillRect(0, 0, width, band);
            g.setComposite(AlphaComposite.SrcOver);
            g.setFont(font);
            FontMetrics metrics = g.getFontMetrics();
            String shown = fit(text, metrics, width - band);
            g.setColor(Color.WHITE);
            int baseline = (band - metrics.getHeight()) / 2 + metrics.getAscent();
            g.drawString(shown, band / 2, baseline);
        } finally {
            g.dispose();
        }
        for (int y = 0; y < band; y++) {
            strip.getRGB(0, y, width, 1, row, 0, width);
            int base = 3 * (top + y) * width;
            for (int x = 0; x < width; x++) {
                int b = base + 3 * x;
                rgb[b] = (byte) (row[x] >>> 16);
                rgb[b + 1] = (byte) (row[x] >>> 8);
                rgb[b + 2] = (byte) row[x];
            }
        }
    }

    /** The text, cut short with an ellipsis where it would run past {@code room} pixels. */
    private static String fit(String text, FontMetrics metrics, int room) {
        if (metrics.stringWidth(text) <= room) {
            return text;
        }
        String shown = text;
        while (shown.length() > 1 && metrics.stringWidth(shown + "…") > room) {
            shown = shown.substring(0, shown.length() - 1);
        }
        return shown.strip() + "…";
    }
}
