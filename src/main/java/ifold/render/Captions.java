package ifold.render;

import java.awt.AlphaComposite;
import java.awt.Color;
import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
import java.awt.image.BufferedImage;
import java.util.List;

/**
 * A caption along the bottom of a frame: the step shown, in white on a dark translucent band,
 * large enough to read at 640×360 (a twenty-fourth of the frame's height, 13 pixels at least).
 * A caption too long for the band is set a fifth smaller, and if it is still too long, on two
 * lines in a band one line taller, so that the step reads whole; only beyond two lines is it cut
 * short. Drawn into the frame's pixels (rows top first, 3 bytes a pixel) after it is rendered.
 */
final class Captions {
    private final int width;
    private final int height;
    private final int band;
    /** The band of a caption on two lines: one line taller. */
    private final int tallBand;
    private final Font font;
    private final Font smallFont;
    private final BufferedImage strip;

    /** How a caption is set: its lines, their font, and the rows of the band they need. */
    record Layout(List<String> lines, Font font, int rows) {
    }

    Captions(int width, int height) {
        this.width = width;
        this.height = height;
        int size = Math.max(13, height / 24);
        this.font = new Font(Font.SANS_SERIF, Font.BOLD, size);
        this.smallFont = font.deriveFont(Math.max(12f, 0.8f * size));
        this.band = Math.min(height, (int) Math.ceil(size * 1.7));
        this.tallBand = Math.min(height, band + (int) Math.ceil(smallFont.getSize2D() * 1.25));
        this.strip = new BufferedImage(width, tallBand, BufferedImage.TYPE_INT_RGB);
    }

    /** The rows a one-line caption covers, from the bottom: what stays background without one. */
    int band() {
        return band;
    }

    /** How {@code text} is set in this frame's width. */
    Layout layout(String text) {
        Graphics2D g = strip.createGraphics();
        try {
            int room = width - band; // half a band's margin either side
            FontMetrics metrics = g.getFontMetrics(font);
            if (metrics.stringWidth(text) <= room) {
                return new Layout(List.of(text), font, band);
            }
            FontMetrics small = g.getFontMetrics(smallFont);
            if (small.stringWidth(text) <= room) {
                return new Layout(List.of(text), smallFont, band);
            }
            // Two lines, broken at the last space that lets the first fit.
            int cut = -1;
            for (int i = text.indexOf(' '); i > 0; i = text.indexOf(' ', i + 1)) {
                if (small.stringWidth(text.substring(0, i)) > room) {
                    break;
                }
                cut = i;
            }
            String first;
            String rest;
            // At a space, unless that leaves the second line too long and the first nearly empty
            // (a long word): then the first line is filled, the word broken.
            if (cut > 0 && (small.stringWidth(text.substring(cut + 1).strip()) <= room
                    || small.stringWidth(text.substring(0, cut)) > room / 2)) {
                first = text.substring(0, cut);
                rest = text.substring(cut + 1).strip();
            } else {
                first = TextFit.cutShort(text, small, room);
                first = first.substring(0, first.length() - 1); // no ellipsis mid-word: it goes on
                rest = text.substring(first.length()).strip();
            }
            return new Layout(List.of(first, TextFit.cutShort(rest, small, room)), smallFont, tallBand);
        } finally {
            g.dispose();
        }
    }

    /** The caption drawn last, and its white text's coverage of each pixel of its band (0–255): most frames repeat it. */
    private String maskText;
    private int[] mask;
    private int maskRows;

    private static final float BAND_ALPHA = 0.62f;
    private static final int BAND = 0x20262E;

