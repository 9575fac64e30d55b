package ifold.print;

import ifold.io.AtomicFile;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.function.IntFunction;

/**
 * Pages as SVG, a file each, in real units (millimetres): the lines' kinds are CSS classes
 * (cut, valley, mountain, flat, tab, scale) that a cutting machine's software can map to its
 * tools (cut the outline, score the folds). Each file is written whole or not at all.
 */
public final class SvgCanvas implements Canvas {
    private final IntFunction<Path> fileOfPage;
    private final List<Path> written = new ArrayList<>();
    private StringBuilder page;
    private int pages;
    /** Clipping rectangles made so far, for their ids. */
    private int clips;

    /** Writes page p (from 0) to {@code fileOfPage.apply(p)}. */
    public SvgCanvas(IntFunction<Path> fileOfPage) {
        this.fileOfPage = fileOfPage;
    }

    /** The files written so far, in order. */
    public List<Path> written() {
        return written;
    }

    @Override
    public void beginPage(double widthMm, double heightMm) {
        page = new StringBuilder(1 << 16);
        page.append("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n")
                .append(String.format(Locale.ROOT, "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%smm\" height=\"%smm\" viewBox=\"0 0 %s %s\">%n",
                        number(widthMm), number(heightMm), number(widthMm), number(heightMm)))
                .append("<style>\n")
                .append(".cut { stroke: #000000; stroke-width: 0.3; fill: none; }\n")
                .append(".valley { stroke: #1f5fbf; stroke-width: 0.25; fill: none; stroke-dasharray: 2.4 1.2; }\n")
                .append(".mountain { stroke: #c62828; stroke-width: 0.25; fill: none; stroke-dasharray: 2.4 0.8 0.4 0.8 0.4 0.8; }\n")
                .append(".flat { stroke: #c8c8c8; stroke-width: 0.1; fill: none; }\n")
                .append(".tab { stroke: #808080; stroke-width: 0.2; fill: none; stroke-dasharray: 0.5 0.7; }\n")
                .append(".scale { stroke: #000000; stroke-width: 0.3; fill: none; }\n")
                .append(".arrow { stroke: #000000; stroke-width: 0.4; fill: none; }\n")
                .append("text { font-family: Helvetica, Arial, sans-serif; fill: #000000; }\n")
                .append(".bold { font-weight: bold; }\n")
                .append("</style>\n");
    }

    @Override
    public void line(double x1, double y1, double x2, double y2, Ink ink) {
        page.append("<line class=\"").append(className(ink)).append("\" x1=\"").append(number(x1)).append("\" y1=\"").append(number(y1))
                .append("\" x2=\"").append(number(x2)).append("\" y2=\"").append(number(y2)).append("\"/>\n");
    }

    @Override
    public void outline(double[] xy, Ink ink) {
        page.append("<polygon class=\"").append(className(ink)).append("\" points=\"");
        for (int k = 0; k < xy.length; k += 2) {
            page.append(k == 0 ? "" : " ").append(number(xy[k])).append(',').append(number(xy[k + 1]));
        }
        page.append("\"/>\n");
    }

    @Override
    public void fill(double[] xy, int argb) {
        page.append("<polygon fill=\"#").append(String.format(Locale.ROOT, "%06x", argb & 0xFFFFFF)).append("\" points=\"");
        for (int k = 0; k < xy.length; k += 2) {
            page.append(k == 0 ? "" : " ").append(number(xy[k])).append(',').append(number(xy[k + 1]));
        }
        page.append("\"/>\n");
    }

    @Override
    public void text(double x, double y, double size, String text, boolean bold) {
        page.append("<text").append(bold ? " class=\"bold\"" : "").append(" x=\"").append(number(x)).append("\" y=\"").append(number(y))
                .append("\" font-size=\"").append(number(size)).append("\">").append(escaped(text)).append("</text>\n");
    }

    @Override
    public void beginClip(double x, double y, double width, double height) {
        clips++;
        page.append("<clipPath id=\"panel").append(clips).append("\"><rect x=\"").append(number(x)).append("\" y=\"").append(number(y))
                .append("\" width=\"").append(number(width)).append("\" height=\"").append(number(height)).append("\"/></clipPath>\n")
                .append("<g clip-path=\"url(#panel").append(clips).append(")\">\n");
    }

    @Override
    public void endClip() {
        page.append("</g>\n");
    }

    @Override
    public void endPage() throws IOException {
        page.append("</svg>\n");
        Path file = fileOfPage.apply(pages++);
        byte[] bytes = page.toString().getBytes(StandardCharsets.UTF_8);
        AtomicFile.write(file, out -> out.write(bytes), true);
        written.add(file);
        page = null;
    }

    static String className(Ink ink) {
        return ink.name().toLowerCase(Locale.ROOT);
    }

    /** A coordinate to a thousandth of a millimetre, without trailing zeros. */
    static String number(double value) {
        String text = String.format(Locale.ROOT, "%.3f", value);
        text = text.contains(".") ? text.replaceAll("0+$", "").replaceAll("\\.$", "") : text;
        return text.equals("-0") ? "0" : text;
    }

    private static String escaped(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
