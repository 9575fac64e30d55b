package ifold.ui;

import ifold.job.Scenes;
import ifold.scene.PathView;
import ifold.ui.model.Job;
import ifold.ui.model.Problem;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import java.awt.CardLayout;
import java.awt.Color;
import java.awt.Component;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.nio.file.Path;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextArea;
import javax.swing.JTextField;
import javax.swing.Timer;
import javax.swing.event.DocumentEvent;
import javax.swing.event.DocumentListener;

/**
 * The parameters of the job the window folds, one card per kind: the zig-zag's triangle
 * (typed, or dragged on its sketch), its ends and entry side, width and thickness; the
 * turn's angle and overhang; the wrap's model, width, thickness, limit on faces and strict mode;
 * the script's file; the view's model (the wrap's), what it shows, its colours and strict mode. A
 * change is told (to re-plan) a moment after the typing stops; a field the core refused is
 * outlined in red with the core's message under it.
 */
final class ParameterPanel extends JPanel implements javax.swing.Scrollable {
    private static final long serialVersionUID = 1L;

    static final String[] CORNERS = {"A", "B", "C"};
    static final String[] ENTRIES = {"(either side)", "A", "B", "C"};
    /** The view's choices, in the order of {@link Scenes.Show} and {@link PathView.Colors}. */
    static final String[] SHOWS = {"Model", "Refinement", "Hamiltonian path"};
    /** The wrap's methods, in the order of {@link Wrap.Method}. */
    static final String[] METHODS = {"Zig-zag", "Hinge strip"};
    static final String[] COLOURS = {"darkness", "rainbow"};

    private final CardLayout cards = new CardLayout();
    private final transient Consumer<Job> changed;
    private final Timer settle;
    /** Every field by the core's name of its parameter, per card. */
    private final Map<String, Map<String, Field>> fields = new LinkedHashMap<>();
    private final JLabel message = new JLabel(" ");
    private String card = "zigzag";
    private boolean quiet;

    // The zig-zag.
    final JTextField triangle = new JTextField();
    final JComboBox<String> start = new JComboBox<>(CORNERS);
    final JComboBox<String> end = new JComboBox<>(CORNERS);
    final JComboBox<String> enterFrom = new JComboBox<>(ENTRIES);
    final JTextField zigzagWidth = new JTextField();
    final JTextField zigzagThickness = new JTextField();
    final TriangleSketch sketch = new TriangleSketch(triangle);
    // The turn.
    final JTextField angle = new JTextField();
    final JTextField overhang = new JTextField();
    final JTextField turnWidth = new JTextField();
    final JTextField turnThickness = new JTextField();
    // The wrap.
    private Path model;
    private final JLabel modelName = new JLabel("no model");
    final JTextField wrapWidth = new JTextField();
    final JTextField wrapThickness = new JTextField();
    final JTextField wrapMaxFaces = new JTextField();
    final JCheckBox wrapStrict = new JCheckBox("refuse defective input");
    final JComboBox<String> wrapMethod = new JComboBox<>(METHODS);
    // The view, of the wrap's model.
    private final JLabel viewModelName = new JLabel("no model");
    final JComboBox<String> viewShow = new JComboBox<>(SHOWS);
    final JComboBox<String> viewColours = new JComboBox<>(COLOURS);
    final JCheckBox viewStrict = new JCheckBox("refuse defective input");
    // The script.
    private Path script;
    private final JLabel scriptName = new JLabel("no script");
    final JTextField scriptMaxFaces = new JTextField();

