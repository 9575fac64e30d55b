package ifold.scene;

/**
 * Something that changes the scene over a number of steps: the path revealed triangle by
 * triangle, a fold swinging shut, a camera turning. Positions are continuous, in steps, from 0
 * (the start) to {@link #stepCount()} (the end).
 */
public interface Animation {
    int stepCount();

    /** Shows the scene at {@code position}, between 0 and {@link #stepCount()}. */
    void apply(double position);

    /** A line for the status bar: what the animation is showing at {@code position}. */
    default String describe(double position) {
        return "step " + (int) Math.floor(position) + " of " + stepCount();
    }
}
