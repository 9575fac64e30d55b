package ifold.ui;

import ifold.image.FrameSink;
import ifold.render.FrameExport;
import ifold.render.RenderUnavailableException;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.ui.model.Renderer;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/** The window's exports drawn as the command line's are: by {@code render}'s offscreen OpenGL, without multisampling for frames. */
public final class OpenGlRenderer implements Renderer {
    public static final OpenGlRenderer INSTANCE = new OpenGlRenderer();

    private OpenGlRenderer() {
    }

    @Override
    public Rendered frames(Scene scene, Animation animation, FrameSink sink, int width, int height, int frames, boolean captions,
            FrameSink.Progress progress) throws IOException, Unavailable {
        try {
            FrameExport.Result result = FrameExport.export(scene, animation, sink, width, height, frames, 0, captions, progress);
            return new Rendered(result.frames(), result.seconds());
        } catch (RenderUnavailableException e) {
            throw new Unavailable(e.getMessage(), e);
        }
    }

    @Override
    public void panel(Scene scene, Animation animation, double[] positions, List<String> labels, int columns, int width, int height,
            int samples, Path file) throws IOException, Unavailable {
        try {
            FrameExport.panel(scene, animation, positions, labels, columns, width, height, samples, file);
        } catch (RenderUnavailableException e) {
            throw new Unavailable(e.getMessage(), e);
        }
    }
}