    /**
     * @param changed told on the event thread of the job as it now stands, 300 ms after the last change
     * @param chooseModel asked to choose a model (File, Open model...)
     * @param chooseScript asked to choose a script
     */
    ParameterPanel(Consumer<Job> changed, Runnable chooseModel, Runnable chooseScript) {
        this.changed = changed;
        setLayout(new java.awt.BorderLayout());
        JPanel deck = new JPanel(cards);
        settle = new Timer(300, e -> changed.accept(job()));
        settle.setRepeats(false);

        Card zigzag = new Card("Zig-zag a triangle", "zigzag");
        zigzag.row("triangle", "Corners", triangle, "x1,y1,x2,y2,x3,y3 (or nine numbers)");
        zigzag.wide(sketch);
        zigzag.row("start", "Start corner", start, "passes run parallel to the edge opposite");
        zigzag.row("end", "End corner", end, null);
        zigzag.row("enterFrom", "Enter beside", enterFrom, null);
        zigzag.row("width", "Width", zigzagWidth, "blank: a fifth of the altitude");
        zigzag.row("thickness", "Thickness", zigzagThickness, "blank: the width / " + Wrap.WIDTHS_A_THICKNESS);
        deck.add(top(zigzag.panel), "zigzag");

        Card turn = new Card("Turn gadget", "turn");
        turn.row("angle", "Angle (degrees)", angle, "from 0.01 to 179.9");
        turn.row("overhang", "Overhang", overhang, "in strip widths; 0 is the basic gadget");
        turn.row("width", "Width", turnWidth, null);
        turn.row("thickness", "Thickness", turnThickness, "blank: the width / " + TurnGadget.Options.WIDTHS_A_THICKNESS);
        deck.add(top(turn.panel), "turn");

        Card wrap = new Card("Wrap a model", "wrap");
        JButton chooseModelButton = new JButton("Choose model...");
        chooseModelButton.addActionListener(e -> chooseModel.run());
        wrap.row("model", "Model", modelName, null);
        wrap.wide(chooseModelButton);
        wrap.row("method", "Method", wrapMethod, "zig-zag: any polyhedron; hinge strip: grid polyhedra only (--method hinge)");
        wrapMethod.addActionListener(e -> edited());
        wrap.row("width", "Width", wrapWidth, "blank: a third of the widest (zig-zag), the lattice's square (hinge strip)");
        wrap.row("thickness", "Thickness", wrapThickness, "blank: the width / " + Wrap.WIDTHS_A_THICKNESS);
        wrap.row("maxFaces", "Max faces", wrapMaxFaces, String.format(java.util.Locale.ROOT, "blank: %,d, a gibibyte's worth (about %,d bytes each)", Wrap.DEFAULT_MAX_FACES,
                Wrap.BYTES_PER_FACE));
        wrap.row("strict", "Strict", wrapStrict, "instead of repairing it (--strict); for the information and refinement too");
        wrapStrict.addActionListener(e -> edited());
        deck.add(top(wrap.panel), "wrap");

        Card play = new Card("Play a fold script", "script");
        JButton chooseScriptButton = new JButton("Choose script or FOLD...");
        chooseScriptButton.addActionListener(e -> chooseScript.run());
        play.row("script", "Script", scriptName, null);
        play.wide(chooseScriptButton);
        play.row("maxFaces", "Max faces", scriptMaxFaces, String.format(java.util.Locale.ROOT,
                "blank: %,d; a fold through a pile costs about the square of its layers", ifold.script.ScriptFolding.DEFAULT_MAX_FACES));
        deck.add(top(play.panel), "script");

        Card look = new Card("View a model", "view");
        JButton chooseViewedButton = new JButton("Choose model...");
        chooseViewedButton.addActionListener(e -> chooseModel.run());
        look.row("model", "Model", viewModelName, null);
        look.wide(chooseViewedButton);
        look.row("show", "Show", viewShow, "the refinement and the path as ifold view --refine and --path");
        look.row("colors", "Colours", viewColours, "along the path: lighter to darker (the seed's Figure 10), or rainbow");
        look.row("strict", "Strict", viewStrict, "instead of repairing it (--strict)");
        viewShow.setSelectedIndex(Scenes.Show.PATH.ordinal());
        viewShow.addActionListener(e -> {
            viewColours.setEnabled(viewShow.getSelectedIndex() == Scenes.Show.PATH.ordinal());
            edited();
        });
        viewColours.addActionListener(e -> edited());
        viewStrict.addActionListener(e -> edited());
        deck.add(top(look.panel), "view");

        add(deck, java.awt.BorderLayout.NORTH);
        message.setForeground(new Color(0xB00020));
        message.setBorder(BorderFactory.createEmptyBorder(6, 10, 6, 10));
        add(message, java.awt.BorderLayout.CENTER);
        setZigZag(Job.ZigZag.DEMO);
        setTurn(Job.Turn.DEMO);
        for (JComboBox<String> box : List.of(start, end, enterFrom)) {
            box.addActionListener(e -> edited());
        }
    }

    /** One card: a title, then rows of label, field and the field's message. */
    private final class Card {
        final JPanel panel = new JPanel(new GridBagLayout());
        final Map<String, Field> own = new LinkedHashMap<>();
        int row;

        Card(String title, String name) {
            panel.setBorder(BorderFactory.createEmptyBorder(10, 10, 4, 10));
            JLabel heading = new JLabel(title);
            heading.setFont(heading.getFont().deriveFont(java.awt.Font.BOLD, heading.getFont().getSize2D() + 2));
            GridBagConstraints c = constraints(0, row++, 2);
            c.insets = new Insets(0, 0, 8, 0);
            panel.add(heading, c);
            fields.put(name, own);
        }

