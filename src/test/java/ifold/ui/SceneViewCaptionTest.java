package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Font;
import java.awt.FontMetrics;
import java.awt.image.BufferedImage;
import org.junit.jupiter.api.Test;

/** The view's status band cuts a line short to the room it has, with an ellipsis, and leaves one that fits whole. */
class SceneViewCaptionTest {
    @Test
    void aLineIsCutShortToItsRoomOnly() {
        java.awt.Graphics2D g = new BufferedImage(1, 1, BufferedImage.TYPE_INT_RGB).createGraphics();
        g.setFont(new Font(Font.MONOSPACED, Font.PLAIN, 12));
        FontMetrics metrics = g.getFontMetrics();
        String step = "tuck 2: excess folded under along edge CA (seen from below)";
        assertEquals(step, SceneView.cutShort(step, metrics, metrics.stringWidth(step)), "it fits: whole");
        String cut = SceneView.cutShort(step, metrics, metrics.stringWidth(step) / 2);
        assertTrue(cut.endsWith("…") && step.startsWith(cut.substring(0, cut.length() - 1)), cut);
        assertTrue(metrics.stringWidth(cut) <= metrics.stringWidth(step) / 2, cut);
        g.dispose();
    }
}
