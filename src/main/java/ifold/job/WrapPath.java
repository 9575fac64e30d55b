package ifold.job;

import ifold.geom.Triangles;
import ifold.geom.Vectors;
import ifold.mesh.GridSquares;
import ifold.mesh.HalfedgeMesh;
import ifold.refine.FacePreparation;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import ifold.wrap.HingeTour;
import ifold.wrap.Wrap;
import java.util.LinkedHashMap;
import java.util.List;
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

    /**
     * The zig-zag's path this one is not: the prepared faces' refinement where this follows the
     * model's own, and the other way round; null where nothing was prepared. Fewer faces are
     * likely on the one {@link #of} follows, but not always fewer layers: a cone's base fanned
     * from its centre in 32 thin triangles piles 64 layers there along the model's own, 37 along
     * the prepared faces.
     */
    public WrapPath other() {
        if (hinge() || preparation.prepared() == 0) {
            return null;
        }
        return prepared ? new WrapPath(preparation, HamiltonianRefinement.refine(preparation.centred()), false)
                : new WrapPath(preparation, HamiltonianRefinement.refine(preparation.mesh()), true);
    }

    /**
     * Whether the prepared faces may lay fewer layers than this path, the model's own, at
     * {@code point}: within {@code reach} of it lies a vertex inside a planar region (every face
     * round it in one plane) where the triangles meet at a corner under the preparation's target
     * (a cone's base fanned from its centre), which the preparation triangles again. At a solid's
     * corner, where a long box's thin triangles meet too, the faces round it turn, and the
     * prepared faces were as many layers or more.
     */
    public boolean fanNear(double[] point, double reach) {
        if (hinge() || prepared || preparation.prepared() == 0) {
            return false;
        }
        HalfedgeMesh own = preparation.centred();
        double[] xyz = own.positionArray();
        for (int v = 0; v < own.vertexCount(); v++) {
            double dx = xyz[3 * v] - point[0];
            double dy = xyz[3 * v + 1] - point[1];
            double dz = xyz[3 * v + 2] - point[2];
            if (dx * dx + dy * dy + dz * dz <= reach * reach && own.halfedge(v) >= 0 && !own.isBoundaryVertex(v) && thinFlatFan(own, v)) {
                return true;
            }
        }
        return false;
    }

    /** Whether every face round vertex {@code v} of {@code mesh} lies in one plane and one has a corner there under the preparation's target. */
    private static boolean thinFlatFan(HalfedgeMesh mesh, int v) {
        double[] xyz = mesh.positionArray();
        double[] pv = point(xyz, v);
        double[] first = null;
        boolean thin = false;
        int start = mesh.halfedge(v);
        int h = start;
        do {
            int a = mesh.toVertex(h);
            int b = mesh.toVertex(mesh.next(h));
            double[] normal = Vectors.unit(Vectors.cross(Vectors.sub(point(xyz, a), pv), Vectors.sub(point(xyz, b), pv)));
            if (first == null) {
                first = normal;
            } else if (Vectors.dot(first, normal) < 1 - 1e-9) {
                return false;
            }
            thin |= Math.toDegrees(Triangles.angleAt(xyz, v, a, b)) < FacePreparation.TARGET_ANGLE;
            h = HalfedgeMesh.twin(mesh.prev(h));
        } while (h != start);
        return thin;
    }

    private static double[] point(double[] xyz, int v) {
        return new double[] {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    }

    /** Prepares and refines {@code mesh}, following the prepared path whatever it costs ({@code refine --prepare}). */
    public static WrapPath prepared(HalfedgeMesh mesh) {
        FacePreparation.Result preparation = FacePreparation.prepare(mesh);
        return new WrapPath(preparation, HamiltonianRefinement.refine(preparation.mesh()), preparation.prepared() > 0);
    }

    /**
     * Why the model's faces were kept as they are although some needed preparing, or which
     * were kept while the others were prepared, in one line naming {@code model}; null where
     * they were all prepared or needed none.
     */
    public String keptNote(String model) {
        if (preparation == null) {
            return null;
        }
        if (preparation.kept() != null) {
            return model + ": faces kept as they are, not prepared: " + preparation.kept();
        }
        List<String> kept = preparation.keptRegions();
        if (kept.isEmpty()) {
            return null;
        }
        int shown = Math.min(kept.size(), KEPT_REGIONS_NAMED);
        return model + ": faces kept as they are in " + kept.size() + (kept.size() == 1 ? " place" : " places") + ", the others prepared: "
                + String.join("; ", kept.subList(0, shown)) + (kept.size() > shown ? "; and " + (kept.size() - shown) + " more" : "");
    }

    /** The most regions kept as they are that {@link #keptNote} names, one line's worth. */
    private static final int KEPT_REGIONS_NAMED = 3;

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
        if (!preparation.keptRegions().isEmpty()) {
            figures.put("keptRegions", preparation.keptRegions());
        }
        return figures;
    }
}
