package ifold.ui;

import ifold.job.Scenes;
import ifold.scene.PathView;
import ifold.ui.model.Job;
import ifold.ui.model.Settings;
import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import javax.imageio.ImageIO;

/**
 * Pictures of the real window for the README (docs/images/app-*.png): run under Xvfb with
 * {@code java -cp ... ifold.ui.Screenshots OUTPUT_FOLDER}. Each is the window painted into an
 * image once its job is planned and drawn, at a point of its timeline.
 */
public final class Screenshots {
    private Screenshots() {
    }

    public static void main(String[] args) throws Exception {
        Path out = Path.of(args.length > 0 ? args[0] : "docs/images");
        Files.createDirectories(out);
        Path settings = Files.createTempFile("ifold-screenshots", ".properties");
        Files.delete(settings);
        MainWindow window = App.open(null, new Settings(settings));
        try {
            WindowTestBase.onEdt(() -> {
                window.setSize(1360, 820);
                return null;
            });
            shoot(window, 0.45, out.resolve("app-zigzag.png"));
            WindowTestBase.onEdt(() -> {
                window.parameters.zigzagWidth.setText("12");
                return null;
            });
            WindowTestBase.waitFor("the width marked", 10, () -> window.parameters.isMarked("width"));
            shoot(window, -1, out.resolve("app-invalid.png"));
            WindowTestBase.onEdt(() -> {
                window.parameters.show(Job.Turn.DEMO);
                return null;
            });
            shoot(window, 0.6, out.resolve("app-turn.png"));
            WindowTestBase.onEdt(() -> {
                window.open(Path.of("models", "icosahedron.off"));
                return null;
            });
            shoot(window, 0.55, out.resolve("app-wrap.png"));
            WindowTestBase.onEdt(() -> {
                window.open(Path.of("models", "scripts", "pleat20.fold"));
                return null;
            });
            shoot(window, 0.7, out.resolve("app-script.png"));
            WindowTestBase.onEdt(() -> {
                window.parameters.show(new Job.View(Path.of("models", "icosahedron.off"), Scenes.Show.PATH, PathView.Colors.DARKNESS, false));
                return null;
            });
            shoot(window, 0.6, out.resolve("app-view.png"));
        } finally {
            WindowTestBase.onEdt(() -> {
                window.dispose();
                return null;
            });
            Files.deleteIfExists(settings);
        }
        System.exit(0);
    }

    /** Waits for the plan, moves the timeline to {@code fraction} of its length (unless negative), and paints the window. */
    private static void shoot(MainWindow window, double fraction, Path file) throws Exception {
        WindowTestBase.waitFor("the plan", 120, () -> !window.isWorking() && window.plan() != null);
        if (fraction >= 0) {
            WindowTestBase.onEdt(() -> {
                window.timeline.seek(fraction * window.timeline.timeline().end());
                return null;
            });
        }
        Thread.sleep(300);
        window.view.awaitFrame(30_000);
        Thread.sleep(300);
        BufferedImage image = WindowTestBase.onEdt(() -> {
            BufferedImage picture = new BufferedImage(window.getRootPane().getWidth(), window.getRootPane().getHeight(),
                    BufferedImage.TYPE_INT_RGB);
            Graphics2D g = picture.createGraphics();
            window.getRootPane().paint(g);
            g.dispose();
            return picture;
        });
        ImageIO.write(image, "png", file.toFile());
        System.out.println("wrote " + file);
    }
}
