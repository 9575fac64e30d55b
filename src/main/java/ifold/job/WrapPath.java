package ifold.job;

import ifold.mesh.HalfedgeMesh;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import java.io.PrintWriter;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The path a wrap follows, as both front ends make it: the model's faces prepared into
 * well-shaped triangles ({@link FacePreparation}), then the Hamiltonian refinement of those.
 *
 * @param preparation what the preparation did (its mesh is the model's where nothing was prepared)
 * @param refinement the refinement of the prepared mesh, whose path the strip follows
 */
public record WrapPath(FacePreparation.Result preparation, HamiltonianRefinement.Result refinement) {
    /** Prepares and refines {@code mesh}, a valid triangle mesh. */
    public static WrapPath of(HalfedgeMesh mesh) {
        FacePreparation.Result preparation = FacePreparation.prepare(mesh);
        return new WrapPath(preparation, HamiltonianRefinement.refine(preparation.mesh()));
    }

    /**
     * Says on {@code err}, in one line naming {@code model}, why the model's faces were kept as
     * they are although some needed preparing; says nothing where they were prepared or needed none.
     */
    public void warnIfKept(String model, PrintWriter err) {
        if (preparation.kept() != null) {
            err.println("ifold: " + model + ": faces kept as they are, not prepared: " + preparation.kept());
            err.flush();
        }
    }

    /** The report's figures of the preparation: regions, triangles, and the smallest angles of the model, the prepared faces and the path, in degrees. */
    public Map<String, Object> figures() {
        Map<String, Object> figures = new LinkedHashMap<>();
        figures.put("planarRegions", preparation.regions());
        figures.put("preparedRegions", preparation.prepared());
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
