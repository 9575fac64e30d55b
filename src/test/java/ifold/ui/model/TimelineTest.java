package ifold.ui.model;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The timeline: seeking, playing at a speed, stepping from fold to fold. */
class TimelineTest {
    /** Three folds beginning at 10, 20 and 30 of an animation 50 long that plays in 5 seconds. */
    private static Timeline threeFolds() {
        return new Timeline(50, List.of(new Fold("one", "tuck", 10), new Fold("two", "tuck", 20), new Fold("three", "tuck", 30)), 5);
    }

    @Test
    void stepsGoFromFoldToFoldAndPause() {
        Timeline timeline = threeFolds();
        assertEquals(-1, timeline.currentFold(), "setup: no fold begun at the start");
        timeline.togglePlaying();
        timeline.stepFold(1);
        assertFalse(timeline.isPlaying(), "a step pauses");
        assertEquals(10, timeline.position());
        assertEquals(0, timeline.currentFold());
        timeline.stepFold(1);
        timeline.stepFold(1);
        timeline.stepFold(1);
        assertEquals(50, timeline.position(), "after the last fold, the end");
        timeline.stepFold(-1);
        assertEquals(30, timeline.position());
        timeline.seek(25);
        assertEquals(1, timeline.currentFold());
        timeline.stepFold(-1);
        assertEquals(20, timeline.position(), "back from between folds: to the fold before");
        timeline.stepFold(-1);
        timeline.stepFold(-1);
        assertEquals(0, timeline.position());
    }

    @Test
    void playingMovesWithTheClockAndTheSpeedAndStopsAtTheEnd() {
        Timeline timeline = threeFolds();
        assertFalse(timeline.advance(1), "paused: nothing moves");
        timeline.togglePlaying();
        assertTrue(timeline.advance(1));
        assertEquals(10, timeline.position(), 1e-12, "a fifth of the length a second");
        timeline.setSpeed(2);
        timeline.advance(1);
        assertEquals(30, timeline.position(), 1e-12);
        timeline.advance(10);
        assertEquals(50, timeline.position());
        assertFalse(timeline.isPlaying(), "stopped at the end");
        timeline.togglePlaying();
        assertEquals(0, timeline.position(), "playing again from the end starts over");
        assertThrows(IllegalArgumentException.class, () -> timeline.setSpeed(0));
    }

    @Test
    void seekingStaysInsideAndJumpingShowsTheFoldMade() {
        Timeline timeline = threeFolds();
        timeline.seek(-4);
        assertEquals(0, timeline.position());
        timeline.seek(99);
        assertEquals(50, timeline.position());
        timeline.jumpTo(1);
        assertEquals(20, timeline.position());
        assertEquals(1, timeline.currentFold());
    }
}
