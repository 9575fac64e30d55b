package ifold.print;

import ifold.scene.Animation;
import ifold.scene.Camera;
import ifold.scene.Scene;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.joml.Vector3d;

/**
 * Step diagrams: a panel a fold, six to an A4 page, each the scene the movie shows as the fold
 * begins, with the fold's crease in its style and an arrow from the flap to where it lands
 * (origami's notation), numbered and captioned as the movie captions it; after a title page
 * with the finished paper and the list of the steps. Drawn from the movie's own scene and
 * animation, as vectors.
 */
public final class StepDiagrams {
    private static final double WIDTH = 210;
    private static final double HEIGHT = 297;
    private static final double MARGIN = 12;
    private static final double HEADER = 14;
    private static final int COLUMNS = 2;
    private static final int ROWS = 3;
    private static final double GUTTER = 6;
    private static final double CAPTION = 9;
    /** How little before its end a panel of many folds shows them: all made, its camera still on them. */
    private static final double DONE = 1e-6;
    /**
     * Below this cosine between the directions two panels are seen from, the later one shows
     * the paper's other side: it gets the turn-over symbol.
     */
    private static final double TURNED_OVER = -0.3;
    /** How many times a panel's camera may move to show its fold whole. */
    private static final int FITTING = 6;

    private StepDiagrams() {
    }

    /** The pages {@code folds} panels take, the title page included. */
    public static int pageCount(int folds) {
        return 1 + (folds + COLUMNS * ROWS - 1) / (COLUMNS * ROWS);
    }

    /**
     * Draws the title page and the panels of {@code animation}'s folds in {@code scene}, which it
     * moves through them.
     *
     * @return the folds drawn
     */
    public static int draw(String title, String method, Scene scene, Animation animation, Canvas canvas) throws IOException {
        int folds = animation.foldCount();
        int pages = pageCount(folds);
        // The title page: the paper folded, and the steps listed.
        canvas.beginPage(WIDTH, HEIGHT);
        canvas.text(MARGIN, MARGIN + 6, 6, "iFold: " + title, true);
        canvas.text(MARGIN, MARGIN + 13, 3.2, String.format(Locale.ROOT, "%s: step diagrams, %d %s, page 1 of %d", method, folds,
                folds == 1 ? "step" : "steps", pages), false);
        animation.apply(animation.stepCount());
        double pictureHeight = 110;
        SceneDrawing.draw(scene, canvas, MARGIN, MARGIN + 18, WIDTH - 2 * MARGIN, pictureHeight);
        double y = MARGIN + 18 + pictureHeight + 8;
        canvas.text(MARGIN, y, 3.6, "The steps", true);
        y += 5;
        double column = MARGIN;
        for (int k = 0; k < folds; k++) {
            if (y > HEIGHT - MARGIN) {
                if (column > MARGIN) {
                    canvas.text(column, y, 2.6, "...", false);
                    break;
                }
                column = WIDTH / 2;
                y = MARGIN + 18 + pictureHeight + 13;
            }
            canvas.text(column, y, 2.6, shortened(String.format(Locale.ROOT, "%d. %s", k + 1, caption(animation, k)), 70), false);
            y += 3.6;
        }
        canvas.endPage();
        Vector3d lookedBefore = null;
        double panelWidth = (WIDTH - 2 * MARGIN - (COLUMNS - 1) * GUTTER) / COLUMNS;
        double panelHeight = (HEIGHT - 2 * MARGIN - HEADER - (ROWS - 1) * GUTTER) / ROWS;
        for (int k = 0; k < folds; k++) {
            int slot = k % (COLUMNS * ROWS);
            if (slot == 0) {
                if (k > 0) {
                    canvas.endPage();
                }
                canvas.beginPage(WIDTH, HEIGHT);
                canvas.text(MARGIN, MARGIN + 6, 4, "iFold: " + title, true);
                canvas.text(MARGIN, MARGIN + 11, 2.8, String.format(Locale.ROOT, "%s; page %d of %d", method, 2 + k / (COLUMNS * ROWS), pages),
                        false);
            }
            double x = MARGIN + (slot % COLUMNS) * (panelWidth + GUTTER);
            double top = MARGIN + HEADER + (slot / COLUMNS) * (panelHeight + GUTTER);
            double start = animation.foldStart(k);
            double end = animation.foldStart(k + 1);
            Animation.FoldLine crease = animation.foldLine(k);
            double[][] path = animation.foldPath(k);
            // A fold as origami diagrams draw it: the paper before it, its crease and its arrow
            // over it. A panel of many folds (a wrap's triangle) shows them made.
            animation.apply(animation.foldIsGroup(k) ? end - DONE * (end - start) : start);
            Camera camera = scene.camera();
            Vector3d target = new Vector3d(camera.target());
            double distance = camera.distance();
            fit(scene, panelWidth, panelHeight - CAPTION, crease, path);
            SceneDrawing.draw(scene, canvas, x, top + CAPTION, panelWidth, panelHeight - CAPTION);
            Vector3d looking = SceneDrawing.viewDirection(scene);
            // A valley seen from the other side is a mountain: the panel says what its eye sees.
            boolean valley = crease == null || crease.valleyLookingAlong(new double[] {looking.x, looking.y, looking.z});
            if (crease != null) {
                SceneDrawing.line(scene, canvas, x, top + CAPTION, panelWidth, panelHeight - CAPTION, crease.from(), crease.to(),
                        valley ? Ink.VALLEY : Ink.MOUNTAIN);
            }
            arrow(scene, animation, k, valley, canvas, x, top + CAPTION, panelWidth, panelHeight - CAPTION);
            if (lookedBefore != null && lookedBefore.dot(looking) < TURNED_OVER) {
                DiagramArrows.turnOver(canvas, x + panelWidth - 9, top + CAPTION + 6, 3.5);
            }
            lookedBefore = looking;
            camera.setTarget(target);
            camera.setDistance(distance);
            canvas.outline(new double[] {x, top + CAPTION, x + panelWidth, top + CAPTION, x + panelWidth, top + panelHeight, x,
                top + panelHeight}, Ink.FLAT);
            canvas.text(x, top + 4.2, 4.2, Integer.toString(k + 1), true);
            List<String> lines = wrapped(caption(animation, k), 58);
            for (int i = 0; i < Math.min(2, lines.size()); i++) {
                canvas.text(x + 8, top + 3.2 + 3.4 * i, 2.7, lines.get(i), false);
            }
        }
        if (folds > 0) {
            canvas.endPage();
        }
        return folds;
    }

