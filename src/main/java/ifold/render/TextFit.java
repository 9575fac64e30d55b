package ifold.render;

import java.awt.FontMetrics;

/** A line of text fitted to the pixels it has: the captions of frames, the window's status band. */
public final class TextFit {
    private TextFit() {
    }

    /** {@code text}, cut short with an ellipsis where it would run past {@code room} pixels. */
    public static String cutShort(String text, FontMetrics metrics, int room) {
        if (metrics.stringWidth(text) <= room) {
            return text;
        }
        String shown = text;
        while (shown.length() > 1 && metrics.stringWidth(shown + "…") > room) {
            shown = shown.substring(0, shown.length() - 1);
        }
        return shown.strip() + "…";
    }
}
