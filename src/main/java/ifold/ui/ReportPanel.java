package ifold.ui;

import ifold.job.ReportGlossary;
import java.awt.FontMetrics;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.swing.JTable;
import javax.swing.table.AbstractTableModel;

/**
 * The figures of the current result as the {@code --report} JSON holds them, one row a value:
 * a nested figure named in words with its unit ("Strip 1: length / width" for
 * {@code strips.1.lengthOverWidth}, "Width (model units)"), a number to six significant digits
 * so that it reads at a glance in its cell, and under the mouse what the figure means (the
 * words of docs/reports.md), its path in the report and the shortest decimal that reads back as
 * the value (what the JSON writes).
 */
final class ReportPanel extends JTable {
    private static final long serialVersionUID = 1L;

    private final Rows rows = new Rows();

    ReportPanel() {
        setModel(rows);
        setFillsViewportHeight(true);
        javax.swing.ToolTipManager.sharedInstance().registerComponent(this);
        getColumnModel().getColumn(0).setPreferredWidth(140);
        getColumnModel().getColumn(1).setPreferredWidth(140);
    }

    /**
     * Under the mouse, what the figure means (the docs' words, {@link ReportGlossary}), its whole
     * value (a long one is cut in its cell) and its path in the report.
     */
    @Override
    public String getToolTipText(java.awt.event.MouseEvent e) {
        int row = rowAtPoint(e.getPoint());
        return row < 0 ? null : toolTip(row);
    }

    /** The tool tip of a row, as HTML: for tests too. */
    String toolTip(int row) {
        String[] shown = rows.rows.get(row);
        String meaning = ReportGlossary.packaged().meaning(section, shown[0]).orElse("");
        return "<html><body style='width: 300px'><b>" + html(shown[3]) + "</b>"
                + (meaning.isEmpty() ? "" : "<br>" + html(meaning))
                + "<br><br>" + html(shown[0] + " = " + shown[2]) + "</body></html>";
    }

    private static String html(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }

    /** The report's section in docs/reports.md: "wrap", "demo zigzag", "demo turn", "fold", "info", "view". */
    private String section = "wrap";

    /** Shows the figures of a report of the kind that {@code section} names (its section in docs/reports.md). */
    void show(String section, Map<String, Object> figures) {
        this.section = section;
        List<String[]> flat = new ArrayList<>();
        if (figures != null) {
            flatten("", figures, flat);
        }
        rows.set(flat);
        fitColumns();
    }

    /** The widest name and the widest value shown, in pixels with their cells' padding. */
    private int namesWidth = 140;
    private int valuesWidth = 140;

    /** Measures what the columns hold, for {@link #doLayout}. */
    private void fitColumns() {
        FontMetrics metrics = getFontMetrics(getFont());
        int names = metrics.stringWidth(rows.getColumnName(0));
        int values = metrics.stringWidth(rows.getColumnName(1));
        for (String[] row : rows.rows) {
            names = Math.max(names, metrics.stringWidth(row[3]));
            values = Math.max(values, metrics.stringWidth(row[1]));
        }
        int padding = 2 * getIntercellSpacing().width + 12;
        namesWidth = names + padding;
        valuesWidth = values + padding;
        revalidate();
    }

    /**
     * The names take the width they need, so that a long one ({@code minAngleInDegrees}) reads
     * whole, up to two thirds of the panel when the values need the rest; the values get what
     * is left (a long one is whole under the mouse).
     */
    @Override
    public void doLayout() {
        int width = getWidth();
        if (width > 0 && getColumnCount() == 2) {
            int names = Math.min(namesWidth, Math.max(width - valuesWidth, width * 2 / 3));
            getColumnModel().getColumn(0).setPreferredWidth(names);
            getColumnModel().getColumn(1).setPreferredWidth(width - names);
        }
        super.doLayout();
    }

    /** The value shown for {@code key}, or null: for tests. */
    String value(String key) {
        for (String[] row : rows.rows) {
            if (row[0].equals(key)) {
                return row[1];
            }
        }
        return null;
    }

