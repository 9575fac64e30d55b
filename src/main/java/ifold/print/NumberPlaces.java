package ifold.print;

import java.util.ArrayList;
import java.util.List;

/**
 * Where the numbers of creases go on a piece, none over another: each beside its crease, at its
 * middle where that is free, else further along it, else on its other side. Creases that meet
 * (a pass's two turn folds, a gadget's folds side by side) would otherwise print "3059" for
 * 30 and 59.
 */
final class NumberPlaces {
    /** Where along its crease a number may go, best first. */
    private static final double[] ALONG = {0.5, 0.35, 0.65, 0.2, 0.8, 0.1, 0.9};
    /** Room kept between two numbers, and between a number and its crease, in millimetres. */
    private static final double GAP = 0.4;
    /** A digit's width, as a share of the text's size (Helvetica's digits are 0.556 em). */
    private static final double DIGIT = 0.56;
    /** Capitals' and digits' height, as a share of the text's size. */
    private static final double CAP = 0.72;

    private final double left;
    private final double top;
    private final double right;
    private final double bottom;
    private final double size;
    private final List<double[]> taken = new ArrayList<>();

    /** Numbers {@code size} mm high, within the rectangle (left, top) to (right, bottom). */
    NumberPlaces(double left, double top, double right, double bottom, double size) {
        this.left = left;
        this.top = top;
        this.right = right;
        this.bottom = bottom;
        this.size = size;
    }

    /**
     * The baseline's start for {@code text} beside the crease (ax, ay) to (bx, by), clear of it:
     * the first place free of the numbers placed so far and inside the rectangle, to the
     * crease's right first (above a crease drawn left to right), then its left; where none is,
     * beside its middle, moved inside the rectangle.
     */
    double[] place(String text, double ax, double ay, double bx, double by) {
        double halfWidth = DIGIT * size * text.length() / 2;
        double halfHeight = CAP * size / 2;
        double length = Math.hypot(bx - ax, by - ay);
        double nx = length > 0 ? (by - ay) / length : 1;
        double ny = length > 0 ? -(bx - ax) / length : 0;
        // How far the box's centre stands off the line so that its nearest corner clears it.
        double off = Math.abs(nx) * halfWidth + Math.abs(ny) * halfHeight + GAP;
        for (int side = 1; side >= -1; side -= 2) {
            for (double t : ALONG) {
                double cx = ax + t * (bx - ax) + side * nx * off;
                double cy = ay + t * (by - ay) + side * ny * off;
                double[] box = {cx - halfWidth, cy - halfHeight, cx + halfWidth, cy + halfHeight};
                if (inside(box) && free(box)) {
                    taken.add(box);
                    return new double[] {box[0], box[3]};
                }
            }
        }
        double cx = Math.max(left + halfWidth, Math.min(right - halfWidth, (ax + bx) / 2 + nx * off));
        double cy = Math.max(top + halfHeight, Math.min(bottom - halfHeight, (ay + by) / 2 + ny * off));
        double[] box = {cx - halfWidth, cy - halfHeight, cx + halfWidth, cy + halfHeight};
        taken.add(box);
        return new double[] {box[0], box[3]};
    }

    private boolean inside(double[] box) {
        return box[0] >= left && box[2] <= right && box[1] >= top && box[3] <= bottom;
    }

    private boolean free(double[] box) {
        for (double[] other : taken) {
            if (box[0] < other[2] + GAP && other[0] < box[2] + GAP && box[1] < other[3] + GAP && other[1] < box[3] + GAP) {
                return false;
            }
        }
        return true;
    }
}
