package ifold.ui;

import ifold.job.PrintJob;
import ifold.print.CreasePatternPages;
import ifold.print.Lengths;
import ifold.print.Page;
import ifold.ui.model.Exports;
import ifold.ui.model.ModelFile;
import ifold.ui.model.Plan;
import ifold.ui.model.Problem;
import ifold.ui.model.Progress;
import ifold.ui.model.Renderer;
import ifold.ui.model.Worker;
import java.awt.Component;
import java.awt.GridLayout;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.function.Consumer;
import javax.swing.JCheckBox;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JSpinner;
import javax.swing.SpinnerNumberModel;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The File menu's exports: each asks what it needs (where to write, and for frames and movies
 * their size, rate, length and captions), then hands the writing to the window, which runs it in
 * the background with progress and Cancel. What is written is what the command line writes:
 * {@link Exports} does the work for both.
 */
final class ExportDialogs {

    /** What the exports need of the window. */
    interface Host {
        /** The plan shown, or null while the first one is being planned. */
        Plan plan();

        /** The model of the wrap's card, or null after saying that none is open. */
        Path openModel();

        /** Whether models are read strictly (the wrap card's Strict box). */
        boolean strict();

        /** Whether the view shows captions: the default for exported frames. */
        boolean captions();

        /** The timeline's speed: a movie's default length is the plan's at that speed. */
        double speed();

        /** A file or, without a filter, a folder the user picks; null if cancelled. */
        Path choose(String title, boolean save, FileNameExtensionFilter filter);

        /**
         * Writes {@code file} in the background (null: no file the user chose, as a check's);
         * {@code written} hears the summary, and a failure
         * is said after {@code failed} ("cannot export the movie").
         */
        void write(String doing, String failed, Path file, Worker.Task<String> task, Consumer<String> written);

        /** Puts {@code text} on the status line. */
        void say(String text);
    }

    private final Component parent;
    private final Host host;
    /** Where the next export's settings start: the last ones used. */
    private Exports.FrameSettings frameSettings = Exports.FrameSettings.DEFAULT;
    /** The last crease pattern's width on paper and page, where the next one starts. */
    private String printWidth = ifold.print.Lengths.AUTOMATIC;
    private Page printPage = Page.A4;

    ExportDialogs(Component parent, Host host) {
        this.parent = parent;
        this.host = host;
    }

    // ---- Asking ----

    /** Export OBJ, FOLD, report (json) or figure (png): asks where, adding the extension if it is missing. */
    void fileAsk(String what, String extension) {
        if (!hasPlan()) {
            return;
        }
        Path file = host.choose("Export " + what, true, new FileNameExtensionFilter(what + " (." + extension + ")", extension));
        if (file == null) {
            return;
        }
        if (!file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith("." + extension)) {
            file = file.resolveSibling(file.getFileName() + "." + extension);
        }
        switch (extension) {
            case "obj" -> obj(file);
            case "fold" -> fold(file);
            case "png" -> figure(file);
            default -> report(file);
        }
    }

    void movieAsk() {
        if (!hasPlan()) {
            return;
        }
        Exports.FrameSettings chosen = askFrameSettings("Export movie");
        if (chosen == null) {
            return;
        }
        Path file = host.choose("Export movie", true, new FileNameExtensionFilter("Movies (MP4, GIF)", "mp4", "gif"));
        if (file == null) {
            return;
        }
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (!name.endsWith(".mp4") && !name.endsWith(".gif")) {
            file = file.resolveSibling(file.getFileName() + ".mp4");
        }
        movie(file, chosen);
    }

    void framesAsk() {
        if (!hasPlan()) {
            return;
        }
        Exports.FrameSettings chosen = askFrameSettings("Export frames");
        if (chosen == null) {
            return;
        }
        Path folder = host.choose("Export frames into a folder", true, null);
        if (folder != null) {
            frames(folder, chosen);
        }
    }

