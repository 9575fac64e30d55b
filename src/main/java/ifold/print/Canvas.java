package ifold.print;

import java.io.IOException;

/**
 * Where pages are drawn, in millimetres from the page's top left corner, y downwards: an SVG
 * file a page ({@link SvgCanvas}) or a PDF document ({@link PdfCanvas}).
 */
public interface Canvas {
    void beginPage(double widthMm, double heightMm) throws IOException;

    void line(double x1, double y1, double x2, double y2, Ink ink) throws IOException;

    /** A closed outline through the points (x, y pairs). */
    void outline(double[] xy, Ink ink) throws IOException;

    /** A polygon filled with colour {@code argb} (its alpha ignored), without outline. */
    void fill(double[] xy, int argb) throws IOException;

    /** Text whose baseline starts at (x, y), {@code size} millimetres high (its capitals about 0.7 of that). */
    void text(double x, double y, double size, String text, boolean bold) throws IOException;

    /** What is drawn until {@link #endClip} shows only inside the rectangle (a panel). */
    void beginClip(double x, double y, double width, double height) throws IOException;

    void endClip() throws IOException;

    void endPage() throws IOException;
}
