package ifold.ui;

import ifold.ui.model.Exports;
import ifold.ui.model.Job;
import ifold.ui.model.ModelFile;
import ifold.ui.model.NewModel;
import ifold.ui.model.Problem;
import java.awt.BorderLayout;
import java.awt.Dimension;
import java.awt.FlowLayout;
import java.awt.event.KeyEvent;
import java.io.File;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import javax.swing.JButton;
import javax.swing.JComponent;
import javax.swing.JFileChooser;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.KeyStroke;
import javax.swing.filechooser.FileNameExtensionFilter;

/**
 * The window's dialogs: a file to open or save, a model's information, and a new model made
 * from a built-in solid.
 */
final class WindowDialogs {
    private final MainWindow window;

    WindowDialogs(MainWindow window) {
        this.window = window;
    }

    /** File, Model information: the model's counts and topology, measured off the event thread, in a window beside this one. */
    void showModelInformation() {
        Path model = window.openModel();
        if (model == null) {
            return;
        }
        boolean strict = window.parameters.wrapStrict.isSelected();
        window.workStarted("measuring " + model.getFileName());
        window.inspector.submit(progress -> ModelFile.information(model, strict, progress), window.new StatusLine<Map<String, Object>>() {
            @Override
            void finished(Map<String, Object> figures) {
                showInformation(model, figures);
                window.say(model.getFileName() + ": " + figures.get("faces") + " faces, genus " + figures.get("genus"));
            }

            @Override
            void refused(Problem problem) {
                window.say("no model information: " + problem.message());
            }
        });
    }

    void showInformation(Path model, Map<String, Object> figures) {
        if (window.informationDialog == null) {
            window.informationDialog = new javax.swing.JDialog(window, false);
            JScrollPane table = new JScrollPane(window.information);
            table.setPreferredSize(new Dimension(360, 420));
            window.informationDialog.add(table, BorderLayout.CENTER);
            JButton close = new JButton("Close");
            close.addActionListener(e -> window.informationDialog.setVisible(false));
            JPanel buttons = new JPanel(new FlowLayout(FlowLayout.RIGHT));
            buttons.add(close);
            window.informationDialog.add(buttons, BorderLayout.SOUTH);
            window.informationDialog.getRootPane().setDefaultButton(close);
            // Esc closes it, as it closes every dialog of the window.
            window.informationDialog.getRootPane().registerKeyboardAction(e -> window.informationDialog.setVisible(false),
                    KeyStroke.getKeyStroke(KeyEvent.VK_ESCAPE, 0), JComponent.WHEN_IN_FOCUSED_WINDOW);
            window.informationDialog.pack();
            window.informationDialog.setLocationRelativeTo(window);
        }
        window.information.show("info", figures);
        window.informationDialog.setTitle("Model information: " + model.getFileName());
        window.informationDialog.setVisible(true);
    }

    /** File, New model: asks the shape and its parameters (each refused at its field), where to save it, and opens it to wrap. */
    void newModelAsk() {
        NewModel chosen = askNewModel();
        if (chosen == null) {
            return;
        }
        JFileChooser chooser = new SaveChooser(window.settings.get("folder", System.getProperty("user.dir")), this::mayReplace);
        chooser.setDialogTitle("Save the new model");
        chooser.setFileFilter(new FileNameExtensionFilter("Meshes (OFF, OBJ, PLY, STL)", "off", "obj", "ply", "stl"));
        chooser.setSelectedFile(new File(chooser.getCurrentDirectory(), chosen.fileName()));
        File target = chooser.showSaveDialog(window) == JFileChooser.APPROVE_OPTION ? chooser.getSelectedFile() : null;
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
        window.write("making the " + model.shape(), "cannot make the " + model.shape(), file, progress -> {
            NewModel.Made made = model.write(file, progress);
            return "wrote " + made.file() + ": " + made.vertices() + " vertices, " + made.faces() + " faces";
        }, summary -> {
            window.open(file);
            window.say(summary);
        });
    }

