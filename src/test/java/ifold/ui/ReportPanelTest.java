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
        panel.show("refine", figures);
        panel.setSize(330, 200); // the window's report column
        panel.doLayout();
        int name = panel.getFontMetrics(panel.getFont()).stringWidth("Refinement: min angle in (°)");
        int value = panel.getFontMetrics(panel.getFont()).stringWidth("12.3457");
        assertTrue(panel.getColumnModel().getColumn(0).getWidth() > name, "the name's column is "
                + panel.getColumnModel().getColumn(0).getWidth() + " px for a name of " + name);
        assertTrue(panel.getColumnModel().getColumn(1).getWidth() > value, "and the value still fits");
    }

    /** The figures read in words; the report's own name is under the mouse. */
    @Test
    void figuresAreNamedInWords() {
        assertEquals("Strip 1: length / width", ReportPanel.words("strips.1.lengthOverWidth"));
        assertEquals("Folds: zig-zag turns", ReportPanel.words("folds.zigzagTurns"));
        assertEquals("Refinement: min angle in (°)", ReportPanel.words("refinement.minAngleInDegrees"));
        assertEquals("Min angle out (°)", ReportPanel.words("minAngleOutDegrees"));
        assertEquals("Face size 4", ReportPanel.words("faceSizes.4"));
        assertEquals("Input triangles", ReportPanel.words("inputTriangles"));
        assertEquals("Seconds: layer order", ReportPanel.words("seconds.layerOrder"));
        assertEquals("Collisions: pairs", ReportPanel.words("collisions.pairs"));
        Map<String, Object> strip = new LinkedHashMap<>();
        strip.put("lengthOverWidth", 126.2);
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("strips", java.util.List.of(strip));
        ReportPanel panel = new ReportPanel();
        panel.show("wrap", figures);
        assertEquals("Strip 1: length / width", panel.getValueAt(0, 0));
        assertEquals("126.2", panel.getValueAt(0, 1));
        assertEquals("126.2", panel.value("strips.1.lengthOverWidth"), "tests and tools still find a figure by its path");
    }

    /** Lengths, areas, angles and times say their unit; counts and ratios say none. */
    @Test
    void figuresSayTheirUnits() {
        assertEquals("Width (model units)", ReportPanel.named("width"));
        assertEquals("Strip 1: length (model units)", ReportPanel.named("strips.1.length"));
        assertEquals("Surface area (square model units)", ReportPanel.named("surfaceArea"));
        assertEquals("Min angle in (°)", ReportPanel.named("minAngleInDegrees"), "a name that says its unit says it once");
        assertEquals("Preparation: min angles: input (°)", ReportPanel.named("preparation.minAngles.input"));
        assertEquals("Seconds: wrap (s)", ReportPanel.named("seconds.wrap"));
        assertEquals("Timing: milliseconds per fold (ms)", ReportPanel.named("timing.millisecondsPerFold"));
        assertEquals("Collisions: deepest (thicknesses T)", ReportPanel.named("collisions.deepest"));
        assertEquals("Max layers", ReportPanel.named("maxLayers"));
        assertEquals("Folds: tucks", ReportPanel.named("folds.tucks"));
        assertEquals("Coverage", ReportPanel.named("coverage"));
    }

    /** Under the mouse: what the figure means, in the docs' words for its kind of report, and its exact value. */
    @Test
    void aFiguresMeaningIsUnderTheMouse() {
        Map<String, Object> strip = new LinkedHashMap<>();
        strip.put("length", 204.07975802370808);
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("strips", java.util.List.of(strip));
        figures.put("length", 204.07975802370808);
        figures.put("maxLayers", 15.0);
        ReportPanel panel = new ReportPanel();
        panel.show("wrap", figures);
        assertEquals("Strip 1: length (model units)", panel.getValueAt(0, 0));
        String strip1 = panel.toolTip(0);
        assertTrue(strip1.contains("per strip: triangles on its path, length L"), strip1);
        assertTrue(strip1.contains("strips.1.length = 204.07975802370808"), strip1);
        assertTrue(panel.toolTip(1).contains("Σ L over the strips"), panel.toolTip(1));
        assertTrue(panel.toolTip(2).contains("the most layers of paper over any point"), panel.toolTip(2));
        Map<String, Object> turn = new LinkedHashMap<>();
        turn.put("overhang", 0.5);
        panel.show("demo turn", turn);
        assertTrue(panel.toolTip(0).contains("how far beyond the fold across the turn fold begins"), panel.toolTip(0));
    }
}
