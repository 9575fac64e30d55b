package ifold.print;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.foldfile.FoldFile.SheetCreases;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The layout of a crease pattern on pages, drawn onto a canvas that records what it is asked to draw. */
class CreasePatternPagesTest {
    /** What a page was asked to draw. */
    static final class Recording implements Canvas {
        final List<double[]> pages = new ArrayList<>();
        final List<List<double[]>> cuts = new ArrayList<>();
        final List<List<double[]>> lines = new ArrayList<>();
        final List<List<Ink>> inks = new ArrayList<>();
        final List<List<String>> texts = new ArrayList<>();

        @Override
        public void beginPage(double widthMm, double heightMm) {
            pages.add(new double[] {widthMm, heightMm});
            cuts.add(new ArrayList<>());
            lines.add(new ArrayList<>());
            inks.add(new ArrayList<>());
            texts.add(new ArrayList<>());
        }

        @Override
        public void line(double x1, double y1, double x2, double y2, Ink ink) {
            lines.get(lines.size() - 1).add(new double[] {x1, y1, x2, y2});
            inks.get(inks.size() - 1).add(ink);
        }

        @Override
        public void outline(double[] xy, Ink ink) {
            if (ink == Ink.CUT) {
                cuts.get(cuts.size() - 1).add(xy);
            }
        }

        @Override
        public void fill(double[] xy, int argb) {
        }

        @Override
        public void beginClip(double x, double y, double width, double height) {
        }

        @Override
        public void endClip() {
        }

        @Override
        public void text(double x, double y, double size, String text, boolean bold) {
            texts.get(texts.size() - 1).add(text);
        }

        @Override
        public void endPage() {
        }
    }

    /**
     * A strip 100 long and 1 wide: a valley (fold 1) across it from (8.8, 0) to (9, 1), over the
     * border of the first two pieces at 20 mm a unit, and a mountain (fold 2) at u = 50.
     */
    static SheetCreases strip() {
        double[] uv = {0, 0, 100, 0, 100, 1, 0, 1, 8.8, 0, 9, 1, 50, 0, 50, 1};
        int[][] edges = {{0, 4}, {4, 6}, {6, 1}, {1, 2}, {2, 7}, {7, 5}, {5, 3}, {3, 0}, {4, 5}, {6, 7}};
        char[] kinds = "BBBBBBBBVM".toCharArray();
        int[] steps = {0, 0, 0, 0, 0, 0, 0, 0, 1, 2};
        return new SheetCreases(100, 1, uv, edges, kinds, steps);
    }

