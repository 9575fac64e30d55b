package ifold.ui;

import ifold.job.BuiltInModels;
import ifold.ui.model.NewModel;
import ifold.ui.model.Problem;
import java.awt.Color;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;

/**
 * File, New model's form: the shape ({@code ifold generate}'s list) and the parameters it takes,
 * as {@code ifold generate --help} describes them; blank is the command line's default. Only the
 * fields the shape uses are enabled. A refused value has the command line's message under it.
 */
final class NewModelForm extends JPanel {
    private static final long serialVersionUID = 1L;

    final JComboBox<BuiltInModels.Shape> shape = new JComboBox<>(BuiltInModels.Shape.values());
    final JTextField around = new JTextField(8);
    final JTextField across = new JTextField(8);
    final JTextField subdivisions = new JTextField(8);
    /** The line under each field by its parameter's name: its hint, or what is wrong with it. */
    private final Map<String, JLabel> notes = new LinkedHashMap<>();
    private final Map<String, String> hints = new LinkedHashMap<>();

    NewModelForm() {
        super(new GridBagLayout());
        shape.setName("shape");
        shape.setSelectedItem(BuiltInModels.Shape.icosphere);
        row(0, "Shape", shape, "shape", "a solid of models/, an icosphere or a torus");
        row(1, "Around", around, "around", "torus: segments around the ring (blank: " + BuiltInModels.DEFAULT_AROUND + ")");
        row(2, "Across", across, "across", "torus: segments around the tube (blank: " + BuiltInModels.DEFAULT_ACROSS + ")");
        row(3, "Subdivisions", subdivisions, "subdivisions", "icosphere: times each triangle is cut in four (blank: "
                + BuiltInModels.DEFAULT_SUBDIVISIONS + ": 1,280 triangles)");
        shape.addActionListener(e -> enableFields());
        enableFields();
    }

    private void row(int row, String label, JComponent input, String parameter, String hint) {
        input.setName(parameter);
        JLabel name = new JLabel(label);
        name.setLabelFor(input);
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = 0;
        c.gridy = 2 * row;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(4, 0, 0, 8);
        add(name, c);
        c = new GridBagConstraints();
        c.gridx = 1;
        c.gridy = 2 * row;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.weightx = 1;
        c.insets = new Insets(4, 0, 0, 0);
        add(input, c);
        JLabel note = new JLabel(hint);
        note.setFont(name.getFont().deriveFont(name.getFont().getSize2D() - 1));
        note.setForeground(Color.GRAY);
        c.gridy = 2 * row + 1;
        c.insets = new Insets(0, 0, 0, 0);
        add(note, c);
        notes.put(parameter, note);
        hints.put(parameter, hint);
    }

    private void enableFields() {
        boolean torus = shape.getSelectedItem() == BuiltInModels.Shape.torus;
        around.setEnabled(torus);
        across.setEnabled(torus);
        subdivisions.setEnabled(shape.getSelectedItem() == BuiltInModels.Shape.icosphere);
    }

    /** The model as the form now stands. */
    NewModel model() {
        return new NewModel((BuiltInModels.Shape) shape.getSelectedItem(), around.getText(), across.getText(), subdivisions.getText());
    }

    /** Says each problem under its field (and the hint under the rest). */
    void mark(List<Problem> problems) {
        for (Map.Entry<String, JLabel> entry : notes.entrySet()) {
            String problem = null;
            for (Problem p : problems) {
                if (entry.getKey().equals(p.field()) && problem == null) {
                    problem = p.message();
                }
            }
            entry.getValue().setText(problem == null ? hints.get(entry.getKey()) : problem);
            entry.getValue().setForeground(problem == null ? Color.GRAY : new Color(0xB00020));
        }
    }

    /** What is said under the field of {@code parameter}: its hint or its problem. */
    String note(String parameter) {
        return notes.get(parameter).getText();
    }
}
