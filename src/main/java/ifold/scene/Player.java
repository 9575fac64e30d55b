package ifold.scene;

/**
 * Plays an {@link Animation}: play and pause, step forward and back, restart; advances with
 * the wall clock at a speed that plays the whole animation in {@code seconds}.
 */
public final class Player {
    private final Animation animation;
    private final double stepsPerSecond;
    private double position;
    private boolean playing;

    public Player(Animation animation, double seconds) {
        if (!(seconds > 0)) {
            throw new IllegalArgumentException("seconds must be positive");
        }
        this.animation = animation;
        this.stepsPerSecond = animation.stepCount() / seconds;
        animation.apply(0);
    }

    public Animation animation() {
        return animation;
    }

    public double position() {
        return position;
    }

    public boolean isPlaying() {
        return playing;
    }

    public void togglePlaying() {
        if (!playing && position >= animation.stepCount()) {
            seek(0); // play again from the start once at the end
        }
        playing = !playing;
    }

    /** Moves on by {@code seconds} of play, if playing; stops at the end. */
    public void advance(double seconds) {
        if (playing) {
            seek(position + seconds * stepsPerSecond);
            if (position >= animation.stepCount()) {
                playing = false;
            }
        }
    }

    /** Steps by {@code count} steps (back when negative), pausing the play; big animations step by 1 % at a time. */
    public void step(int count) {
        playing = false;
        int stride = Math.max(1, animation.stepCount() / 100);
        seek(position + (double) count * stride); // equal steps from wherever it stands
    }

    public void restart() {
        seek(0);
    }

    public void seek(double newPosition) {
        position = Math.max(0, Math.min(animation.stepCount(), newPosition));
        animation.apply(position);
    }

    public String describe() {
        return animation.describe(position) + (playing ? " (playing)" : "");
    }
}
