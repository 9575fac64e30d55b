package ifold.render;

import ifold.image.FrameSink;
import ifold.scene.Animation;
import ifold.scene.Geometry;
import ifold.scene.RevealAnimation;
import ifold.scene.Scene;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * Renders an animation offscreen into a numbered PNG sequence: frame i shows the animation at
 * i / (frames - 1) of the way through, so the first frame is the start and the last the end.
 *
 * <p>A reveal of the scene's only geometry under a still camera is composited rather than
 * rendered frame by frame: three renders (everything revealed, nothing revealed, and the index
 * of the triangle at each pixel) give every frame, each pixel taken from the first or the
 * second picture as its triangle's index is below the frame's count or not. On a software
 * renderer a frame of a 500,000-triangle path then costs a pass over the pixels instead of
 * drawing every triangle again.
 */
public final class FrameExport {
    private FrameExport() {
    }

    /**
     * What an export did.
     *
     * @param frames frames written
     * @param seconds wall time, encoding included
     * @param renderer the OpenGL version and renderer used
     * @param composited whether the frames were composited from three renders
     */
    public record Result(int frames, double seconds, String renderer, boolean composited) {
        public double framesPerSecond() {
            return frames / seconds;
        }
    }

    /**
     * Renders {@code frames} frames of the animation into {@code sink}.
     *
     * @param samples samples per pixel for antialiasing (0 for none)
     * @param captions whether each frame carries a caption naming the step it shows, the legend of
     *     the scene's colours and its labels
     * @param progress told of each frame done, or null
     */
    public static Result export(Scene scene, Animation animation, FrameSink sink, int width, int height, int frames,
            int samples, boolean captions, FrameSink.Progress progress) throws RenderUnavailableException, IOException {
        long start = System.nanoTime();
        scene.bindToThread(Thread.currentThread());
        try (OffscreenRenderer renderer = new OffscreenRenderer(width, height, samples)) {
            Captions caption = captions ? new Captions(width, height) : null;
            Annotations notes = captions ? new Annotations(width, height) : null;
            // A GIF picks its palette from frames spread over the movie, before the first.
            int samplesWanted = Math.min(sink.samplesWanted(), frames);
            for (int k = 0; k < samplesWanted; k++) {
                double at = samplesWanted == 1 ? 0 : animation.stepCount() * (double) k / (samplesWanted - 1);
                animation.apply(at);
                byte[] picture = renderer.render(scene);
                annotate(picture, scene, caption, notes, animation, at);
                sink.sample(picture);
            }
            boolean composite = animation instanceof RevealAnimation reveal && isOnlyGeometry(scene, reveal.geometry());
            if (composite) {
                composite(scene, (RevealAnimation) animation, renderer, sink, frames, caption, notes, progress);
            } else {
                for (int i = 0; i < frames; i++) {
                    double at = position(animation, i, frames);
                    animation.apply(at);
                    byte[] picture = renderer.render(scene, sink.buffer(3 * width * height));
                    annotate(picture, scene, caption, notes, animation, at);
                    sink.write(i, width, height, picture);
                    if (progress != null) {
                        progress.framesDone(i + 1, frames);
                    }
                }
            }
            sink.finish();
            return new Result(frames, (System.nanoTime() - start) * 1e-9, renderer.describe(), composite);
        } finally {
            scene.bindToThread(null);
        }
    }

    /** Writes the caption of the animation at {@code at}, the legend and the labels into a frame, where they are asked for (non-null). */
    private static void annotate(byte[] picture, Scene scene, Captions caption, Annotations notes, Animation animation, double at) {
        if (caption != null) {
            caption.draw(picture, animation.describe(at));
        }
        if (notes != null) {
            notes.drawLegend(picture, scene.legend());
            notes.drawLabels(picture, scene, scene.labels());
        }
    }

    /** The rows of a frame that a caption covers, from the bottom. */
    public static int captionBand(int width, int height) {
        return new Captions(width, height).band();
    }

    /**
     * Renders the animation at each of {@code positions} into a tile of {@code width} by
     * {@code height} and writes them as one picture, {@code columns} tiles a row, left to right
     * and top to bottom, with a thin grey line between tiles: a figure of stages, each labelled
     * in its top left corner by its entry of {@code labels} (null for none). Written under a
     * temporary name and renamed.
     */
    public static void panel(Scene scene, Animation animation, double[] positions, List<String> labels, int columns, int width,
            int height, int samples, Path file) throws RenderUnavailableException, IOException {
        int rows = (positions.length + columns - 1) / columns;
        int gap = 2;
        int panelWidth = columns * width + (columns - 1) * gap;
        int panelHeight = rows * height + (rows - 1) * gap;
        byte[] panel = new byte[3 * panelWidth * panelHeight];
        java.util.Arrays.fill(panel, (byte) 0xC8);
        scene.bindToThread(Thread.currentThread());
        try (OffscreenRenderer renderer = new OffscreenRenderer(width, height, samples)) {
            for (int i = 0; i < positions.length; i++) {
                animation.apply(positions[i]);
                byte[] tile = renderer.render(scene);
                if (labels != null && i < labels.size()) {
                    Captions.label(tile, width, height, labels.get(i));
                }
                int left = (i % columns) * (width + gap);
                int top = (i / columns) * (height + gap);
                for (int y = 0; y < height; y++) {
                    System.arraycopy(tile, 3 * y * width, panel, 3 * ((top + y) * panelWidth + left), 3 * width);
                }
            }
        } finally {
            scene.bindToThread(null);
        }
        ifold.io.AtomicFile.write(file, out -> ifold.image.PngEncoder.encode(panelWidth, panelHeight, panel, out), true);
    }

    private static double position(Animation animation, int frame, int frames) {
        return frames == 1 ? animation.stepCount() : (double) animation.stepCount() * frame / (frames - 1);
    }

    private static boolean isOnlyGeometry(Scene scene, Geometry geometry) {
        List<Geometry> all = new ArrayList<>();
        scene.root().visitGeometry(all::add);
        return all.size() == 1 && all.get(0) == geometry;
    }

    private static void composite(Scene scene, RevealAnimation reveal, OffscreenRenderer renderer, FrameSink writer,
            int frames, Captions caption, Annotations notes, FrameSink.Progress progress) throws IOException {
        Geometry geometry = reveal.geometry();
        geometry.setRevealed(Geometry.ALL);
        byte[] revealed = renderer.render(scene);
        geometry.setRevealed(0);
        byte[] hidden = renderer.render(scene);
        int[] index = renderer.renderIndices(scene);
        for (int i = 0; i < frames; i++) {
            int count = RevealAnimation.revealedAt(position(reveal, i, frames));
            reveal.apply(position(reveal, i, frames)); // keeps the scene in step for whoever looks next
            byte[] frame = writer.buffer(revealed.length);
            for (int p = 0, b = 0; p < index.length; p++, b += 3) {
                byte[] source = index[p] != 0 && index[p] - 1 < count ? revealed : hidden;
                frame[b] = source[b];
                frame[b + 1] = source[b + 1];
                frame[b + 2] = source[b + 2];
            }
            annotate(frame, scene, caption, notes, reveal, position(reveal, i, frames));
            writer.write(i, renderer.width(), renderer.height(), frame);
            if (progress != null) {
                progress.framesDone(i + 1, frames);
            }
        }
    }
}
