package ifold.job;

import ifold.mesh.HalfedgeMesh;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import ifold.wrap.Wrap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The path a wrap follows, as both front ends make it: the Hamiltonian refinement of the model's
 * faces, prepared into well-shaped triangles first ({@link FacePreparation}) where that is
 * likely to make less paper. The paper lies flat across the triangles of a convex face (one host,
 * {@link Wrap}), so a long thin face needs no preparation for its tucks; but slivers set a narrow
 * strip, and then the prepared triangles take a wider one.
 *
 * @param preparation what the preparation did (its mesh is the model's where nothing was prepared)
 * @param refinement the refinement the strip follows: of the prepared mesh, or of the model's own
 * @param prepared whether the refinement is of the prepared mesh; false where the preparation
 *     changed nothing, or the model's own triangles are likely to make fewer faces
 */
public record WrapPath(FacePreparation.Result preparation, HamiltonianRefinement.Result refinement, boolean prepared) {
    /** Prepares and refines {@code mesh}, a valid triangle mesh, and follows whichever path is likely to make fewer faces. */
    public static WrapPath of(HalfedgeMesh mesh) {
        FacePreparation.Result preparation = FacePreparation.prepare(mesh);
        HamiltonianRefinement.Result refined = HamiltonianRefinement.refine(preparation.mesh());
        if (preparation.prepared() == 0) {
            return new WrapPath(preparation, refined, false);
        }
        HamiltonianRefinement.Result own = HamiltonianRefinement.refine(mesh);
        return Wrap.likelyFaces(own) <= Wrap.likelyFaces(refined) ? new WrapPath(preparation, own, false)
                : new WrapPath(preparation, refined, true);
    }

    /** Prepares and refines {@code mesh}, following the prepared path whatever it costs ({@code refine --prepare}). */
    public static WrapPath prepared(HalfedgeMesh mesh) {
        FacePreparation.Result preparation = FacePreparation.prepare(mesh);
        return new WrapPath(preparation, HamiltonianRefinement.refine(preparation.mesh()), preparation.prepared() > 0);
    }

    /**
     * Why the model's faces were kept as they are although some needed preparing, in one line
     * naming {@code model}; null where they were prepared or needed none.
     */
    public String keptNote(String model) {
        return preparation.kept() != null ? model + ": faces kept as they are, not prepared: " + preparation.kept() : null;
    }

    /** The report's figures of the preparation: regions, triangles, and the smallest angles of the model, the prepared faces and the path, in degrees. */
    public Map<String, Object> figures() {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("planarRegions", preparation.regions());
        figures.put("preparedRegions", preparation.prepared());
        figures.put("used", prepared);
        figures.put("trianglesBefore", preparation.trianglesBefore());
        figures.put("trianglesAfter", preparation.trianglesAfter());
        figures.put("targetAngle", FacePreparation.TARGET_ANGLE);
        Map<String, Object> angles = new LinkedHashMap<>();
        angles.put("input", preparation.minAngleBefore());
        angles.put("prepared", preparation.minAngleAfter());
        angles.put("path", RefinementClaims.minAngleDegrees(refinement.mesh()));
        figures.put("minAngles", angles);
        if (preparation.kept() != null) {
            figures.put("kept", preparation.kept());
        }
        return figures;
    }
}
