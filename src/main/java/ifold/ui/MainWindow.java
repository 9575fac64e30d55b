package ifold.ui;

import ifold.job.Scenes;
import ifold.scene.CollisionView;
import ifold.scene.PathView;
import ifold.ui.model.Exports;
import ifold.ui.model.Job;
import ifold.ui.model.ModelFile;
import ifold.ui.model.NewModel;
import ifold.ui.model.Plan;
import ifold.ui.model.Planning;
import ifold.ui.model.Problem;
import ifold.ui.model.Settings;
import ifold.ui.model.Timeline;
import ifold.ui.model.Worker;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.Toolkit;
import java.awt.event.ActionEvent;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.function.Consumer;
import javax.swing.AbstractAction;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuBar;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.KeyStroke;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The main window: menus, the parameters on the left, the 3D view in the middle, the report
 * and the folds on the right, the timeline below, and a status bar with progress and Cancel.
 * Everything here runs on the event thread; planning and exports run on two {@link Worker}s,
 * whose reports come back to it.
 */
final class MainWindow extends JFrame {
    private static final long serialVersionUID = 1L;

    private final transient Settings settings;
    private final transient Worker planner = new Worker("ifold plan", SwingUtilities::invokeLater);
    private final transient Worker exporter = new Worker("ifold export", SwingUtilities::invokeLater);
    /** Measures a model for Model information: of its own, so that it neither stops nor waits for a plan or an export. */
    private final transient Worker inspector = new Worker("ifold info", SwingUtilities::invokeLater);
    final SceneView view;
    final ParameterPanel parameters;
    final TimelinePanel timeline;
    final ReportPanel report = new ReportPanel();
    /** The list of folds, or of a view's steps, under its title. */
    private final JScrollPane foldList;
    final JProgressBar progress = new JProgressBar();
    final JButton cancel = new JButton("Cancel");
    final JLabel message = new JLabel(" ");
    private final JMenu recent = new JMenu("Open recent");
    private final JCheckBoxMenuItem showModel = new JCheckBoxMenuItem("Model", true);
    private final JCheckBoxMenuItem showCollisions = new JCheckBoxMenuItem("Collisions", false);
    private final JCheckBoxMenuItem captions = new JCheckBoxMenuItem("Captions", true);
    private final JCheckBoxMenuItem refinement = new JCheckBoxMenuItem("Refinement and Hamiltonian path", false);
    /** What needs a model open: the wrap's card has one. */
    private final JMenuItem modelInformation;
    private final JMenuItem exportRefinement;
    /** The last Model information shown, kept open beside the window; null before the first. */
    javax.swing.JDialog informationDialog;
    final ReportPanel information = new ReportPanel();
    /** The New model form, kept between askings so that it opens as it was left. */
    final NewModelForm newModelForm = new NewModelForm();
    private transient Plan plan;
    /** The File menu's exports, which ask what and where and hand the writing back here. */
    final transient ExportDialogs exports;
    /** A fold script or FOLD file being opened, until its plan ends; and the job shown before it, if any. */
    private Path opening;
    private Job beforeOpening;
    /** Told of every message shown, for tests: a failure must be seen, not just logged. */
    transient Consumer<String> messages = text -> { };

