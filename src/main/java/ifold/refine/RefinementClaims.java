package ifold.refine;

import ifold.geom.Tolerance;
import ifold.geom.Triangles;
import ifold.mesh.HalfedgeMesh;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * Checks what the Hamiltonian refinement promises, independently of how it was computed, and
 * measures its angles. Used by the tests on every model and by {@code ifold refine --json}.
 */
public final class RefinementClaims {
    private RefinementClaims() {
    }

    /** The smallest angle over all faces of a triangle mesh, in degrees. */
    public static double minAngleDegrees(HalfedgeMesh mesh) {
        double[] xyz = mesh.positionArray();
        double min = Math.PI;
        for (int f = 0; f < mesh.faceCount(); f++) {
            int h = mesh.faceHalfedge(f);
            min = Math.min(min, Triangles.minAngle(xyz, mesh.fromVertex(h), mesh.toVertex(h), mesh.toVertex(mesh.next(h))));
        }
        return Math.toDegrees(min);
    }

    /** The smallest angle over all refined triangles, in degrees. */
    public static double minAngleDegrees(RefinedMesh mesh) {
        double[] corners = new double[9];
        double min = Math.PI;
        for (int t = 0; t < mesh.faceCount(); t++) {
            for (int k = 0; k < 3; k++) {
                int v = mesh.faceVertex(t, k);
                for (int axis = 0; axis < 3; axis++) {
                    corners[3 * k + axis] = mesh.coordinate(v, axis);
                }
            }
            min = Math.min(min, Triangles.minAngle(corners, 0, 1, 2));
        }
        return Math.toDegrees(min);
    }

    /** All vertex positions of {@code mesh}, interleaved, for the measures of {@link Triangles}. */
    private static double[] positions(RefinedMesh mesh) {
        double[] xyz = new double[3 * mesh.vertexCount()];
        for (int v = 0; v < mesh.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                xyz[3 * v + axis] = mesh.coordinate(v, axis);
            }
        }
        return xyz;
    }

    /**
     * Every claim of the refinement that {@code result} breaks for {@code input}, as sentences;
     * empty when all hold: 5n - 2c triangles; consecutive triangles of a component share an
     * edge; no triangle twice; each parent covered by its sub-triangles with its area; the
     * original vertices kept in place; the smallest angle at least half the input's.
     */
    public static List<String> violations(HalfedgeMesh input, HamiltonianRefinement.Result result) {
        List<String> problems = new ArrayList<>();
        int n = input.faceCount();
        int c = result.componentCount();
        int count = result.mesh().faceCount();
        if (count != 5 * n - 2 * c) {
            problems.add(count + " triangles, expected 5n - 2c = " + (5 * n - 2 * c));
        }
        if (!addPathViolations(input, result, problems)) {
            return problems;
        }
        double in = minAngleDegrees(input);
        double out = minAngleDegrees(result.mesh());
        // Half the input's angle is reached exactly at the corners, so allow rounding only.
        if (out < in / 2 * (1 - 1e-9)) {
            problems.add("smallest angle " + out + " degrees is less than half the input's " + in);
        }
        return problems;
    }

    /**
     * Every claim that any path of triangles through {@code input} makes and {@code result}
     * breaks, as sentences (the refinement's, or the path through its own triangles,
     * {@link CycleCoverPath}): consecutive triangles of a component share an edge; no triangle
     * twice; each face covered by the path's triangles within it, with its area; the original
     * vertices kept in place.
     */
    public static List<String> pathViolations(HalfedgeMesh input, HamiltonianRefinement.Result result) {
        List<String> problems = new ArrayList<>();
        addPathViolations(input, result, problems);
        return problems;
    }

    /** Adds {@link #pathViolations} to {@code problems}; false where the path is of another model, its faces not to be compared. */
    private static boolean addPathViolations(HalfedgeMesh input, HamiltonianRefinement.Result result, List<String> problems) {
        RefinedMesh refined = result.mesh();
        int n = input.faceCount();
        int c = result.componentCount();
        int count = refined.faceCount();
        HalfedgeMesh refinedFrom = refined.original();
        if (refinedFrom.faceCount() != n || refinedFrom.vertexCount() != input.vertexCount()) {
            // The claims below compare each face with its sub-triangles: on another model they cannot be read.
            problems.add("the refinement is of another model: " + refinedFrom.faceCount() + " faces and " + refinedFrom.vertexCount()
                    + " vertices, not " + n + " and " + input.vertexCount());
            return false;
        }
        int[] tri = new int[3 * count];
        for (int t = 0; t < count; t++) {
            for (int k = 0; k < 3; k++) {
                tri[3 * t + k] = refined.faceVertex(t, k);
            }
        }
        int[] componentStart = result.componentStart();
        for (int k = 0; k < c; k++) {
            for (int t = componentStart[k]; t + 1 < componentStart[k + 1]; t++) {
                if (sharedVertices(tri, t, t + 1) != 2) {
                    problems.add("triangles " + t + " and " + (t + 1) + " of the path share no edge");
                    break;
                }
            }
        }
        long[] keys = new long[count];
        for (int t = 0; t < count; t++) {
            int[] sorted = {tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]};
            Arrays.sort(sorted);
            keys[t] = ((long) sorted[0] * 0x1F1F1F1FL + sorted[1]) * 0x3C3C3C3CL + sorted[2];
        }
        Arrays.sort(keys);
        for (int i = 1; i < count; i++) {
            if (keys[i] == keys[i - 1]) {
                problems.add("a triangle appears twice in the path");
                break;
            }
        }
        double[] xyzIn = input.positionArray();
        double[] xyzOut = positions(refined);
        double[] areaOut = new double[n];
        for (int t = 0; t < count; t++) {
            areaOut[refined.parentFace(t)] += Triangles.twiceArea(xyzOut, tri[3 * t], tri[3 * t + 1], tri[3 * t + 2]);
        }
        double totalIn = 0;
        double totalOut = 0;
        for (int f = 0; f < n; f++) {
            int h = input.faceHalfedge(f);
            double areaIn = Triangles.twiceArea(xyzIn, input.fromVertex(h), input.toVertex(h), input.toVertex(input.next(h)));
            totalIn += areaIn;
            totalOut += areaOut[f];
            if (Math.abs(areaIn - areaOut[f]) > Tolerance.RELATIVE_EQUALITY * areaIn) {
                problems.add("face " + f + " has area " + areaIn / 2 + " but its sub-triangles " + areaOut[f] / 2);
                break;
            }
        }
        if (Math.abs(totalIn - totalOut) > Tolerance.RELATIVE_EQUALITY * totalIn) {
            problems.add("total area " + totalIn / 2 + " became " + totalOut / 2);
        }
        for (int i = 0; i < 3 * input.vertexCount(); i++) {
            if (xyzIn[i] != xyzOut[i]) {
                problems.add("original vertex " + i / 3 + " moved or was lost");
                break;
            }
        }
        return true;
    }

    private static int sharedVertices(int[] tri, int s, int t) {
        int shared = 0;
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                if (tri[3 * s + i] == tri[3 * t + j]) {
                    shared++;
                }
            }
        }
        return shared;
    }
}
