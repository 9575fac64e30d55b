package ifold.cli;

import ifold.job.ModelFiles;
import ifold.job.Scenes;
import ifold.job.ViewJob;
import ifold.render.RenderUnavailableException;
import ifold.render.ViewerWindow;
import ifold.scene.Animation;
import ifold.scene.PathView;
import ifold.scene.Player;
import ifold.scene.Scene;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code ifold view MODEL [--refine] [--path]}: the viewer, in a window or as frames. */
@Command(name = "view", mixinStandardHelpOptions = true,
        description = {"Shows a model in a window with a virtual trackball, or renders it into frames with --frames (one movie, view.mp4,"
            + " where there is no display).",
            "With --path, the Hamiltonian path appears triangle by triangle (spanning-tree edges in green).",
            "The animation takes ten seconds unless --seconds says otherwise."})
final class ViewCommand implements Callable<Integer> {

    @Spec
    CommandSpec spec;

    @Parameters(index = "0", paramLabel = "MODEL", description = "an .off, .obj, .ply or .stl model")
    Path model;

    @Option(names = "--refine", description = "show the Hamiltonian refinement of the model")
    boolean refine;

    @Option(names = "--path", description = "animate the Hamiltonian path (implies --refine)")
    boolean path;

    @Option(names = "--colors", paramLabel = "darkness|rainbow", defaultValue = "darkness",
            description = "how --path colours the triangles along the path: lighter to darker, as the seed's Figure 10 (default), or rainbow")
    String colorsName;

    private PathView.Colors colors;

    @Option(names = "--strict", description = "refuse defective input instead of repairing it")
    boolean strict;

    @Option(names = "--close-after", paramLabel = "S", hidden = true,
            description = "close the window after S seconds and print its frames per second (for benchmarks)")
    double closeAfter;

    @Mixin
    FrameOptions frameOptions = new FrameOptions();

    @Override
    public Integer call() {
        colors = switch (colorsName.strip().toLowerCase(Locale.ROOT)) {
            case "darkness" -> PathView.Colors.DARKNESS;
            case "rainbow" -> PathView.Colors.RAINBOW;
            default -> throw UserError.usage("option --colors: expected darkness or rainbow, got '" + colorsName + "'");
        };
        PrintWriter err = spec.commandLine().getErr();
        // Without a display it renders one movie where the window was wanted, as every command does.
        if (!frameOptions.renders() && closeAfter == 0 && !PaperOutputs.hasDisplay()) {
            frameOptions.movie = PaperOutputs.movieWithoutDisplay("view", err);
        }
        frameOptions.check();
        PrintWriter out = spec.commandLine().getOut();
        Scenes.Show show = path ? Scenes.Show.PATH : refine ? Scenes.Show.REFINEMENT : Scenes.Show.MODEL;
        ViewJob.Outcome shown;
        try {
            shown = ViewJob.run(new ViewJob.Request(model, strict, show, colors), LoadedModel.printingNotes(err));
        } catch (ModelFiles.LoadFailure e) {
            throw LoadedModel.refusal(e);
        }
        Scene scene = shown.scene();
        Scenes.View view = shown.view();
        Animation animation = view.animation();
        String caption = view.caption();
        int samples = view.samples();
        if (!frameOptions.renders()) {
            Player player = new Player(animation, frameOptions.seconds);
            if (path) {
                player.togglePlaying(); // the path grows from its first triangle; space pauses it
            }
            try {
                double fps = new ViewerWindow(scene, player, caption, err, samples).show("iFold - " + model.getFileName(), 1280, 720, closeAfter);
                if (closeAfter > 0) {
                    out.printf(Locale.ROOT, "viewer: %.1f frames/s at 1280x720%n", fps);
                    out.flush();
                }
            } catch (RenderUnavailableException e) {
                throw new UserError(e.getMessage() + "; or render frames with --frames DIR");
            }
            return 0;
        }
        frameOptions.export(scene, animation, frameOptions.frameCount(), samples, out, err);
        return 0;
    }
}
