package ifold.cli;

import ifold.ui.App;
import ifold.ui.model.Settings;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code ifold app [FILE]}, and {@code ifold} alone where there is a display: the desktop window. */
@Command(name = "app", mixinStandardHelpOptions = true,
        description = {"Opens the desktop window: menus, the parameters of the zig-zag, the turn and the wrap, a timeline "
            + "to play and scrub through the folds, the report, and every export of the command line. It opens on FILE "
            + "(a model to wrap, a fold script or a FOLD file to play), or on the zig-zag demo as it was left. "
            + "'ifold' with no arguments does the same where there is a display."})
final class AppCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE", description = "an .off, .obj, .ply or .stl model, a fold script or a .fold file")
    Path file;

    @Option(names = "--settings", paramLabel = "FILE", hidden = true,
            description = "keep the window's settings in FILE instead of ~/.config/ifold/settings.properties (for tests)")
    Path settings;

    @Override
    public Integer call() throws InterruptedException {
        // As every command refuses a file it cannot read: one line, exit 1.
        if (file != null && !Files.exists(file)) {
            throw new UserError(file + ": no such file");
        }
        if (file != null) {
            LoadedModel.requireRegularFile(file);
        }
        open(file, settings, spec.commandLine().getErr());
        return 0;
    }

    /**
     * Opens the window and waits for it to close; without a display, says so in one line. What
     * is wrong with the settings file is said on {@code err}, once.
     */
    static void open(Path file, Path settings, PrintWriter err) throws InterruptedException {
        if (!PaperOutputs.hasDisplay() || !App.canOpen()) {
            throw new UserError("no display: the window needs one (the command line works without: try 'ifold --help')");
        }
        Settings remembered = new Settings(settings != null ? settings : Settings.defaultFile());
        remembered.problem().ifPresent(problem -> {
            err.println("ifold: " + problem);
            err.flush();
        });
        App.run(file, remembered);
    }
}
