package ifold.job;

import ifold.mesh.HalfedgeMesh;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The Hamiltonian refinement of a model's mesh, as {@code ifold refine} and the window's View a
 * model (its refinement and path) both make it: the triangles on one path, prepared first where
 * asked (as the wrap prepares its faces), and the counts and angles both report.
 */
public final class RefineJob {
    private RefineJob() {
    }

    /**
     * A mesh refined.
     *
     * @param mesh the mesh refined
     * @param prepared its faces prepared and refined, where preparing was asked; null otherwise
     * @param refinement the refinement: the path's triangles
     */
    public record Outcome(HalfedgeMesh mesh, WrapPath prepared, HamiltonianRefinement.Result refinement) {
        /**
         * The figures both report: {@code inputTriangles}, {@code preparation} where prepared,
         * {@code components}, {@code outputTriangles}, {@code outputVertices} and the smallest
         * angles in and out.
         */
        public Map<String, Object> figures() {
            Map<String, Object> figures = new LinkedHashMap<>();
            figures.put("inputTriangles", mesh.faceCount());
            if (prepared != null) {
                figures.put("preparation", prepared.figures());
            }
            figures.put("components", refinement.componentCount());
            figures.put("outputTriangles", refinement.mesh().faceCount());
            figures.put("outputVertices", refinement.mesh().vertexCount());
            figures.put("minAngleInDegrees", minAngleIn());
            figures.put("minAngleOutDegrees", minAngleOut());
            return figures;
        }

        /** The smallest angle of the mesh's triangles, in degrees. */
        public double minAngleIn() {
            return RefinementClaims.minAngleDegrees(mesh);
        }

        /** The smallest angle of the path's triangles, in degrees. */
        public double minAngleOut() {
            return RefinementClaims.minAngleDegrees(refinement.mesh());
        }
    }

    /** Refines {@code mesh} (triangles), preparing its faces first where {@code prepare} says. */
    public static Outcome run(HalfedgeMesh mesh, boolean prepare) {
        WrapPath path = prepare ? WrapPath.prepared(mesh) : null;
        return new Outcome(mesh, path, path != null ? path.refinement() : HamiltonianRefinement.refine(mesh));
    }
}
