package ifold.job;

import ifold.foldfile.FoldFile;
import ifold.geom.Triangle;
import ifold.print.CreasePatternPages;
import ifold.print.Page;
import ifold.print.PdfCanvas;
import ifold.print.StepDiagrams;
import ifold.print.SvgCanvas;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.sheet.HostFrame;
import ifold.sheet.Sheet;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Folded sheets' crease pattern printed at real size, as {@code --export-pdf}, {@code
 * --export-svg} and the window's Export crease pattern print it ({@link CreasePatternPages}):
 * a PDF of every page, or SVG files a page ({@code NAME-01.svg}, ...; {@code NAME.svg} itself
 * where there is one page).
 */
public final class PrintJob {
    private PrintJob() {
    }

    /** How each job folded, for a printed page's header, as both front ends say it. */
    public static final String ZIGZAG = "the zig-zag of one triangle (Demaine, Demaine and Mitchell)";
    /** See {@link #ZIGZAG}. */
    public static final String TURN = "the turn gadget (Demaine, Demaine and Mitchell)";
    /** See {@link #ZIGZAG}. */
    public static final String WRAP = "the zig-zag wrap (Demaine, Demaine and Mitchell)";
    /** See {@link #ZIGZAG}. */
    public static final String HINGE = "the hinge strip (Benbernou, Demaine, Demaine and Lubiw)";

    /** The header's words for a wrap by {@code method}. */
    public static String wrap(ifold.wrap.Wrap.Method method) {
        return method == ifold.wrap.Wrap.Method.HINGE ? HINGE : WRAP;
    }
    /** See {@link #ZIGZAG}. */
    public static final String SCRIPT = "a fold script's sheet";
    public static final String FOLD = "a FOLD file's crease pattern";

    /**
     * What to print.
     *
     * @param sheets the folded sheets, as their FOLD file has them
     * @param title what was folded: the model's or the script's name, "a triangle zig-zagged"
     * @param method how, in words, for the header
     * @param options the strip's width on paper and the page
     * @param file where: .pdf or .svg
     */
    public record Request(List<FoldFile.Folded> sheets, String title, String method, CreasePatternPages.Options options, Path file,
            CreasePatternPages.Template template) {
        /** Without a template. */
        public Request(List<FoldFile.Folded> sheets, String title, String method, CreasePatternPages.Options options, Path file) {
            this(sheets, title, method, options, file, null);
        }
    }

    /**
     * The zig-zag demo's triangle as a template to print beside its strip: {@code shape}'s corners
     * A, B, C in the plane of {@code frame} (the host the strip was folded on), and where the
     * strip's first piece lies on it.
     */
    public static CreasePatternPages.Template triangle(Triangle shape, HostFrame frame, Sheet strip) {
        double[] xy = new double[6];
        for (int k = 0; k < 3; k++) {
            double[] p = {shape.corner(k).x(), shape.corner(k).y(), shape.corner(k).z()};
            xy[2 * k] = frame.localX(p);
            xy[2 * k + 1] = frame.localY(p);
        }
        // The strip's first face, as it lies on the triangle: where piece 1 goes, and which side up.
        boolean faceUp = !strip.pose(0).mirrors();
        return new CreasePatternPages.Template("the triangle the strip wraps, at the same scale: cut it out of card, top side up",
                xy, new String[] {"A", "B", "C"}, strip.placed(0), "piece 1 starts here, printed side " + (faceUp ? "up" : "down"));
    }

    /** What was printed: the files written, the pages and the pieces. */
    public record Printed(List<Path> files, int pages, int pieces) {
        /** "wrote zigzag.pdf: 1 page, 4 pieces", or "wrote cube-01.svg to cube-45.svg: 45 pages, 360 pieces". */
        public String summary() {
            String where = files.size() == 1 ? files.get(0).toString() : files.get(0) + " to " + files.get(files.size() - 1).getFileName();
            return String.format(Locale.ROOT, "wrote %s: %d page%s, %d piece%s", where, pages, pages == 1 ? "" : "s", pieces,
                    pieces == 1 ? "" : "s");
        }

        /** Step diagrams' line, their pieces being steps: "wrote steps.pdf: 4 pages, 12 steps". */
        public String stepsSummary() {
            return String.format(Locale.ROOT, "wrote %s: %d page%s, %d step%s", files.get(0), pages, pages == 1 ? "" : "s", pieces,
                    pieces == 1 ? "" : "s");
        }
    }