    /**
     * Export crease pattern: asks the strip's width on paper and the page, then where (PDF or
     * SVG by the name; PDF where it says neither), as {@code --export-pdf} and {@code --export-svg}
     * print it.
     */
    void creasePatternAsk() {
        if (!hasPlan()) {
            return;
        }
        if (!host.plan().hasPaper()) {
            host.say("nothing to print: a model's view folds no paper");
            return;
        }
        javax.swing.JTextField width = new javax.swing.JTextField(printWidth, 8);
        javax.swing.JComboBox<String> page = new javax.swing.JComboBox<>();
        for (Page each : Page.values()) {
            page.addItem(each.optionName());
        }
        page.setSelectedItem(printPage.optionName());
        javax.swing.JPanel form = new javax.swing.JPanel(new java.awt.GridLayout(2, 2, 8, 8));
        form.add(new javax.swing.JLabel("Strip width on paper (auto, 2cm, 20mm, 0.8in)"));
        form.add(width);
        form.add(new javax.swing.JLabel("Page"));
        form.add(page);
        CreasePatternPages.Options options;
        while (true) {
            int answer = javax.swing.JOptionPane.showConfirmDialog(parent, form, "Export crease pattern", javax.swing.JOptionPane.OK_CANCEL_OPTION,
                    javax.swing.JOptionPane.PLAIN_MESSAGE);
            if (answer != javax.swing.JOptionPane.OK_OPTION) {
                return;
            }
            try {
                options = new CreasePatternPages.Options(Lengths.millimetres(width.getText()), Page.of((String) page.getSelectedItem()));
                break;
            } catch (IllegalArgumentException e) {
                javax.swing.JOptionPane.showMessageDialog(parent, "Strip width: " + e.getMessage(), "Export crease pattern",
                        javax.swing.JOptionPane.ERROR_MESSAGE);
            }
        }
        printWidth = width.getText();
        printPage = options.page();
        Path file = host.choose("Export crease pattern", true, new FileNameExtensionFilter("Crease pattern (PDF, SVG)", "pdf", "svg"));
        if (file == null) {
            return;
        }
        if (!PrintJob.prints(file)) {
            file = file.resolveSibling(file.getFileName() + ".pdf");
        }
        creasePattern(file, options);
    }