    /** Asks for a shape and its parameters until they are good (each problem under its field) or the asking is cancelled. */
    NewModel askNewModel() {
        window.newModelForm.mark(List.of());
        while (true) {
            if (JOptionPane.showConfirmDialog(window, window.newModelForm, "New model", JOptionPane.OK_CANCEL_OPTION, JOptionPane.PLAIN_MESSAGE)
                    != JOptionPane.OK_OPTION) {
                return null;
            }
            NewModel chosen = window.newModelForm.model();
            List<Problem> problems = chosen.check();
            if (problems.isEmpty()) {
                return chosen;
            }
            window.newModelForm.mark(problems);
        }
    }

    void chooseModel() {
        Path file = choose("Open a model", false, new FileNameExtensionFilter("Models (OFF, OBJ, PLY, STL)", "off", "obj", "ply", "stl"));
        if (file != null) {
            window.open(file);
        }
    }

    void chooseScript() {
        Path file = choose("Open a fold script or FOLD file", false, new FileNameExtensionFilter("Fold scripts and FOLD files", "fold", "txt"));
        if (file != null) {
            window.open(file);
        }
    }

    Path choose(String title, boolean save, FileNameExtensionFilter filter) {
        String lastFolder = window.settings.get("folder", System.getProperty("user.dir"));
        JFileChooser chooser = save ? new SaveChooser(lastFolder, this::mayReplace) : new JFileChooser(lastFolder);
        chooser.setDialogTitle(title);
        if (filter != null) {
            chooser.setFileFilter(filter);
            if (save) {
                // The name of what is shown, with the filter's first extension: typing it each time is a chore.
                Job job = window.plan != null ? window.plan.job() : window.parameters.job();
                chooser.setSelectedFile(new File(chooser.getCurrentDirectory(), Exports.suggestedName(job, filter.getExtensions()[0])));
            }
        } else {
            chooser.setFileSelectionMode(JFileChooser.DIRECTORIES_ONLY);
        }
        int answer = save ? chooser.showSaveDialog(window) : chooser.showOpenDialog(window);
        File chosen = chooser.getSelectedFile();
        if (answer != JFileChooser.APPROVE_OPTION || chosen == null) {
            return null;
        }
        Path folder = chosen.toPath().toAbsolutePath().getParent();
        if (folder != null) {
            window.settings.put("folder", folder.toString());
        }
        return chosen.toPath();
    }

    /** Asks whether {@code file}, which is there, may be replaced. */
    private boolean mayReplace(Path file) {
        return JOptionPane.showConfirmDialog(window, file.getFileName() + " is there already, in " + file.toAbsolutePath().getParent()
                + ".\nReplace it?", "Replace the file?", JOptionPane.YES_NO_OPTION, JOptionPane.WARNING_MESSAGE) == JOptionPane.YES_OPTION;
    }

    /**
     * A save dialog that asks before it replaces a file that is there: exports open in the folder
     * a model was opened from, with its name, and File, Export OBJ on models/cube.off offered
     * models/cube.obj, another model, which it replaced without a word.
     */
    static final class SaveChooser extends JFileChooser {
        private static final long serialVersionUID = 1L;
        private final transient java.util.function.Predicate<Path> mayReplace;

        SaveChooser(String folder, java.util.function.Predicate<Path> mayReplace) {
            super(folder);
            this.mayReplace = mayReplace;
        }

        @Override
        public void approveSelection() {
            File file = getSelectedFile();
            if (file != null && getFileFilter() instanceof FileNameExtensionFilter filter && !file.exists()) {
                // A name typed without its extension is given the filter's first, as the exports do.
                String name = file.getName().toLowerCase(java.util.Locale.ROOT);
                boolean named = java.util.Arrays.stream(filter.getExtensions()).anyMatch(e -> name.endsWith("." + e));
                file = named ? file : new File(file.getPath() + "." + filter.getExtensions()[0]);
            }
            if (file != null && file.exists() && !file.isDirectory() && !mayReplace.test(file.toPath())) {
                return; // the dialog stays, for another name
            }
            super.approveSelection();
        }
    }
}
