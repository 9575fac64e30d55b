package ifold.cli;

import ifold.fold.FoldFile;
import ifold.geom.Triangle;
import ifold.mesh.PolygonSoup;
import ifold.render.FrameExport;
import ifold.render.RenderUnavailableException;
import ifold.scene.Animation;
import ifold.scene.Geometry;
import ifold.scene.Material;
import ifold.scene.Scene;
import ifold.scene.SceneMesh;
import ifold.scene.WrapView;
import ifold.sheet.FoldException;
import ifold.sheet.Sheet;
import ifold.wrap.ParameterException;
import ifold.wrap.TurnGadget;
import ifold.wrap.Wrap;
import ifold.wrap.WrapAnalysis;
import ifold.wrap.WrapGeometry;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.LinkedHashMap;
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
                + "In a window where there is a display; as frames in zigzag-frames/ where there is none. "
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

        @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: the width / 80)")
        Double thickness;

        @Option(names = "--figure", paramLabel = "FILE.png",
                description = "also write the seed's Figure 11 re-made: the first turn, all passes laid, the excess tucked under, the underside")
        Path figure;

        @Mixin
        PaperOutputs outputs = new PaperOutputs();

        @Override
        public Integer call() {
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
                        width == null ? Double.NaN : width, thickness == null ? Double.NaN : thickness);
            } catch (ParameterException e) {
                throw UserError.usage(e);
            }
            double w = options.width();
            double t = options.thickness();
            PrintWriter out = spec.commandLine().getOut();
            outputs.check("zigzag", spec.commandLine().getErr(), true);
            PolygonSoup path = new PolygonSoup();
            for (int i = 0; i < 3; i++) {
                path.addVertex(shape.corner(i).x(), shape.corner(i).y(), shape.corner(i).z());
            }
            path.addTriangle(0, 1, 2);
            Wrap.Result result;
            try {
                result = Wrap.wrap(path, new int[] {0, 1}, options);
            } catch (Wrap.WrapException e) {
                outputs.frameOptions.removeFolderIfUnused();
                throw new UserError("cannot wrap this triangle: " + e.getMessage());
            }
            List<WrapGeometry> geometries = List.of(WrapGeometry.of(result.strips().get(0).sheet(), result.frames()));
            WrapAnalysis analysis = WrapAnalysis.of(result, geometries);
            Sheet sheet = result.strips().get(0).sheet();
            int turns = result.count(Wrap.Kind.ZIGZAG_TURN);
            int overlaps = result.count(Wrap.Kind.OVERLAP);
            int tucks = result.count(Wrap.Kind.TUCK);
            // Two turn folds between passes, and the overlap is a pass of its own.
            int passes = turns / 2 + 1 + overlaps;
            Map<String, Object> figures = new LinkedHashMap<>();
            figures.put("triangle", triangle);
            figures.put("start", Triangle.name(startCorner));
            figures.put("end", Triangle.name(endCorner));
            figures.put("stripLength", sheet.length());
            figures.put("stripWidth", sheet.width());
            figures.put("aspectRatio", sheet.length() / sheet.width());
            figures.put("folds", turns + overlaps + tucks);
            figures.put("zigzagFolds", turns + overlaps);
            figures.put("tucks", tucks);
            figures.put("passes", passes);
            figures.put("lastPassOverlapped", overlaps > 0);
            figures.put("maxLayers", analysis.maxLayers());
            figures.put("stackLayers", analysis.stackLevels());
            figures.put("paperEfficiency", analysis.surfaceArea() / analysis.paperArea());
            figures.put("coverage", analysis.coverage());
            figures.put("paperOutsideArea", WrapAnalysis.outsideArea(result));
            figures.put("paperOutside", analysis.outsidePaper());
            figures.put("farthestFromTriangle", analysis.farthest());
            figures.put("isometryError", analysis.isometryError());
            figures.put("triangleArea", analysis.surfaceArea());
            figures.put("thickness", t);
            outputs.exportFold(List.of(new FoldFile.Folded(sheet, result.frames())), "demo zigzag --triangle " + triangle, figures, out);
            outputs.write(result, geometries, "demo zigzag --triangle " + triangle, figures, out);
            out.printf(Locale.ROOT, "zigzag: strip %.4g x %.4g (L/w %.1f), %d passes%s, %d turn folds, %d tucks, %d layers at most (a stack of %d), "
                    + "paper efficiency %.3f, coverage %.3f, paper outside %.2g, isometry error %.1e%n",
                    sheet.length(), sheet.width(), sheet.length() / sheet.width(), passes, overlaps > 0 ? " (last overlapped)" : "",
                    turns + overlaps, tucks, analysis.maxLayers(), analysis.stackLevels(), analysis.surfaceArea() / analysis.paperArea(),
                    analysis.coverage(), WrapAnalysis.outsideArea(result), analysis.isometryError());
            out.flush();

            Scene scene = new Scene();
            scene.root().attach(solid(shape));
            scene.root().attach(outline(shape));
            WrapView.Playback animation = playback(scene, result, geometries);
            if (figure != null) {
                int laid = turns + overlaps;
                double[] stages = {animation.positionAfter(Math.min(2, laid)), animation.positionAfter(laid),
                    animation.positionAfter(result.steps().size()), animation.halfTurn()};
                try {
                    FrameExport.panel(scene, animation, stages, 2, 800, 500, 4, figure);
                    outputs.wrote(figure);
                    out.println("wrote " + figure);
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

        @Option(names = "--thickness", paramLabel = "T", description = "the paper's thickness (default: the width / 50)")
        Double thickness;

        @Mixin
        PaperOutputs outputs = new PaperOutputs();

        @Override
        public Integer call() {
            TurnGadget.Options options;
            try {
                options = new TurnGadget.Options(angle, overhang, width, thickness == null ? Double.NaN : thickness);
            } catch (ParameterException e) {
                throw UserError.usage(e);
            }
            double t = options.thickness();
            PrintWriter out = spec.commandLine().getOut();
            outputs.check("turn", spec.commandLine().getErr(), true);
            TurnGadget.Result gadget;
            try {
                gadget = TurnGadget.turn(options);
            } catch (FoldException e) {
                outputs.frameOptions.removeFolderIfUnused();
                throw new UserError("cannot make this turn: " + e.getMessage());
            }
            Wrap.Result result = gadget.wrap();
            List<WrapGeometry> geometries = List.of(WrapGeometry.of(gadget.sheet(), result.frames()));
            WrapAnalysis analysis = WrapAnalysis.of(result, geometries);
            Map<String, Object> figures = new LinkedHashMap<>();
            figures.put("angle", angle);
            figures.put("measuredAngle", gadget.measuredAngle());
            figures.put("overhang", overhang * width);
            figures.put("topSideUp", gadget.endFacesUp());
            figures.put("stripLength", gadget.length());
            figures.put("stripWidth", width);
            figures.put("thickness", t);
            figures.put("folds", result.count(Wrap.Kind.TURN_GADGET));
            figures.put("maxLayers", analysis.maxLayers());
            figures.put("stackLayers", analysis.stackLevels());
            figures.put("isometryError", analysis.isometryError());
            outputs.exportFold(List.of(new FoldFile.Folded(gadget.sheet(), result.frames())),
                    String.format(Locale.ROOT, "demo turn --angle %s", angle), figures, out);
            outputs.write(result, geometries, String.format(Locale.ROOT, "demo turn --angle %s", angle), figures, out);
            out.printf(Locale.ROOT, "turn: %.6g degrees asked, %.6g measured, top side %s, %d layers at most, strip %.4g x %.4g%n",
                    angle, gadget.measuredAngle(), gadget.endFacesUp() ? "up" : "down", analysis.maxLayers(), gadget.length(), width);
            out.flush();

            Scene scene = new Scene();
            Animation animation = playback(scene, result, geometries);
            outputs.show(scene, animation, String.format(Locale.ROOT, "turn gadget: %.4g degrees", angle), 6, true, spec, 0);
            return 0;
        }
    }

    /** The strip laid fold by fold over what the scene holds (the triangle's outline, or nothing), then turned round. */
    private static WrapView.Playback playback(Scene scene, Wrap.Result result, List<WrapGeometry> geometries) {
        // White paper on a white background would not be seen where it leaves the triangle.
        scene.setBackground(BACKGROUND);
        return WrapView.play(scene, result, geometries);
    }

    /** A soft grey-blue: the white paper stands out on it, and the triangle's colour is darker still. */
    private static final int BACKGROUND = 0xFFD3DAE2;

    /**
     * Parses {@code x1,y1,x2,y2,x3,y3} (a triangle in the plane z = 0) or
     * {@code x1,y1,z1,x2,y2,z2,x3,y3,z3} (one in space); a bad value or a triangle with no area
     * is the option's error.
     */
    static Triangle parseTriangle(String text) {
        String[] parts = text.split(",", -1);
        if (parts.length != 6 && parts.length != 9) {
            throw UserError.usage("option --triangle: expected six numbers x1,y1,x2,y2,x3,y3 or nine x1,y1,z1,...,z3, got '" + text + "'");
        }
        double[] values = new double[parts.length];
        for (int i = 0; i < parts.length; i++) {
            try {
                values[i] = Double.parseDouble(parts[i].strip());
            } catch (NumberFormatException e) {
                throw UserError.usage("option --triangle: '" + parts[i].strip() + "' is not a number");
            }
            if (!Double.isFinite(values[i])) {
                throw UserError.usage("option --triangle: '" + parts[i].strip() + "' is not a finite number");
            }
        }
        Triangle triangle;
        try {
            triangle = values.length == 6 ? Triangle.planar(values[0], values[1], values[2], values[3], values[4], values[5])
                    : new Triangle(new org.joml.Vector3d(values[0], values[1], values[2]), new org.joml.Vector3d(values[3], values[4], values[5]),
                            new org.joml.Vector3d(values[6], values[7], values[8]));
        } catch (IllegalArgumentException e) {
            throw UserError.usage("option --triangle: " + e.getMessage());
        }
        double size = Math.max(triangle.opposite(0), Math.max(triangle.opposite(1), triangle.opposite(2)));
        double far = 0;
        for (double value : values) {
            far = Math.max(far, Math.abs(value));
        }
        if (far > 1e6 * size) {
            // Thickness offsets of a millionth of the size would drown in the coordinates' rounding.
            throw UserError.usage("option --triangle: the triangle is too small for its distance from the origin: move it nearer");
        }
        if (far > 1e150 || size < 1e-150) {
            // Lengths squared (areas, the stacks' overlaps) would overflow or underflow a double.
            throw UserError.usage(String.format(Locale.ROOT, "option --triangle: iFold wraps triangles of sizes from 1e-150 to 1e150,"
                    + " got %s up to %.3g", far > 1e150 ? "coordinates" : "sides", far > 1e150 ? far : size));
        }
        return triangle;
    }

    private static int corner(String name, String option) {
        return switch (name.strip().toUpperCase(Locale.ROOT)) {
            case "A" -> 0;
            case "B" -> 1;
            case "C" -> 2;
            default -> throw UserError.usage("option " + option + ": expected A, B or C, got '" + name + "'");
        };
    }

    /**
     * The triangle itself, in the wrap's quiet model colour, seen from its front only: from
     * behind, the paper tucked under it shows through.
     */
    private static Geometry solid(Triangle triangle) {
        double[] positions = new double[9];
        for (int i = 0; i < 3; i++) {
            positions[3 * i] = triangle.corner(i).x();
            positions[3 * i + 1] = triangle.corner(i).y();
            positions[3 * i + 2] = triangle.corner(i).z();
        }
        SceneMesh mesh = new SceneMesh(positions, new int[] {0, 1, 2}, new int[] {WrapView.MODEL}, new int[0], new int[0]);
        Geometry solid = new Geometry("triangle face", mesh, new Material(WrapView.MODEL, WrapView.MODEL, false, false));
        solid.setClosed(true);
        return solid;
    }

    /** The triangle's edges, drawn in green: the paper must cover them and end inside them. */
    private static Geometry outline(Triangle triangle) {
        double[] positions = new double[9];
        for (int i = 0; i < 3; i++) {
            positions[3 * i] = triangle.corner(i).x();
            positions[3 * i + 1] = triangle.corner(i).y();
            positions[3 * i + 2] = triangle.corner(i).z();
        }
        int green = 0xFF1E8C3A;
        SceneMesh mesh = new SceneMesh(positions, new int[0], new int[0], new int[] {0, 1, 1, 2, 2, 0}, new int[] {green, green, green});
        return new Geometry("triangle", mesh, new Material(green, green, false, true));
    }
}
