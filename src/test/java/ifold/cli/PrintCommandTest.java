package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Crease patterns printed from the command line: --export-pdf, --export-svg, --paper-width, --page. */
class PrintCommandTest {
    @TempDir
    Path dir;

    @Test
    void theZigZagsStripPrintsOnOnePageAsPdfAndSvg() throws Exception {
        Path pdf = dir.resolve("zigzag.pdf");
        Path svg = dir.resolve("zigzag.svg");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--no-view", "--export-pdf", pdf.toString(), "--export-svg", svg.toString());
        assertEquals(0, run.code(), run.err());
        assertEquals("", run.err());
        assertTrue(run.out().contains("wrote " + pdf + ": 1 page, 4 pieces"), run.out());
        assertTrue(run.out().contains("wrote " + svg + ": 1 page, 4 pieces"), run.out());
        assertTrue(new String(Files.readAllBytes(pdf), 0, 5).equals("%PDF-"), "a PDF");
        String page = Files.readString(svg);
        assertTrue(page.contains("width=\"210mm\" height=\"297mm\""), "A4 in millimetres");
        for (String kind : List.of("cut", "valley", "mountain", "tab", "scale")) {
            assertTrue(page.contains("class=\"" + kind + "\""), kind + " lines");
        }
        // The triangle to fold it on, at the strip's scale (12.5 mm a unit): the demo's 0,0 10,0 3.5,8.
        assertTrue(page.contains("the triangle the strip wraps, at the same scale"), "the triangle's template");
        Matcher triangle = Pattern.compile("<polygon class=\"cut\" points=\"([-0-9.,]+) ([-0-9.,]+) ([-0-9.,]+)\"/>").matcher(page);
        assertTrue(triangle.find(), "a triangle cut out");
        double[] xs = new double[3];
        double[] ys = new double[3];
        for (int k = 0; k < 3; k++) {
            String[] xy = triangle.group(k + 1).split(",");
            xs[k] = Double.parseDouble(xy[0]);
            ys[k] = Double.parseDouble(xy[1]);
        }
        double ab = Math.hypot(xs[1] - xs[0], ys[1] - ys[0]);
        double area = Math.abs((xs[1] - xs[0]) * (ys[2] - ys[0]) - (xs[2] - xs[0]) * (ys[1] - ys[0])) / 2;
        assertEquals(10 * 12.5, ab, 1e-2, "side AB, 10 units");
        assertEquals(10 * 8 / 2.0 * 12.5 * 12.5, area, 1, "its area, at the strip's scale");
    }

