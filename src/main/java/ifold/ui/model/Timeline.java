package ifold.ui.model;

import java.util.List;

/**
 * Where the animation stands and how it plays: a position from 0 to the animation's
 * {@code stepCount}, playing or paused, at a speed; the folds it steps between. Plain state,
 * owned by the window's event thread; the view is told the position and shows it.
 */
public final class Timeline {
    /** The speeds offered, as multiples of the command line's default length. */
    public static final double[] SPEEDS = {0.25, 0.5, 1, 2, 4, 8};

    private final double end;
    private final List<Fold> folds;
    private final double seconds;
    private double position;
    private boolean playing;
    private double speed = 1;

    /**
     * @param end the animation's length, in its steps
     * @param folds the folds, in order, with the positions at which each begins
     * @param seconds how long the whole plays at speed 1
     */
    public Timeline(double end, List<Fold> folds, double seconds) {
        if (!(end >= 0) || !(seconds > 0)) {
            throw new IllegalArgumentException("a timeline needs a length of 0 or more and seconds above 0, got " + end + ", " + seconds);
        }
        this.end = end;
        this.folds = List.copyOf(folds);
        this.seconds = seconds;
    }

    /** The timeline of a plan, at its start. */
    public static Timeline of(Plan plan) {
        return new Timeline(plan.stepCount(), plan.folds(), plan.seconds());
    }

    public double end() {
        return end;
    }

    public List<Fold> folds() {
        return folds;
    }

    public double position() {
        return position;
    }

    public boolean isPlaying() {
        return playing;
    }

    public double speed() {
        return speed;
    }

    public void setSpeed(double speed) {
        if (!(speed > 0) || !Double.isFinite(speed)) {
            throw new IllegalArgumentException("the speed must be above 0, got " + speed);
        }
        this.speed = speed;
    }

    /** Moves to {@code newPosition}, kept between 0 and the end; playing goes on from there. */
    public void seek(double newPosition) {
        position = Math.max(0, Math.min(end, newPosition));
    }

    /** Plays or pauses; playing again once at the end starts from the beginning. */
    public void togglePlaying() {
        if (!playing && position >= end) {
            position = 0;
        }
        playing = !playing;
    }

    public void pause() {
        playing = false;
    }

    /**
     * Moves on by {@code elapsed} seconds of play, if playing; stops at the end.
     *
     * @return whether the position moved
     */
    public boolean advance(double elapsed) {
        if (!playing) {
            return false;
        }
        double before = position;
        seek(position + elapsed * speed * end / seconds);
        if (position >= end) {
            playing = false;
        }
        return position != before;
    }

    /**
     * Pauses and moves a fold forward or back: to the positions at which folds begin (so that
     * a step forward makes one fold), the start and the end.
     */
    public void stepFold(int direction) {
        playing = false;
        double tolerance = 1e-9 * Math.max(1, end);
        if (direction > 0) {
            for (Fold fold : folds) {
                if (fold.position() > position + tolerance) {
                    position = fold.position();
                    return;
                }
            }
            position = end;
        } else if (direction < 0) {
            for (int i = folds.size() - 1; i >= 0; i--) {
                if (folds.get(i).position() < position - tolerance) {
                    position = folds.get(i).position();
                    return;
                }
            }
            position = 0;
        }
    }

    /** Pauses at the beginning of fold {@code index}: the folds before it made, and it next. */
    public void jumpTo(int index) {
        playing = false;
        seek(folds.get(index).position());
    }

    /** The fold under way (or next) at this position: the last that has begun; -1 before the first. */
    public int currentFold() {
        double tolerance = 1e-9 * Math.max(1, end);
        int low = 0;
        int high = folds.size() - 1;
        int found = -1;
        while (low <= high) { // folds are in order of position: a binary search serves a wrap of 100,000 folds
            int mid = (low + high) >>> 1;
            if (folds.get(mid).position() <= position + tolerance) {
                found = mid;
                low = mid + 1;
            } else {
                high = mid - 1;
            }
        }
        return found;
    }
}
