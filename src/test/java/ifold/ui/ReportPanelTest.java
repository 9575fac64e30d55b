package ifold.ui;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
