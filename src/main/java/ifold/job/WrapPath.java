package ifold.job;

import ifold.mesh.GridSquares;
import ifold.mesh.HalfedgeMesh;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import ifold.wrap.HingeTour;
import ifold.wrap.Wrap;
import java.util.LinkedHashMap;
import java.util.Map;

/**
 * The path a wrap follows, as both front ends make it. The zig-zag's: the Hamiltonian refinement of the model's
 * faces, prepared into well-shaped triangles first ({@link FacePreparation}) where that is
 * likely to make less paper. The paper lies flat across the triangles of a convex face (one host,
 * {@link Wrap}), so a long thin face needs no preparation for its tucks; but slivers set a narrow
 * strip, and then the prepared triangles take a wider one. The hinge strip's: the tour of a grid
 * polyhedron's squares ({@link HingeTour}).
 *
 * @param preparation what the preparation did (its mesh is the model's where nothing was prepared)
 * @param refinement the refinement the strip follows: of the prepared mesh, or of the model's own
 * @param prepared whether the refinement is of the prepared mesh; false where the preparation
 *     changed nothing, or the model's own triangles are likely to make fewer faces
 * @param squares the hinge strip's squares; null for the zig-zag (whose preparation and refinement are null for the hinge strip)
 * @param tour the hinge strip's tour of them
 */
public record WrapPath(FacePreparation.Result preparation, HamiltonianRefinement.Result refinement, boolean prepared,
        GridSquares squares, HingeTour tour) {
    /** The zig-zag's path. */
    public WrapPath(FacePreparation.Result preparation, HamiltonianRefinement.Result refinement, boolean prepared) {
        this(preparation, refinement, prepared, null, null);
    }

    /** The hinge strip's path: the tour of {@code squares}. */
    public static WrapPath hinge(GridSquares squares, HingeTour tour) {
        return new WrapPath(null, null, false, squares, tour);
    }

    /** Whether this is the hinge strip's tour rather than the zig-zag's refinement. */
    public boolean hinge() {
        return tour != null;
    }

    /** The triangles of the path: the refinement's, or a pass of the tour each. */
    public int pathTriangles() {
        return hinge() ? tour.passes() : refinement.mesh().faceCount();
    }

    /** The strips: one a component. */
    public int components() {
        return hinge() ? tour.components() : refinement.componentCount();
    }

    /** Prepares and refines {@code mesh}, a valid triangle mesh, and follows whichever path is likely to make fewer faces. */
    public static WrapPath of(HalfedgeMesh mesh) {
        FacePreparation.Result preparation = FacePreparation.prepare(mesh);
        HamiltonianRefinement.Result refined = HamiltonianRefinement.refine(preparation.mesh());
        if (preparation.prepared() == 0) {
            return new WrapPath(preparation, refined, false);
        }
        // The model's own triangles, but for the regions fanned from their centre (FacePreparation).
        HamiltonianRefinement.Result own = HamiltonianRefinement.refine(preparation.centred());
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
        return preparation != null && preparation.kept() != null ? model + ": faces kept as they are, not prepared: " + preparation.kept() : null;
    }

    /**
     * The report's figures of the path: for the zig-zag, the preparation's regions, triangles, and
     * the smallest angles of the model, the prepared faces and the path, in degrees; for the hinge
     * strip, the squares and the tour's passes.
     */
    public Map<String, Object> figures() {
        Map<String, Object> figures = new LinkedHashMap<>();
        if (hinge()) {
            figures.put("squareSide", squares.spacing());
            figures.put("squares", squares.count());
            figures.put("passes", tour.passes());
            figures.put("turningPasses", tour.turnCount());
            figures.put("straightPasses", tour.passes() - tour.turnCount());
            return figures;
        }
        figures.put("planarRegions", preparation.regions());
        figures.put("centredRegions", preparation.centredRegions());
        figures.put("preparedRegions", preparation.prepared());
        figures.put("used", prepared);
        // The Hamiltonian refinement's 5n - 2 triangles, or the model's own where the seam kept them.
        figures.put("follows", refinement.mesh().ownTriangles() ? "ownTriangles" : "refinement");
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