        void row(String parameter, String label, JComponent input, String hint) {
            JLabel name = new JLabel(label);
            name.setLabelFor(input);
            GridBagConstraints c = constraints(0, row, 1);
            c.weightx = 0;
            c.insets = new Insets(3, 0, 0, 8);
            panel.add(name, c);
            c = constraints(1, row++, 1);
            c.insets = new Insets(3, 0, 0, 0);
            panel.add(input, c);
            // A message wraps under its field: the column keeps its width, however long the core's message.
            JTextArea note = new JTextArea(hint == null ? " " : hint, 1, 1);
            note.setLineWrap(true);
            note.setWrapStyleWord(true);
            note.setEditable(false);
            note.setFocusable(false);
            note.setOpaque(false);
            note.setBorder(BorderFactory.createEmptyBorder());
            note.setFont(name.getFont().deriveFont(name.getFont().getSize2D() - 1));
            note.setForeground(Color.GRAY);
            c = constraints(1, row++, 1);
            panel.add(note, c);
            if (input instanceof JTextField text) {
                text.setColumns(8);
                text.getDocument().addDocumentListener(new DocumentListener() {
                    @Override
                    public void insertUpdate(DocumentEvent e) {
                        edited();
                    }

                    @Override
                    public void removeUpdate(DocumentEvent e) {
                        edited();
                    }

                    @Override
                    public void changedUpdate(DocumentEvent e) {
                        edited();
                    }
                });
            }
            own.put(parameter, new Field(input, note, hint == null ? " " : hint));
        }

        void wide(Component component) {
            GridBagConstraints c = constraints(0, row++, 2);
            c.insets = new Insets(4, 0, 4, 0);
            panel.add(component, c);
        }
    }

    /** A card held at the top of the deck: the cards are as tall as the tallest, and a short one would float in the middle. */
    private static JPanel top(JPanel card) {
        JPanel holder = new JPanel(new java.awt.BorderLayout());
        holder.add(card, java.awt.BorderLayout.NORTH);
        return holder;
    }

