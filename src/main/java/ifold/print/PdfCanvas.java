package ifold.print;

import ifold.io.AtomicFile;
import java.io.IOException;
import java.nio.file.Path;
import org.apache.pdfbox.pdmodel.PDDocument;
import org.apache.pdfbox.pdmodel.PDPage;
import org.apache.pdfbox.pdmodel.PDPageContentStream;
import org.apache.pdfbox.pdmodel.common.PDRectangle;
import org.apache.pdfbox.pdmodel.font.PDType1Font;
import org.apache.pdfbox.pdmodel.font.Standard14Fonts;

/**
 * Pages as one PDF document (Apache PDFBox), at real size: a millimetre is 72 / 25.4 points, the
 * lines in the styles and colours of the SVG's classes. Written whole or not at all on
 * {@link #save}.
 */
public final class PdfCanvas implements Canvas, AutoCloseable {
    private static final float POINTS_A_MM = (float) (72 / 25.4);
    /** The longest side of a page PDF readers open: 14,400 units of a point, 200 inches (PDF 1.7, Annex C). */
    public static final double LONGEST_SIDE_MM = 200 * 25.4;

    static {
        // PDFBox logs through commons-logging: its notes on fonts (the standard fonts' stand-ins,
        // the system font cache it builds) would break the command's one line on stderr. Its
        // cache of the system's fonts goes to the temporary folder, not the user's home.
        if (System.getProperty("org.apache.commons.logging.Log") == null) {
            System.setProperty("org.apache.commons.logging.Log", "org.apache.commons.logging.impl.NoOpLog");
        }
        if (System.getProperty("pdfbox.fontcache") == null) {
            System.setProperty("pdfbox.fontcache", System.getProperty("java.io.tmpdir"));
        }
    }

    private final PDDocument document = new PDDocument();
    private final PDType1Font regular = new PDType1Font(Standard14Fonts.FontName.HELVETICA);
    private final PDType1Font bold = new PDType1Font(Standard14Fonts.FontName.HELVETICA_BOLD);
    private PDPageContentStream content;
    private float height;

    @Override
    public void beginPage(double widthMm, double heightMm) throws IOException {
        PDPage page = new PDPage(new PDRectangle((float) widthMm * POINTS_A_MM, (float) heightMm * POINTS_A_MM));
        document.addPage(page);
        content = new PDPageContentStream(document, page);
        height = (float) heightMm;
    }

    private float x(double mm) {
        return (float) mm * POINTS_A_MM;
    }

    private float y(double mm) {
        return (height - (float) mm) * POINTS_A_MM;
    }

    private void ink(Ink ink) throws IOException {
        switch (ink) {
            case CUT, SCALE -> style(0, 0, 0, 0.3, new float[0]);
            case VALLEY -> style(0x1f, 0x5f, 0xbf, 0.25, new float[] {2.4f, 1.2f});
            case MOUNTAIN -> style(0xc6, 0x28, 0x28, 0.25, new float[] {2.4f, 0.8f, 0.4f, 0.8f, 0.4f, 0.8f});
            case FLAT -> style(0xc8, 0xc8, 0xc8, 0.1, new float[0]);
            case TAB -> style(0x80, 0x80, 0x80, 0.2, new float[] {0.5f, 0.7f});
            case ARROW -> style(0, 0, 0, 0.4, new float[0]);
            default -> throw new IllegalArgumentException("no style for " + ink);
        }
    }

    private void style(int r, int g, int b, double widthMm, float[] dashesMm) throws IOException {
        content.setStrokingColor(r / 255f, g / 255f, b / 255f);
        content.setLineWidth((float) widthMm * POINTS_A_MM);
        float[] dashes = new float[dashesMm.length];
        for (int i = 0; i < dashes.length; i++) {
            dashes[i] = dashesMm[i] * POINTS_A_MM;
        }
        content.setLineDashPattern(dashes, 0);
    }

    @Override
    public void line(double x1, double y1, double x2, double y2, Ink ink) throws IOException {
        ink(ink);
        content.moveTo(x(x1), y(y1));
        content.lineTo(x(x2), y(y2));
        content.stroke();
    }

    @Override
    public void outline(double[] xy, Ink ink) throws IOException {
        ink(ink);
        content.moveTo(x(xy[0]), y(xy[1]));
        for (int k = 2; k < xy.length; k += 2) {
            content.lineTo(x(xy[k]), y(xy[k + 1]));
        }
        content.closePath();
        content.stroke();
    }

    @Override
    public void fill(double[] xy, int argb) throws IOException {
        content.setNonStrokingColor(((argb >> 16) & 255) / 255f, ((argb >> 8) & 255) / 255f, (argb & 255) / 255f);
        content.moveTo(x(xy[0]), y(xy[1]));
        for (int k = 2; k < xy.length; k += 2) {
            content.lineTo(x(xy[k]), y(xy[k + 1]));
        }
        content.closePath();
        content.fill();
    }

    @Override
    public void text(double x, double y, double size, String text, boolean heavy) throws IOException {
        content.beginText();
        content.setNonStrokingColor(0f, 0f, 0f);
        content.setFont(heavy ? bold : regular, (float) size * POINTS_A_MM);
        content.newLineAtOffset(x(x), y(y));
        content.showText(text);
        content.endText();
    }

    @Override
    public void beginClip(double x, double y, double width, double height) throws IOException {
        content.saveGraphicsState();
        content.addRect(x(x), y(y + height), (float) width * POINTS_A_MM, (float) height * POINTS_A_MM);
        content.clip();
    }

    @Override
    public void endClip() throws IOException {
        content.restoreGraphicsState();
    }

    @Override
    public void endPage() throws IOException {
        content.close();
        content = null;
    }

    /** Writes the document to {@code file}, whole or not at all. */
    public void save(Path file) throws IOException {
        AtomicFile.write(file, document::save, true);
    }

    @Override
    public void close() throws IOException {
        if (content != null) {
            content.close();
        }
        document.close();
    }
}