    /** The cube's strip on A4 pages: its pieces end to end, in the SVGs' millimetres, are the report's L. */
    @Test
    void theCubesWrapPrintsAsNumberedPiecesThatAddUpToTheStrip() throws Exception {
        Path svg = dir.resolve("cube.svg");
        Path report = dir.resolve("cube.json");
        CliTest.Run run = CliTest.run("wrap", "models/cube.off", "--no-view", "--export-svg", svg.toString(), "--paper-width", "3cm",
                "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        Matcher counts = Pattern.compile("wrote \\S+cube-0*1\\.svg to cube-(\\d+)\\.svg: (\\d+) pages, (\\d+) pieces").matcher(run.out());
        assertTrue(counts.find(), run.out());
        int pages = Integer.parseInt(counts.group(2));
        int pieces = Integer.parseInt(counts.group(3));
        String json = Files.readString(report);
        double length = CliTest.number(json.substring(json.indexOf("\"strips\"")), "length");
        double width = CliTest.number(json, "width");
        double mm = 0;
        int outlines = 0;
        Pattern cut = Pattern.compile("<polygon class=\"cut\" points=\"([-0-9.]+),[-0-9.]+ ([-0-9.]+),");
        String digits = "%0" + counts.group(1).length() + "d"; // as wide as the last page's number is written
        for (int p = 1; p <= pages; p++) {
            String page = Files.readString(dir.resolve("cube-" + String.format(digits, p) + ".svg"));
            Matcher m = cut.matcher(page);
            while (m.find()) {
                mm += Double.parseDouble(m.group(2)) - Double.parseDouble(m.group(1));
                outlines++;
            }
            assertTrue(page.contains(String.format("page %d of %d", p, pages)), "page " + p + " says which it is");
        }
        assertEquals(pieces, outlines, "an outline a piece");
        // SVG coordinates are written to a thousandth of a millimetre: a rounding of 5e-4 mm a piece.
        assertEquals(length, mm / (30 / width), pieces * 1e-3 / (30 / width) + 1e-6 * length, "the pieces end to end are the strip");
    }

    @Test
    void badValuesAreRefusedInOneLineAndNothingIsWritten() throws Exception {
        Path pdf = dir.resolve("out.pdf");
        Object[][] cases = {
            {new String[] {"--paper-width", "2"}, "option --paper-width: expected auto or a length with its unit"},
            {new String[] {"--paper-width", "1mm"}, "option --paper-width: must be from 2 mm to 1 m"},
            {new String[] {"--page", "a5"}, "option --page: expected a4, a4-landscape, letter, letter-landscape or none"},
            {new String[] {"--paper-width", "30cm"}, "option --paper-width: a strip 300.0 mm wide does not fit the page (a4): at most"},
            // One page as long as the strip: 48.4 units at 100 mm a unit is 4.8 m, within PDF's 5.08 m; at 1 m wide, 30 m.
            {new String[] {"--page", "none", "--paper-width", "1m"}, "option --page: --page none makes one page 30.3 m long, and a PDF page"
                + " is at most 5.08 m"},
            // Two outputs into one file: the second would overwrite the first.
            {new String[] {"--export-diagrams", pdf.toString()}, "option --export-diagrams: " + pdf + " is the file --export-pdf writes too"},
        };
        for (Object[] c : cases) {
            String[] extra = (String[]) c[0];
            String[] args = new String[4 + extra.length];
            args[0] = "demo";
            args[1] = "zigzag";
            args[2] = "--no-view";
            args[3] = "--export-pdf=" + pdf;
            System.arraycopy(extra, 0, args, 4, extra.length);
            CliTest.Run run = CliTest.run(args);
            CliTest.assertOneLineError(run, (String) c[1]);
            assertFalse(Files.exists(pdf), "nothing written for " + String.join(" ", extra));
        }
        // Print options with nothing to print would be ignored without a word.
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--page", "letter"), "option --page: only with");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--paper-width", "3cm", "--export-diagrams",
                dir.resolve("d.pdf").toString()), "option --paper-width: only with --export-pdf or --export-svg");
        // A device, or a pipe, is not replaced by a file (a link to /dev/full became a PDF).
        Path device = dir.resolve("full.pdf");
        Files.createSymbolicLink(device, Path.of("/dev/null"));
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--export-pdf", device.toString()),
                "option --export-pdf: " + device + " is not a regular file");
        assertTrue(Files.isSymbolicLink(device) && !Files.isRegularFile(device), "the link and its device stay as they were");
        CliTest.assertOneLineError(CliTest.run("demo", "zigzag", "--no-view", "--export-pdf", dir.toString()), "option --export-pdf: "
                + dir + " is a folder");
        CliTest.Run wrongName = CliTest.run("demo", "zigzag", "--no-view", "--export-pdf", dir.resolve("out.png").toString());
        CliTest.assertOneLineError(wrongName, "--export-pdf");
        CliTest.Run wrongSvg = CliTest.run("demo", "zigzag", "--no-view", "--export-svg", dir.resolve("out.pdf").toString());
        CliTest.assertOneLineError(wrongSvg, "--export-svg");
    }

    /**
     * Step diagrams: a title page, then the zig-zag's 12 folds and its end six to a page, each captioned as the
     * movie captions it; a fold script's 20 folds likewise. Their text read back by pdftotext and
     * their panels' paper by pixels (pdftoppm), where poppler-utils is installed.
     */
    @Test
    void stepDiagramsHaveAPanelAFoldCaptionedAsTheMovie() throws Exception {
        Path pdf = dir.resolve("steps.pdf");
        CliTest.Run run = CliTest.run("demo", "zigzag", "--no-view", "--export-diagrams", pdf.toString());
        assertEquals(0, run.code(), run.err());
        // 12 folds, numbered, and the strip's end, drawn but no step.
        assertTrue(run.out().contains("wrote " + pdf + ": 4 pages, 12 steps"), run.out());
        Path script = dir.resolve("script.pdf");
        CliTest.Run folded = CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--export-diagrams", script.toString());
        assertEquals(0, folded.code(), folded.err());
        assertTrue(folded.out().contains("wrote " + script + ": 5 pages, 20 steps"), folded.out());
        Path none = dir.resolve("none.pdf");
        CliTest.Run unfolded = CliTest.run("fold", Files.writeString(dir.resolve("flat.fold"), "paper square 4\n").toString(), "--no-view",
                "--export-diagrams", none.toString());
        assertTrue(unfolded.out().contains("wrote " + none + ": 1 page, 0 steps"), unfolded.out());
        CliTest.Run wrong = CliTest.run("demo", "zigzag", "--no-view", "--export-diagrams", dir.resolve("steps.png").toString());
        CliTest.assertOneLineError(wrong, "--export-diagrams");
        if (!tool("pdftotext") || !tool("pdftoppm")) {
            return; // poppler-utils missing: scripts/setup installs it
        }
        Path text = dir.resolve("steps.txt");
        assertEquals(0, new ProcessBuilder("pdftotext", "-layout", pdf.toString(), text.toString()).start().waitFor());
        String words = Files.readString(text);
        assertTrue(words.contains("The steps") && words.contains("1. pass 1 of 5: turn, 45° valley fold"), words);
        assertTrue(words.contains("tuck 1: excess folded under along edge"), words);
        // The title page counts the steps its list numbers: the strip's end is listed without a number.
        assertTrue(words.contains("step diagrams, 12 steps, page 1 of 4") && words.contains("\n12. tuck 4")
                && !words.contains("13.") && words.contains("\nthe strip ends"), words);
        assertEquals(0, new ProcessBuilder("pdftoppm", "-r", "50", "-png", "-f", "2", "-l", "2", pdf.toString(), dir.resolve("page").toString())
                .start().waitFor());
        Path png;
        try (var files = Files.list(dir)) {
            png = files.filter(f -> f.getFileName().toString().startsWith("page") && f.getFileName().toString().endsWith(".png")).findFirst()
                    .orElseThrow();
        }
        java.awt.image.BufferedImage page = javax.imageio.ImageIO.read(png.toFile());
        // The first panel: 12 mm in, below the header and its caption, 90 by about 68 mm; at 50 dpi a mm is 1.97 px.
        int paper = 0;
        int model = 0;
        for (int y = (int) (40 * 1.97); y < (int) (100 * 1.97); y++) {
            for (int x = (int) (14 * 1.97); x < (int) (100 * 1.97); x++) {
                int rgb = page.getRGB(x, y) & 0xFFFFFF;
                int r = rgb >> 16;
                int g = (rgb >> 8) & 255;
                int b = rgb & 255;
                paper += r > 200 && r < 250 && Math.abs(r - g) < 12 && b < r ? 1 : 0; // the cream top side, lit
                model += r < 140 && g < 150 && b < 170 && b > r ? 1 : 0; // the blue-grey triangle
            }
        }
        assertTrue(paper > 200, "paper in the first panel: " + paper + " pixels");
        assertTrue(model > 1000, "the triangle in the first panel: " + model + " pixels");
        // Each fold's crease in its style's colour: the first fold a valley (blue), the second a mountain (red).
        assertTrue(inked(page, 50, 14, 100, true) > 5 && inked(page, 50, 14, 100, false) == 0, "fold 1's valley, and no mountain, in panel 1");
        assertTrue(inked(page, 50, 110, 196, false) > 5 && inked(page, 50, 110, 196, true) == 0, "fold 2's mountain, and no valley, in panel 2");
        // A fold script's too: pleat20's first fold a valley, its second a mountain.
        // Its creases are short (the strip's width), so at 150 dpi.
        assertEquals(0, new ProcessBuilder("pdftoppm", "-r", "150", "-png", "-f", "2", "-l", "2", script.toString(), dir.resolve("pleat").toString())
                .start().waitFor());
        java.awt.image.BufferedImage pleat;
        try (var files = Files.list(dir)) {
            pleat = javax.imageio.ImageIO.read(files.filter(f -> f.getFileName().toString().startsWith("pleat")).findFirst().orElseThrow()
                    .toFile());
        }
        assertTrue(inked(pleat, 150, 14, 100, true) > 5 && inked(pleat, 150, 14, 100, false) == 0, "pleat20's fold 1, a valley");
        assertTrue(inked(pleat, 150, 110, 196, false) > 5 && inked(pleat, 150, 110, 196, true) == 0, "pleat20's fold 2, a mountain");
    }

    /**
     * A wrap's diagrams: its first triangle fold by fold, then a panel a triangle of its path, its
     * folds counted by kind; the paper beyond a panel not drawn.
     */
    @Test
    void aWrapsStepDiagramsHaveAPanelATriangle() throws Exception {
        Path pdf = dir.resolve("cube-steps.pdf");
        CliTest.Run run = CliTest.run("wrap", "models/cube.off", "--no-view", "--export-diagrams", pdf.toString());
        assertEquals(0, run.code(), run.err());
        // The first triangle fold by fold (15 panels: the strip runs along the cube's own 12
        // triangles, where it has fewest layers and its paper is sound), then the 11 others a
        // panel each; the list of steps on the title page and one more.
        assertTrue(run.out().contains("wrote " + pdf + ": 6 pages, 26 steps"), run.out());
        assertTrue(Files.size(pdf) < 5_000_000, "the paper outside each panel left out: " + Files.size(pdf) + " bytes");
        if (!tool("pdftotext")) {
            return;
        }
        Path text = dir.resolve("cube-steps.txt");
        assertEquals(0, new ProcessBuilder("pdftotext", "-f", "2", "-l", "2", pdf.toString(), text.toString()).start().waitFor());
        String words = Files.readString(text).replaceAll("\\s+", " ");
        assertTrue(words.contains("triangle 1 of 12: pass 1 of 5: turn, 45° valley fold (fold 1 of 15)"), words);
        Path later = dir.resolve("cube-later.txt");
        assertEquals(0, new ProcessBuilder("pdftotext", "-f", "4", "-l", "4", pdf.toString(), later.toString()).start().waitFor());
        words = Files.readString(later).replaceAll("\\s+", " ");
        // Its panel says which printed creases it makes: those after the first triangle's 15.
        assertTrue(words.contains("triangle 2 of 12: 4 turn folds, 2 gadget folds (creases 16–21 on the print)"), words);
    }

    /** The pixels of a valley's blue (or a mountain's red) in a panel of the top row, from x0 to x1 mm across, at {@code dpi}. */
    private static int inked(java.awt.image.BufferedImage page, double dpi, double x0, double x1, boolean blue) {
        int count = 0;
        double mm = dpi / 25.4;
        for (int y = (int) (40 * mm); y < (int) (100 * mm); y++) {
            for (int x = (int) (x0 * mm); x < (int) (x1 * mm); x++) {
                int rgb = page.getRGB(x, y) & 0xFFFFFF;
                int r = rgb >> 16;
                int g = (rgb >> 8) & 255;
                int b = rgb & 255;
                count += blue ? (b > r + 60 && b > g + 30 ? 1 : 0) : (r > g + 60 && r > b + 60 ? 1 : 0);
            }
        }
        return count;
    }

    private static boolean tool(String name) {
        try {
            Process p = new ProcessBuilder(name, "-v").redirectErrorStream(true).start();
            p.getInputStream().readAllBytes();
            return p.waitFor() >= 0;
        } catch (Exception e) {
            return false;
        }
    }
}
