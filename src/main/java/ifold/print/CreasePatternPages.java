package ifold.print;

import ifold.foldfile.FoldFile.SheetCreases;
import ifold.sheet.Polygons2;
import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;

/**
 * The crease pattern of strips (or sheets) laid out on pages at real size and drawn: each strip
 * cut across into pieces as long as a page is wide, a glue tab at the end of each piece but the
 * last, where the next piece's start is glued, both marked with the same letter; pieces one
 * under another, numbered ("piece 3 of 12"); valleys dashed, mountains dash-dot-dot, the
 * outline solid, flat edges faint; each crease numbered in folding order; a header naming the
 * model, the width and the method, and a legend with a 5 cm scale bar.
 *
 * <p>The strip is drawn along the page, its u axis rightwards and its v axis upwards, top side
 * up: the side the paper shows outside once folded, so that valleys fold towards the reader.
 */
public final class CreasePatternPages {
    /** Margin all round, in millimetres. */
    static final double MARGIN = 12;
    /** The header's band: the title and what was printed. */
    static final double HEADER = 16;
    /** The footer's band: the legend and the scale bar. */
    static final double FOOTER = 22;
    /** A piece's label above it. */
    static final double LABEL = 5;
    /** Between a piece and the next one's label. */
    static final double GAP = 4;
    /** A glue tab's length beyond its piece. */
    static final double TAB = 8;
    /** The most pages printed: beyond, the width asked is refused as too wide for the strip's length. */
    public static final int MOST_PAGES = 500;

    /** The width a strip is printed at unless told: 2 cm, a strip a hand folds. */
    public static final double STRIP_WIDTH_MM = 20;
    /** Paper at most this many times as long as wide is a sheet, not a strip: printed as large as fits a page. */
    static final double SHEET_ASPECT = 3;

    /**
     * How to print: the strip's width on paper, in millimetres (NaN: {@link #STRIP_WIDTH_MM} for a
     * strip, a sheet as large as fits the page, in whole centimetres), and the page.
     */
    public record Options(double paperWidthMm, Page page) {
    }

    /**
     * A shape printed at the same scale as the strip, to cut out of card and fold the strip on:
     * the triangle of the zig-zag demo.
     *
     * @param label what it is, printed above it
     * @param xy its corners in its own plane, in the model's units (x, y pairs)
     * @param names each corner's name, printed inside it
     * @param start where the strip's first piece lies on it (x, y pairs in the same plane), or null
     * @param startLabel what to say of it ("piece 1 starts here, printed side up")
     */
    public record Template(String label, double[] xy, String[] names, double[] start, String startLabel) {
        /** A shape alone, without where the strip starts on it. */
        public Template(String label, double[] xy, String[] names) {
            this(label, xy, names, null, null);
        }
    }

    /** Strip {@code strip}'s paper from u0 to u1, its top left corner at (x, y) on its page. */
    record Piece(int strip, int index, int count, double u0, double u1, double x, double y, String markIn, String markOut) {
    }

    record Sheet(double width, double height, List<Piece> pieces) {
    }

    private final String title;
    private final String method;
    private final List<SheetCreases> strips;
    /** Millimetres a model unit. */
    private final double scale;
    private final double paperWidth;
    private final List<Sheet> pages = new ArrayList<>();
    /** The template, where it is drawn (page, x, y of its box's top left corner); null where none. */
    private Template template;
    private int templatePage = -1;
    private double templateX;
    private double templateY;
    /** Each strip's edges sorted by their smallest u, and the longest any spans along u. */
    private final List<Integer[]> byU = new ArrayList<>();
    private final double[] longestSpan;
    /** For each strip, whether its border is the rectangle it spans (else its border edges are cut, not the rectangle). */
    private final boolean[] rectangular;

    private CreasePatternPages(String title, String method, List<SheetCreases> strips, double scale, double paperWidth) {
        this.title = title;
        this.method = method;
        this.strips = strips;
        this.scale = scale;
        this.paperWidth = paperWidth;
        this.longestSpan = new double[strips.size()];
        this.rectangular = new boolean[strips.size()];
        for (int k = 0; k < strips.size(); k++) {
            rectangular[k] = onItsRectangle(strips.get(k));
        }
    }

