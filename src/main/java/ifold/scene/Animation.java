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

    /** How many folds it shows one after another, for step diagrams (a panel a fold): its steps unless it says otherwise. */
    default int foldCount() {
        return stepCount();
    }

    /** The position at which fold {@code k} (from 0) begins; {@code foldStart(foldCount())} is where the last has ended. */
    default double foldStart(int k) {
        return k;
    }

    /**
     * Fold {@code k}'s crease in space, for its panel: from x, y, z to x, y, z, and whether it is a
     * valley seen from the paper's top side (else a mountain); null where the animation does not
     * say.
     */
    record FoldLine(double[] from, double[] to, boolean valley) {
    }

    /** See {@link FoldLine}. */
    default FoldLine foldLine(int k) {
        return null;
    }

    /** Fold {@code k}'s caption for its panel: what the animation says half way through it. */
    default String foldCaption(int k) {
        return describe((foldStart(k) + foldStart(k + 1)) / 2);
    }
}
