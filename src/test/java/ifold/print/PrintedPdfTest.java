package ifold.print;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.imageio.ImageIO;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The PDF as a printer sees it: rendered by poppler's pdftoppm at 10 pixels a millimetre and
 * read back by pixels (its text by pdftotext). Skipped where poppler-utils is not installed
 * (scripts/setup installs it).
 */
class PrintedPdfTest {
    @TempDir
    Path dir;

    private static boolean has(String tool) {
        try {
            Process p = new ProcessBuilder(tool, "-v").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor(20, TimeUnit.SECONDS);
        } catch (Exception e) {
            return false;
        }
    }

    private static void run(String... command) throws Exception {
        Process p = new ProcessBuilder(command).redirectErrorStream(true).start();
        String output = new String(p.getInputStream().readAllBytes());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "finished: " + String.join(" ", command));
        assertEquals(0, p.exitValue(), output);
    }

    private Path printed() throws Exception {
        CreasePatternPages pages = CreasePatternPages.of("test", "by hand", List.of(CreasePatternPagesTest.strip()),
                new CreasePatternPages.Options(20, Page.A4));
        Path pdf = dir.resolve("strip.pdf");
        try (PdfCanvas canvas = new PdfCanvas()) {
            pages.draw(canvas);
            canvas.save(pdf);
        }
        return pdf;
    }

    /** Runs of dark pixels along the column x from y0 to y1: their lengths in order. */
    private static List<Integer> darkRuns(BufferedImage image, int x, int y0, int y1) {
        List<Integer> runs = new ArrayList<>();
        int run = 0;
        for (int y = y0; y <= y1; y++) {
            boolean dark = false;
            for (int dx = -2; dx <= 2 && !dark; dx++) {
                int rgb = image.getRGB(x + dx, y);
                int r = (rgb >> 16) & 255;
                int g = (rgb >> 8) & 255;
                int b = rgb & 255;
                dark = r + g + b < 500;
            }
            if (dark) {
                run++;
            } else if (run > 0) {
                runs.add(run);
                run = 0;
            }
        }
        if (run > 0) {
            runs.add(run);
        }
        return runs;
    }

    @Test
    void theScaleBarIsFiveCentimetresAndTheFoldsHaveTheirLineStyles() throws Exception {
        assumeTrue(has("pdftoppm"), "pdftoppm (poppler-utils) is not installed");
        Path pdf = printed();
        run("pdftoppm", "-r", "254", "-png", pdf.toString(), dir.resolve("page").toString());
        List<Path> pngs;
        try (var files = Files.list(dir)) {
            pngs = files.filter(f -> f.getFileName().toString().endsWith(".png")).sorted().toList();
        }
        assertEquals(2, pngs.size(), "two pages");
        BufferedImage page = ImageIO.read(pngs.get(0).toFile());
        assertEquals(2100, page.getWidth(), 2, "210 mm at 10 px a millimetre");
        assertEquals(2970, page.getHeight(), 2);
        // The scale bar: 1.5 mm above the bottom margin, from x = 12 mm, 50 mm long.
        int row = (int) Math.round((297 - 12 - 1.5) * 10);
        int first = 0;
        while (first < 1000 && (page.getRGB(first, row) & 255) >= 100) {
            first++;
        }
        int last = first;
        while (last + 1 < page.getWidth() && (page.getRGB(last + 1, row) & 255) < 100) {
            last++; // the bar, unbroken, up to the gap before its caption
        }
        assertEquals(120, first, 3, "the bar starts at the margin, 12 mm in");
        assertEquals(500, last - first, 4, "the scale bar measures 5 cm");
        // The mountain at u = 50, 1,000 mm along the strip, lies in the sixth piece of 178 mm (the
        // sixth row), 1,000 - 5 × 178 = 110 mm in from its start.
        int pieceTop6 = (12 + 16 + 5 + 5 * (5 + 20 + 4)) * 10;
        List<Integer> mountain = darkRuns(page, (12 + 110) * 10, pieceTop6 + 8, pieceTop6 + 192);
        assertTrue(mountain.stream().anyMatch(r -> r >= 18) && mountain.stream().anyMatch(r -> r <= 8),
                "dash-dot-dot: long dashes and short dots along the mountain: " + mountain);
        // The valley above runs at a slant and is cut by a piece's end: sample a valley of its own,
        // straight across a strip at u = 5, 100 mm from its start.
        double[] uv = {0, 0, 10, 0, 10, 1, 0, 1, 5, 0, 5, 1};
        int[][] edges = {{0, 4}, {4, 1}, {1, 2}, {2, 5}, {5, 3}, {3, 0}, {4, 5}};
        ifold.foldfile.FoldFile.SheetCreases across = new ifold.foldfile.FoldFile.SheetCreases(10, 1, uv, edges, "BBBBBBV".toCharArray(),
                new int[] {0, 0, 0, 0, 0, 0, 1});
        CreasePatternPages one = CreasePatternPages.of("valley", "by hand", List.of(across), new CreasePatternPages.Options(20, Page.A4));
        Path valleyPdf = dir.resolve("valley.pdf");
        try (PdfCanvas canvas = new PdfCanvas()) {
            one.draw(canvas);
            canvas.save(valleyPdf);
        }
        run("pdftoppm", "-r", "254", "-png", valleyPdf.toString(), dir.resolve("valley").toString());
        BufferedImage valleyPage = ImageIO.read(dir.resolve("valley-1.png").toFile());
        int pieceTop = (12 + 16 + 5) * 10;
        List<Integer> valley = darkRuns(valleyPage, (12 + 100) * 10, pieceTop + 8, pieceTop + 192);
        // The sampled stretch cuts the first and last dashes short: the whole ones between.
        assertTrue(valley.size() >= 5 && valley.subList(1, valley.size() - 1).stream().allMatch(r -> r >= 20),
                "dashes of 2.4 mm, no dots, along the valley: " + valley);
    }

    @Test
    void theNumbersAndLabelsAreText() throws Exception {
        assumeTrue(has("pdftotext"), "pdftotext (poppler-utils) is not installed");
        Path pdf = printed();
        Path text = dir.resolve("strip.txt");
        run("pdftotext", "-layout", pdf.toString(), text.toString());
        String words = Files.readString(text);
        assertTrue(words.contains("piece 1 of 12; glue piece 2 on its tab at mark A"), words);
        assertTrue(words.contains("5 cm"), words);
        assertTrue(words.contains("page 1 of 2"), words);
        assertTrue(words.matches("(?s).*\\b2\\b.*"), "fold 2's number: " + words);
    }
}