    /** Whether every border edge of the sheet runs along the rectangle it spans: a strip, a fold script's sheet. */
    private static boolean onItsRectangle(SheetCreases sheet) {
        double tolerance = 1e-9 * Math.max(sheet.length(), sheet.width());
        double[] uv = sheet.uv();
        for (int e = 0; e < sheet.edges().length; e++) {
            if (sheet.assignments()[e] != 'B') {
                continue;
            }
            double ua = uv[2 * sheet.edges()[e][0]];
            double va = uv[2 * sheet.edges()[e][0] + 1];
            double ub = uv[2 * sheet.edges()[e][1]];
            double vb = uv[2 * sheet.edges()[e][1] + 1];
            boolean alongU = Math.abs(va - vb) <= tolerance && (Math.abs(va) <= tolerance || Math.abs(va - sheet.width()) <= tolerance);
            boolean alongV = Math.abs(ua - ub) <= tolerance && (Math.abs(ua) <= tolerance || Math.abs(ua - sheet.length()) <= tolerance);
            if (!alongU && !alongV) {
                return false;
            }
        }
        return true;
    }

    /**
     * Lays out {@code strips} ({@code title}: what was folded; {@code method}: how, in words).
     *
     * @throws IllegalArgumentException where the width asked does not fit the page, or would take
     *     more than {@link #MOST_PAGES} pages (naming the width that fits)
     */
    public static CreasePatternPages of(String title, String method, List<SheetCreases> strips, Options options) {
        return of(title, method, strips, options, null);
    }

    /** As {@link #of(String, String, List, Options)}, with {@code template} (or none) printed after the strips. */
    public static CreasePatternPages of(String title, String method, List<SheetCreases> strips, Options options, Template template) {
        if (strips.isEmpty()) {
            throw new IllegalArgumentException("nothing to print");
        }
        double width = strips.get(0).width();
        double paperWidth = Double.isNaN(options.paperWidthMm()) ? automaticWidth(strips, options.page()) : options.paperWidthMm();
        double scale = paperWidth / width;
        CreasePatternPages pages = new CreasePatternPages(title, method, strips, scale, paperWidth);
        pages.layOut(options.page());
        if (template != null) {
            pages.placeTemplate(template, options.page());
        }
        pages.sortEdges();
        return pages;
    }

    /**
     * The width printed where none is asked: a strip {@link #STRIP_WIDTH_MM} wide; a sheet (no
     * longer than {@link #SHEET_ASPECT} times its width, a fold script's square) in one piece, as
     * wide as fits the page (an A4 where the page is as long as the paper), in whole centimetres.
     */
    static double automaticWidth(List<SheetCreases> strips, Page page) {
        double width = strips.get(0).width();
        double longest = strips.stream().mapToDouble(SheetCreases::length).max().orElse(0);
        if (longest > SHEET_ASPECT * width) {
            return STRIP_WIDTH_MM;
        }
        Page on = page == Page.NONE ? Page.A4 : page;
        double across = on.width() - 2 * MARGIN - TAB;
        double down = (on.height() - 2 * MARGIN - HEADER - FOOTER) / strips.size() - LABEL - GAP;
        double fits = Math.min(down, across * width / longest);
        return Math.max(STRIP_WIDTH_MM, 10 * Math.floor(fits / 10));
    }

    /** The longest side of any page, in millimetres: one long page (--page none) is as long as the strip. */
    public double longestSide() {
        return pages.stream().mapToDouble(page -> Math.max(page.width(), page.height())).max().orElse(0);
    }

    public int pageCount() {
        return pages.size();
    }

    /** The pieces the strips are cut into, all pages together. */
    public int pieceCount() {
        return pages.stream().mapToInt(p -> p.pieces().size()).sum();
    }

    /** Millimetres on paper a unit of the model. */
    public double scale() {
        return scale;
    }

