package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A long wrap's bar: redrawn in place on a terminal, wiped at the end, and absent elsewhere. */
class ProgressBarTest {
    @Test
    void aLongWrapOnATerminalShowsABarAndWipesIt() {
        StringWriter text = new StringWriter();
        long[] now = {0};
        ProgressBar.WrapBar bar = ProgressBar.wrapping(new PrintWriter(text), true, () -> now[0]);
        bar.wrapped(0, 2000);
        assertEquals("", text.toString(), "nothing in the first seconds");
        now[0] = (long) (ProgressBar.LONG_WRAP_SECONDS * 1e9);
        for (int done = 1; done <= 2000; done++) {
            bar.wrapped(done, 2000);
        }
        bar.wipe();
        String[] draws = text.toString().split("\r", -1);
        // "", then 31 steps of the bar (0 to 30 of 30 filled), then the wipe: "\r" spaces "\r".
        assertEquals(1 + 31 + 2, draws.length, text.toString());
        assertTrue(draws[1].startsWith("[" + " ".repeat(30) + "] 1/2000"), draws[1]);
        assertTrue(draws[31].startsWith("[" + "#".repeat(30) + "] 2000/2000 triangles wrapped"), draws[31]);
        assertTrue(draws[32].isBlank() && draws[32].length() > draws[31].length() && draws[33].isEmpty(), "the line is wiped");
        assertFalse(bar.stopped());
    }

    @Test
    void theStagesAfterTheFoldsTakeTheBarsPlaceAndAreWiped() {
        StringWriter text = new StringWriter();
        long[] now = {0};
        ProgressBar.WrapBar bar = ProgressBar.wrapping(new PrintWriter(text), true, () -> now[0]);
        bar.stage("reading big.off");
        assertEquals("", text.toString(), "nothing in the first seconds");
        now[0] = (long) (ProgressBar.LONG_WRAP_SECONDS * 1e9);
        bar.wrapped(500, 1000);
        bar.stage("analysing");
        bar.wipe();
        bar.stage("checking the paper for collisions");
        bar.wipe();
        String[] draws = text.toString().split("\r", -1);
        assertTrue(draws[1].startsWith("[" + "#".repeat(15) + " ".repeat(15) + "] 500/1000 triangles wrapped"), draws[1]);
        // The stage over the bar, its line as long as the bar's (spaces over the rest), then wiped.
        assertTrue(draws[2].startsWith("analysing ...") && draws[2].length() == draws[1].length(), "[" + draws[2] + "]");
        assertTrue(draws[3].isBlank() && draws[4].isEmpty(), "wiped");
        assertEquals("checking the paper for collisions ...", draws[5]);
        assertTrue(draws[6].isBlank() && draws[6].length() >= draws[5].length() && draws[7].isEmpty(), "wiped again");
        assertEquals(8, draws.length, text.toString());
        // Off a terminal, no stage either: the summary line says it all.
        StringWriter log = new StringWriter();
        ProgressBar.WrapBar quiet = ProgressBar.wrapping(new PrintWriter(log), false, () -> now[0]);
        quiet.stage("analysing");
        quiet.wipe();
        assertEquals("", log.toString());
    }

    @Test
    void noBarInALogNorForAShortWrap() {
        for (boolean terminal : new boolean[] {false, true}) {
            StringWriter text = new StringWriter();
            int triangles = 100_000;
            // On a terminal, a wrap that ends before the seconds are up; in a log, one that takes minutes.
            long seconds = terminal ? ProgressBar.LONG_WRAP_SECONDS - 1 : 600;
            long[] now = {0};
            ProgressBar.WrapBar bar = ProgressBar.wrapping(new PrintWriter(text), terminal, () -> now[0]);
            now[0] = seconds * 1_000_000_000L;
            bar.wrapped(1, triangles);
            bar.wrapped(triangles, triangles);
            bar.wipe();
            assertEquals("", text.toString(), terminal ? "a short wrap" : "a log");
        }
    }

    /** Into a log or a pipe a frame export says one line, at the end (it said one every tenth of the way). */
    @Test
    void aFrameExportOffATerminalSaysOneLineAtTheEnd() {
        java.io.StringWriter text = new java.io.StringWriter();
        ProgressBar bar = new ProgressBar(new java.io.PrintWriter(text), false);
        for (int done = 0; done <= 100; done++) {
            bar.framesDone(done, 100);
        }
        java.util.List<String> lines = text.toString().lines().toList();
        assertEquals(1, lines.size(), text::toString);
        assertTrue(lines.get(0).contains("100/100 frames"), lines.get(0));
        java.io.StringWriter shown = new java.io.StringWriter();
        ProgressBar onTerminal = new ProgressBar(new java.io.PrintWriter(shown), true);
        for (int done = 0; done <= 100; done++) {
            onTerminal.framesDone(done, 100);
        }
        assertTrue(shown.toString().chars().filter(c -> c == '\r').count() > 50, "on a terminal the bar is redrawn in place");
    }

    @Test
    void stderrIsATerminalOnlyWhereItLinksToOne(@TempDir Path dir) throws Exception {
        Path toTerminal = Files.createSymbolicLink(dir.resolve("2"), Path.of("/dev/pts/3"));
        Path toLog = Files.createSymbolicLink(dir.resolve("log"), dir.resolve("err.log"));
        Path toPipe = Files.createSymbolicLink(dir.resolve("pipe"), Path.of("pipe:[123456]"));
        assertTrue(ProgressBar.stderrIsTerminal(false, toTerminal), "a terminal's device, whatever the console");
        assertFalse(ProgressBar.stderrIsTerminal(true, toLog), "2> err.log with a console: no bar in the log");
        assertFalse(ProgressBar.stderrIsTerminal(true, toPipe), "a pipe");
        // Where there is no link to read (not Linux), the console decides.
        assertTrue(ProgressBar.stderrIsTerminal(true, dir.resolve("absent")));
        assertFalse(ProgressBar.stderrIsTerminal(false, dir.resolve("absent")));
    }
}
