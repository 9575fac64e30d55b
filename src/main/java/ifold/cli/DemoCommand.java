package ifold.cli;

import ifold.foldfile.FoldFile;
import ifold.geom.ParameterException;
import ifold.geom.Triangle;
import ifold.job.PrintJob;
import ifold.job.Reports;
import ifold.job.Scenes;
import ifold.job.TriangleText;
import ifold.job.TurnJob;
import ifold.job.ZigZagJob;
import ifold.render.FrameExport;
import ifold.render.RenderUnavailableException;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.scene.WrapPlayback;
import ifold.sheet.FoldException;
import ifold.sheet.Sheet;
import ifold.wrap.PaperInSpace;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold demo}: the zig-zag method on one triangle, and the turn gadget. */
@Command(name = "demo", mixinStandardHelpOptions = true,
        description = "Demonstrations of the zig-zag method: 'ifold demo zigzag' wraps a triangle, 'ifold demo turn' turns a strip.",
        subcommands = {DemoCommand.ZigZagDemo.class, DemoCommand.TurnDemo.class})
final class DemoCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        throw new CommandLine.ParameterException(spec.commandLine(), "missing demo: zigzag or turn");
    }

    @Command(name = "zigzag", mixinStandardHelpOptions = true,
            description = {"Wraps a triangle in a strip of paper the zig-zag way (Figure 11 of the seed): the passes and their "
                + "turns, then the tucks that hide the excess, then the camera turns to show the underside and its layers. "
                + "In a window where there is a display; as one movie, zigzag.mp4, where there is none (--frames DIR for PNGs). "
                + "The animation takes two seconds a step unless --seconds says otherwise."})
    static final class ZigZagDemo implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Option(names = "--triangle", paramLabel = "x1,y1,x2,y2,x3,y3", defaultValue = "0,0,10,0,3.5,8",
                description = "the triangle's corners A, B and C in the plane z = 0, or nine numbers for a triangle in space "
                    + "(default ${DEFAULT-VALUE}: acute and scalene)")
        String triangle;

        @Option(names = "--start", paramLabel = "A|B|C", defaultValue = "C",
                description = "the corner the strip starts at; its passes run parallel to the opposite edge (default ${DEFAULT-VALUE})")
        String start;

        @Option(names = "--end", paramLabel = "A|B|C",
                description = "the corner the strip ends at (default: the corner after the start: A after C, B after A, C after B)")
        String end;

        @Option(names = "--enter-from", paramLabel = "A|B|C",
                description = "the corner beside which the strip comes in; if the last pass then runs the wrong way it is laid back over itself (default: whichever side needs no overlap)")
        String enterFrom;

        @Option(names = "--width", paramLabel = "W", description = "the strip's width (default: a fifth of the altitude from the start corner)")
        Double width;

        @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: the width / " + Wrap.WIDTHS_A_THICKNESS + ")")
        Double thickness;

        @Option(names = "--figure", paramLabel = "FILE.png",
                description = "also write the seed's Figure 11 re-made: the first turn, all passes laid, the excess tucked under, the underside")
        Path figure;

        @Mixin
        PaperOutputs outputs = new PaperOutputs();

        @Mixin
        DiagramOutput diagrams = new DiagramOutput();

        @Override
        public Integer call() {
            diagrams.check(outputs);
            if (figure != null) {
                OutputFiles.checkWritableFile(figure, "--figure", ".png");
            }
            Triangle shape = parseTriangle(triangle);
            int startCorner = corner(start, "--start");
            int endCorner = end == null ? (startCorner + 1) % 3 : corner(end, "--end");
            int enterCorner = enterFrom == null ? -1 : corner(enterFrom, "--enter-from");
            Wrap.Options options;
            try {
                options = Wrap.Options.loneTriangle(shape, new Wrap.Ends(startCorner, endCorner, enterCorner),
                        Defaults.orDefault(width, "width"), Defaults.orDefault(thickness, "thickness"));
            } catch (ParameterException e) {
                throw UserError.usage(e);
            }
            double w = options.width();
            double t = options.thickness();
            PrintWriter out = spec.commandLine().getOut();
            outputs.check("zigzag", spec.commandLine().getErr(), true);
            ZigZagJob.Outcome zigzag;
            try {
                zigzag = ZigZagJob.run(new ZigZagJob.Request(triangle, shape, options), Wrap.Watcher.NONE);
            } catch (ParameterException e) {
                throw UserError.usage(e); // a thickness too thin for the triangle's size
            } catch (Wrap.WrapException e) {
                throw new UserError("cannot wrap this triangle: " + e.getMessage());
            }
            Wrap.Result result = zigzag.result();
            List<PaperInSpace> geometries = zigzag.geometries();
            WrapAnalysis analysis = zigzag.analysis();
            Sheet sheet = zigzag.sheet();
            int turns = result.count(Wrap.Kind.ZIGZAG_TURN);
            int overlaps = result.count(Wrap.Kind.OVERLAP);
            int tucks = result.count(Wrap.Kind.TUCK);
            int passes = Reports.passes(result);
            Map<String, Object> figures = zigzag.figures();
            List<FoldFile.Folded> folded = List.of(new FoldFile.Folded(sheet, result.frames()));
            outputs.exportFold(folded, zigzag.source(), figures);
            outputs.exportPrint(folded, "a triangle zig-zagged", PrintJob.ZIGZAG, PrintJob.triangle(shape, result.frames()[0], result.strips().get(0).sheet()));
            diagrams.write(outputs, "a triangle zig-zagged", PrintJob.ZIGZAG, in -> Scenes.zigzag(in, shape, result, geometries));
            outputs.write(result, geometries, zigzag.source(), figures);
            out.printf(Locale.ROOT, "zigzag: strip %.4g x %.4g (L/w %.1f), %d passes%s, %d turn folds, %d tucks, %d layers at most (a stack of %d), "
                    + "paper efficiency %.3f, coverage %.3f, paper outside %.2g, isometry error %.1e%n",
                    sheet.length(), sheet.width(), sheet.length() / sheet.width(), passes, overlaps > 0 ? " (last overlapped)" : "",
                    turns + overlaps, tucks, analysis.maxLayers(), analysis.stackLevels(), analysis.surfaceArea() / analysis.paperArea(),
                    analysis.coverage(), WrapAnalysis.outsideArea(result), analysis.isometryError());
            outputs.printChecksAndFiles(out);
            out.flush();

            Scene scene = new Scene();
            WrapPlayback animation = Scenes.zigzag(scene, shape, result, geometries);
            if (figure != null) {
                double[] stages = Scenes.figure11Stages(animation, result);
                try {
                    FrameExport.panel(scene, animation, stages, Scenes.FIGURE11_LABELS, 2, 800, 500, 4, figure);
                    outputs.wrote(figure);
                    outputs.printFiles(out);
                } catch (RenderUnavailableException e) {
                    outputs.discardWritten();
                    throw new UserError(e.getMessage());
                } catch (IOException e) {
                    outputs.discardWritten();
                    throw new UserError("option --figure: cannot write " + figure + ": " + e.getMessage());
                }
                animation.apply(0);
            }
            // About two seconds a fold, and four for the turn at the end: under a minute for the
            // default triangle, and two minutes at most.
            outputs.show(scene, animation, "zig-zag: " + result.steps().size() + " folds",
                    Math.min(120, 2.0 * (result.steps().size() + 2)), true, spec, 0);
            return 0;
        }
    }

    @Command(name = "turn", mixinStandardHelpOptions = true,
            description = {"Turns a strip by an angle with the turn gadget (Figures 1 and 2 of the seed): a fold across the strip, "
                + "then the turn fold; the strip goes on top side up. --overhang 0 is the basic gadget. "
                + "The animation takes six seconds unless --seconds says otherwise."})
    static final class TurnDemo implements Callable<Integer> {
        @Spec
        CommandSpec spec;

        @Option(names = "--angle", paramLabel = "DEG", required = true, description = "the turn, from 0.01 to 179.9 degrees")
        double angle;

        @Option(names = "--overhang", paramLabel = "X", defaultValue = "0",
                description = "how far beyond the fold across the turn fold begins, in strip widths (default ${DEFAULT-VALUE}: the basic gadget)")
        double overhang;

        @Option(names = "--width", paramLabel = "W", defaultValue = "1", description = "the strip's width (default ${DEFAULT-VALUE})")
        double width;

        @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: the width / " + TurnGadget.Options.WIDTHS_A_THICKNESS + ")")
        Double thickness;

        @Mixin
        PaperOutputs outputs = new PaperOutputs();

        @Mixin
        DiagramOutput diagrams = new DiagramOutput();

        @Override
        public Integer call() {
            diagrams.check(outputs);
            TurnGadget.Options options;
            try {
                options = new TurnGadget.Options(angle, overhang, width, Defaults.orDefault(thickness, "thickness"));
            } catch (ParameterException e) {
                throw UserError.usage(e);
            }
            double t = options.thickness();
            PrintWriter out = spec.commandLine().getOut();
            outputs.check("turn", spec.commandLine().getErr(), true);
            TurnJob.Outcome turn;
            try {
                turn = TurnJob.run(options);
            } catch (FoldException e) {
                throw new UserError("cannot make this turn: " + e.getMessage());
            }
            TurnGadget.Result gadget = turn.gadget();
            Wrap.Result result = turn.result();
            List<PaperInSpace> geometries = turn.geometries();
            WrapAnalysis analysis = turn.analysis();
            Map<String, Object> figures = turn.figures();
            List<FoldFile.Folded> folded = List.of(new FoldFile.Folded(gadget.sheet(), result.frames()));
            outputs.exportFold(folded, turn.source(), figures);
            outputs.exportPrint(folded, String.format(Locale.ROOT, "a turn of %.4g degrees", angle), PrintJob.TURN);
            diagrams.write(outputs, String.format(Locale.ROOT, "a turn of %.4g degrees", angle), PrintJob.TURN,
                    in -> Scenes.turn(in, result, geometries));
            outputs.write(result, geometries, turn.source(), figures);
            out.printf(Locale.ROOT, "turn: %.6g degrees asked, %.6g measured, top side %s, %d layers at most, strip %.4g x %.4g%n",
                    angle, gadget.measuredAngle(), gadget.endFacesUp() ? "up" : "down", analysis.maxLayers(), gadget.length(), width);
            outputs.printChecksAndFiles(out);
            out.flush();

            Scene scene = new Scene();
            Animation animation = Scenes.turn(scene, result, geometries);
            outputs.show(scene, animation, String.format(Locale.ROOT, "turn gadget: %.4g degrees", angle), 6, true, spec, 0);
            return 0;
        }
    }

    /**
     * Parses {@code x1,y1,x2,y2,x3,y3} (a triangle in the plane z = 0) or
     * {@code x1,y1,z1,x2,y2,z2,x3,y3,z3} (one in space); a bad value or a triangle with no area
     * is the option's error.
     */
    static Triangle parseTriangle(String text) {
        try {
            return TriangleText.parse(text);
        } catch (ParameterException e) {
            throw UserError.usage(e);
        }
    }

    private static int corner(String name, String option) {
        return switch (name.strip().toUpperCase(Locale.ROOT)) {
            case "A" -> 0;
            case "B" -> 1;
            case "C" -> 2;
            default -> throw UserError.usage("option " + option + ": expected A, B or C, got '" + name + "'");
        };
    }
}
