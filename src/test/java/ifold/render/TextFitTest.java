package ifold.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** A line is cut short to the room it has, with an ellipsis, and one that fits is left whole. */
class TextFitTest {
    @Test
    void aLineIsCutShortToItsRoomOnly() {
        Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        FontMetrics metrics = g.getFontMetrics();
        String step = "tuck 2: excess folded under along edge CA (seen from below)";
        assertEquals(step, TextFit.cutShort(step, metrics, metrics.stringWidth(step)), "it fits: whole");
        String cut = TextFit.cutShort(step, metrics, metrics.stringWidth(step) / 2);
        assertTrue(cut.endsWith("…") && step.startsWith(cut.substring(0, cut.length() - 1)), cut);
        assertTrue(metrics.stringWidth(cut) <= metrics.stringWidth(step) / 2, cut);
        g.dispose();
    }
}
