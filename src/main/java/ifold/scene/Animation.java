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
     * valley (else a mountain) seen from the side {@code seenFrom} points to (a unit vector; null:
     * from wherever the panel looks, as a fold script says it). A diagram draws a valley seen from
     * the other side as a mountain.
     */
    record FoldLine(double[] from, double[] to, boolean valley, double[] seenFrom) {
        /** Whether it is a valley seen by an eye looking along {@code looking}. */
        public boolean valleyLookingAlong(double[] looking) {
            if (seenFrom == null) {
                return valley;
            }
            double along = seenFrom[0] * looking[0] + seenFrom[1] * looking[1] + seenFrom[2] * looking[2];
            return along > 0 ? !valley : valley;
        }
    }

    /** See {@link FoldLine}. */
    default FoldLine foldLine(int k) {
        return null;
    }

    /**
     * Whether "fold" {@code k} is many folds together (a wrap's triangle, its passes, gadgets and
     * tucks): its panel shows them made, not about to be.
     */
    default boolean foldIsGroup(int k) {
        return false;
    }

    /**
     * What panel {@code k} is called: the number of the crease it folds as the printed crease
     * pattern numbers it (its steps' numbers unless it says otherwise); blank for a step that
     * folds nothing.
     */
    default String foldLabel(int k) {
        return Integer.toString(k + 1);
    }

    /** How many points a {@link #foldPath} has. */
    int PATH_POINTS = 9;

    /**
     * The way a point of fold {@code k}'s flap travels, in space: where it lies before the fold,
     * points along its swing, where it lands; for the panel's arrow. Null where the animation does
     * not say (a step of many folds).
     */
    default double[][] foldPath(int k) {
        return null;
    }

    /** Fold {@code k}'s caption for its panel: what the animation says half way through it. */
    default String foldCaption(int k) {
        return describe((foldStart(k) + foldStart(k + 1)) / 2);
    }
}
