package ifold.ui.model;

/**
 * One fold of a result, for the timeline's list.
 *
 * @param name what it does, as the captions say it ("pass 2 of 5: turn, 45° valley fold")
 * @param kind its kind ("zig-zag turn", "tuck", "valley", ...)
 * @param position the animation's position where it begins: the folds before it made, itself not yet
 */
public record Fold(String name, String kind, double position) {
}
