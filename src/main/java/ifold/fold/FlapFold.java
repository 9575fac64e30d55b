package ifold.fold;

/**
 * A fold of one flap: the crease is a line on the unfolded sheet, in paper coordinates, and only
 * the paper on the moving side of that line turns, wherever it lies now. On a strip this is the
 * strip's tail beyond the crease, however many layers lie under or over the crease; a
 * {@link Fold} through all layers would catch them too. The crease must cross paper that lies
 * flat where it runs (the tail being laid is one rigid piece).
 *
 * @param kind valley (the flap turns up, towards the sheet's top normal as it lies in space) or
 *     mountain (down)
 * @param angleDegrees how far the flap turns, in (0, 180]
 * @param u1 paper coordinate u of the crease line's first point
 * @param v1 paper coordinate v of the first point
 * @param u2 paper coordinate u of the second point
 * @param v2 paper coordinate v of the second point
 * @param moving which side of the line moves, on the unfolded sheet seen from its top with the
 *     line running from the first point to the second
 */
public record FlapFold(Fold.Kind kind, double angleDegrees, double u1, double v1, double u2, double v2, Fold.Side moving) {
}
