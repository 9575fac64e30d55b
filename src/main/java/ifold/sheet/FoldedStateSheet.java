package ifold.sheet;

/**
 * A sheet whose folded state is given whole rather than folded here, as a FOLD file of another
 * tool gives it: paper of any outline, its faces already cut, each on its host where its pose
 * puts it, stacked in a given order. The same {@link Sheet} the folds make, so that everything
 * that reads a folded sheet (the paper in space, its FOLD file, its checks) reads this one.
 */
public final class FoldedStateSheet {
    private FoldedStateSheet() {
    }

    /**
     * The sheet.
     *
     * @param uv each vertex's paper coordinates (u, v pairs)
     * @param loops each face's vertices, counter-clockwise on the paper
     * @param hosts each face's host
     * @param poses each face's pose on its host
     * @param bottomUp every face once, in the order they are laid: each lands over the faces laid
     *     before it that it overlaps on its host; the sheet numbers them in this order
     * @param creases the paper edges folded, as vertex pairs (a, b)
     * @param creaseFolds for each crease, the fold that made it (from 0): the order to fold it back in
     * @param thickness the paper's
     * @param tolerance lengths below it are nothing
     */
    public static Sheet of(double[] uv, int[][] loops, int[] hosts, Isometry2[] poses, int[] bottomUp, int[][] creases, int[] creaseFolds,
            double thickness, double tolerance) {
        double[] box = Polygons2.bounds(uv);
        Sheet sheet = new Sheet(box[3] - box[1], thickness, tolerance, 0, Isometry2.IDENTITY);
        // A strip's constructor makes the two corners of its tail: a folded state has no tail.
        sheet.vertexCount = 0;
        sheet.tailA = -1;
        sheet.tailB = -1;
        sheet.length = box[2] - box[0];
        for (int i = 0; i < uv.length; i += 2) {
            sheet.addVertex(uv[i], uv[i + 1]);
        }
        // The sheet numbers its faces as they are laid: face bottomUp[k] becomes face k
        // ({@link #faceNumbers}).
        for (int f : bottomUp) {
            sheet.landing.addFace(loops[f], hosts[f], poses[f], Sheet.Placement.OVER, -1);
        }
        for (int c = 0; c < creases.length; c++) {
            sheet.creases.put(Sheet.undirected(creases[c][0], creases[c][1]), Sheet.Crease.FOLD.ordinal() + Sheet.CREASES.length * creaseFolds[c]);
        }
        sheet.creasingFolds = 0;
        for (int fold : creaseFolds) {
            sheet.creasingFolds = Math.max(sheet.creasingFolds, fold + 1);
        }
        return sheet;
    }

    /** The face number the sheet gives face {@code f} of {@code bottomUp}'s numbering: its place in that order. */
    public static int[] faceNumbers(int[] bottomUp) {
        int[] number = new int[bottomUp.length];
        for (int k = 0; k < bottomUp.length; k++) {
            number[bottomUp[k]] = k;
        }
        return number;
    }
}
