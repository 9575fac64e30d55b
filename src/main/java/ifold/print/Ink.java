package ifold.print;

/** How a line is drawn: what the paper does there. */
public enum Ink {
    /** The paper's outline: cut along it (solid). */
    CUT,
    /** A valley fold: dashed, blue. */
    VALLEY,
    /** A mountain fold: dash-dot-dot, red. */
    MOUNTAIN,
    /** An edge between faces that stays flat: faint grey, no fold. */
    FLAT,
    /** A glue tab's outline: dotted grey. */
    TAB,
    /** The scale bar and its ticks: solid black. */
    SCALE,
    /** A diagram's arrow (the motion of a fold, turn over): solid black, heavier. */
    ARROW
}