    void draw(byte[] rgb, String text) {
        if (text == null || text.isBlank()) {
            return;
        }
        if (!text.equals(maskText)) {
            drawMask(text);
        }
        // The band over the picture, then the text over the band: what Java2D's composites do,
        // by the pixel, without setting the text again.
        int rows = maskRows;
        int top = height - rows;
        int keep = Math.round((1 - BAND_ALPHA) * 256);
        int[] band = {Math.round(BAND_ALPHA * (BAND >> 16 & 0xFF)), Math.round(BAND_ALPHA * (BAND >> 8 & 0xFF)), Math.round(BAND_ALPHA * (BAND & 0xFF))};
        for (int y = 0; y < rows; y++) {
            int base = 3 * (top + y) * width;
            for (int x = 0; x < width; x++) {
                int cover = mask[y * width + x];
                for (int k = 0; k < 3; k++) {
                    int b = base + 3 * x + k;
                    int under = ((rgb[b] & 0xFF) * keep >> 8) + band[k];
                    rgb[b] = (byte) ((under * (255 - cover) + 255 * cover + 127) / 255);
                }
            }
        }
    }

    /** Sets {@code text} in white on black, to read its coverage of each pixel. */
    private void drawMask(String text) {
        Layout layout = layout(text.strip());
        int rows = layout.rows();
        Graphics2D g = strip.createGraphics();
        try {
            g.setColor(Color.BLACK);
            g.fillRect(0, 0, width, strip.getHeight());
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setFont(layout.font());
            FontMetrics metrics = g.getFontMetrics();
            g.setColor(Color.WHITE);
            int lines = layout.lines().size();
            int lineHeight = lines == 1 ? metrics.getHeight() : (int) Math.ceil(layout.font().getSize2D() * 1.25);
            int baseline = (rows - lines * lineHeight) / 2 + (lineHeight - metrics.getHeight()) / 2 + metrics.getAscent();
            for (String line : layout.lines()) {
                g.drawString(line, band / 2, baseline);
                baseline += lineHeight;
            }
        } finally {
            g.dispose();
        }
        int[] coverage = new int[rows * width];
        strip.getRGB(0, 0, width, rows, coverage, 0, width);
        for (int i = 0; i < coverage.length; i++) {
            coverage[i] &= 0xFF; // white on black: any channel is the coverage
        }
        mask = coverage;
        maskRows = rows;
        maskText = text;
    }

    /**
     * Writes {@code text} into the top left corner of a picture (rows top first, 3 bytes a
     * pixel), dark on a pale translucent box: the label of a figure's stage, as a printed
     * figure's "(a)", "(b)" are.
     */
    static void label(byte[] rgb, int width, int height, String text) {
        BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
        int[] row = new int[width];
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                int b = 3 * (y * width + x);
                row[x] = (rgb[b] & 0xff) << 16 | (rgb[b + 1] & 0xff) << 8 | (rgb[b + 2] & 0xff);
            }
            image.setRGB(0, y, width, 1, row, 0, width);
        }
        Graphics2D g = image.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            Font font = new Font(Font.SANS_SERIF, Font.BOLD, Math.max(13, height / 20));
            FontMetrics metrics = g.getFontMetrics(font);
            int pad = font.getSize() / 2;
            String shown = TextFit.cutShort(text, metrics, width - 4 * pad);
            g.setComposite(AlphaComposite.getInstance(AlphaComposite.SRC_OVER, 0.75f));
            g.setColor(Color.WHITE);
            g.fillRoundRect(pad, pad, metrics.stringWidth(shown) + 2 * pad, metrics.getHeight() + pad, pad, pad);
            g.setComposite(AlphaComposite.SrcOver);
            g.setFont(font);
            g.setColor(new Color(0x20, 0x26, 0x2E));
            g.drawString(shown, 2 * pad, pad + pad / 2 + metrics.getAscent());
        } finally {
            g.dispose();
        }
        for (int y = 0; y < height; y++) {
            image.getRGB(0, y, width, 1, row, 0, width);
            for (int x = 0; x < width; x++) {
                int b = 3 * (y * width + x);
                rgb[b] = (byte) (row[x] >>> 16);
                rgb[b + 1] = (byte) (row[x] >>> 8);
                rgb[b + 2] = (byte) row[x];
            }
        }
    }

}