    /**
     * Moves the camera back, and towards them, until the fold's crease and the way its flap
     * travels lie inside the panel, a tenth of it clear of the border: a wrap's view follows its
     * triangle, and a fold at its edge would fall outside.
     */
    static void fit(Scene scene, double width, double height, Animation.FoldLine crease, double[][] path) {
        List<double[]> points = new ArrayList<>();
        if (crease != null) {
            points.add(crease.from());
            points.add(crease.to());
        }
        if (path != null) {
            points.addAll(List.of(path));
        }
        if (points.isEmpty()) {
            return;
        }
        Camera camera = scene.camera();
        for (int tries = 0; tries < FITTING && !inside(scene, width, height, points); tries++) {
            if (tries == 0) {
                Vector3d centre = new Vector3d();
                for (double[] p : points) {
                    centre.add(p[0], p[1], p[2]);
                }
                centre.div(points.size());
                camera.setTarget(new Vector3d(camera.target()).lerp(centre, 0.5));
            } else {
                camera.setDistance(1.3 * camera.distance());
            }
        }
    }

    private static boolean inside(Scene scene, double width, double height, List<double[]> points) {
        for (double[] point : points) {
            double[] p = SceneDrawing.project(scene, 0, 0, width, height, point);
            if (p == null || p[0] < 0.1 * width || p[0] > 0.9 * width || p[1] < 0.1 * height || p[1] > 0.9 * height) {
                return false;
            }
        }
        return true;
    }

    /**
     * Fold k's arrow over its panel: the way its flap travels, from before the fold to after, as
     * the panel's camera sees it.
     *
     * @return whether one was drawn
     */
    static boolean arrow(Scene scene, Animation animation, int k, boolean valley, Canvas canvas, double x, double y, double width,
            double height) throws IOException {
        double[][] path = animation.foldPath(k);
        if (path == null) {
            return false;
        }
        double[] start = SceneDrawing.project(scene, x, y, width, height, path[0]);
        double[] middle = SceneDrawing.project(scene, x, y, width, height, path[path.length / 2]);
        double[] end = SceneDrawing.project(scene, x, y, width, height, path[path.length - 1]);
        if (start == null || middle == null || end == null) {
            return false;
        }
        canvas.beginClip(x, y, width, height);
        boolean drawn = DiagramArrows.fold(canvas, start, middle, end, valley);
        canvas.endClip();
        return drawn;
    }

    /** Fold k's caption, as the movie says it while the fold is made. */
    static String caption(Animation animation, int k) {
        return animation.foldCaption(k).replaceAll(" \\(\\d+ %\\)", "");
    }

    private static String shortened(String text, int most) {
        return text.length() <= most ? text : text.substring(0, most - 3) + "...";
    }

    /** Words in lines of at most {@code most} characters. */
    static List<String> wrapped(String text, int most) {
        List<String> lines = new ArrayList<>();
        StringBuilder line = new StringBuilder();
        for (String word : text.split(" ")) {
            if (line.length() > 0 && line.length() + 1 + word.length() > most) {
                lines.add(line.toString());
                line.setLength(0);
            }
            line.append(line.length() == 0 ? "" : " ").append(word);
        }
        if (line.length() > 0) {
            lines.add(line.toString());
        }
        return lines;
    }
}
