package ifold.print;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.geom.Triangle;
import ifold.job.Scenes;
import ifold.job.WrapJob;
import ifold.job.ZigZagFixture;
import ifold.mesh.MeshBuilder;
import ifold.scene.Animation;
import ifold.scene.Scene;
import ifold.wrap.PaperInSpace;
import ifold.wrap.Wrap;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * Step diagrams in origami notation, drawn onto a canvas that records what each panel is asked
 * to draw: a fold's arrow from its flap across its crease, a full head for a valley and a half
 * one for a mountain, and the turn-over symbol where the view turns to the paper's other side.
 */
class StepDiagramsTest {
    /** What one panel was asked to draw, in order. */
    static final class Panel {
        final List<double[]> arrowLines = new ArrayList<>();
        final List<double[]> creases = new ArrayList<>();
        final List<Ink> creaseInks = new ArrayList<>();
        int fullHeads;
        int halfHeads;
        boolean turnOver;
        String caption = "";
    }

    /**
     * Records the panels: what is drawn before a panel's bold number belongs to it (the number
     * and caption are drawn last), its caption the text after.
     */
    static final class Panels implements Canvas {
        final List<Panel> panels = new ArrayList<>();
        /** The title page's line under the title. */
        String title = "";
        Panel drawing = new Panel();
        Panel captioned;

        @Override
        public void beginPage(double widthMm, double heightMm) {
        }

        @Override
        public void line(double x1, double y1, double x2, double y2, Ink ink) {
            if (ink == Ink.ARROW) {
                drawing.arrowLines.add(new double[] {x1, y1, x2, y2});
            } else if (ink == Ink.VALLEY || ink == Ink.MOUNTAIN) {
                drawing.creases.add(new double[] {x1, y1, x2, y2});
                drawing.creaseInks.add(ink);
            }
        }

        @Override
        public void outline(double[] xy, Ink ink) {
            drawing.halfHeads += ink == Ink.ARROW ? 1 : 0;
        }

        @Override
        public void fill(double[] xy, int argb) {
            drawing.fullHeads += xy.length == 6 && (argb & 0xFFFFFF) == 0 ? 1 : 0;
        }

        @Override
        public void text(double x, double y, double size, String text, boolean bold) {
            if (size == 3.2 && title.isEmpty()) {
                title = text;
            } else if (bold && size == 4.2) {
                panels.add(drawing);
                captioned = drawing;
                drawing = new Panel();
            } else if (text.equals("turn over")) {
                drawing.turnOver = true;
            } else if (captioned != null && !bold) {
                captioned.caption += (captioned.caption.isEmpty() ? "" : " ") + text;
            }
        }

        @Override
        public void beginClip(double x, double y, double width, double height) {
        }

        @Override
        public void endClip() {
        }

        @Override
        public void endPage() {
            captioned = null;
        }
    }

    /** Which side of the line (x1, y1)-(x2, y2) the point lies on. */
    private static double side(double[] line, double x, double y) {
        return Math.signum((line[2] - line[0]) * (y - line[1]) - (line[3] - line[1]) * (x - line[0]));
    }

    @Test
    void eachFoldOfTheZigZagHasItsArrowAcrossItsCreaseAndTheTucksBeginWithTurnOver() throws Exception {
        Triangle shape = ZigZagFixture.SHAPE;
        Wrap.Result result = ZigZagFixture.wrapped();
        Scene scene = new Scene();
        Animation playback = Scenes.zigzag(scene, shape, result, List.of(PaperInSpace.of(result.strips().get(0).sheet(), result.frames())));
        Panels canvas = new Panels();
        StepDiagrams.draw("a triangle", "zig-zag", scene, playback, canvas, Page.A4);
        int folds = playback.foldCount();

        assertEquals(result.steps().size(), folds);
        assertEquals(folds, canvas.panels.size());
        // The steps a reader counts are the numbered ones: the strip's end is drawn, unnumbered, and is no step.
        assertEquals(1, result.count(Wrap.Kind.END), "setup: the strip ends once");
        assertEquals(folds - 1, StepDiagrams.stepCount(playback));
        assertTrue(canvas.title.contains("step diagrams, " + (folds - 1) + " steps, page 1 of"), canvas.title);
        int turnedOver = 0;
        boolean below = false;
        for (int k = 0; k < folds; k++) {
            Panel panel = canvas.panels.get(k);
            Wrap.Step step = result.steps().get(k);
            String what = "panel " + (k + 1) + " (" + panel.caption + ")";
            if (step.kind() == Wrap.Kind.END) {
                assertTrue(panel.arrowLines.isEmpty() && panel.fullHeads + panel.halfHeads == 0, what + ": no fold, no arrow");
            } else {
                // A tuck folds its flap under the paper: a mountain from above, a valley from below,
                // where the diagram shows it.
                boolean valley = step.kind() == Wrap.Kind.TUCK ? panel.caption.contains("seen from below") : panel.caption.contains("valley");
                assertTrue(valley || panel.caption.contains("mountain") || step.kind() == Wrap.Kind.TUCK, what);
                assertEquals(List.of(valley ? Ink.VALLEY : Ink.MOUNTAIN), panel.creaseInks, what + ": the crease's style");
                int symbolHead = panel.turnOver ? 1 : 0;
                assertEquals(valley ? 1 : 0, panel.fullHeads - symbolHead, what + ": a valley's arrow has a full head");
                assertEquals(valley ? 0 : 1, panel.halfHeads, what + ": a mountain's a half head");
                // The arc starts on the flap and ends where it lands: on either side of the crease.
                double[] crease = panel.creases.get(0);
                double[] first = panel.arrowLines.get(0);
                double[] last = panel.arrowLines.get(15);
                assertEquals(-side(crease, first[0], first[1]), side(crease, last[2], last[3]), what + ": the arrow crosses the crease");
                assertTrue(Math.hypot(last[2] - first[0], last[3] - first[1]) >= DiagramArrows.SHORTEST - 1e-9, what);
            }
            // The turn-over symbol where the view turns under the paper, and nowhere else.
            boolean nowBelow = panel.caption.contains("seen from below");
            assertEquals(nowBelow && !below, panel.turnOver, what);
            turnedOver += panel.turnOver ? 1 : 0;
            below = nowBelow;
        }
        assertEquals(1, turnedOver, "the tucks are seen from below, together at the end");
    }

