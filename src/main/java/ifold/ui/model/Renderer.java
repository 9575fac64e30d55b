package ifold.ui.model;

import ifold.image.FrameSink;
import ifold.scene.Animation;
import ifold.scene.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

/**
 * What draws a plan's scene into frames or a picture. The window gives it ({@code ui} passes
 * {@code render}'s frame export), so that its model draws nothing itself: {@link Exports} decides
 * what is written, where, and what a failure says, and is tested with or without OpenGL.
 */
public interface Renderer {
    /**
     * Frames drawn.
     *
     * @param frames frames written
     * @param seconds wall time, encoding included
     */
    record Rendered(int frames, double seconds) {
    }

    /** The frames of the animation into {@code sink}, a caption on each where {@code captions}; {@code progress} told of each. */
    Rendered frames(Scene scene, Animation animation, FrameSink sink, int width, int height, int frames, boolean captions,
            FrameSink.Progress progress) throws IOException, Unavailable;

    /**
     * One picture of the animation at several {@code positions}, a panel each with its label,
     * in {@code columns} columns of {@code width} by {@code height}, at {@code samples} samples
     * a pixel, written to {@code file}.
     */
    void panel(Scene scene, Animation animation, double[] positions, List<String> labels, int columns, int width, int height,
            int samples, Path file) throws IOException, Unavailable;

    /** Nothing can draw here (no display, no Xvfb, a driver too old): the message says what to do. */
    final class Unavailable extends Exception {
        private static final long serialVersionUID = 1L;

        public Unavailable(String message, Throwable cause) {
            super(message, cause);
        }
    }
}
