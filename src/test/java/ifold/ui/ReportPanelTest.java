package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.Map;

import org.junit.jupiter.api.Test;

/** The report's numbers read at a glance in their cells; the exact value is under the mouse. */
class ReportPanelTest {
    private static String readable(double d) {
        return ReportPanel.readable(d, Double.toString(d));
    }

    @Test
    void numbersAreShownToSixSignificantDigits() {
        assertEquals("48.4", readable(48.400000000000006));
        assertEquals("0.516529", readable(0.5165289256198347));
        assertEquals("1.44419e-15", readable(1.4441925523e-15));
        assertEquals("3180.59", readable(3180.586196));
        assertEquals("2.80614e+7", readable(28061429.64526199));
        assertEquals("1.6", readable(1.6), "short values as they are");
        assertEquals("0.0208333", readable(0.020833333333333332));
        assertEquals("-0.333333", readable(-1.0 / 3));
    }

    @Test
    void aLongFigureNameReadsWholeInThePanelsWidth() {
        Map<String, Object> refinement = new LinkedHashMap<>();
        refinement.put("minAngleInDegrees", 12.345678901);
        refinement.put("outputTriangles", 2878);
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("refinement", refinement);
        ReportPanel panel = new ReportPanel();
        panel.show(figures);
        panel.setSize(330, 200); // the window's report column
        panel.doLayout();
        int name = panel.getFontMetrics(panel.getFont()).stringWidth("refinement.minAngleInDegrees");
        int value = panel.getFontMetrics(panel.getFont()).stringWidth("12.3457");
        assertTrue(panel.getColumnModel().getColumn(0).getWidth() > name, "the name's column is "
                + panel.getColumnModel().getColumn(0).getWidth() + " px for a name of " + name);
        assertTrue(panel.getColumnModel().getColumn(1).getWidth() > value, "and the value still fits");
    }
}
