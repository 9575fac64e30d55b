package ifold.ui;

import ifold.ui.model.Fold;
import ifold.ui.model.Timeline;
import java.awt.BorderLayout;
import java.awt.Component;
import java.awt.FlowLayout;
import java.awt.FontMetrics;
import java.awt.Insets;
import java.util.List;
import javax.swing.AbstractListModel;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JList;
import javax.swing.JPanel;
import javax.swing.JSlider;
import javax.swing.ListSelectionModel;
import javax.swing.Timer;

/**
 * The timeline: play and pause, a fold back and forward, a slider over the whole animation
 * (dragging shows each position at once), the speed; and the list of folds by name and kind,
 * where choosing one shows it made. It drives the {@link Timeline} and tells the view.
 */
final class TimelinePanel extends JPanel {
    private static final long serialVersionUID = 1L;
    /** The slider's resolution: enough for a position per pixel of any screen. */
    static final int TICKS = 100_000;

    final JButton play = new JButton("Play");
    final JButton back = new JButton("\u25C0 Fold");
    final JButton forward = new JButton("Fold \u25B6");
    final JSlider slider = new JSlider(0, TICKS, 0);
    final JComboBox<String> speed = new JComboBox<>();
    final JList<String> folds = new JList<>() {
        private static final long serialVersionUID = 1L;

        /** A long name is cut in the list: the whole of it under the mouse. */
        @Override
        public String getToolTipText(java.awt.event.MouseEvent e) {
            int index = locationToIndex(e.getPoint());
            return index < 0 ? null : getModel().getElementAt(index);
        }
    };
    final JLabel where = new JLabel(" ");
    private final SceneView view;
    private final Timer clock;
    private Timeline timeline;
    private long lastTick;
    /** Set while the panel moves its own controls, so that they do not answer back. */
    private boolean updating;

    TimelinePanel(SceneView view) {
        super(new BorderLayout(8, 0));
        this.view = view;
        setBorder(BorderFactory.createEmptyBorder(4, 8, 4, 8));
        for (double s : Timeline.SPEEDS) {
            speed.addItem(s + "\u00D7");
        }
        speed.setSelectedIndex(2);
        speed.setToolTipText("speed");
        back.setToolTipText("back one fold");
        forward.setToolTipText("forward one fold");
        slider.setToolTipText("drag through the folds");
        JPanel buttons = new JPanel(new FlowLayout(FlowLayout.LEFT, 4, 0));
        buttons.add(back);
        buttons.add(play);
        buttons.add(forward);
        buttons.add(speed);
        // The slider on a row of its own, as wide as the view: beside the buttons, a window of
        // 1024 × 640 left it no width at all, and "fold 5 of 279" shrank to "279".
        JPanel controls = new JPanel(new BorderLayout(8, 0));
        controls.add(buttons, BorderLayout.WEST);
        where.setBorder(BorderFactory.createEmptyBorder(0, 8, 0, 0));
        controls.add(where, BorderLayout.EAST);
        add(slider, BorderLayout.NORTH);
        add(controls, BorderLayout.SOUTH);
        folds.setSelectionMode(ListSelectionModel.SINGLE_SELECTION);
        javax.swing.ToolTipManager.sharedInstance().registerComponent(folds);
        folds.setPrototypeCellValue("pass 12 of 40: turn, 45° valley fold and more"); // a fixed height: 100,000 folds list at once
        folds.setCellRenderer(new FoldRenderer());
        play.addActionListener(e -> togglePlaying());
        back.addActionListener(e -> step(-1));
        forward.addActionListener(e -> step(1));
        slider.addChangeListener(e -> {
            if (!updating && timeline != null) {
                timeline.pause();
                timeline.seek(timeline.end() * slider.getValue() / TICKS);
                shown();
            }
        });
        speed.addActionListener(e -> {
            if (timeline != null) {
                timeline.setSpeed(Timeline.SPEEDS[speed.getSelectedIndex()]);
            }
        });
        folds.addListSelectionListener(e -> {
            if (!updating && !e.getValueIsAdjusting() && timeline != null && folds.getSelectedIndex() >= 0) {
                timeline.jumpTo(folds.getSelectedIndex());
                shown();
            }
        });
        clock = new Timer(33, e -> tick());
        setEnabled(false);
    }

    /** What the steps are called where the timeline says where it is: "fold 3 of 12", "step 3 of 10". */
    private String unit = "fold";

    /** Takes a new timeline (a new plan), at its position, playing if {@code playing}; its steps are {@code unit}s. */
    /**
     * A fold's row, fitted to the list's width so that rows stay told apart: the kind in
     * brackets goes first, then the middle of the name, keeping its number (and what it is of,
     * up to the first colon, where that leaves room) and as much of its end, which differs from
     * row to row, as fits.
     * The whole name is under the mouse.
     */
    static final class FoldRenderer extends javax.swing.DefaultListCellRenderer {
        private static final long serialVersionUID = 1L;

