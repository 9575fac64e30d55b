package ifold.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Canvas;
import java.awt.FontMetrics;
import org.junit.jupiter.api.Test;

/** A caption reads whole: made smaller, then set on two lines, before anything is cut. */
class CaptionsTest {
    private static final String GADGET = "triangle 25 of 58: turn gadget, turn to run along the next triangle's first pass";
    private static final String SHIFT = "strip 2, triangle 117 of 198: turn gadget, pass 3 of 4: shift by less than a width, two 90° gadgets";

    private static void assertFits(Captions captions, Captions.Layout layout, int width) {
        FontMetrics metrics = new Canvas().getFontMetrics(layout.font());
        for (String line : layout.lines()) {
            assertTrue(metrics.stringWidth(line) <= width - captions.band(), "'" + line + "' fits in " + width + " pixels");
        }
    }

    @Test
    void aShortCaptionIsOneLineInTheBand() {
        Captions captions = new Captions(640, 360);
        Captions.Layout layout = captions.layout("pass 3 of 5: turn, 45° valley fold");
        assertEquals(1, layout.lines().size());
        assertEquals(captions.band(), layout.rows());
        assertEquals(15, layout.font().getSize(), "a twenty-fourth of the height");
    }

    @Test
    void longCaptionsReadWholeAtTheUsualSizes() {
        for (int[] size : new int[][] {{1280, 720}, {960, 540}, {640, 360}}) {
            Captions captions = new Captions(size[0], size[1]);
            for (String text : new String[] {GADGET, SHIFT}) {
                Captions.Layout layout = captions.layout(text);
                assertEquals(text, String.join(" ", layout.lines()), size[0] + "x" + size[1] + ": nothing cut");
                assertTrue(layout.lines().size() <= 2);
                assertFits(captions, layout, size[0]);
                if (layout.lines().size() == 2) {
                    assertTrue(layout.rows() > captions.band(), "a taller band for two lines");
                }
            }
        }
        assertEquals(2, new Captions(640, 360).layout(SHIFT).lines().size(), "the longest takes two lines at 640x360");
    }

    @Test
    void onlyWhatTwoLinesCannotHoldIsCut() {
        Captions captions = new Captions(320, 180);
        String text = (GADGET + " " + SHIFT + " ").repeat(3).strip();
        Captions.Layout layout = captions.layout(text);
        assertEquals(2, layout.lines().size());
        assertTrue(layout.lines().get(1).endsWith("…"), layout.lines().toString());
        assertFits(captions, layout, 320);
        String longWord = "a " + "Supercalifragilisticexpialidocious".repeat(2);
        Captions.Layout broken = captions.layout(longWord);
        assertEquals(longWord.replace(" ", ""), String.join("", broken.lines()).replace(" ", ""),
                "a long word is broken across the lines rather than cut: " + broken.lines());
        Captions.Layout word = captions.layout("x".repeat(200));
        assertNotEquals("", word.lines().get(0), "a word longer than a line is broken, not lost");
        assertFits(captions, word, 320);
    }

    @Test
    void aTwoLineCaptionDrawsInItsTallerBandOnly() {
        Captions captions = new Captions(640, 360);
        Captions.Layout layout = captions.layout(SHIFT);
        byte[] rgb = new byte[3 * 640 * 360];
        java.util.Arrays.fill(rgb, (byte) 0xFF);
        captions.draw(rgb, SHIFT);
        int firstChanged = -1;
        for (int y = 0; y < 360 && firstChanged < 0; y++) {
            for (int x = 0; x < 640; x++) {
                if (rgb[3 * (y * 640 + x)] != (byte) 0xFF) {
                    firstChanged = y;
                    break;
                }
            }
        }
        assertEquals(360 - layout.rows(), firstChanged, "the band starts its rows above the bottom, and nothing above it changes");
    }
}