    /** Export step diagrams: asks where (a PDF), then draws them in the background, as {@code --export-diagrams} does. */
    void diagramsAsk() {
        if (!hasPlan()) {
            return;
        }
        if (!host.plan().hasPaper()) {
            host.say("nothing to draw: a model's view folds no paper");
            return;
        }
        Path file = host.choose("Export step diagrams", true, new FileNameExtensionFilter("Step diagrams (PDF)", "pdf"));
        if (file == null) {
            return;
        }
        if (!file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".pdf")) {
            file = file.resolveSibling(file.getFileName() + ".pdf");
        }
        diagrams(file);
    }

    /** Draws the plan's step diagrams to {@code file}, in the background. */
    void diagrams(Path file) {
        plan("step diagrams", file, (shown, progress) -> {
            return Exports.diagrams(shown, file, printPage, progress).stepsSummary();
        });
    }

    /** Prints the plan's crease pattern to {@code file}, in the background. */
    void creasePattern(Path file, CreasePatternPages.Options options) {
        plan("crease pattern", file, (shown, progress) -> Exports.creasePattern(shown, file, options, progress).summary());
    }

    /** Export refinement: the open model's, as {@code ifold refine} writes it; OFF unless the name says OBJ, PLY or STL (binary). */
    void refinementAsk() {
        if (host.openModel() == null) {
            return;
        }
        Path file = host.choose("Export refinement", true, new FileNameExtensionFilter("Meshes (OFF, OBJ, PLY, STL)", "off", "obj", "ply", "stl"));
        if (file == null) {
            return;
        }
        if (!ModelFile.isWritableModelName(file)) {
            file = file.resolveSibling(file.getFileName() + ".off");
        }
        refinement(file);
    }

    private boolean hasPlan() {
        if (host.plan() == null) {
            host.say("nothing to export yet: the fold is still being planned");
            return false;
        }
        return true;
    }

    /**
     * A spinner whose value follows its text as it is typed (each valid edit is committed), so
     * that OK takes the number typed even when the field was never left: by default a spinner
     * commits on losing the focus, and OK pressed at once read the old value (6 of 7 tries gave
     * the default 120 s).
     */
    static JSpinner committing(JSpinner spinner) {
        if (spinner.getEditor() instanceof JSpinner.DefaultEditor editor
                && editor.getTextField().getFormatter() instanceof javax.swing.text.DefaultFormatter formatter) {
            formatter.setCommitsOnValidEdit(true);
        }
        return spinner;
    }

    /**
     * What is wrong with the number typed in {@code spinner}, or null where it is what the
     * spinner holds: a number out of its range, or no number, is not committed to its value,
     * which silently kept the last one that was ("5000" seconds became 500, as typed up to
     * its fourth digit).
     */
    static String typedProblem(JSpinner spinner, String name) {
        if (!(spinner.getEditor() instanceof JSpinner.DefaultEditor editor) || !(spinner.getModel() instanceof SpinnerNumberModel model)) {
            return null;
        }
        javax.swing.JFormattedTextField field = editor.getTextField();
        String text = field.getText().strip();
        try {
            spinner.setValue(field.getFormatter().stringToValue(text)); // typed, committed or not (the field never left): it counts
            return null;
        } catch (java.text.ParseException | IllegalArgumentException e) {
            return name + ": '" + text + "' is not a number from " + plain(model.getMinimum()) + " to " + plain(model.getMaximum());
        }
    }

    /** A bound as people write it: 3600, not 3600.0. */
    private static String plain(Object bound) {
        return bound instanceof Number n && n.doubleValue() == Math.rint(n.doubleValue()) ? Long.toString(n.longValue()) : String.valueOf(bound);
    }

    /** Asks the size, frames a second, length and captions of frames or a movie; null if cancelled. */
    private Exports.FrameSettings askFrameSettings(String title) {
        String[] sizes = {"640x360", "960x540", "1280x720", "1920x1080"};
        JComboBox<String> size = new JComboBox<>(sizes);
        size.setEditable(true);
        size.setSelectedItem(frameSettings.width() + "x" + frameSettings.height());
        JSpinner fps = committing(new JSpinner(new SpinnerNumberModel(frameSettings.fps(), 1, 240, 1)));
        Plan plan = host.plan();
        double length = plan == null ? frameSettings.seconds() : Math.min(3600, plan.seconds() / host.speed());
        JSpinner seconds = committing(new JSpinner(new SpinnerNumberModel(length, 0.1, 3600, 1)));
        JCheckBox withCaptions = new JCheckBox("captions naming each fold", host.captions());
        JPanel form = new JPanel(new GridLayout(0, 2, 6, 6));
        form.add(new JLabel("Size (width x height)"));
        form.add(size);
        form.add(new JLabel("Frames a second"));
        form.add(fps);
        form.add(new JLabel("Seconds"));
        form.add(seconds);
        form.add(new JLabel(""));
        form.add(withCaptions);
        while (true) {
            if (JOptionPane.showConfirmDialog(parent, form, title, JOptionPane.OK_CANCEL_OPTION, JOptionPane.PLAIN_MESSAGE)
                    != JOptionPane.OK_OPTION) {
                return null;
            }
            // What is typed counts, whether or not the field was left first (Tab) or Enter pressed.
            Object typedSize = size.getEditor().getItem();
            if (typedSize != null && !String.valueOf(typedSize).isBlank()) {
                size.setSelectedItem(typedSize);
            }
            String[] wh = String.valueOf(size.getSelectedItem()).strip().split("x");
            String refused = typedProblem(fps, "frames a second");
            refused = refused != null ? refused : typedProblem(seconds, "seconds");
            if (refused != null) {
                JOptionPane.showMessageDialog(parent, refused, title, JOptionPane.WARNING_MESSAGE);
                continue;
            }
            try {
                Exports.FrameSettings chosen = new Exports.FrameSettings(Integer.parseInt(wh[0].strip()), Integer.parseInt(wh[1].strip()),
                        (Integer) fps.getValue(), ((Number) seconds.getValue()).doubleValue(), withCaptions.isSelected());
                List<Problem> problems = chosen.check(null);
                if (problems.isEmpty()) {
                    frameSettings = chosen;
                    return chosen;
                }
                JOptionPane.showMessageDialog(parent, problems.get(0).field() + ": " + problems.get(0).message(), title,
                        JOptionPane.WARNING_MESSAGE);
            } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
                JOptionPane.showMessageDialog(parent, "size: '" + size.getSelectedItem() + "' is not WIDTHxHEIGHT, e.g. 1280x720", title,
                        JOptionPane.WARNING_MESSAGE);
            }
        }
    }

    // ---- Writing, once asked (the tests start here) ----

    void obj(Path file) {
        file("OBJ", file, Exports::obj);
    }

    void fold(Path file) {
        file("FOLD", file, Exports::fold);
    }

    void figure(Path file) {
        file("figure", file, (shown, to, progress) -> Exports.figure(OpenGlRenderer.INSTANCE, shown, to, progress));
    }

    void report(Path file) {
        file("report", file, Exports::report);
    }

    /** One of the plan's files (OBJ, FOLD, figure, report), as {@link Exports} writes it. */
    private interface FileExport {
        void write(Plan shown, Path file, Progress progress) throws Exception;
    }

    private void file(String what, Path file, FileExport export) {
        plan(what, file, (shown, progress) -> {
            export.write(shown, file, progress);
            return "wrote " + file;
        });
    }

    void movie(Path file, Exports.FrameSettings chosen) {
        plan("movie", file, (shown, progress) -> {
            Renderer.Rendered result = Exports.movie(OpenGlRenderer.INSTANCE, shown, file, chosen, progress);
            return String.format(Locale.ROOT, "wrote %s: %d %s of %dx%d in %.1f s", file, result.frames(),
                    result.frames() == 1 ? "frame" : "frames", chosen.width(),
                    chosen.height(), result.seconds());
        });
    }

    void frames(Path folder, Exports.FrameSettings chosen) {
        plan("frames", folder, (shown, progress) -> {
            Renderer.Rendered result = Exports.frames(OpenGlRenderer.INSTANCE, shown, folder, chosen, progress);
            return String.format(Locale.ROOT, "wrote %d %s of %dx%d to %s in %.1f s", result.frames(),
                    result.frames() == 1 ? "frame" : "frames", chosen.width(),
                    chosen.height(), folder, result.seconds());
        });
    }

    /**
     * Fold, Check the wrap: the wrap shown checked as {@code ifold check} checks it, by the
     * independent checkers reading its OBJ and FOLD files (the truths, the collisions, the layer
     * order), in the background; the lines shown when it ends, the truths' on the status line.
     */
    void checkAsk() {
        Plan shown = host.plan();
        if (shown == null) {
            host.say("nothing to check yet: the fold is still being planned");
            return;
        }
        if (!(shown.job() instanceof ifold.ui.model.Job.WrapModel)) {
            host.say("only a wrap of a model is checked: Fold, Wrap the model first");
            return;
        }
        // The task's summary: the verdict and the truths on its first line, then the check's lines.
        host.write("checking the wrap", "cannot check the wrap", null, progress -> {
            Exports.Checked checked = Exports.check(shown, progress);
            return (checked.holds() ? "every check holds; " : "a check fails; ") + checked.lines().get(1) + "\n"
                    + String.join("\n", checked.lines());
        }, summary -> {
            int end = summary.indexOf('\n');
            host.say(summary.substring(0, end));
            javax.swing.JTextArea lines = new javax.swing.JTextArea(summary.substring(end + 1), 0, 80);
            lines.setEditable(false);
            lines.setLineWrap(true);
            lines.setWrapStyleWord(true);
            JOptionPane.showMessageDialog(parent, new javax.swing.JScrollPane(lines), "Check the wrap",
                    summary.startsWith("every") ? JOptionPane.INFORMATION_MESSAGE : JOptionPane.WARNING_MESSAGE);
        });
    }

    /** Writes the open model's Hamiltonian refinement to {@code file}, as {@code ifold refine MODEL -o FILE} does. */
    void refinement(Path file) {
        Path model = host.openModel();
        if (model == null) {
            return;
        }
        boolean strict = host.strict();
        host.write("exporting the refinement", "cannot export the refinement", file, progress -> {
            Exports.Refined refined = Exports.refinement(model, strict, file, progress);
            return String.format(Locale.ROOT, "wrote %s: %d %s in %d %s -> %d triangles, in path order", file,
                    refined.inputTriangles(), refined.inputTriangles() == 1 ? "triangle" : "triangles", refined.components(),
                    refined.components() == 1 ? "component" : "components", refined.outputTriangles());
        }, host::say);
    }

    /** An export of the plan shown now: later plans do not change what this one writes. */
    private interface PlanExport {
        String write(Plan shown, Progress progress) throws Exception;
    }

    private void plan(String what, Path file, PlanExport export) {
        Plan shown = host.plan();
        if (shown == null) {
            host.say("nothing to export yet");
            return;
        }
        host.write("exporting " + what, "cannot export the " + what, file, progress -> export.write(shown, progress), host::say);
    }
}
