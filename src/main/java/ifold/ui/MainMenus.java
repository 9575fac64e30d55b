package ifold.ui;

import java.awt.Toolkit;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Path;
import java.util.List;
import javax.swing.AbstractAction;
import javax.swing.JComponent;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.KeyStroke;

/**
 * The window's menus, and the viewer's keys: each an action of the window.
 */
final class MainMenus {
    private final MainWindow window;

    MainMenus(MainWindow window) {
        this.window = window;
    }

    JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        int shift = InputEvent.SHIFT_DOWN_MASK;

        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(item("Open model (OFF, OBJ)...", KeyEvent.VK_O, ctrl, window.dialogs::chooseModel));
        file.add(item("Open fold script or FOLD...", KeyEvent.VK_O, ctrl | shift, window.dialogs::chooseScript));
        file.add(window.recent);
        file.add(item("New model...", KeyEvent.VK_N, ctrl, window.dialogs::newModelAsk));
        file.add(window.modelInformation);
        file.addSeparator();
        file.add(item("Export frames...", KeyEvent.VK_F, ctrl | shift, window.exports::framesAsk));
        file.add(item("Export movie (MP4, GIF)...", KeyEvent.VK_M, ctrl, window.exports::movieAsk));
        file.add(item("Export OBJ...", KeyEvent.VK_E, ctrl, () -> window.exports.fileAsk("OBJ", "obj")));
        file.add(item("Export FOLD...", KeyEvent.VK_E, ctrl | shift, () -> window.exports.fileAsk("FOLD", "fold")));
        file.add(item("Export crease pattern (PDF, SVG)...", KeyEvent.VK_P, ctrl | shift, window.exports::creasePatternAsk));
        file.add(item("Export step diagrams (PDF)...", KeyEvent.VK_D, ctrl | shift, window.exports::diagramsAsk));
        file.add(item("Export report (JSON)...", KeyEvent.VK_J, ctrl, () -> window.exports.fileAsk("report", "json")));
        file.add(item("Export figure (PNG)...", KeyEvent.VK_G, ctrl, () -> window.exports.fileAsk("figure", "png")));
        file.add(window.exportRefinement);
        file.addSeparator();
        file.add(item("Quit", KeyEvent.VK_Q, ctrl, window::dispose));
        bar.add(file);