    /**
     * The hinge strip's diagrams, a panel a fold: the strip's end has a panel, unnumbered, and is
     * not one of its pass's folds; each numbered panel is fold k of its pass's n creasing folds.
     */
    @Test
    void theHingeStripsEndIsNoFold() throws Exception {
        WrapJob.Outcome wrapped = cubeWrapped(Wrap.Method.HINGE);
        Wrap.Result result = wrapped.result();
        Scene scene = new Scene();
        Animation playback = Scenes.wrap(scene, wrapped.mesh(), result, wrapped.geometries());
        assertEquals(result.steps().size(), playback.foldCount(), "setup: a panel a fold");
        int ends = 0;
        for (int k = 0; k < playback.foldCount(); k++) {
            String caption = playback.foldCaption(k);
            if (result.steps().get(k).kind() == Wrap.Kind.END) {
                ends++;
                assertEquals("", playback.foldLabel(k), caption);
                assertFalse(caption.contains("(fold "), caption);
            } else if (!playback.foldLabel(k).isEmpty()) {
                java.util.regex.Matcher fold = java.util.regex.Pattern.compile("\\(fold (\\d+) of (\\d+)\\)$").matcher(caption);
                assertTrue(fold.find(), caption);
                assertTrue(Integer.parseInt(fold.group(1)) <= Integer.parseInt(fold.group(2)), caption);
            }
        }
        assertEquals(1, ends, "setup: one strip, one end");
        assertTrue(playback.foldCaption(playback.foldCount() - 1).startsWith("pass "), "setup: the end last");
        Panels canvas = new Panels();
        StepDiagrams.draw("cube", "hinge", scene, playback, canvas, Page.A4);
        int numbered = StepDiagrams.stepCount(playback);
        assertEquals(playback.foldCount() - 1, numbered, "every fold of the cube's hinge strip creases");
        assertTrue(canvas.title.contains(numbered + " steps"), canvas.title);
    }

    /** The cube of models/ wrapped by {@code method} at the defaults. */
    private static WrapJob.Outcome cubeWrapped(Wrap.Method method) throws Exception {
        return WrapJob.run(new WrapJob.Request(Path.of("models/cube.off"), new MeshBuilder.Options(false, true),
                new Wrap.Options(Double.NaN, Double.NaN, null), method), new WrapJob.Watcher() {
                    @Override
                    public void wrapped(int done, int total) {
                    }

                    @Override
                    public boolean stopped() {
                        return false;
                    }
                });
    }

    /** A wrap's first triangle fold by fold, each with its crease; then a panel a triangle, without. */
    @Test
    void aWrapsFirstTriangleIsDrawnFoldByFold() throws Exception {
        WrapJob.Outcome wrapped = cubeWrapped(Wrap.Method.ZIGZAG);
        Wrap.Result result = wrapped.result();
        Scene scene = new Scene();
        Animation playback = Scenes.wrap(scene, wrapped.mesh(), result, wrapped.geometries());
        int first = 0;
        while (first < result.steps().size() && result.steps().get(first).pathIndex() == 0) {
            first++;
        }
        int triangles = result.strips().get(0).triangles();
        assertEquals(first + triangles - 1, playback.foldCount());
        for (int k = 0; k < playback.foldCount(); k++) {
            boolean alone = k < first;
            assertEquals(alone, playback.foldLine(k) != null, "fold " + k);
            assertTrue(playback.foldStart(k) < playback.foldStart(k + 1), "fold " + k + " takes time");
            if (!alone) {
                assertNull(playback.foldPath(k));
                assertTrue(playback.foldCaption(k).startsWith("triangle " + (k - first + 2) + " of " + triangles + ":"), playback.foldCaption(k));
            } else {
                assertTrue(playback.foldCaption(k).endsWith("(fold " + (k + 1) + " of " + first + ")"), playback.foldCaption(k));
            }
        }
        assertNotNull(playback.foldPath(0), "the first fold swings its tail");
        // The last triangle's panel counts its folds by kind, and says the strip ends there without counting it as one.
        String last = playback.foldCaption(playback.foldCount() - 1);
        assertTrue(last.contains(", the strip's end (creases ") && !last.contains("1 end"), last);
        assertFalse(playback.foldCaption(first - 1).isEmpty());
    }
}