    private void layOut(Page page) {
        double h = paperWidth;
        if (page == Page.NONE) {
            double longest = strips.stream().mapToDouble(SheetCreases::length).max().orElse(0) * scale;
            double height = 2 * MARGIN + HEADER + FOOTER + strips.size() * (LABEL + h + GAP);
            List<Piece> pieces = new ArrayList<>();
            double y = MARGIN + HEADER + LABEL;
            for (int k = 0; k < strips.size(); k++) {
                pieces.add(new Piece(k, 0, 1, 0, strips.get(k).length(), MARGIN, y, null, null));
                y += LABEL + h + GAP;
            }
            pages.add(new Sheet(Math.max(longest + 2 * MARGIN, 180), height, pieces));
            return;
        }
        double pieceLength = page.width() - 2 * MARGIN - TAB;
        double usable = page.height() - 2 * MARGIN - HEADER - FOOTER;
        int rows = (int) Math.floor((usable + GAP) / (LABEL + h + GAP));
        if (rows < 1) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "a strip %.1f mm wide does not fit the page (%s): at most %.0f mm",
                    h, page.optionName(), usable - LABEL));
        }
        long total = 0;
        for (SheetCreases strip : strips) {
            total += (long) Math.ceil(strip.length() * scale / pieceLength - 1e-9);
        }
        long pageCount = (total + rows - 1) / rows;
        if (pageCount > MOST_PAGES) {
            double fits = paperWidth * MOST_PAGES / pageCount;
            throw new IllegalArgumentException(String.format(Locale.ROOT, "a strip %.1f mm wide is %.1f m long: %d pages, more than %d;"
                    + " give a narrower width (about %.1f mm fits)", h, strips.stream().mapToDouble(SheetCreases::length).sum() * scale / 1000,
                    pageCount, MOST_PAGES, fits));
        }
        List<Piece> current = new ArrayList<>();
        int row = 0;
        int mark = 0;
        for (int k = 0; k < strips.size(); k++) {
            SheetCreases strip = strips.get(k);
            int count = (int) Math.ceil(strip.length() * scale / pieceLength - 1e-9);
            String markIn = null;
            for (int j = 0; j < count; j++) {
                if (row == rows) {
                    pages.add(new Sheet(page.width(), page.height(), current));
                    current = new ArrayList<>();
                    row = 0;
                }
                double u0 = j * pieceLength / scale;
                double u1 = j + 1 == count ? strip.length() : (j + 1) * pieceLength / scale;
                String markOut = j + 1 < count ? letters(mark++) : null;
                double y = MARGIN + HEADER + LABEL + row * (LABEL + h + GAP);
                current.add(new Piece(k, j, count, u0, u1, MARGIN, y, markIn, markOut));
                markIn = markOut;
                row++;
            }
        }
        if (!current.isEmpty()) {
            pages.add(new Sheet(page.width(), page.height(), current));
        }
    }

    /** Places the template under the last piece where it fits there, else on a page of its own. */
    private void placeTemplate(Template shape, Page page) {
        double[] box = Polygons2.bounds(shape.xy());
        double width = (box[2] - box[0]) * scale;
        double height = (box[3] - box[1]) * scale;
        Sheet last = pages.get(pages.size() - 1);
        double pageWidth = page == Page.NONE ? Math.max(last.width(), width + 2 * MARGIN) : page.width();
        if (width > pageWidth - 2 * MARGIN) {
            return; // larger than a page at this scale: the strip alone is printed
        }
        double y = MARGIN + HEADER + LABEL;
        for (Piece piece : last.pieces()) {
            y = Math.max(y, piece.y() + paperWidth + GAP + LABEL);
        }
        double bottom = (page == Page.NONE ? last.height() : page.height()) - MARGIN - FOOTER;
        if (page == Page.NONE) {
            pages.set(pages.size() - 1, new Sheet(pageWidth, last.height() + height + LABEL + GAP, last.pieces()));
            bottom += height + LABEL + GAP;
        }
        if (y + height > bottom) {
            if (height > page.height() - 2 * MARGIN - HEADER - FOOTER - LABEL) {
                return;
            }
            pages.add(new Sheet(page.width(), page.height(), List.of()));
            y = MARGIN + HEADER + LABEL;
        }
        template = shape;
        templatePage = pages.size() - 1;
        templateX = MARGIN;
        templateY = y;
    }


    private void drawTemplate(Canvas canvas) throws IOException {
        double[] box = Polygons2.bounds(template.xy());
        int n = template.xy().length / 2;
        double[] at = new double[2 * n];
        double cx = 0;
        double cy = 0;
        for (int k = 0; k < n; k++) {
            // Its y upwards, as the strip's v.
            at[2 * k] = templateX + (template.xy()[2 * k] - box[0]) * scale;
            at[2 * k + 1] = templateY + (box[3] - template.xy()[2 * k + 1]) * scale;
            cx += at[2 * k] / n;
            cy += at[2 * k + 1] / n;
        }
        canvas.text(templateX, templateY - 1.4, 2.6, template.label(), false);
        canvas.outline(at, Ink.CUT);
        if (template.start() != null) {
            // Where the strip starts: its first piece's outline, dotted, and what to do there.
            int m = template.start().length / 2;
            double[] start = new double[2 * m];
            double sx = 0;
            double sy = 0;
            for (int k = 0; k < m; k++) {
                start[2 * k] = templateX + (template.start()[2 * k] - box[0]) * scale;
                start[2 * k + 1] = templateY + (box[3] - template.start()[2 * k + 1]) * scale;
                sx += start[2 * k] / m;
                sy += start[2 * k + 1] / m;
            }
            canvas.outline(start, Ink.TAB);
            canvas.text(sx - 12, sy + 1, 2.6, template.startLabel(), false);
        }
        for (int k = 0; k < n && k < template.names().length; k++) {
            // Each name a little way in from its corner, towards the middle.
            double x = at[2 * k] + 0.12 * (cx - at[2 * k]);
            double y = at[2 * k + 1] + 0.12 * (cy - at[2 * k + 1]);
            canvas.text(x - 1.2, y + 1.4, 3.6, template.names()[k], true);
        }
    }

    /** Marks A to Z, then AA, AB, ... */
    static String letters(int n) {
        StringBuilder text = new StringBuilder();
        int k = n;
        do {
            text.insert(0, (char) ('A' + k % 26));
            k = k / 26 - 1;
        } while (k >= 0);
        return text.toString();
    }

    private void sortEdges() {
        for (int k = 0; k < strips.size(); k++) {
            SheetCreases strip = strips.get(k);
            Integer[] order = new Integer[strip.edges().length];
            double[] min = new double[order.length];
            for (int e = 0; e < order.length; e++) {
                order[e] = e;
                double ua = strip.uv()[2 * strip.edges()[e][0]];
                double ub = strip.uv()[2 * strip.edges()[e][1]];
                min[e] = Math.min(ua, ub);
                longestSpan[k] = Math.max(longestSpan[k], Math.abs(ua - ub));
            }
            Arrays.sort(order, Comparator.comparingDouble(e -> min[e]));
            byU.add(order);
        }
    }

    /** Draws every page. */
    public void draw(Canvas canvas) throws IOException {
        for (int p = 0; p < pages.size(); p++) {
            Sheet page = pages.get(p);
            canvas.beginPage(page.width(), page.height());
            header(canvas, page, p);
            for (Piece piece : page.pieces()) {
                piece(canvas, piece);
            }
            if (p == templatePage) {
                drawTemplate(canvas);
            }
            footer(canvas, page);
            canvas.endPage();
        }
    }

    private void header(Canvas canvas, Sheet page, int p) throws IOException {
        canvas.text(MARGIN, MARGIN + 5, 4.5, "iFold: " + title, true);
        boolean sheet = strips.stream().mapToDouble(SheetCreases::length).max().orElse(0) <= SHEET_ASPECT * strips.get(0).width();
        String width = String.format(Locale.ROOT, "%s; the %s %s wide (%.4g model units, %.4g mm a unit)", method, sheet ? "sheet" : "strip",
                millimetres(paperWidth), strips.get(0).width(), scale);
        String pages = this.pages.size() > 1 ? String.format(Locale.ROOT, "; page %d of %d", p + 1, this.pages.size()) : "";
        canvas.text(MARGIN, MARGIN + 11, 3, width + pages, false);
    }

    private static String millimetres(double mm) {
        return mm >= 10 && Math.abs(mm / 10 - Math.rint(mm / 10)) < 1e-9 ? String.format(Locale.ROOT, "%.0f cm", mm / 10)
                : String.format(Locale.ROOT, "%.3g mm", mm);
    }

    private void piece(Canvas canvas, Piece piece) throws IOException {
        SheetCreases strip = strips.get(piece.strip());
        double h = paperWidth;
        double x0 = piece.x();
        double x1 = piece.x() + (piece.u1() - piece.u0()) * scale;
        double top = piece.y();
        double bottom = piece.y() + h;
        // The label: which piece, and where it joins.
        StringBuilder label = new StringBuilder(String.format(Locale.ROOT, "piece %d of %d", piece.index() + 1, piece.count()));
        if (strips.size() > 1) {
            label.append(String.format(Locale.ROOT, " of strip %d", piece.strip() + 1));
        }
        if (piece.markIn() != null) {
            label.append(String.format(Locale.ROOT, "; its start goes over the tab of piece %d at mark %s", piece.index(), piece.markIn()));
        }
        if (piece.markOut() != null) {
            label.append(String.format(Locale.ROOT, "; glue piece %d on its tab at mark %s", piece.index() + 2, piece.markOut()));
        }
        canvas.text(x0, top - 1.4, 2.6, label.toString(), false);
        // The creases and flat edges within the piece.
        Map<Integer, List<double[]>> numberAt = new TreeMap<>();
        Integer[] order = byU.get(piece.strip());
        double[] uv = strip.uv();
        int start = lowerBound(order, strip, piece.u0() - longestSpan[piece.strip()]);
        for (int i = start; i < order.length; i++) {
            int e = order[i];
            int a = strip.edges()[e][0];
            int b = strip.edges()[e][1];
            double ua = uv[2 * a];
            double va = uv[2 * a + 1];
            double ub = uv[2 * b];
            double vb = uv[2 * b + 1];
            if (Math.min(ua, ub) > piece.u1()) {
                break;
            }
            char kind = strip.assignments()[e];
            if (kind == 'B' && rectangular[piece.strip()]) {
                continue; // the outline is drawn whole below
            }
            double[] clipped = clip(ua, va, ub, vb, piece.u0(), piece.u1());
            if (clipped == null) {
                continue;
            }
            double ax = x0 + (clipped[0] - piece.u0()) * scale;
            double ay = bottom - clipped[1] * scale;
            double bx = x0 + (clipped[2] - piece.u0()) * scale;
            double by = bottom - clipped[3] * scale;
            Ink ink = kind == 'V' ? Ink.VALLEY : kind == 'M' ? Ink.MOUNTAIN : kind == 'B' ? Ink.CUT : Ink.FLAT;
            canvas.line(ax, ay, bx, by, ink);
            int step = strip.steps()[e];
            if (step > 0) {
                numberAt.computeIfAbsent(step, k -> new ArrayList<>()).add(new double[] {ax, ay, bx, by});
            }
        }
        // Each crease of a fold numbered beside its longest piece here (a fold through several
        // layers leaves several creases apart), in folding order, none over another.
        double size = Math.min(2.4, 0.3 * h);
        NumberPlaces places = new NumberPlaces(x0, top, x1, bottom, size);
        for (Map.Entry<Integer, List<double[]>> entry : numberAt.entrySet()) {
            String number = Integer.toString(entry.getKey());
            for (double[] at : CreaseRuns.longestOfEach(entry.getValue())) {
                if (Math.hypot(at[2] - at[0], at[3] - at[1]) > 0.5) {
                    double[] place = places.place(number, at[0], at[1], at[2], at[3]);
                    canvas.text(place[0], place[1], size, number, false);
                }
            }
        }
        // The outline: cut all round; where a tab follows, round the tab instead, its base a fold.
        // A sheet of another outline (an L, a box's net) has its border edges cut instead.
        if (!rectangular[piece.strip()] && piece.markOut() == null && piece.markIn() == null) {
            return;
        }
        if (piece.markOut() == null) {
            canvas.outline(new double[] {x0, top, x1, top, x1, bottom, x0, bottom}, Ink.CUT);
        } else {
            double slant = Math.min(1.5, h / 4);
            canvas.outline(new double[] {x0, top, x1, top, x1 + TAB, top + slant, x1 + TAB, bottom - slant, x1, bottom, x0, bottom}, Ink.CUT);
            canvas.line(x1, top, x1, bottom, Ink.TAB);
            canvas.text(x1 + 1.2, (top + bottom) / 2 + 1.2, Math.min(3.2, 0.5 * h), piece.markOut(), true);
        }
        if (piece.markIn() != null) {
            canvas.text(x0 + 0.8, top + Math.min(3.4, 0.5 * h), Math.min(3.2, 0.5 * h), piece.markIn(), true);
        }
    }

    /** The first place in {@code order} whose edge's smallest u is at least {@code u}. */
    private static int lowerBound(Integer[] order, SheetCreases strip, double u) {
        int low = 0;
        int high = order.length;
        while (low < high) {
            int mid = (low + high) >>> 1;
            int e = order[mid];
            double min = Math.min(strip.uv()[2 * strip.edges()[e][0]], strip.uv()[2 * strip.edges()[e][1]]);
            if (min < u) {
                low = mid + 1;
            } else {
                high = mid;
            }
        }
        return low;
    }

    /** The segment (ua, va)-(ub, vb) within u0 <= u <= u1, as ua va ub vb; null where none of it is (or a point). */
    static double[] clip(double ua, double va, double ub, double vb, double u0, double u1) {
        double t0 = 0;
        double t1 = 1;
        double du = ub - ua;
        if (du == 0) {
            if (ua < u0 || ua > u1) {
                return null;
            }
        } else {
            double s0 = (u0 - ua) / du;
            double s1 = (u1 - ua) / du;
            t0 = Math.max(t0, Math.min(s0, s1));
            t1 = Math.min(t1, Math.max(s0, s1));
        }
        if (!(t1 > t0)) {
            return null;
        }
        double dv = vb - va;
        return new double[] {ua + t0 * du, va + t0 * dv, ua + t1 * du, va + t1 * dv};
    }

    private void footer(Canvas canvas, Sheet page) throws IOException {
        double y = page.height() - MARGIN - FOOTER + 7;
        double x = MARGIN;
        Ink[] inks = {Ink.VALLEY, Ink.MOUNTAIN, Ink.CUT, Ink.FLAT};
        String[] words = {"valley fold", "mountain fold", "cut", "edge of a face: no fold"};
        for (int i = 0; i < inks.length; i++) {
            canvas.line(x, y - 1, x + 10, y - 1, inks[i]);
            canvas.text(x + 12, y, 2.8, words[i], false);
            x += 16 + 2.8 * 0.5 * words[i].length();
        }
        boolean sheet = strips.stream().mapToDouble(SheetCreases::length).max().orElse(0) <= SHEET_ASPECT * strips.get(0).width();
        boolean glued = pieceCount() > strips.size();
        // Two lines of about equal length, small enough to fit an A4 page upright between its margins.
        canvas.text(MARGIN, y + 5, 2.4, "Numbers: the order of the folds, as the step diagrams number them. Printed side: the "
                + (sheet ? "sheet's" : "strip's") + " top side, so its valleys fold towards you.", false);
        // At most about 165 characters a line: 190 ended 2 mm from an A4 page's edge, where a printer cuts.
        canvas.text(MARGIN, y + 8.6, 2.4, (glued ? "Glue each piece's start on the tab before it, mark on mark. " : "")
                + "Where a fold turned the paper over, its printed valleys fold away from you, as the step diagrams show.", false);
        // The scale bar: 5 cm, a tick each centimetre.
        double bar = page.height() - MARGIN - 1.5;
        canvas.line(MARGIN, bar, MARGIN + 50, bar, Ink.SCALE);
        for (int cm = 0; cm <= 5; cm++) {
            canvas.line(MARGIN + 10 * cm, bar - (cm % 5 == 0 ? 2.5 : 1.5), MARGIN + 10 * cm, bar, Ink.SCALE);
        }
        canvas.text(MARGIN + 52, bar, 2.8, "5 cm (check the printer's scale against it)", false);
    }
}
