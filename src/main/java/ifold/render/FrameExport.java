package ifold.render;

import ifold.image.FrameWriter;
import ifold.scene.Animation;
import ifold.scene.Geometry;
import ifold.scene.RevealAnimation;
import ifold.scene.Scene;
import java.io.IOException;
import java.io.PrintWriter;
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
     * @param samples samples per pixel for antialiasing (0 for none)
     * @param progress where the progress bar goes, or null
     */
    public static Result export(Scene scene, Animation animation, Path folder, int width, int height, int frames,
            int samples, PrintWriter progress) throws RenderUnavailableException, IOException {
        long start = System.nanoTime();
        scene.bindToThread(Thread.currentThread());
        try (OffscreenRenderer renderer = new OffscreenRenderer(width, height, samples);
                FrameWriter writer = new FrameWriter(folder, frames, progress)) {
            boolean composite = animation instanceof RevealAnimation reveal && isOnlyGeometry(scene, reveal.geometry());
            if (composite) {
                composite(scene, (RevealAnimation) animation, renderer, writer, frames);
            } else {
                for (int i = 0; i < frames; i++) {
                    animation.apply(position(animation, i, frames));
                    writer.write(i, width, height, renderer.render(scene, writer.buffer(3 * width * height)));
                }
            }
            writer.finish();
            return new Result(frames, (System.nanoTime() - start) * 1e-9, renderer.describe(), composite);
        } finally {
            scene.bindToThread(null);
        }
    }

    /**
     * Renders the animation at each of {@code positions} into a tile of {@code width} by
     * {@code height} and writes them as one picture, {@code columns} tiles a row, left to right
     * and top to bottom, on a white ground with a thin grey line between tiles: a figure of
     * stages. Written under a temporary name and renamed.
     */
    public static void panel(Scene scene, Animation animation, double[] positions, int columns, int width, int height,
            int samples, Path file) throws RenderUnavailableException, IOException {
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

    private static void composite(Scene scene, RevealAnimation reveal, OffscreenRenderer renderer, FrameWriter writer,
            int frames) throws IOException {
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
            writer.write(i, renderer.width(), renderer.height(), frame);
        }
    }
}