    private static void flatten(String prefix, Object value, List<String[]> out) {
        if (value instanceof Map<?, ?> map) {
            for (Map.Entry<?, ?> entry : map.entrySet()) {
                flatten(prefix.isEmpty() ? String.valueOf(entry.getKey()) : prefix + "." + entry.getKey(), entry.getValue(), out);
            }
        } else if (value instanceof List<?> list) {
            for (int i = 0; i < list.size(); i++) {
                flatten(prefix + "." + (i + 1), list.get(i), out);
            }
        } else if (value instanceof Double d) {
            String exact = d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString(d.longValue()) : d.toString();
            out.add(new String[] {prefix, readable(d, exact), exact, named(prefix)});
        } else {
            out.add(new String[] {prefix, String.valueOf(value), String.valueOf(value), named(prefix)});
        }
    }

    /** A figure's name in words with its unit: "Width (model units)", "Seconds: wrap (s)", "Min angle in (°)". */
    static String named(String path) {
        String words = words(path);
        String unit = ReportGlossary.unit(path).symbol();
        return unit.isEmpty() || words.endsWith("(" + unit + ")") ? words : words + " (" + unit + ")";
    }

    /**
     * A figure's path in the report, in words: each name's camel case split into words, a
     * number after a name (a list's item) joined to it, singular ("strips.1" → "strip 1"), the
     * parts joined by colons: "strips.1.lengthOverWidth" → "Strip 1: length / width",
     * "folds.zigzagTurns" → "Folds: zig-zag turns", "minAngleOutDegrees" → "Min angle out (°)".
     */
    static String words(String path) {
        List<String> parts = new ArrayList<>();
        for (String name : path.split("\\.")) {
            if (!name.isEmpty() && name.chars().allMatch(Character::isDigit) && !parts.isEmpty()) {
                String before = parts.remove(parts.size() - 1);
                parts.add((before.endsWith("s") && !before.endsWith("ss") ? before.substring(0, before.length() - 1) : before) + " " + name);
            } else {
                parts.add(spaced(name));
            }
        }
        String text = String.join(": ", parts);
        return text.isEmpty() ? text : Character.toUpperCase(text.charAt(0)) + text.substring(1);
    }

    /**
     * "lengthOverWidth" → "length / width", "zigzagTurns" → "zig-zag turns", "degrees" → "(°)":
     * the refinement's "minAngleInDegrees" and "minAngleOutDegrees" (of its input and output)
     * read "min angle in (°)" and "min angle out (°)".
     */
    private static String spaced(String name) {
        StringBuilder words = new StringBuilder();
        for (int i = 0; i < name.length(); i++) {
            char c = name.charAt(i);
            boolean capital = Character.isUpperCase(c);
            // A capital starts a word, unless it continues a run of capitals (an acronym: "OBJ").
            if (capital && i > 0 && !(Character.isUpperCase(name.charAt(i - 1))
                    && (i + 1 == name.length() || Character.isUpperCase(name.charAt(i + 1))))) {
                words.append(' ');
            }
            boolean acronym = capital && (i + 1 < name.length() && Character.isUpperCase(name.charAt(i + 1))
                    || i > 0 && Character.isUpperCase(name.charAt(i - 1)));
            words.append(acronym ? c : Character.toLowerCase(c));
        }
        String text = words.toString().replace(" over ", " / ").replace("zigzag", "zig-zag");
        return text.endsWith(" degrees") ? text.substring(0, text.length() - " degrees".length()) + " (°)" : text;
    }

    /** Six significant digits, plainly written between 1e-4 and 1e7, in powers of ten beyond. */
    static String readable(double d, String exact) {
        if (!Double.isFinite(d) || d == 0 || exact.length() <= 8) {
            return exact;
        }
        java.math.BigDecimal rounded = new java.math.BigDecimal(d).round(new java.math.MathContext(6)).stripTrailingZeros();
        double size = Math.abs(d);
        return size >= 1e-4 && size < 1e7 ? rounded.toPlainString() : rounded.toString().replace("E", "e");
    }

    private static final class Rows extends AbstractTableModel {
        private static final long serialVersionUID = 1L;
        private List<String[]> rows = List.of();

        void set(List<String[]> next) {
            rows = next;
            fireTableDataChanged();
        }

        @Override
        public int getRowCount() {
            return rows.size();
        }

        @Override
        public int getColumnCount() {
            return 2;
        }

        @Override
        public String getColumnName(int column) {
            return column == 0 ? "figure" : "value";
        }

        @Override
        public Object getValueAt(int row, int column) {
            return column == 0 ? rows.get(row)[3] : rows.get(row)[1];
        }
    }
}
