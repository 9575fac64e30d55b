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
    private static final double MARGIN = 12;
    private static final double HEADER = 14;
    private static final int COLUMNS = 2;
    private static final int ROWS = 3;
    private static final double GUTTER = 6;
    /** Room above a panel for its number and up to three lines of caption. */
    private static final double CAPTION = 11.5;
    /** How little before its end a panel of many folds shows them: all made, its camera still on them. */
    private static final double DONE = 1e-6;
    /**
     * Below this cosine between the directions two panels are seen from, the later one shows
     * the paper's other side: it gets the turn-over symbol.
     */
    private static final double TURNED_OVER = -0.3;
    /** A fold spanning less of its panel than this is brought closer. */
    private static final double SMALL_FOLD = 1.0 / 3;
    /** How many times a panel's camera may move to show its fold whole. */
    private static final int FITTING = 6;

    private StepDiagrams() {
    }

    /** A line of the list of steps: where on which page of the list, and its words. */
    private record Entry(int page, double x, double y, String text) {
    }

    /**
     * Draws the title page (the paper folded, the list of steps, continued on pages of its own
     * where it is long) and the panels of {@code animation}'s folds in {@code scene}, which it
     * moves through them, on pages of {@code page}'s size (A4 for {@link Page#NONE}): two panels
     * across and three down, or three across and two down on a page on its side.
     *
     * @return the pages drawn
     */
    public static int draw(String title, String method, Scene scene, Animation animation, Canvas canvas, Page page) throws IOException {
        Page sheet = page == Page.NONE ? Page.A4 : page;
        double width = sheet.width();
        double height = sheet.height();
        boolean wide = width > height;
        int columns = wide ? ROWS : COLUMNS;
        int rows = wide ? COLUMNS : ROWS;
        int folds = animation.foldCount();
        int numbered = stepCount(animation);
        double pictureHeight = wide ? 80 : 110;
        List<Entry> contents = contents(animation, width, height, MARGIN + 18 + pictureHeight + 13);
        int listPages = contents.isEmpty() ? 1 : contents.get(contents.size() - 1).page() + 1;
        int pages = listPages + (folds + columns * rows - 1) / (columns * rows);
        // The title page: the paper folded, and the steps listed.
        canvas.beginPage(width, height);
        canvas.text(MARGIN, MARGIN + 6, 6, "iFold: " + title, true);
        canvas.text(MARGIN, MARGIN + 13, 3.2, String.format(Locale.ROOT, "%s: step diagrams, %d %s, page 1 of %d", method, numbered,
                numbered == 1 ? "step" : "steps", pages), false);
        animation.apply(animation.stepCount());
        SceneDrawing.draw(scene, canvas, MARGIN, MARGIN + 18, width - 2 * MARGIN, pictureHeight);
        canvas.text(MARGIN, MARGIN + 18 + pictureHeight + 8, 3.6, "The steps", true);
        canvas.text(MARGIN + 24, MARGIN + 18 + pictureHeight + 8, 2.4, "A valley or mountain as its panel sees it: the print marks each"
                + " as its printed side sees it, and a strip turned over folds a printed valley as a mountain.", false);
        int listPage = 0;
        for (Entry entry : contents) {
            while (entry.page() > listPage) {
                canvas.endPage();
                canvas.beginPage(width, height);
                listPage++;
                canvas.text(MARGIN, MARGIN + 6, 4, "iFold: " + title, true);
                canvas.text(MARGIN, MARGIN + 11, 2.8, String.format(Locale.ROOT, "%s; the steps, continued; page %d of %d", method, listPage + 1,
                        pages), false);
            }
            canvas.text(entry.x(), entry.y(), 2.6, entry.text(), false);
        }
        canvas.endPage();
        Vector3d lookedBefore = null;
        double panelWidth = (width - 2 * MARGIN - (columns - 1) * GUTTER) / columns;
        double panelHeight = (height - 2 * MARGIN - HEADER - (rows - 1) * GUTTER) / rows;
        for (int k = 0; k < folds; k++) {
            int slot = k % (columns * rows);
            if (slot == 0) {
                if (k > 0) {
                    canvas.endPage();
                }
                canvas.beginPage(width, height);
                canvas.text(MARGIN, MARGIN + 6, 4, "iFold: " + title, true);
                canvas.text(MARGIN, MARGIN + 11, 2.8, String.format(Locale.ROOT, "%s; page %d of %d", method, listPages + 1 + k / (columns * rows),
                        pages), false);
            }
            double x = MARGIN + (slot % columns) * (panelWidth + GUTTER);
            double top = MARGIN + HEADER + (slot / columns) * (panelHeight + GUTTER);
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
            canvas.text(x, top + 4.2, 4.2, animation.foldLabel(k), true);
            // Helvetica's letters average about half their height across.
            List<String> lines = wrapped(caption(animation, k), (int) ((panelWidth - 9) / (0.5 * 2.7)));
            for (int i = 0; i < Math.min(3, lines.size()); i++) {
                canvas.text(x + 8, top + 3.2 + 3.4 * i, 2.7, lines.get(i), false);
            }
        }
        if (folds > 0) {
            canvas.endPage();
        }
        return pages;
    }

    /**
     * The steps a reader counts: the numbered panels. A panel of a step that folds nothing (the
     * strip's end, paper running on flat into the next piece of a face) is drawn, unnumbered, to
     * show where the paper goes, but is not one of the steps to make.
     */
    public static int stepCount(Animation animation) {
        int steps = 0;
        for (int k = 0; k < animation.foldCount(); k++) {
            steps += animation.foldLabel(k).isEmpty() ? 0 : 1;
        }
        return steps;
    }

    /**
     * The list of steps, each "label. caption" wrapped to its column, two columns a page: on the
     * title page from {@code firstTop} down, then on pages of their own from under their header.
     */
    private static List<Entry> contents(Animation animation, double width, double height, double firstTop) {
        List<Entry> entries = new ArrayList<>();
        double columnWidth = (width - 2 * MARGIN - GUTTER) / 2;
        // Helvetica's letters average about half their height across.
        int characters = (int) Math.floor(columnWidth / (0.5 * 2.6));
        int page = 0;
        int column = 0;
        double y = firstTop;
        for (int k = 0; k < animation.foldCount(); k++) {
            String label = animation.foldLabel(k);
            List<String> lines = wrapped((label.isEmpty() ? "" : label + ". ") + caption(animation, k), characters);
            if (y + 3.6 * (lines.size() - 1) > height - MARGIN) {
                column++;
                if (column == 2) {
                    column = 0;
                    page++;
                }
                y = page == 0 ? firstTop : MARGIN + HEADER + 4;
            }
            for (int i = 0; i < lines.size(); i++) {
                entries.add(new Entry(page, MARGIN + column * (columnWidth + GUTTER) + (i > 0 ? 4 : 0), y, lines.get(i)));
                y += 3.6;
            }
        }
        return entries;
    }

    /**
     * Moves the camera closer where the fold's crease and the way its flap travels span little
     * of the panel, and back, towards them, until they lie inside it, a tenth of it clear of the
     * border: a wrap's view follows its triangle, and a fold at its edge would fall outside.
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
        // A fold small in its view (a pleat at the end of a long strip, a tuck's flap) is brought
        // closer, up to four times, until it spans a third of the panel.
        double[] extent = extent(scene, width, height, points);
        double span = Math.max(extent[2] - extent[0], (extent[3] - extent[1]) * width / height) / width;
        if (span > 0 && span < SMALL_FOLD && inside(scene, width, height, points)) {
            Vector3d centre = new Vector3d();
            for (double[] p : points) {
                centre.add(p[0], p[1], p[2]);
            }
            camera.setTarget(centre.div(points.size()));
            camera.setDistance(camera.distance() * Math.max(0.25, span / SMALL_FOLD));
        }
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

    /** The box the points take on the panel: x0, y0, x1, y1 (millimetres from its corner). */
    private static double[] extent(Scene scene, double width, double height, List<double[]> points) {
        double[] box = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        for (double[] point : points) {
            double[] p = SceneDrawing.project(scene, 0, 0, width, height, point);
            if (p != null) {
                box[0] = Math.min(box[0], p[0]);
                box[1] = Math.min(box[1], p[1]);
                box[2] = Math.max(box[2], p[0]);
                box[3] = Math.max(box[3], p[1]);
            }
        }
        return box;
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