        JMenu show = new JMenu("View");
        show.setMnemonic(KeyEvent.VK_V);
        window.showModel.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_M, ctrl | shift));
        window.showModel.addActionListener(e -> window.showSurface());
        show.add(window.showModel);
        window.refinement.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_H, ctrl | shift));
        window.refinement.setToolTipText("the triangles the strip follows, lighter to darker along its path: the refinement's, tree edges"
                + " in green, or the model's own where the wrap follows them");
        window.refinement.addActionListener(e -> window.showSurface());
        show.add(window.refinement);
        window.showCollisions.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_C, ctrl | shift));
        window.showCollisions.setToolTipText("a wrap's faces of paper that cross paper or the model, in red, seen through the layers above"
                + " them: where a fold is impossible");
        window.showCollisions.addActionListener(e -> window.showSurface());
        show.add(window.showCollisions);
        window.captions.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_K, ctrl));
        window.captions.setToolTipText("the status line in the view, and the caption of exported frames and movies");
        window.captions.addActionListener(e -> window.view.setShowStatus(window.captions.isSelected()));
        show.add(window.captions);
        show.add(item("Paper colours...", KeyEvent.VK_L, ctrl, this::choosePaperColours));
        show.addSeparator();
        show.add(item("Reset camera", KeyEvent.VK_0, ctrl, window.view::resetCamera));
        show.add(item("Underside", KeyEvent.VK_U, ctrl, window.view::underside));
        bar.add(show);

        JMenu fold = new JMenu("Fold");
        fold.setMnemonic(KeyEvent.VK_O);
        // Each job as its fields were left: switching back and forth loses nothing.
        fold.add(item("Zig-zag a triangle", KeyEvent.VK_1, ctrl, () -> window.parameters.show(window.parameters.zigzag())));
        fold.add(item("Turn gadget", KeyEvent.VK_2, ctrl, () -> window.parameters.show(window.parameters.turn())));
        fold.add(item("Wrap the model", KeyEvent.VK_3, ctrl, window::wrapModel));
        fold.add(item("Play a script", KeyEvent.VK_4, ctrl, window::playScript));
        fold.add(item("View a model", KeyEvent.VK_5, ctrl, window::viewModel));
        fold.add(item("Check the wrap", KeyEvent.VK_6, ctrl, window.exports::checkAsk));
        fold.addSeparator();
        fold.add(item("Play / pause", KeyEvent.VK_P, ctrl, window.timeline::togglePlaying));
        fold.add(item("Previous fold", KeyEvent.VK_OPEN_BRACKET, ctrl, () -> window.timeline.step(-1)));
        fold.add(item("Next fold", KeyEvent.VK_CLOSE_BRACKET, ctrl, () -> window.timeline.step(1)));
        fold.add(item("Back to the start", KeyEvent.VK_HOME, ctrl, window.timeline::restart));
        bar.add(fold);

        JMenu help = new JMenu("Help");
        help.setMnemonic(KeyEvent.VK_H);
        help.add(item("Keys", KeyEvent.VK_F1, 0, this::showKeys));
        help.add(item("About iFold", 0, 0, this::showAbout));
        bar.add(help);
        return bar;
    }

    static JMenuItem item(String name, int key, int modifiers, Runnable action) {
        JMenuItem item = new JMenuItem(name);
        if (key != 0) {
            item.setAccelerator(KeyStroke.getKeyStroke(key, modifiers));
        }
        item.addActionListener(e -> action.run());
        return item;
    }

    /** The viewer's keys, where the view has the focus (a click gives it): typing in a field stays typing. */
    void keys() {
        bind("SPACE", window.timeline::togglePlaying);
        bind("LEFT", () -> window.timeline.step(-1));
        bind("RIGHT", () -> window.timeline.step(1));
        bind("HOME", window.timeline::restart);
        bind("R", window.view::resetCamera);
        bind("U", window.view::underside);
        bind("H", () -> window.view.setShowHelp(!window.view.isShowingHelp()));
    }

    void bind(String key, Runnable action) {
        window.view.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(key), key);
        window.view.getActionMap().put(key, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                action.run();
            }
        });
    }

    /** Asks the paper's top and bottom colours; "as planned" keeps the plan's own (white, with grey caps; blue-grey below). */
    void choosePaperColours() {
        int top = window.settings.getInt("paper.top", 0);
        int bottom = window.settings.getInt("paper.bottom", 0);
        java.awt.Color chosenTop = javax.swing.JColorChooser.showDialog(window, "The paper's top side",
                new java.awt.Color(top == 0 ? 0xF4F1EA : top));
        if (chosenTop == null) {
            return;
        }
        java.awt.Color chosenBottom = javax.swing.JColorChooser.showDialog(window, "The paper's bottom side",
                new java.awt.Color(bottom == 0 ? 0x8FAACB : bottom));
        if (chosenBottom == null) {
            return;
        }
        setPaperColours(chosenTop.getRGB(), chosenBottom.getRGB());
    }

    /** Colours the paper, top and bottom (0xAARRGGBB; 0 keeps the plan's own), and remembers it. */
    void setPaperColours(int top, int bottom) {
        window.settings.putInt("paper.top", top);
        window.settings.putInt("paper.bottom", bottom);
        window.view.setPaperColours(top, bottom);
    }

    void showKeys() {
        StringBuilder text = new StringBuilder("In the view (click it first):\n");
        for (String line : SceneView.HELP) {
            text.append("  ").append(line).append('\n');
        }
        text.append("\nEverywhere: the shortcuts shown in the menus.");
        // In the view's own monospaced letters: its lines are aligned by spaces, which a
        // proportional font scattered.
        javax.swing.JTextArea keys = new javax.swing.JTextArea(text.toString());
        keys.setEditable(false);
        keys.setOpaque(false);
        keys.setFont(new java.awt.Font(java.awt.Font.MONOSPACED, java.awt.Font.PLAIN, keys.getFont().getSize()));
        JOptionPane.showMessageDialog(window, keys, "Keys", JOptionPane.INFORMATION_MESSAGE);
    }

    void showAbout() {
        JOptionPane.showMessageDialog(window, "iFold " + App.version() + "\n\nWraps polyhedra in a strip of paper, the zig-zag way\n"
                + "(Demaine, Demaine and Mitchell), folded with the paper's thickness.", "About iFold", JOptionPane.INFORMATION_MESSAGE);
    }

    void refreshRecent() {
        window.recent.removeAll();
        List<Path> files = window.settings.recent();
        for (int i = 0; i < files.size(); i++) {
            Path file = files.get(i);
            JMenuItem item = new JMenuItem((i + 1) + "  " + file.getFileName());
            item.setToolTipText(file.toString());
            if (i < 9) {
                item.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_1 + i, InputEvent.ALT_DOWN_MASK));
            }
            item.addActionListener(e -> window.open(file));
            window.recent.add(item);
        }
        window.recent.setEnabled(!files.isEmpty());
    }
}
