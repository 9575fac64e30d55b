package ifold.sheet;

/**
 * What a tuck did.
 *
 * @param host the host whose paper was tucked
 * @param moved the faces that turned under (after cutting)
 * @param px a point of the tuck line, in the host's frame
 * @param py its y
 * @param dx the line's direction; the paper on its right turned
 * @param dy its y
 * @param facesBefore the faces of the sheet before the tuck: those from it on were cut off by it
 * @param changed the faces that were there before and were cut or moved
 * @param loopsBefore their loops before the tuck
 * @param posesBefore their poses before the tuck
 */
public record Tuck(int host, int[] moved, double px, double py, double dx, double dy, int facesBefore, int[] changed,
        int[][] loopsBefore, Isometry2[] posesBefore) {
}
