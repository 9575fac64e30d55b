package ifold.cli;

import ifold.io.AtomicFile;
import ifold.job.CheckJob;
import ifold.job.JobWatcher;
import ifold.job.Json;
import ifold.job.ModelFiles;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code ifold check MODEL PAPER.obj}: an exported wrap checked against its model by the independent checkers alone. */
@Command(name = "check", mixinStandardHelpOptions = true,
        description = {"Checks a wrap that 'ifold wrap --export-obj' wrote against its model, reading the files alone"
                + " (nothing of the wrap is asked): the five truths of a wrap (each strip's paper tiles it once; no face is"
                + " stretched, but where thick paper stands back from a concave edge; no face is torn from its neighbours;"
                + " the model is covered; every face lies on it, at most as high as the stack), the collisions (paper"
                + " crossing itself or the model, layers in one plane), and with --fold the layer order of the FOLD file"
                + " --export-fold wrote. Unlike the wrap's report, a check is never skipped for the paper's size: half a"
                + " million faces take minutes. Prints a line a check; exits 0 where every one holds, 1 where one does not.",
                "The thickness and the stack's height are read from the OBJ's first line, the model moved as the wrap moved it."})
final class CheckCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL", description = "the model that was wrapped: an OFF, OBJ, PLY or STL file")
    Path model;

    @Parameters(index = "1", paramLabel = "PAPER.obj", description = "the paper, as 'ifold wrap --export-obj' wrote it")
    Path paper;

    @Option(names = "--fold", paramLabel = "FILE.fold", description = "the same wrap as 'ifold wrap --export-fold' wrote it: its layer order is checked too")
    Path fold;

    @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: as the OBJ's first line says)")
    Double thickness;

    @Option(names = "--stack", paramLabel = "N", description = "the levels of the deepest stack: paper may lie N + 1 thicknesses above the surface"
            + " (default: as the OBJ's first line says)")
    Integer stack;

    @Option(names = "--samples", paramLabel = "N", description = "random points of the model that must lie under paper (default: 2000)")
    int samples = CheckJob.DEFAULT_SAMPLES;

    @Option(names = "--report", paramLabel = "FILE", description = "write the figures of the checks as JSON")
    Path report;

    @Option(names = "--strict", description = "refuse a defective model instead of repairing it")
    boolean strict;

    @Override
    public Integer call() {
        PrintWriter err = spec.commandLine().getErr();
        if (thickness != null && !(thickness >= 0 && Double.isFinite(thickness))) {
            throw UserError.usage("option --thickness: " + thickness + " is not a thickness (0 or more)");
        }
        if (stack != null && stack < 0) {
            throw UserError.usage("option --stack: " + stack + " is not a number of levels (0 or more)");
        }
        if (samples < 0 || samples > CheckJob.MOST_SAMPLES) {
            throw UserError.usage(String.format(java.util.Locale.ROOT, "option --samples: %d is not a number of points (0 to %,d)", samples,
                    CheckJob.MOST_SAMPLES));
        }
        for (Path file : fold == null ? List.of(paper) : List.of(paper, fold)) {
            String notAFile = ModelFiles.notAFile(file); // a missing one: reading it says so
            if (notAFile != null) {
                throw new UserError(notAFile);
            }
        }
        if (report != null) {
            OutputFiles.checkWritableFile(report, "--report", ".json");
        }
        CheckJob.Checked checked;
        ProgressBar.WrapBar bar = ProgressBar.wrapping(err);
        JobWatcher notes = LoadedModel.printingNotes(err);
        JobWatcher watcher = new JobWatcher() {
            @Override
            public void stage(String what) {
                bar.stage(what); // on a terminal, once the check has taken two seconds: a scan's take minutes
            }

            @Override
            public void note(String line) {
                bar.wipe();
                notes.note(line);
            }
        };
        try {
            checked = CheckJob.run(new CheckJob.Request(model, paper, fold, thickness == null ? Double.NaN : thickness,
                    stack == null ? -1 : stack, samples, strict), watcher);
        } catch (ModelFiles.LoadFailure e) {
            throw LoadedModel.refusal(e);
        } catch (CheckJob.TooThick e) {
            // Too thick as the options say: what the user typed; as the OBJ's header says: its data.
            throw thickness != null || stack != null ? UserError.usage("option " + (thickness != null ? "--thickness" : "--stack") + ": "
                    + e.getMessage()) : new UserError(paper + ": " + e.getMessage());
        } catch (CheckJob.Unreadable e) {
            throw new UserError(e.getMessage());
        } finally {
            bar.wipe();
        }
        PrintWriter out = spec.commandLine().getOut();
        for (String line : CheckJob.lines(checked, model + ", " + paper)) {
            out.println(line);
        }
        out.flush();
        if (report != null) {
            String json = Json.write(checked.figures());
            try {
                AtomicFile.write(report, stream -> stream.write(json.getBytes(StandardCharsets.UTF_8)), true);
            } catch (java.io.IOException e) {
                throw new UserError(report + ": cannot write: " + e.getMessage());
            }
        }
        return checked.holds() ? 0 : UserError.EXIT_CODE;
    }
}
