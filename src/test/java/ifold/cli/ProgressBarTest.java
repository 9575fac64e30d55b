package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.junit.jupiter.api.Test;

/** A long wrap's bar: redrawn in place on a terminal, wiped at the end, and absent elsewhere. */
class ProgressBarTest {
    @Test
    void aLongWrapOnATerminalShowsABarAndWipesIt() {
        StringWriter text = new StringWriter();
        ProgressBar.WrapBar bar = ProgressBar.wrapping(new PrintWriter(text), 2000, true);
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
    void noBarInALogNorForAShortWrap() {
        for (boolean terminal : new boolean[] {false, true}) {
            StringWriter text = new StringWriter();
            int triangles = terminal ? ProgressBar.LONG_WRAP - 1 : 100_000;
            ProgressBar.WrapBar bar = ProgressBar.wrapping(new PrintWriter(text), triangles, terminal);
            bar.wrapped(1, triangles);
            bar.wrapped(triangles, triangles);
            bar.wipe();
            assertEquals("", text.toString(), terminal ? "a short wrap" : "a log");
        }
    }
}
