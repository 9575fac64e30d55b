package ifold.ui;

import ifold.job.Scenes;
import ifold.scene.CollisionView;
import ifold.scene.PathView;
import ifold.ui.model.Job;
import ifold.ui.model.ModelFile;
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
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.function.Consumer;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JProgressBar;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
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
    static final long serialVersionUID = 1L;

    final transient Settings settings;
    final transient Worker planner = new Worker("ifold plan", SwingUtilities::invokeLater);
    final transient Worker exporter = new Worker("ifold export", SwingUtilities::invokeLater);
    /** What the exporter's task does where it writes no file (a check), for Cancel to say; null for an export. */
    private String exporting;
    /** Measures a model for Model information: of its own, so that it neither stops nor waits for a plan or an export. */
    final transient Worker inspector = new Worker("ifold info", SwingUtilities::invokeLater);
    final SceneView view;
    final ParameterPanel parameters;
    final TimelinePanel timeline;
    final ReportPanel report = new ReportPanel();
    /** The list of folds, or of a view's steps, under its title. */
    final JScrollPane foldList;
    final JProgressBar progress = new JProgressBar();
    final JButton cancel = new JButton("Cancel");
    final JLabel message = new JLabel(" ");
    final JMenu recent = new JMenu("Open recent");
    final JCheckBoxMenuItem showModel = new JCheckBoxMenuItem("Model", true);
    final JCheckBoxMenuItem showCollisions = new JCheckBoxMenuItem("Collisions", false);
    final JCheckBoxMenuItem captions = new JCheckBoxMenuItem("Captions", true);
    final JCheckBoxMenuItem refinement = new JCheckBoxMenuItem("Path of triangles", false);
    /** What needs a model open: the wrap's card has one. */
    final JMenuItem modelInformation;
    final JMenuItem exportRefinement;
    /** The last Model information shown, kept open beside the window; null before the first. */
    javax.swing.JDialog informationDialog;
    final ReportPanel information = new ReportPanel();
    /** The New model form, kept between askings so that it opens as it was left. */
    final NewModelForm newModelForm = new NewModelForm();
    transient Plan plan;
    /** The File menu's exports, which ask what and where and hand the writing back here. */
    final transient ExportDialogs exports;
    /** A fold script or FOLD file being opened, until its plan ends; and the job shown before it, if any. */
    Path opening;
    Job beforeOpening;
    /** The menus and the viewer's keys. */
    final transient MainMenus menuBar = new MainMenus(this);
    /** What is remembered between sessions. */
    final transient WindowSettings remembered = new WindowSettings(this);
    /** The dialogs: files to open and save, model information, new models. */
    final transient WindowDialogs dialogs = new WindowDialogs(this);
    /** Told of every message shown, for tests: a failure must be seen, not just logged. */
    transient Consumer<String> messages = text -> { };

    MainWindow(Settings settings) {
        super("iFold");
        this.settings = settings;
        int ctrl = Toolkit.getDefaultToolkit().getMenuShortcutKeyMaskEx();
        modelInformation = MainMenus.item("Model information...", KeyEvent.VK_I, ctrl, dialogs::showModelInformation);
        modelInformation.setToolTipText("the model's counts and topology, as ifold info prints them");
        exports = new ExportDialogs(this, new ExportHost());
        exportRefinement = MainMenus.item("Export refinement (OFF, OBJ)...", KeyEvent.VK_R, ctrl, exports::refinementAsk);
        exportRefinement.setToolTipText("the model's Hamiltonian refinement, its triangles in path order, as ifold refine writes it");
        view = new SceneView(this::say);
        parameters = new ParameterPanel(this::planLater, dialogs::chooseModel, dialogs::chooseScript);
        timeline = new TimelinePanel(view);
        setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        setJMenuBar(menuBar.menus());

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

        menuBar.keys();
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
        menuBar.refreshRecent();
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
            remembered.saveSettings();
        }
        super.dispose();
    }

    // ---- Menus and keys ----

    /** The model, or its refinement with the path in its place (they lie on the same surface), or neither. */
    void showSurface() {
        view.setVisible(Scenes.MODEL, showModel.isSelected() && !refinement.isSelected());
        view.setVisible(Scenes.REFINEMENT, showModel.isSelected() && refinement.isSelected());
        view.setVisible(CollisionView.NAME, showCollisions.isSelected());
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
        Job job = !model ? new Job.Script(file, parameters.scriptMaxFaces.getText()) : parameters.card().equals("view") ? parameters.view(file) : parameters.wrap(file);
        Path folder = file.toAbsolutePath().getParent();
        if (folder != null) {
            settings.put("folder", folder.toString());
        }
        if (model) {
            // A model stays open when its wrap is refused (another width may do): it is recent at once.
            opening = null;
            settings.addRecent(file);
            menuBar.refreshRecent();
        } else {
            // A script or FOLD file is recent, and replaces what is shown, only once it plays.
            opening = file;
            beforeOpening = plan == null ? null : plan.job();
        }
        parameters.show(job);
    }

    void wrapModel() {
        if (parameters.job() instanceof Job.WrapModel) {
            return;
        }
        Job last = lastModel();
        if (last == null) {
            dialogs.chooseModel();
        } else {
            parameters.show(last);
        }
    }

    /** The view's card, on the open model (or the last one opened); without one, asks for it. */
    void viewModel() {
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
            dialogs.chooseModel();
        }
    }

    Job lastModel() {
        for (Path file : settings.recent()) {
            if (ModelFile.isModelName(file) && Files.isRegularFile(file)) {
                return parameters.wrap(file);
            }
        }
        return null;
    }

    void playScript() {
        for (Path file : settings.recent()) {
            if (!ModelFile.isModelName(file) && Files.isRegularFile(file)) {
                parameters.show(new Job.Script(file, parameters.scriptMaxFaces.getText()));
                return;
            }
        }
        dialogs.chooseScript();
    }

    /** The parameters changed: check them at once (marking the fields), and plan if they pass. */
    void planLater(Job job) {
        boolean modelOpen = parameters.model() != null;
        modelInformation.setEnabled(modelOpen);
        exportRefinement.setEnabled(modelOpen);
        remembered.rememberParameters(job);
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

    void plan(Job job) {
        workStarted("planning");
        planner.submit(progress -> Planning.plan(job, progress), new StatusLine<Plan>() {
            @Override
            void finished(Plan next) {
                if (isOpening(job)) {
                    settings.addRecent(opening);
                    menuBar.refreshRecent();
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
                if (job instanceof Job.WrapModel wrap && "model".equals(problem.field()) && !wrap.strict()) {
                    // Not a model iFold can read (strict, it may be one its repairs would mend):
                    // recent when it was opened, it is not one to open again.
                    settings.removeRecent(wrap.model());
                    menuBar.refreshRecent();
                }
                if (job instanceof Job.WrapModel wrap && !shows(wrap.model())) {
                    showModelAlone(wrap, problem.message());
                }
            }
        });
    }

    /** Whether the plan shown is of {@code model}: its wrap, or its view. */
    boolean shows(Path model) {
        Job shown = plan == null ? null : plan.job();
        return shown instanceof Job.WrapModel w && w.model().equals(model) || shown instanceof Job.View v && v.model().equals(model);
    }

    /**
     * A model whose wrap was refused is drawn anyway, as the view draws it, the wrap's card and
     * its marked field kept for another try: before, the view stayed empty or on the model before.
     */
    void showModelAlone(Job.WrapModel wrap, String refusal) {
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
    boolean isOpening(Job job) {
        return opening != null && job instanceof Job.Script s && opening.equals(s.file());
    }

    /** The section of docs/reports.md that explains a job's report. */
    static String reportSection(Job job) {
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
    void show(Plan next) {
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
    final class ExportHost implements ExportDialogs.Host {
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
            return dialogs.choose(title, save, filter);
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
     * Writes {@code file} in the background with progress and Cancel (null: the task writes no
     * file the user chose, as a check); {@code written} hears the summary, and a failure is said
     * after {@code failed} ("cannot export the movie").
     */
    void write(String doing, String failed, Path file, Worker.Task<String> task, Consumer<String> written) {
        workStarted(doing);
        exporting = file == null ? doing : null;
        exporter.submit(task, new StatusLine<String>() {
            @Override
            void finished(String summary) {
                Path folder = file == null ? null : file.toAbsolutePath().getParent();
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
    abstract class StatusLine<T> implements Worker.Listener<T> {
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

    // ---- The model: its information, its refinement, a new one ----

    /** The model of the wrap's card, or null after saying in the status line that none is open. */
    Path openModel() {
        Path model = parameters.model();
        if (model == null) {
            say("no model open: File, Open model or New model first");
        }
        return model;
    }

    // ---- Work in progress ----

    void workStarted(String what) {
        progress.setIndeterminate(true);
        progress.setVisible(true);
        progress.setString(what);
        cancel.setVisible(true);
        say(what + "...");
    }

    void done(int done, int total) {
        progress.setIndeterminate(false);
        progress.setMaximum(total);
        progress.setValue(done);
        progress.setStringPainted(true);
        progress.setString(done + " / " + total);
    }

    void workEnded() {
        if (!isWorking()) {
            progress.setVisible(false);
            progress.setStringPainted(false);
            cancel.setVisible(false);
        }
    }

    /** Cancel: the export if one runs (its file is not written), else the planning (the last plan stays). */
    void cancelWork() {
        if (exporter.cancel()) {
            say(exporting != null ? exporting + " cancelled" : "export cancelled: nothing written");
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

}
