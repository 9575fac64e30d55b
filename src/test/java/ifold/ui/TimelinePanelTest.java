package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.Canvas;
import java.awt.Font;
import java.awt.FontMetrics;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** The list of folds keeps its rows told apart when their names are longer than it is wide. */
class TimelinePanelTest {
    private static final FontMetrics METRICS = new Canvas().getFontMetrics(new Font(Font.SANS_SERIF, Font.PLAIN, 13));

    @Test
    void aRowFitsItsWidthKeepingItsNumberAndTheEndOfItsName() {
        List<String> rows = List.of(
                "1061. triangle 68 of 98: pass 2 of 4: turn, 45° mountain fold  [zig-zag turn]",
                "1062. triangle 68 of 98: turn gadget, pass 2 of 4: shift by less than a width, two 90° gadgets  [turn gadget]",
                "1063. triangle 68 of 98: turn gadget, pass 2 of 4: shift by less than a width, two 90° gadgets  [turn gadget]",
                "1068. triangle 68 of 98: fold over the edge to the next triangle  [edge crossing]");
        Set<String> shown = new HashSet<>();
        for (String row : rows) {
            String fitted = TimelinePanel.FoldRenderer.fit(row, METRICS, 260);
            assertTrue(METRICS.stringWidth(fitted) <= 260, fitted);
            assertTrue(fitted.startsWith(row.substring(0, 6)), "its number: " + fitted);
            String name = row.substring(0, row.lastIndexOf("  ["));
            assertTrue(fitted.endsWith(name.substring(name.length() - 12)), "the end of its name: " + fitted);
            shown.add(fitted);
        }
        assertEquals(rows.size(), shown.size(), "every row told apart: " + shown);
        assertEquals("12. fold 1: valley 180°  [valley]", TimelinePanel.FoldRenderer.fit("12. fold 1: valley 180°  [valley]", METRICS, 260),
                "a row that fits is as it is");
        String kindless = TimelinePanel.FoldRenderer.fit("1068. triangle 68 of 98: fold over the edge  [edge crossing]", METRICS,
                METRICS.stringWidth("1068. triangle 68 of 98: fold over the edge") + 2);
        assertEquals("1068. triangle 68 of 98: fold over the edge", kindless, "the kind goes first");
    }
}
