package ifold.job;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.geom.Triangle;
import ifold.scene.Scene;
import ifold.scene.WrapPlayback;
import ifold.scene.WrapView;
import ifold.wrap.Wrap;
import ifold.wrap.PaperInSpace;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The zig-zag demo's scene says what its captions refer to: the corners by name, the colours, the view from below. */
class ZigZagSceneTest {
    @Test
    void theCornersAreLabelledTheColoursExplainedAndTheTucksSeenFromBelow() throws Exception {
        Triangle shape = ZigZagFixture.SHAPE;
        Wrap.Result result = ZigZagFixture.wrapped();
        Scene scene = new Scene();
        WrapPlayback playback = Scenes.zigzag(scene, shape, result,
                List.of(PaperInSpace.of(result.strips().get(0).sheet(), result.frames())));

        List<Scene.Label> labels = scene.labels();
        assertEquals(List.of("A", "B", "C"), labels.stream().map(Scene.Label::text).toList());
        for (int i = 0; i < 3; i++) {
            assertEquals(shape.corner(i).x(), labels.get(i).x());
            assertEquals(shape.corner(i).y(), labels.get(i).y());
        }
        assertEquals(List.of("paper, top side", "paper, underside", "the triangle"),
                scene.legend().stream().map(Scene.Swatch::meaning).toList());
        assertEquals(WrapView.PAPER.back(), scene.legend().get(1).color(), "the underside's swatch is the colour it is drawn in");

        // Each fold's caption, at the middle of its time: the tucks are seen from below, nothing else.
        int tucks = 0;
        for (int j = 0; j < result.steps().size(); j++) {
            String caption = playback.describe((playback.positionAfter(j) + playback.positionAfter(j + 1)) / 2);
            boolean tuck = result.steps().get(j).kind() == Wrap.Kind.TUCK;
            tucks += tuck ? 1 : 0;
            assertEquals(tuck, caption.endsWith("(seen from below)"), caption);
        }
        assertTrue(tucks > 0, "check the setup: the triangle has tucks");
        assertFalse(playback.describe(playback.halfTurn()).contains("below"), "the final turn is not named so");

        // And at every moment, not just the middles: while a caption says "seen from below", the
        // camera is below the triangle (the last tuck's caption stayed on screen for 0.7 s of a
        // movie after the camera had come back up).
        assertCaptionsSeenFromBelowOnlyFromBelow(scene, playback);
        // A short movie groups the folds a caption each (--seconds 20): the grouped tucks are seen
        // from below too, and a group of one fold is "fold 13 of 13", not "folds 13-13".
        playback.pace(20);
        assertCaptionsSeenFromBelowOnlyFromBelow(scene, playback);
        boolean groupedTuck = false;
        for (int k = 0; k <= 2000; k++) {
            String caption = playback.describe(playback.halfTurn() * k / 2000);
            assertFalse(caption.matches(".*folds (\\d+)\u2013\\1 of.*"), caption);
            groupedTuck |= caption.startsWith("tuck") && caption.endsWith("(seen from below)");
        }
        assertTrue(groupedTuck, "check the setup: a grouped tuck's caption");
    }

    /** While a caption says "seen from below", the camera is below the triangle (in z = 0, its normal +z), at every moment. */
    private static void assertCaptionsSeenFromBelowOnlyFromBelow(Scene scene, WrapPlayback playback) {
        org.joml.Vector3d eye = new org.joml.Vector3d();
        int below = 0;
        for (int k = 0; k <= 2000; k++) {
            double position = playback.halfTurn() * k / 2000;
            playback.apply(position);
            String caption = playback.describe(position);
            if (caption.endsWith("(seen from below)")) {
                below++;
                double height = scene.camera().eye(eye).z;
                assertTrue(height < 0, "at " + position + " the caption says \"" + caption + "\" and the camera is at height " + height);
            }
        }
        assertTrue(below > 0, "check the setup: some moments are captioned as seen from below");
    }
}
