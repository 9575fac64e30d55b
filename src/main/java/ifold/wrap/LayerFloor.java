package ifold.wrap;

import ifold.mesh.IndexedPolygons;

/**
 * The fewest layers that any wrap of a surface by a strip must have somewhere, whatever the
 * strip's width and however it is folded: ⌈π / (2Θ)⌉, where Θ is the smallest sum of the face
 * angles about one vertex (a spike's apex). It shows which piles of layers no method can avoid,
 * and it bounds the analysis from below: a wrap that counts fewer layers has miscounted.
 *
 * <p>Why: a folding maps each face of paper onto the surface without stretching, so it moves no
 * two points of the paper farther apart on the surface than they were on the strip. Some point p
 * of the strip lands on the vertex V (the paper covers the surface, and the strip is compact).
 * The paper within a small r of p is at least a quarter disk, of area πr²/4 (p a corner of the
 * strip: for r under the strip's width), and it lands within r of V. Within r of V, for r under
 * V's distance to the edges of its faces that do not end at V, the surface is the faces' sectors
 * of radius r about V, of area Θr²/2. So the layers over that ball average at least
 * (πr²/4) / (Θr²/2) = π / (2Θ), and at some point they are at least that, rounded up. Where p is
 * on a side of the strip, not a corner, the bound doubles; inside the strip it doubles again.
 * Over one face alone (paper that near V stays on a face of angle θ, as a tuck along its edges
 * keeps it), Θ is that face's θ.
 *
 * @param vertex the vertex of the smallest angle sum, in the mesh measured
 * @param point its position
 * @param angleSum the sum of the angles of its faces at it, in radians
 * @param layers the floor, ⌈π / (2Θ)⌉ and at least 1
 */
public record LayerFloor(int vertex, double[] point, double angleSum, int layers) {

    /** The floor of {@code mesh}, a triangle mesh with at least one face. */
    public static LayerFloor of(IndexedPolygons mesh) {
        double[] sums = angleSums(mesh);
        int sharpest = -1;
        for (int v = 0; v < sums.length; v++) {
            if (!Double.isNaN(sums[v]) && (sharpest < 0 || sums[v] < sums[sharpest])) {
                sharpest = v;
            }
        }
        if (sharpest < 0) {
            throw new IllegalArgumentException("a surface without faces has no floor of layers");
        }
        double sum = sums[sharpest];
        // Rounded up, but a bound that is a whole number up to rounding (Θ = π/2) stays one.
        int layers = (int) Math.max(1, Math.ceil(Math.PI / (2 * sum) - 1e-9));
        return new LayerFloor(sharpest, new double[] {mesh.coordinate(sharpest, 0), mesh.coordinate(sharpest, 1), mesh.coordinate(sharpest, 2)}, sum, layers);
    }

    /** The sum of the face angles about each vertex of {@code mesh}, in radians; NaN at a vertex of no face. */
    static double[] angleSums(IndexedPolygons mesh) {
        double[] sums = new double[mesh.vertexCount()];
        java.util.Arrays.fill(sums, Double.NaN);
        for (int f = 0; f < mesh.faceCount(); f++) {
            int n = mesh.faceSize(f);
            for (int k = 0; k < n; k++) {
                int v = mesh.faceVertex(f, k);
                double angle = angle(mesh, v, mesh.faceVertex(f, (k + 1) % n), mesh.faceVertex(f, (k + n - 1) % n));
                sums[v] = Double.isNaN(sums[v]) ? angle : sums[v] + angle;
            }
        }
        return sums;
    }

    /**
     * Whether a vertex of angle sum {@code angleSum} (radians) is sharp: one where every strip
     * lays at least two layers, its sum under a right angle (a spike's apex; a cube's corner,
     * 270°, is not, nor a tetrahedron's, 180°).
     */
    static boolean sharp(double angleSum) {
        return angleSum < Math.PI / 2 * (1 - 1e-9); // the 30° spike's right angle, summed with rounding, is none
    }

    /** The angle at corner v between the edges to a and to b, in radians (a triangle's corner: at most π). */
    static double angle(IndexedPolygons mesh, int v, int a, int b) {
        double ux = mesh.coordinate(a, 0) - mesh.coordinate(v, 0);
        double uy = mesh.coordinate(a, 1) - mesh.coordinate(v, 1);
        double uz = mesh.coordinate(a, 2) - mesh.coordinate(v, 2);
        double vx = mesh.coordinate(b, 0) - mesh.coordinate(v, 0);
        double vy = mesh.coordinate(b, 1) - mesh.coordinate(v, 1);
        double vz = mesh.coordinate(b, 2) - mesh.coordinate(v, 2);
        double cx = uy * vz - uz * vy;
        double cy = uz * vx - ux * vz;
        double cz = ux * vy - uy * vx;
        // atan2 of the cross and dot products: exact for the needle-sharp corners this is for,
        // where acos of the dot product loses half the digits.
        return Math.atan2(Math.sqrt(cx * cx + cy * cy + cz * cz), ux * vx + uy * vy + uz * vz);
    }
}
