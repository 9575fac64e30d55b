package ifold.zigzag;

import ifold.fold.FlapFold;
import ifold.fold.Fold;
import ifold.fold.FoldException;
import ifold.fold.Folder;
import ifold.fold.Paper;
import java.util.List;
import org.joml.Vector3d;

/**
 * The turn gadget (the seed, Figures 1 and 2): turns a strip by any angle θ in (0°, 180°) and
 * keeps its top side up, as wrapping the next triangle of a path needs. The strip runs along +x
 * (its band 0 &lt;= y &lt;= w in the plane z = 0); a valley fold across it at u = p lays it back
 * over itself, back up; a second valley fold, along a crease at (90° + θ/2) to the strip,
 * turns it again and sets it running at θ from +x, top up. Its crease crosses the strip from
 * paper point (p + X, 0) to (p + X + w·tan(θ/2), w): the overhang X is how far beyond the first
 * fold the second one begins. X = 0 is the basic gadget (Figure 1), the two creases touching at
 * the strip's edge; any X &gt; 0 the generalised one (Figure 2), which lets the turn's corner fall
 * where the next triangle needs it.
 */
public final class TurnGadget {
    private TurnGadget() {
    }

    /**
     * The gadget's folds.
     *
     * @param start the flat strip
     * @param folds the fold across, then the turn fold
     * @param folded the paper with both folds made
     * @param angle the turn asked, in degrees
     * @param overhang X
     * @param length the strip's length
     */
    public record Result(Paper start, List<Folder.Prepared> folds, Paper folded, double angle, double overhang, double length) {
        /**
         * The direction, in degrees from +x, in which the strip's end now runs, measured on the
         * folded paper: along the edge v = 0 of the face holding the strip's end.
         */
        public double measuredAngle() {
            Paper paper = folded;
            int[] face = paper.face(endFace(paper));
            int end = -1;
            int before = -1;
            for (int v : face) {
                if (paper.v(v) == 0 && paper.u(v) == length) {
                    end = v;
                } else if (paper.v(v) == 0 && (before < 0 || paper.u(v) < paper.u(before))) {
                    before = v;
                }
            }
            return Math.toDegrees(Math.atan2(paper.y(end) - paper.y(before), paper.x(end) - paper.x(before)));
        }

        /** Whether the strip's end lies top side up, as it came in. */
        public boolean endFacesUp() {
            Paper paper = folded;
            int[] face = paper.face(endFace(paper));
            Vector3d normal = new Vector3d();
            for (int i = 0; i < face.length; i++) {
                int a = face[i];
                int b = face[(i + 1) % face.length];
                normal.add((paper.y(a) - paper.y(b)) * (paper.z(a) + paper.z(b)),
                        (paper.z(a) - paper.z(b)) * (paper.x(a) + paper.x(b)),
                        (paper.x(a) - paper.x(b)) * (paper.y(a) + paper.y(b)));
            }
            return normal.dot(paper.normal()) > 0; // Newell's normal: faces run counter-clockwise on the sheet
        }

        /** The paper face that holds the strip's end edge (u = length, from v = 0). */
        private int endFace(Paper paper) {
            for (int f = 0; f < paper.faceCount(); f++) {
                if (paper.isCap(f)) {
                    continue;
                }
                for (int v : paper.face(f)) {
                    if (paper.v(v) == 0 && paper.u(v) == length) {
                        return f;
                    }
                }
            }
            throw new IllegalStateException("the strip's end is not on the paper");
        }
    }

    /**
     * Plans and makes the gadget on a strip of width {@code width} that runs {@code lead} before
     * the turn and {@code tail} after it.
     *
     * @throws IllegalArgumentException for an angle outside (0, 180), a negative overhang or a
     *     bad size
     */
    public static Result turn(double angleDegrees, double overhang, double width, double thickness, double lead, double tail)
            throws FoldException {
        if (!(angleDegrees > 0 && angleDegrees < 180)) {
            throw new IllegalArgumentException("the turn angle must be more than 0 and less than 180 degrees, got " + angleDegrees);
        }
        if (!(overhang >= 0) || !Double.isFinite(overhang)) {
            throw new IllegalArgumentException("the overhang must be zero or more, got " + overhang);
        }
        if (!(width > 0) || !(lead > 0) || !(tail > 0) || !Double.isFinite(width + lead + tail)) {
            throw new IllegalArgumentException("the strip needs a positive width and lengths");
        }
        double slant = width * Math.tan(Math.toRadians(angleDegrees / 2));
        double p = lead;
        double length = p + overhang + slant + tail;
        Paper start = Paper.strip(length, width, thickness);
        Folder.Prepared across = Folder.prepare(start,
                new FlapFold(Fold.Kind.VALLEY, 180, p, 0, p, width, Fold.Side.RIGHT));
        // Right of the crease from (p + X, 0) to (p + X + slant, w) is the side of larger u.
        Folder.Prepared turn = Folder.prepare(across.at(1),
                new FlapFold(Fold.Kind.VALLEY, 180, p + overhang, 0, p + overhang + slant, width, Fold.Side.RIGHT));
        return new Result(start, List.of(across, turn), turn.at(1), angleDegrees, overhang, length);
    }
}