    private static GridBagConstraints constraints(int x, int y, int span) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridx = x;
        c.gridy = y;
        c.gridwidth = span;
        c.weightx = 1;
        c.fill = GridBagConstraints.HORIZONTAL;
        c.anchor = GridBagConstraints.WEST;
        return c;
    }

    /** A parameter's input and the line under it: its hint, or what is wrong with it. */
    private record Field(JComponent input, JTextArea note, String hint) {
        void mark(String problem) {
            input.putClientProperty("JComponent.outline", problem == null ? null : "error");
            note.setText(problem == null ? hint : problem);
            note.setForeground(problem == null ? Color.GRAY : new Color(0xB00020));
            note.setToolTipText(problem);
            input.repaint();
            note.revalidate();
        }
    }

    private void edited() {
        if (!quiet) {
            sketch.repaint();
            settle.restart();
        }
    }

    /** The zig-zag as its fields now stand, whichever card is shown. */
    Job.ZigZag zigzag() {
        return new Job.ZigZag(triangle.getText(), start.getSelectedIndex(), end.getSelectedIndex(), enterFrom.getSelectedIndex() - 1,
                zigzagWidth.getText(), zigzagThickness.getText());
    }

    /** The turn as its fields now stand, whichever card is shown. */
    Job.Turn turn() {
        return new Job.Turn(angle.getText(), overhang.getText(), turnWidth.getText(), turnThickness.getText());
    }

    /**
     * Clears the wrap's fields that depend on the model (width, thickness: blank is the model's
     * own default); returns whether any held a value.
     */
    boolean resetModelParameters() {
        boolean held = !wrapWidth.getText().isBlank() || !wrapThickness.getText().isBlank();
        wrapWidth.setText("");
        wrapThickness.setText("");
        return held;
    }

    /** A wrap of {@code file} with the wrap's fields as they now stand, whichever card is shown. */
    Job.WrapModel wrap(Path file) {
        return new Job.WrapModel(file, wrapWidth.getText(), wrapThickness.getText(), wrapMaxFaces.getText(), wrapStrict.isSelected(),
                Wrap.Method.values()[wrapMethod.getSelectedIndex()]);
    }

    /** A view of {@code file} with the view's fields as they now stand, whichever card is shown. */
    Job.View view(Path file) {
        return new Job.View(file, Scenes.Show.values()[viewShow.getSelectedIndex()], PathView.Colors.values()[viewColours.getSelectedIndex()],
                viewStrict.isSelected());
    }

    /** The model of the wrap's and the view's cards, whichever card is shown; null before one is opened. */
    Path model() {
        return model;
    }

    /** The job as the fields now stand. */
    Job job() {
        return switch (card) {
            case "turn" -> turn();
            case "wrap" -> wrap(model);
            case "script" -> new Job.Script(script, scriptMaxFaces.getText());
            case "view" -> view(model);
            default -> zigzag();
        };
    }

    /** Shows the card of {@code job}'s kind, its fields set from it, and tells of the change at once. */
    void show(Job job) {
        restore(job);
        changed.accept(job());
    }

    /** Sets the fields and the card to {@code job} without planning it: the job already shown, back after a failed open. */
    void restore(Job job) {
        quiet = true;
        try {
            if (job instanceof Job.ZigZag z) {
                setZigZag(z);
                card = "zigzag";
            } else if (job instanceof Job.Turn t) {
                setTurn(t);
                card = "turn";
            } else if (job instanceof Job.WrapModel w) {
                setModel(w.model());
                wrapWidth.setText(w.width());
                wrapThickness.setText(w.thickness());
                wrapMaxFaces.setText(w.maxFaces());
                wrapStrict.setSelected(w.strict());
                wrapMethod.setSelectedIndex(w.method().ordinal());
                card = "wrap";
            } else if (job instanceof Job.Script s) {
                script = s.file();
                scriptName.setText(script == null ? "no script" : script.getFileName().toString());
                scriptName.setToolTipText(script == null ? null : script.toString());
                scriptMaxFaces.setText(s.maxFaces());
                card = "script";
            } else if (job instanceof Job.View v) {
                setModel(v.model());
                viewShow.setSelectedIndex(v.show().ordinal());
                viewColours.setSelectedIndex(v.colors().ordinal());
                viewStrict.setSelected(v.strict());
                card = "view";
            }
        } finally {
            quiet = false;
        }
        cards.show((JPanel) getComponent(0), card);
        settle.stop();
        mark(List.of());
    }

    /** The model the wrap and the view both work on, named on both cards. */
    private void setModel(Path file) {
        model = file;
        for (JLabel name : List.of(modelName, viewModelName)) {
            name.setText(model == null ? "no model" : model.getFileName().toString());
            name.setToolTipText(model == null ? null : model.toString());
        }
    }

    private void setZigZag(Job.ZigZag z) {
        triangle.setText(z.triangle());
        start.setSelectedIndex(z.start());
        end.setSelectedIndex(z.end());
        enterFrom.setSelectedIndex(z.enterFrom() + 1);
        zigzagWidth.setText(z.width());
        zigzagThickness.setText(z.thickness());
    }

    private void setTurn(Job.Turn t) {
        angle.setText(t.angle());
        overhang.setText(t.overhang());
        turnWidth.setText(t.width());
        turnThickness.setText(t.thickness());
    }

    /**
     * Marks the fields of the problems (and clears the rest); a problem of no field on this
     * card is said under the card.
     */
    void mark(List<Problem> problems) {
        Map<String, Field> own = fields.get(card);
        for (Map.Entry<String, Field> field : own.entrySet()) {
            String text = null;
            for (Problem problem : problems) {
                if (field.getKey().equals(problem.field())) {
                    text = text == null ? problem.message() : text;
                }
            }
            field.getValue().mark(text);
        }
        String loose = null;
        for (Problem problem : problems) {
            if (problem.field() == null || !own.containsKey(problem.field())) {
                loose = loose == null ? problem.message() : loose;
            }
        }
        message.setText(loose == null ? " " : "<html>" + escape(loose) + "</html>");
    }

    /** What is now said under the field of {@code parameter} on the card shown: its hint or its problem. */
    String note(String parameter) {
        Field field = fields.get(card).get(parameter);
        return field == null ? null : field.note().getText();
    }

    /** Whether the field of {@code parameter} on the card shown is marked as wrong. */
    boolean isMarked(String parameter) {
        Field field = fields.get(card).get(parameter);
        return field != null && "error".equals(field.input().getClientProperty("JComponent.outline"));
    }

    String card() {
        return card;
    }

    // As wide as its scroll pane, so that the fields fit the column and only long hints are cut.

    @Override
    public java.awt.Dimension getPreferredScrollableViewportSize() {
        return getPreferredSize();
    }

    @Override
    public int getScrollableUnitIncrement(java.awt.Rectangle visible, int orientation, int direction) {
        return 16;
    }

    @Override
    public int getScrollableBlockIncrement(java.awt.Rectangle visible, int orientation, int direction) {
        return visible.height - 16;
    }

    @Override
    public boolean getScrollableTracksViewportWidth() {
        return true;
    }

    @Override
    public boolean getScrollableTracksViewportHeight() {
        return false;
    }

    private static String escape(String text) {
        return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;");
    }
}