    @Test
    void piecesPutEndToEndGiveBackTheStripAndJoinMarkOnMark() throws Exception {
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(20, Page.A4));
        assertEquals(20, pages.scale(), 1e-12);
        // A4: pieces 210 - 2 × 12 - 8 = 178 mm long; 2,000 mm of strip make 12; 8 rows a page.
        assertEquals(12, pages.pieceCount());
        assertEquals(2, pages.pageCount());
        Recording canvas = new Recording();
        pages.draw(canvas);
        double length = 0;
        int pieces = 0;
        for (List<double[]> page : canvas.cuts) {
            for (double[] outline : page) {
                length += outline[2] - outline[0]; // from its start to its end (a tab beyond, if any)
                assertEquals(20, Math.abs(outline[outline.length - 1] - outline[1]), 1e-9, "20 mm wide");
                pieces++;
            }
        }
        assertEquals(12, pieces);
        assertEquals(100, length / pages.scale(), 1e-6, "the pieces end to end are the strip");
        assertEquals(210, canvas.pages.get(0)[0], 1e-12);
        assertEquals(297, canvas.pages.get(0)[1], 1e-12);
        // Each join's mark is on both pieces: A on the first's tab and on the second's start.
        List<String> first = canvas.texts.get(0);
        assertTrue(first.contains("piece 1 of 12; glue piece 2 on its tab at mark A"), first.toString());
        assertTrue(first.contains("piece 2 of 12; its start goes over the tab of piece 1 at mark A; glue piece 3 on its tab at mark B"),
                first.toString());
        assertTrue(canvas.texts.get(1).contains("piece 12 of 12; its start goes over the tab of piece 11 at mark K"),
                canvas.texts.get(1).toString());
    }

    @Test
    void aCreaseOverTheBorderOfTwoPiecesIsDrawnOnBothAndNumberedInEach() throws Exception {
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(20, Page.A4));
        Recording canvas = new Recording();
        pages.draw(canvas);
        List<double[]> valleys = new ArrayList<>();
        List<double[]> mountains = new ArrayList<>();
        for (int i = 0; i < canvas.lines.get(0).size(); i++) {
            if (canvas.inks.get(0).get(i) == Ink.VALLEY && canvas.lines.get(0).get(i)[1] < 250) {
                valleys.add(canvas.lines.get(0).get(i));
            }
        }
        for (int p = 0; p < canvas.lines.size(); p++) {
            for (int i = 0; i < canvas.lines.get(p).size(); i++) {
                if (canvas.inks.get(p).get(i) == Ink.MOUNTAIN && canvas.lines.get(p).get(i)[1] < 250) {
                    mountains.add(canvas.lines.get(p).get(i));
                }
            }
        }
        assertEquals(2, valleys.size(), "the valley's two parts, one a piece");
        // The border is at u = 8.9: the first part ends at the first piece's end, x = 12 + 178; the
        // second starts at the second piece's start, x = 12; both halfway up the strip.
        double[] a = valleys.get(0);
        double[] b = valleys.get(1);
        assertEquals(12 + 178, Math.max(a[0], a[2]), 1e-9);
        assertEquals(12, Math.min(b[0], b[2]), 1e-9);
        assertEquals(Math.min(a[1], a[3]) + 10, Math.max(a[1], a[3]), 1e-9, "the first half rises 10 mm");
        assertEquals(1, mountains.size(), "the mountain at u = 50 inside one piece");
        assertEquals(20, Math.abs(mountains.get(0)[3] - mountains.get(0)[1]), 1e-9, "across the whole strip");
        long ones = canvas.texts.get(0).stream().filter("1"::equals).count();
        assertEquals(2, ones, "fold 1 numbered on each piece it crosses");
        assertTrue(canvas.texts.get(0).contains("5 cm (check the printer's scale against it)"));
    }

    @Test
    void oneLongPageHoldsTheWholeStrip() throws Exception {
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(20, Page.NONE));
        assertEquals(1, pages.pageCount());
        assertEquals(1, pages.pieceCount());
        Recording canvas = new Recording();
        pages.draw(canvas);
        assertEquals(2000 + 2 * CreasePatternPages.MARGIN, canvas.pages.get(0)[0], 1e-9);
        assertEquals(2000, canvas.cuts.get(0).get(0)[2] - canvas.cuts.get(0).get(0)[0], 1e-9);
    }

    @Test
    void whatDoesNotFitIsRefusedNamingAWidthThatDoes() {
        IllegalArgumentException wide = assertThrows(IllegalArgumentException.class,
                () -> CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(300, Page.A4)));
        assertTrue(wide.getMessage().contains("a strip 300.0 mm wide does not fit the page (a4): at most 230 mm"),
                wide.getMessage());
        SheetCreases long1 = new SheetCreases(1e5, 1, new double[] {0, 0, 1e5, 0, 1e5, 1, 0, 1}, new int[][] {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
                "BBBB".toCharArray(), new int[4]);
        IllegalArgumentException many = assertThrows(IllegalArgumentException.class,
                () -> CreasePatternPages.of("test", "by hand", List.of(long1), new CreasePatternPages.Options(20, Page.A4)));
        assertTrue(many.getMessage().contains("more than 500") && many.getMessage().contains("mm fits"), many.getMessage());
    }

    @Test
    void marksRunFromAToZThenTwoLetters() {
        assertEquals("A", CreasePatternPages.letters(0));
        assertEquals("Z", CreasePatternPages.letters(25));
        assertEquals("AA", CreasePatternPages.letters(26));
        assertEquals("AB", CreasePatternPages.letters(27));
        assertEquals("ZZ", CreasePatternPages.letters(701));
        assertEquals("AAA", CreasePatternPages.letters(702));
    }

    /**
     * Where no width is asked, a strip is printed 2 cm wide, and a sheet (a fold script's square)
     * in one piece as large as the page holds, in whole centimetres, said so in the header.
     */
    @Test
    void automaticWidthPrintsAStripTwoCentimetresWideAndASheetAsLargeAsThePageHolds() throws Exception {
        CreasePatternPages strip = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(Double.NaN, Page.A4));
        assertEquals(20, strip.scale(), 1e-12);
        double[] uv = {0, 0, 10, 0, 10, 10, 0, 10, 5, 0, 5, 10};
        int[][] edges = {{0, 4}, {4, 1}, {1, 2}, {2, 5}, {5, 3}, {3, 0}, {4, 5}};
        SheetCreases square = new SheetCreases(10, 10, uv, edges, "BBBBBBV".toCharArray(), new int[] {0, 0, 0, 0, 0, 0, 1});
        CreasePatternPages sheet = CreasePatternPages.of("test", "by hand", List.of(square), new CreasePatternPages.Options(Double.NaN, Page.A4));
        // A4 is 210 mm wide: 12 mm margins and room for a tab leave 178 mm, so 17 cm.
        assertEquals(17, sheet.scale(), 1e-12);
        assertEquals(1, sheet.pieceCount());
        assertEquals(13, CreasePatternPages.of("test", "by hand", List.of(square), new CreasePatternPages.Options(Double.NaN, Page.A4_LANDSCAPE))
                .scale(), 1e-12, "on its side the page's height limits it: 210 mm less margins, header, footer and label leave 139 mm");
        Recording canvas = new Recording();
        sheet.draw(canvas);
        assertTrue(canvas.texts.get(0).stream().anyMatch(t -> t.contains("the sheet 17 cm wide")), canvas.texts.get(0).toString());
        assertTrue(Double.isNaN(Lengths.millimetres("auto")));
    }

    /**
     * A fold through two layers leaves two creases apart: each is numbered. A crease cut into
     * edges by a flat edge across it is still one crease, numbered once.
     */
    @Test
    void eachCreaseOfAFoldIsNumberedButACreaseCutInEdgesOnce() throws Exception {
        // Fold 1 creases at u = 5 (cut in two at v = 0.5 by a flat edge) and at u = 7, both on the first piece.
        double[] uv = {0, 0, 60, 0, 60, 1, 0, 1, 5, 0, 5, 0.5, 5, 1, 7, 0, 7, 1, 0, 0.5};
        int[][] edges = {{0, 4}, {4, 7}, {7, 1}, {1, 2}, {2, 8}, {8, 6}, {6, 3}, {3, 9}, {9, 0}, {4, 5}, {5, 6}, {7, 8}, {9, 5}};
        char[] kinds = "BBBBBBBBBVVMF".toCharArray();
        int[] steps = {0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 0};
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(new SheetCreases(60, 1, uv, edges, kinds, steps)),
                new CreasePatternPages.Options(20, Page.A4));
        Recording canvas = new Recording();
        pages.draw(canvas);
        long ones = canvas.texts.stream().flatMap(List::stream).filter("1"::equals).count();
        assertEquals(2, ones, "the crease at u = 5 (two edges) and the one at u = 7: " + canvas.texts);
    }

    @Test
    void lengthsAndPagesAreReadAsWritten() {
        assertEquals(20, Lengths.millimetres("2cm"), 1e-12);
        assertEquals(20, Lengths.millimetres("20 mm"), 1e-12);
        assertEquals(25.4, Lengths.millimetres("1in"), 1e-12);
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Lengths.millimetres("2")).getMessage().contains("with its unit"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Lengths.millimetres("0.1mm")).getMessage().contains("from 2 mm"));
        assertEquals(Page.A4_LANDSCAPE, Page.of("A4-Landscape"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Page.of("a5")).getMessage().contains("expected a4"));
    }

    @Test
    void aTemplateGoesUnderTheLastPieceWhereItFitsElseOnAPageOfItsOwn() throws Exception {
        CreasePatternPages.Template small = new CreasePatternPages.Template("the triangle", new double[] {0, 0, 5, 0, 2, 4},
                new String[] {"A", "B", "C"});
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(20, Page.A4),
                small);
        assertEquals(2, pages.pageCount(), "under the last piece of page 2 (4 pieces there, 80 mm of template)");
        Recording canvas = new Recording();
        pages.draw(canvas);
        assertTrue(canvas.texts.get(1).contains("the triangle"));
        assertEquals(5, canvas.cuts.get(1).size(), "four pieces and the triangle");
        CreasePatternPages.Template large = new CreasePatternPages.Template("the triangle", new double[] {0, 0, 8, 0, 2, 11},
                new String[] {"A", "B", "C"});
        CreasePatternPages more = CreasePatternPages.of("test", "by hand", List.of(strip()), new CreasePatternPages.Options(20, Page.A4),
                large);
        assertEquals(3, more.pageCount(), "220 mm high: a page of its own");
    }
}