    /** Whether iFold prints to {@code file}: its name ends in .pdf or .svg, in any case. */
    public static boolean prints(Path file) {
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        return name.endsWith(".pdf") || name.endsWith(".svg");
    }

    /**
     * Lays out and prints to the request's file. On failure the files already written are taken back.
     *
     * @throws IllegalArgumentException where the width asked does not fit the page, or would take
     *     more than {@link CreasePatternPages#MOST_PAGES} pages (naming a width that fits)
     * @throws IOException where a file cannot be written
     */
    public static Printed run(Request request, JobWatcher watcher) throws IOException {
        return write(layOut(request, watcher), request.file(), watcher);
    }

    /**
     * The request's crease pattern laid out on pages, to write to one file or more ({@link #write}).
     *
     * @throws IllegalArgumentException as {@link #run} says
     */
    public static CreasePatternPages layOut(Request request, JobWatcher watcher) {
        watcher.stage("laying out the crease pattern");
        CreasePatternPages pages = CreasePatternPages.of(request.title(), request.method(), FoldFile.creases(request.sheets()),
                request.options(), request.template());
        String name = request.file().getFileName() == null ? "" : request.file().getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".pdf") && pages.longestSide() > PdfCanvas.LONGEST_SIDE_MM) {
            throw new IllegalArgumentException(String.format(Locale.ROOT, "--page none makes one page %.1f m long, and a PDF page is at most"
                    + " %.2f m (200 in), the most PDF readers open: print on pages (--page a4) or as SVG", pages.longestSide() / 1000,
                    PdfCanvas.LONGEST_SIDE_MM / 1000));
        }
        watcher.stopIfAsked();
        return pages;
    }

    /**
     * Writes {@code pages} to {@code file}: a PDF, or SVG files a page. On failure the files
     * already written are taken back.
     *
     * @throws IllegalArgumentException where the file is named neither .pdf nor .svg
     * @throws IOException where a file cannot be written
     */
    public static Printed write(CreasePatternPages pages, Path file, JobWatcher watcher) throws IOException {
        if (!prints(file)) {
            throw new IllegalArgumentException("a crease pattern is printed as .pdf or .svg, got " + file.getFileName());
        }
        watcher.stage("printing " + file.getFileName());
        List<Path> written = new ArrayList<>();
        boolean done = false;
        try {
            if (file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pdf")) {
                try (PdfCanvas pdf = new PdfCanvas()) {
                    pages.draw(pdf);
                    watcher.stopIfAsked();
                    pdf.save(file);
                }
                written.add(file);
            } else {
                int count = pages.pageCount();
                String name = file.getFileName().toString();
                String stem = name.substring(0, name.length() - 4);
                String digits = "%0" + Math.max(2, Integer.toString(count).length()) + "d"; // cube-01.svg, as the README says
                SvgCanvas svg = new SvgCanvas(p -> count == 1 ? file
                        : file.resolveSibling(stem + "-" + String.format(Locale.ROOT, digits, p + 1) + name.substring(name.length() - 4)));
                try {
                    pages.draw(svg);
                } finally {
                    written.addAll(svg.written());
                }
            }
            done = true;
        } finally {
            if (!done) {
                for (Path path : written) {
                    java.nio.file.Files.deleteIfExists(path);
                }
            }
        }
        return new Printed(List.copyOf(written), pages.pageCount(), pages.pieceCount());
    }

    /**
     * Step diagrams of {@code animation} in {@code scene} (the movie's own, made afresh for them):
     * a title page and a panel a fold, as one PDF of pages of {@code page}'s size written to
     * {@code file}, whole or not at all.
     *
     * @return the file, its pages and its steps, the numbered panels (as {@link Printed#pieces}: {@link StepDiagrams#stepCount})
     */
    public static Printed diagrams(String title, String method, Scene scene, Animation animation, Path file, Page page, JobWatcher watcher)
            throws IOException {
        watcher.stage("drawing the step diagrams");
        int pages;
        try (PdfCanvas pdf = new PdfCanvas()) {
            pages = StepDiagrams.draw(title, method, scene, animation, pdf, page);
            watcher.stopIfAsked();
            pdf.save(file);
        }
        return new Printed(List.of(file), pages, StepDiagrams.stepCount(animation));
    }
}