        @Override
        public Component getListCellRendererComponent(JList<?> list, Object value, int index, boolean selected,
                boolean focused) {
            super.getListCellRendererComponent(list, value, index, selected, focused);
            Insets insets = getInsets();
            int room = list.getWidth() - insets.left - insets.right - 4;
            if (room > 0 && value != null) {
                setText(fit(String.valueOf(value), getFontMetrics(getFont()), room));
            }
            return this;
        }

        /** {@code text} shortened to {@code room} pixels as the class says. */
        static String fit(String text, FontMetrics metrics, int room) {
            if (metrics.stringWidth(text) <= room) {
                return text;
            }
            int kind = text.lastIndexOf("  [");
            String name = kind > 0 ? text.substring(0, kind) : text;
            if (metrics.stringWidth(name) <= room) {
                return name;
            }
            // The number always (the folds of one gadget share a name), what it is of where there is room.
            int number = name.indexOf(". ");
            int colon = name.indexOf(": ");
            String head = colon > 0 && metrics.stringWidth(name.substring(0, colon + 2)) < room / 2 ? name.substring(0, colon + 2)
                    : number > 0 ? name.substring(0, number + 2) : "";
            String tail = name.substring(head.length());
            String whole = tail;
            while (tail.length() > 1 && metrics.stringWidth(head + "…" + tail) > room) {
                tail = tail.substring(1);
            }
            int cut = whole.length() - tail.length();
            int space = tail.indexOf(' ');
            if (cut > 0 && whole.charAt(cut - 1) != ' ' && space > 0 && space < tail.length() - 1) {
                tail = tail.substring(space + 1); // from a word's start, not its middle
            }
            return head + "…" + tail.stripLeading();
        }
    }

    void setTimeline(Timeline next, boolean playing, String unit) {
        timeline = next;
        this.unit = unit;
        // A view reveals steps, not folds: the buttons say which.
        String name = Character.toUpperCase(unit.charAt(0)) + unit.substring(1);
        back.setText("\u25C0 " + name);
        forward.setText(name + " \u25B6");
        back.setToolTipText("back one " + unit);
        forward.setToolTipText("forward one " + unit);
        slider.setToolTipText("drag through the " + unit + "s");
        timeline.setSpeed(Timeline.SPEEDS[speed.getSelectedIndex()]);
        List<Fold> list = next.folds();
        updating = true;
        try {
            folds.setModel(new AbstractListModel<>() {
                private static final long serialVersionUID = 1L;

                @Override
                public int getSize() {
                    return list.size();
                }

                @Override
                public String getElementAt(int index) {
                    Fold fold = list.get(index);
                    return (index + 1) + ". " + fold.name() + "  [" + fold.kind() + "]";
                }
            });
        } finally {
            updating = false;
        }
        setEnabled(true);
        if (playing && !timeline.isPlaying()) {
            timeline.togglePlaying();
        }
        shown();
    }

    Timeline timeline() {
        return timeline;
    }

    @Override
    public void setEnabled(boolean enabled) {
        super.setEnabled(enabled);
        for (javax.swing.JComponent c : List.of(play, back, forward, slider, speed, folds)) {
            c.setEnabled(enabled);
        }
    }

    void togglePlaying() {
        if (timeline != null) {
            timeline.togglePlaying();
            shown();
        }
    }

    void step(int direction) {
        if (timeline != null) {
            timeline.stepFold(direction);
            shown();
        }
    }

    void restart() {
        if (timeline != null) {
            timeline.pause();
            timeline.seek(0);
            shown();
        }
    }

    /** Moves to {@code position} as the slider would (for tests and keys). */
    void seek(double position) {
        if (timeline != null) {
            timeline.pause();
            timeline.seek(position);
            shown();
        }
    }

    private void tick() {
        long now = System.nanoTime();
        double elapsed = Math.min(0.25, (now - lastTick) * 1e-9); // a stall does not jump the animation ahead
        lastTick = now;
        if (timeline != null && timeline.advance(elapsed)) {
            shown();
        } else if (timeline == null || !timeline.isPlaying()) {
            shown();
        }
    }

    /** Brings the view and the controls to the timeline's state. */
    private void shown() {
        view.setPosition(timeline.position());
        updating = true;
        try {
            if (!slider.getValueIsAdjusting()) {
                slider.setValue((int) Math.round(timeline.end() == 0 ? 0 : TICKS * timeline.position() / timeline.end()));
            }
            int current = timeline.currentFold();
            if (current != folds.getSelectedIndex()) {
                if (current < 0) {
                    folds.clearSelection();
                } else {
                    folds.setSelectedIndex(current);
                    folds.ensureIndexIsVisible(current);
                }
            }
        } finally {
            updating = false;
        }
        int current = timeline.currentFold();
        where.setText(String.format(java.util.Locale.ROOT, "%s %d of %d", unit, current + 1, timeline.folds().size()));
        play.setText(timeline.isPlaying() ? "Pause" : "Play");
        if (timeline.isPlaying() && !clock.isRunning()) {
            lastTick = System.nanoTime();
            clock.start();
        } else if (!timeline.isPlaying()) {
            clock.stop();
        }
    }
}