    MainWindow(Settings settings) {
        super("iFold");
        this.settings = settings;
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        modelInformation = item("Model information...", KeyEvent.VK_I, ctrl, this::showModelInformation);
        modelInformation.setToolTipText("the model's counts and topology, as ifold info prints them");
        exports = new ExportDialogs(this, new ExportHost());
        exportRefinement = item("Export refinement (OFF, OBJ)...", KeyEvent.VK_R, ctrl, exports::refinementAsk);
        exportRefinement.setToolTipText("the model's Hamiltonian refinement, its triangles in path order, as ifold refine writes it");
        view = new SceneView(this::say);
        parameters = new ParameterPanel(this::planLater, this::chooseModel, this::chooseScript);
        timeline = new TimelinePanel(view);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        setJMenuBar(menus());

        JScrollPane left = new JScrollPane(parameters);
        left.setBorder(BorderFactory.createEmptyBorder());
        left.setPreferredSize(new Dimension(320, 400));
        left.setHorizontalScrollBarPolicy(JScrollPane.HORIZONTAL_SCROLLBAR_NEVER);
        left.setMinimumSize(new Dimension(280, 200)); // the split panes share out what is left, never the parameters' room
        JScrollPane figures = new JScrollPane(report);
        figures.setBorder(BorderFactory.createTitledBorder("Report"));
        foldList = new JScrollPane(timeline.folds);
        foldList.setBorder(BorderFactory.createTitledBorder("Folds"));
        JSplitPane right = new JSplitPane(JSplitPane.VERTICAL_SPLIT, figures, foldList);
        right.setResizeWeight(0.5);
        right.setPreferredSize(new Dimension(330, 400));
        right.setMinimumSize(new Dimension(260, 200));
        JPanel centre = new JPanel(new BorderLayout());
        centre.add(view, BorderLayout.CENTER);
        centre.add(timeline, BorderLayout.SOUTH);
        JSplitPane main = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, left,
                new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, centre, right) {
                    private static final long serialVersionUID = 1L;

                    {
                        setResizeWeight(1);
                    }
                });
        add(main, BorderLayout.CENTER);

        JPanel status = new JPanel(new BorderLayout(8, 0));
        status.setBorder(BorderFactory.createEmptyBorder(3, 8, 3, 8));
        message.setToolTipText("what iFold is doing, or why it could not");
        status.add(message, BorderLayout.CENTER);
        JPanel work = new JPanel(new FlowLayout(FlowLayout.RIGHT, 6, 0));
        // As high as it is with its text ("1234 / 6398"), which it shows once the work counts:
        // measured without, the bar was a few pixels high and cut the text in half.
        progress.setStringPainted(true);
        progress.setString("0 / 0");
        int high = progress.getPreferredSize().height;
        progress.setStringPainted(false);
        progress.setPreferredSize(new Dimension(180, high));
        progress.setVisible(false);
        cancel.setVisible(false);
        cancel.addActionListener(e -> cancelWork());
        work.add(progress);
        work.add(cancel);
        status.add(work, BorderLayout.EAST);
        add(status, BorderLayout.SOUTH);

        keys();
        int width = settings.getInt("window.width", 1360);
        int height = settings.getInt("window.height", 860);
        Dimension screen = Toolkit.getDefaultToolkit().getScreenSize();
        setSize(Math.min(width, screen.width), Math.min(height, screen.height));
        setMinimumSize(new Dimension(900, 600));
        setLocationRelativeTo(null);
        int x = settings.getInt("window.x", Integer.MIN_VALUE);
        int y = settings.getInt("window.y", Integer.MIN_VALUE);
        if (x != Integer.MIN_VALUE && y != Integer.MIN_VALUE && x >= 0 && y >= 0 && x < screen.width - 100 && y < screen.height - 100) {
            setLocation(x, y); // where it was left, if that is still on the screen
        }
        refreshRecent();
        view.setPaperColours(settings.getInt("paper.top", 0), settings.getInt("paper.bottom", 0));
    }

    /** Closes the window: the work under way is cancelled (an export writes nothing), the settings are saved first. */
    @Override
    public void dispose() {
        if (isDisplayable()) {
            planner.cancel();
            exporter.cancel();
            inspector.cancel();
            if (informationDialog != null) {
                informationDialog.dispose();
            }
            view.dispose();
            saveSettings();
        }
        super.dispose();
    }

    // ---- Menus and keys ----

    private JMenuBar menus() {
        JMenuBar bar = new JMenuBar();
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        int shift = InputEvent.SHIFT_DOWN_MASK;

        JMenu file = new JMenu("File");
        file.setMnemonic(KeyEvent.VK_F);
        file.add(item("Open model (OFF, OBJ)...", KeyEvent.VK_O, ctrl, this::chooseModel));
        file.add(item("Open fold script or FOLD...", KeyEvent.VK_O, ctrl | shift, this::chooseScript));
        file.add(recent);
        file.add(item("New model...", KeyEvent.VK_N, ctrl, this::newModelAsk));
        file.add(modelInformation);
        file.addSeparator();
        file.add(item("Export frames...", KeyEvent.VK_F, ctrl | shift, exports::framesAsk));
        file.add(item("Export movie (MP4, GIF)...", KeyEvent.VK_M, ctrl, exports::movieAsk));
        file.add(item("Export OBJ...", KeyEvent.VK_E, ctrl, () -> exports.fileAsk("OBJ", "obj")));
        file.add(item("Export FOLD...", KeyEvent.VK_E, ctrl | shift, () -> exports.fileAsk("FOLD", "fold")));
        file.add(item("Export report (JSON)...", KeyEvent.VK_J, ctrl, () -> exports.fileAsk("report", "json")));
        file.add(item("Export figure (PNG)...", KeyEvent.VK_G, ctrl, () -> exports.fileAsk("figure", "png")));
        file.add(exportRefinement);
        file.addSeparator();
        file.add(item("Quit", KeyEvent.VK_Q, ctrl, this::dispose));
        bar.add(file);

        JMenu show = new JMenu("View");
        show.setMnemonic(KeyEvent.VK_V);
        showModel.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_M, ctrl | shift));
        showModel.addActionListener(e -> showSurface());
        show.add(showModel);
        refinement.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_H, ctrl | shift));
        refinement.setToolTipText("a wrap's model refined, lighter to darker along the path the strip follows, tree edges in green");
        refinement.addActionListener(e -> showSurface());
        show.add(refinement);
        showCollisions.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_C, ctrl | shift));
        showCollisions.setToolTipText("a wrap's faces of paper that cross paper or the model, in red, seen through the layers above"
                + " them: where a fold is impossible");
        showCollisions.addActionListener(e -> showSurface());
        show.add(showCollisions);
        captions.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_K, ctrl));
        captions.setToolTipText("the status line in the view, and the caption of exported frames and movies");
        captions.addActionListener(e -> view.setShowStatus(captions.isSelected()));
        show.add(captions);
        show.add(item("Paper colours...", KeyEvent.VK_L, ctrl, this::choosePaperColours));
        show.addSeparator();
        show.add(item("Reset camera", KeyEvent.VK_0, ctrl, view::resetCamera));
        show.add(item("Underside", KeyEvent.VK_U, ctrl, view::underside));
        bar.add(show);

        JMenu fold = new JMenu("Fold");
        fold.setMnemonic(KeyEvent.VK_O);
        // Each job as its fields were left: switching back and forth loses nothing.
        fold.add(item("Zig-zag a triangle", KeyEvent.VK_1, ctrl, () -> parameters.show(parameters.zigzag())));
        fold.add(item("Turn gadget", KeyEvent.VK_2, ctrl, () -> parameters.show(parameters.turn())));
        fold.add(item("Wrap the model", KeyEvent.VK_3, ctrl, this::wrapModel));
        fold.add(item("Play a script", KeyEvent.VK_4, ctrl, this::playScript));
        fold.add(item("View a model", KeyEvent.VK_5, ctrl, this::viewModel));
        fold.addSeparator();
        fold.add(item("Play / pause", KeyEvent.VK_P, ctrl, timeline::togglePlaying));
        fold.add(item("Previous fold", KeyEvent.VK_OPEN_BRACKET, ctrl, () -> timeline.step(-1)));
        fold.add(item("Next fold", KeyEvent.VK_CLOSE_BRACKET, ctrl, () -> timeline.step(1)));
        fold.add(item("Back to the start", KeyEvent.VK_HOME, ctrl, timeline::restart));
        bar.add(fold);

        JMenu help = new JMenu("Help");
        help.setMnemonic(KeyEvent.VK_H);
        help.add(item("Keys", KeyEvent.VK_F1, 0, this::showKeys));
        help.add(item("About iFold", 0, 0, this::showAbout));
        bar.add(help);
        return bar;
    }

    private static JMenuItem item(String name, int key, int modifiers, Runnable action) {
        JMenuItem item = new JMenuItem(name);
        if (key != 0) {
            item.setAccelerator(KeyStroke.getKeyStroke(key, modifiers));
        }
        item.addActionListener(e -> action.run());
        return item;
    }

    /** The viewer's keys, where the view has the focus (a click gives it): typing in a field stays typing. */
    private void keys() {
        bind("SPACE", timeline::togglePlaying);
        bind("LEFT", () -> timeline.step(-1));
        bind("RIGHT", () -> timeline.step(1));
        bind("HOME", timeline::restart);
        bind("R", view::resetCamera);
        bind("U", view::underside);
        bind("H", () -> view.setShowHelp(!view.isShowingHelp()));
    }

    private void bind(String key, Runnable action) {
        view.getInputMap(JComponent.WHEN_FOCUSED).put(KeyStroke.getKeyStroke(key), key);
        view.getActionMap().put(key, new AbstractAction() {
            private static final long serialVersionUID = 1L;

            @Override
            public void actionPerformed(ActionEvent e) {
                action.run();
            }
        });
    }

    /** The model, or its refinement with the path in its place (they lie on the same surface), or neither. */
    private void showSurface() {
        view.setVisible(Scenes.MODEL, showModel.isSelected() && !refinement.isSelected());
        view.setVisible(Scenes.REFINEMENT, showModel.isSelected() && refinement.isSelected());
        view.setVisible(CollisionView.NAME, showCollisions.isSelected());
    }

    /** Asks the paper's top and bottom colours; "as planned" keeps the plan's own (white, with grey caps; blue-grey below). */
    private void choosePaperColours() {
        int top = settings.getInt("paper.top", 0);
        int bottom = settings.getInt("paper.bottom", 0);
        java.awt.Color chosenTop = javax.swing.JColorChooser.showDialog(this, "The paper's top side",
                new java.awt.Color(top == 0 ? 0xF4F1EA : top));
        if (chosenTop == null) {
            return;
        }
        java.awt.Color chosenBottom = javax.swing.JColorChooser.showDialog(this, "The paper's bottom side",
                new java.awt.Color(bottom == 0 ? 0x8FAACB : bottom));
        if (chosenBottom == null) {
            return;
        }
        setPaperColours(chosenTop.getRGB(), chosenBottom.getRGB());
    }

    /** Colours the paper, top and bottom (0xAARRGGBB; 0 keeps the plan's own), and remembers it. */
    void setPaperColours(int top, int bottom) {
        settings.putInt("paper.top", top);
        settings.putInt("paper.bottom", bottom);
        view.setPaperColours(top, bottom);
    }

    private void showKeys() {
        StringBuilder text = new StringBuilder("In the view (click it first):\n");
        for (String line : SceneView.HELP) {
            text.append("  ").append(line).append('\n');
        }
        text.append("\nEverywhere: the shortcuts shown in the menus.");
        JOptionPane.showMessageDialog(this, text.toString(), "Keys", JOptionPane.INFORMATION_MESSAGE);
    }

    private void showAbout() {
        JOptionPane.showMessageDialog(this, "iFold " + App.version() + "\n\nWraps polyhedra in a strip of paper, the zig-zag way\n"
                + "(Demaine, Demaine and Mitchell), folded with the paper's thickness.", "About iFold", JOptionPane.INFORMATION_MESSAGE);
    }

    // ---- Jobs ----

    /**
     * Opens a file: a model to wrap (or to view, while the view's card is shown), or a fold
     * script or FOLD file to play (as {@code ifold app FILE}).
     */
    void open(Path file) {
        boolean model = ModelFile.isModelName(file);
        // A width or thickness typed for one model rarely suits another (a spike's triangles
        // refuse the cube's 0.1): another model starts from its own defaults, and says so.
        boolean another = model && !file.equals(parameters.model());
        if (another && parameters.resetModelParameters()) {
            say("width and thickness back to this model's defaults");
        }
        Job job = !model ? new Job.Script(file) : parameters.card().equals("view") ? parameters.view(file) : parameters.wrap(file);
        Path folder = file.toAbsolutePath().getParent();
        if (folder != null) {
            settings.put("folder", folder.toString());
        }
        if (model) {
            // A model stays open when its wrap is refused (another width may do): it is recent at once.
            opening = null;
            settings.addRecent(file);
            refreshRecent();
        } else {
            // A script or FOLD file is recent, and replaces what is shown, only once it plays.
            opening = file;
            beforeOpening = plan == null ? null : plan.job();
        }
        parameters.show(job);
    }

    private void wrapModel() {
        if (parameters.job() instanceof Job.WrapModel) {
            return;
        }
        Job last = lastModel();
        if (last == null) {
            chooseModel();
        } else {
            parameters.show(last);
        }
    }

    /** The view's card, on the open model (or the last one opened); without one, asks for it. */
    private void viewModel() {
        if (parameters.job() instanceof Job.View) {
            return;
        }
        Path model = parameters.model();
        if (model == null) {
            Job last = lastModel();
            model = last == null ? null : ((Job.WrapModel) last).model();
        }
        parameters.show(parameters.view(model));
        if (model == null) {
            chooseModel();
        }
    }

    private Job lastModel() {
        for (Path file : settings.recent()) {
            if (ModelFile.isModelName(file) && Files.isRegularFile(file)) {
                return parameters.wrap(file);
            }
        }
        return null;
    }

    private void playScript() {
        for (Path file : settings.recent()) {
            if (!ModelFile.isModelName(file) && Files.isRegularFile(file)) {
                parameters.show(new Job.Script(file));
                return;
            }
        }
        chooseScript();
    }

    private void chooseModel() {
        Path file = choose("Open a model", false, new FileNameExtensionFilter("Models (OFF, OBJ, PLY, STL)", "off", "obj", "ply", "stl"));
        if (file != null) {
            open(file);
        }
    }

    private void chooseScript() {
        Path file = choose("Open a fold script or FOLD file", false, new FileNameExtensionFilter("Fold scripts and FOLD files", "fold", "txt"));
        if (file != null) {
            open(file);
        }
    }

    private void refreshRecent() {
        recent.removeAll();
        List<Path> files = settings.recent();
        for (int i = 0; i < files.size(); i++) {
            Path file = files.get(i);
            JMenuItem item = new JMenuItem((i + 1) + "  " + file.getFileName());
            item.setToolTipText(file.toString());
            if (i < 9) {
                item.setAccelerator(KeyStroke.getKeyStroke(KeyEvent.VK_1 + i, InputEvent.ALT_DOWN_MASK));
            }
            item.addActionListener(e -> open(file));
            recent.add(item);
        }
        recent.setEnabled(!files.isEmpty());
    }

    /** The parameters changed: check them at once (marking the fields), and plan if they pass. */
    private void planLater(Job job) {
        boolean modelOpen = parameters.model() != null;
        modelInformation.setEnabled(modelOpen);
        exportRefinement.setEnabled(modelOpen);
        rememberParameters(job);
        List<Problem> problems = Planning.check(job);
        parameters.mark(problems);
        if (!problems.isEmpty()) {
            planner.cancel();
            workEnded();
            say("fix the marked values to fold again");
            return;
        }
        plan(job);
    }

    private void plan(Job job) {
        workStarted("planning");
        planner.submit(progress -> Planning.plan(job, progress), new StatusLine<Plan>() {
            @Override
            void finished(Plan next) {
                if (isOpening(job)) {
                    settings.addRecent(opening);
                    refreshRecent();
                    opening = null;
                }
                show(next);
            }

            @Override
            void refused(Problem problem) {
                if (isOpening(job)) {
                    // A failed open changes nothing but the error shown: the panel goes back to
                    // the job the view, the report and the folds still show.
                    Path failed = opening;
                    opening = null;
                    if (beforeOpening != null) {
                        parameters.restore(beforeOpening);
                    }
                    say("cannot open " + failed.getFileName() + ": " + problem.message());
                    return;
                }
                parameters.mark(List.of(problem));
                say(problem.message());
                if (job instanceof Job.WrapModel wrap && !shows(wrap.model())) {
                    showModelAlone(wrap, problem.message());
                }
            }
        });
    }

    /** Whether the plan shown is of {@code model}: its wrap, or its view. */
    private boolean shows(Path model) {
        Job shown = plan == null ? null : plan.job();
        return shown instanceof Job.WrapModel w && w.model().equals(model) || shown instanceof Job.View v && v.model().equals(model);
    }

    /**
     * A model whose wrap was refused is drawn anyway, as the view draws it, the wrap's card and
     * its marked field kept for another try: before, the view stayed empty or on the model before.
     */
    private void showModelAlone(Job.WrapModel wrap, String refusal) {
        Job.View view = new Job.View(wrap.model(), Scenes.Show.MODEL, PathView.Colors.DARKNESS, wrap.strict());
        workStarted("drawing the model");
        planner.submit(progress -> Planning.plan(view, progress), new StatusLine<Plan>() {
            @Override
            void finished(Plan next) {
                show(next);
                setTitle("iFold - " + wrap.model().getFileName() + " (not wrapped)");
                say(refusal);
            }

            @Override
            void refused(Problem problem) {
                say(refusal); // a model that cannot be read was refused for that already
            }
        });
    }

    /** Whether {@code job} plays the script or FOLD file being opened. */
    private boolean isOpening(Job job) {
        return opening != null && job instanceof Job.Script s && opening.equals(s.file());
    }

    /** The section of docs/reports.md that explains a job's report. */
    private static String reportSection(Job job) {
        if (job instanceof Job.ZigZag) {
            return "demo zigzag";
        }
        if (job instanceof Job.Turn) {
            return "demo turn";
        }
        if (job instanceof Job.Script) {
            return "fold";
        }
        return job instanceof Job.View ? "view" : "wrap";
    }

    /** Shows a new plan: at the same point of its animation as the one before if it is the same kind of job, else from the start, playing. */
    private void show(Plan next) {
        Plan before = plan;
        Timeline old = timeline.timeline();
        boolean sameKind = before != null && before.job().getClass() == next.job().getClass()
                && !(next.job() instanceof Job.WrapModel w && !w.model().equals(((Job.WrapModel) before.job()).model()))
                && !(next.job() instanceof Job.View v && !(v.model().equals(((Job.View) before.job()).model())
                        && v.show() == ((Job.View) before.job()).show()));
        double fraction = sameKind && old != null && old.end() > 0 ? old.position() / old.end() : 0;
        plan = next;
        Timeline fresh = Timeline.of(next);
        fresh.seek(fraction * fresh.end());
        view.show(next.shown(), fresh.position(), next.title());
        showSurface();
        // A view reveals triangles and folds no paper: its steps are not folds.
        timeline.setTimeline(fresh, !sameKind || (old != null && old.isPlaying()), next.hasPaper() ? "fold" : "step");
        foldList.setBorder(BorderFactory.createTitledBorder(next.hasPaper() ? "Folds" : "Steps"));
        report.show(reportSection(next.job()), next.figures());
        setTitle("iFold - " + next.title());
        say(next.title());
    }

    Plan plan() {
        return plan;
    }

    // ---- Writing in the background ----

    /** What the exports need of the window. */
    private final class ExportHost implements ExportDialogs.Host {
        @Override
        public Plan plan() {
            return plan;
        }

        @Override
        public Path openModel() {
            return MainWindow.this.openModel();
        }

        @Override
        public boolean strict() {
            return parameters.wrapStrict.isSelected();
        }

        @Override
        public boolean captions() {
            return captions.isSelected();
        }

        @Override
        public double speed() {
            return timeline.timeline().speed();
        }

        @Override
        public Path choose(String title, boolean save, FileNameExtensionFilter filter) {
            return MainWindow.this.choose(title, save, filter);
        }

        @Override
        public void write(String doing, String failed, Path file, Worker.Task<String> task, Consumer<String> written) {
            MainWindow.this.write(doing, failed, file, task, written);
        }

        @Override
        public void say(String text) {
            MainWindow.this.say(text);
        }
    }

    /**
     * Writes {@code file} in the background with progress and Cancel; {@code written} hears the
     * summary, and a failure is said after {@code failed} ("cannot export the movie").
     */
    private void write(String doing, String failed, Path file, Worker.Task<String> task, Consumer<String> written) {
        workStarted(doing);
        exporter.submit(task, new StatusLine<String>() {
            @Override
            void finished(String summary) {
                Path folder = file.toAbsolutePath().getParent();
                if (folder != null) {
                    settings.put("folder", folder.toString());
                }
                written.accept(summary);
            }

            @Override
            void refused(Problem problem) {
                say(failed + ": " + problem.message());
                String title = Character.toUpperCase(failed.charAt(0)) + failed.substring(1);
                JOptionPane.showMessageDialog(MainWindow.this, problem.message(), title, JOptionPane.ERROR_MESSAGE);
            }
        });
    }

    /**
     * What the window hears of background work: its stages and progress on the status line, and
     * its end, whichever it is, ends the work shown before {@link #finished} or {@link #refused}.
     */
    private abstract class StatusLine<T> implements Worker.Listener<T> {
        @Override
        public final void stage(String what) {
            say(what + "...");
        }

        @Override
        public final void done(int done, int total) {
            MainWindow.this.done(done, total);
        }

        @Override
        public final void succeeded(T value) {
            workEnded();
            finished(value);
        }

        @Override
        public final void failed(Problem problem) {
            workEnded();
            refused(problem);
        }

        abstract void finished(T value);

        abstract void refused(Problem problem);
    }

    private Path choose(String title, boolean save, FileNameExtensionFilter filter) {
        JFileChooser chooser = new JFileChooser(settings.get("folder", System.getProperty("user.dir")));
        chooser.setDialogTitle(title);
        if (filter != null) {
            chooser.setFileFilter(filter);
            if (save) {
                // The name of what is shown, with the filter's first extension: typing it each time is a chore.
                Job job = plan != null ? plan.job() : parameters.job();
                chooser.setSelectedFile(new File(chooser.getCurrentDirectory(), Exports.suggestedName(job, filter.getExtensions()[0])));
            }
        } else {
            chooser.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        }
        int answer = save ? chooser.showSaveDialog(this) : chooser.showOpenDialog(this);
        File chosen = chooser.getSelectedFile();
        if (answer != JFileChooser.APPROVE_OPTION || chosen == null) {
            return null;
        }
        Path folder = chosen.toPath().toAbsolutePath().getParent();
        if (folder != null) {
            settings.put("folder", folder.toString());
        }
        return chosen.toPath();
    }

    // ---- The model: its information, its refinement, a new one ----

    /** The model of the wrap's card, or null after saying in the status line that none is open. */
    private Path openModel() {
        Path model = parameters.model();
        if (model == null) {
            say("no model open: File, Open model or New model first");
        }
        return model;
    }

    /** File, Model information: the model's counts and topology, measured off the event thread, in a window beside this one. */
    void showModelInformation() {
        Path model = openModel();
        if (model == null) {
            return;
        }
        boolean strict = parameters.wrapStrict.isSelected();
        workStarted("measuring " + model.getFileName());
        inspector.submit(progress -> ModelFile.information(model, strict, progress), new StatusLine<Map<String, Object>>() {
            @Override
            void finished(Map<String, Object> figures) {
                showInformation(model, figures);
                say(model.getFileName() + ": " + figures.get("faces") + " faces, genus " + figures.get("genus"));
            }

            @Override
            void refused(Problem problem) {
                say("no model information: " + problem.message());
            }
        });
    }

    private void showInformation(Path model, Map<String, Object> figures) {
        if (informationDialog == null) {
            informationDialog = new javax.swing.JDialog(this, false);
            JScrollPane table = new JScrollPane(information);
            table.setPreferredSize(new Dimension(360, 420));
            informationDialog.add(table, BorderLayout.CENTER);
            JButton close = new JButton("Close");
            close.addActionListener(e -> informationDialog.setVisible(false));
            JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
            buttons.add(close);
            informationDialog.add(buttons, BorderLayout.SOUTH);
            informationDialog.getRootPane().setDefaultButton(close);
            // Esc closes it, as it closes every dialog of the window.
            informationDialog.getRootPane().registerKeyboardAction(e -> informationDialog.setVisible(false),
                    KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), JComponent.WHEN_IN_FOCUSED_WINDOW);
            informationDialog.pack();
            informationDialog.setLocationRelativeTo(this);
        }
        information.show("info", figures);
        informationDialog.setTitle("Model information: " + model.getFileName());
        informationDialog.setVisible(true);
    }

    /** File, New model: asks the shape and its parameters (each refused at its field), where to save it, and opens it to wrap. */
    private void newModelAsk() {
        NewModel chosen = askNewModel();
        if (chosen == null) {
            return;
        }
        JFileChooser chooser = new JFileChooser(settings.get("folder", System.getProperty("user.dir")));
        chooser.setDialogTitle("Save the new model");
        chooser.setFileFilter(new FileNameExtensionFilter("Meshes (OFF, OBJ, PLY, STL)", "off", "obj", "ply", "stl"));
        chooser.setSelectedFile(new File(chooser.getCurrentDirectory(), chosen.fileName()));
        File target = chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION ? chooser.getSelectedFile() : null;
        if (target == null) {
            return;
        }
        Path file = target.toPath();
        if (!ModelFile.isWritableModelName(file)) {
            file = file.resolveSibling(file.getFileName() + ".off");
        }
        newModel(chosen, file);
    }

    /** Makes {@code model}, writes it to {@code file}, and opens it to wrap once it is written. */
    void newModel(NewModel model, Path file) {
        write("making the " + model.shape(), "cannot make the " + model.shape(), file, progress -> {
            NewModel.Made made = model.write(file, progress);
            return "wrote " + made.file() + ": " + made.vertices() + " vertices, " + made.faces() + " faces";
        }, summary -> {
            open(file);
            say(summary);
        });
    }

    /** Asks for a shape and its parameters until they are good (each problem under its field) or the asking is cancelled. */
    private NewModel askNewModel() {
        newModelForm.mark(List.of());
        while (true) {
            if (JOptionPane.showConfirmDialog(this, newModelForm, "New model", JOptionPane.OK_CANCEL_OPTION, JOptionPane.PLAIN_MESSAGE)
                    != JOptionPane.OK_OPTION) {
                return null;
            }
            NewModel chosen = newModelForm.model();
            List<Problem> problems = chosen.check();
            if (problems.isEmpty()) {
                return chosen;
            }
            newModelForm.mark(problems);
        }
    }

    // ---- Work in progress ----

    private void workStarted(String what) {
        progress.setIndeterminate(true);
        progress.setVisible(true);
        progress.setString(what);
        cancel.setVisible(true);
        say(what + "...");
    }

    private void done(int done, int total) {
        progress.setIndeterminate(false);
        progress.setMaximum(total);
        progress.setValue(done);
        progress.setStringPainted(true);
        progress.setString(done + " / " + total);
    }

    private void workEnded() {
        if (!isWorking()) {
            progress.setVisible(false);
            progress.setStringPainted(false);
            cancel.setVisible(false);
        }
    }

    /** Cancel: the export if one runs (its file is not written), else the planning (the last plan stays). */
    void cancelWork() {
        if (exporter.cancel()) {
            say("export cancelled: nothing written");
        } else if (inspector.cancel()) {
            say("model information cancelled");
        } else if (planner.cancel()) {
            say("planning cancelled" + (plan == null ? "" : ": still showing " + plan.title()));
        }
        workEnded();
    }

    boolean isWorking() {
        return planner.isBusy() || exporter.isBusy() || inspector.isBusy();
    }

    /** Waits for the export's thread to end, cancelled or not: for tests. */
    boolean awaitExport(long millis) throws InterruptedException {
        return exporter.await(millis);
    }

    void say(String text) {
        message.setText(text);
        message.setToolTipText(text);
        messages.accept(text);
    }

    // ---- Settings ----

    private void rememberParameters(Job job) {
        if (job instanceof Job.ZigZag z) {
            settings.put("zigzag.triangle", z.triangle());
            settings.putInt("zigzag.start", z.start());
            settings.putInt("zigzag.end", z.end());
            settings.putInt("zigzag.enterFrom", z.enterFrom());
            settings.put("zigzag.width", z.width());
            settings.put("zigzag.thickness", z.thickness());
        } else if (job instanceof Job.Turn t) {
            settings.put("turn.angle", t.angle());
            settings.put("turn.overhang", t.overhang());
            settings.put("turn.width", t.width());
            settings.put("turn.thickness", t.thickness());
        } else if (job instanceof Job.WrapModel w) {
            settings.put("wrap.width", w.width());
            settings.put("wrap.thickness", w.thickness());
            settings.put("wrap.maxFaces", w.maxFaces());
            settings.put("wrap.strict", Boolean.toString(w.strict()));
        } else if (job instanceof Job.View v) {
            settings.put("view.show", v.show().name());
            settings.put("view.colors", v.colors().name());
            settings.put("view.strict", Boolean.toString(v.strict()));
        }
        settings.put("job", job instanceof Job.ZigZag ? "zigzag" : job instanceof Job.Turn ? "turn" : job instanceof Job.WrapModel
                ? "wrap" : job instanceof Job.View ? "view" : "script");
    }

    /** The zig-zag as it was left last time, or the demo. */
    Job.ZigZag rememberedZigZag() {
        Job.ZigZag demo = Job.ZigZag.DEMO;
        return new Job.ZigZag(settings.get("zigzag.triangle", demo.triangle()), clampCorner(settings.getInt("zigzag.start", demo.start()), 0),
                clampCorner(settings.getInt("zigzag.end", demo.end()), 0), Math.max(-1, Math.min(2, settings.getInt("zigzag.enterFrom", -1))),
                settings.get("zigzag.width", ""), settings.get("zigzag.thickness", ""));
    }

    /** Sets the fields of the turn and the wrap as they were left, without planning them. */
    void restoreOtherParameters() {
        Job.Turn demo = Job.Turn.DEMO;
        parameters.angle.setText(settings.get("turn.angle", demo.angle()));
        parameters.overhang.setText(settings.get("turn.overhang", demo.overhang()));
        parameters.turnWidth.setText(settings.get("turn.width", demo.width()));
        parameters.turnThickness.setText(settings.get("turn.thickness", ""));
        parameters.wrapWidth.setText(settings.get("wrap.width", ""));
        parameters.wrapThickness.setText(settings.get("wrap.thickness", ""));
        parameters.wrapMaxFaces.setText(settings.get("wrap.maxFaces", ""));
        parameters.wrapStrict.setSelected(Boolean.parseBoolean(settings.get("wrap.strict", "false")));
        parameters.viewShow.setSelectedIndex(enumIndex(Scenes.Show.values(), settings.get("view.show", Scenes.Show.PATH.name())));
        parameters.viewColours.setSelectedIndex(enumIndex(PathView.Colors.values(), settings.get("view.colors", PathView.Colors.DARKNESS.name())));
        parameters.viewStrict.setSelected(Boolean.parseBoolean(settings.get("view.strict", "false")));
    }

    /** The index of the constant named {@code name}; the first for a name no longer known (a settings file edited or older). */
    private static int enumIndex(Enum<?>[] constants, String name) {
        for (Enum<?> constant : constants) {
            if (constant.name().equals(name)) {
                return constant.ordinal();
            }
        }
        return 0;
    }

    private static int clampCorner(int corner, int fallback) {
        return corner >= 0 && corner <= 2 ? corner : fallback;
    }

    private void saveSettings() {
        settings.putInt("window.width", getWidth());
        settings.putInt("window.height", getHeight());
        settings.putInt("window.x", getX());
        settings.putInt("window.y", getY());
        try {
            settings.save();
        } catch (IOException e) {
            // Settings are a convenience: the window closes all the same.
            System.err.println("ifold: cannot save the settings to " + settings.file() + ": " + e.getMessage());
        }
    }
}
