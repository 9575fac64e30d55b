package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.Solids;
import java.lang.reflect.Field;
import java.util.List;
import org.junit.jupiter.api.Test;

/**
 * The claims' checker finds each claim broken: a refinement of the cube, made wrong one way at a
 * time (two triangles of the path swapped, one triangle twice, a face's centre moved towards a
 * corner, the wrong model), is refused naming what broke; the refinement itself breaks none.
 */
class RefinementClaimsTest {
    private static final HalfedgeMesh CUBE = HamiltonianRefinementTest.triangles(Solids.cube());

    private static Object field(Object of, String name) throws Exception {
        Field field = of.getClass().getDeclaredField(name);
        field.setAccessible(true);
        return field.get(of);
    }

    /** The cube's refinement with its path, incentres or input replaced. */
    private static HamiltonianRefinement.Result broken(int[] path, double[] incentres) throws Exception {
        HamiltonianRefinement.Result good = HamiltonianRefinement.refine(CUBE);
        RefinedMesh mesh = good.mesh();
        RefinedMesh wrong = new RefinedMesh(mesh.original(), path != null ? path : (int[]) field(mesh, "path"),
                incentres != null ? incentres : (double[]) field(mesh, "incentres"), (EdgeSet) field(mesh, "treeEdges"), false);
        return new HamiltonianRefinement.Result(wrong, good.componentStart(), good.treeEdge());
    }

    private static int[] path() throws Exception {
        return ((int[]) field(HamiltonianRefinement.refine(CUBE).mesh(), "path")).clone();
    }

    @Test
    void theRefinementBreaksNoClaim() throws Exception {
        assertEquals(List.of(), RefinementClaims.violations(CUBE, HamiltonianRefinement.refine(CUBE)));
        assertEquals(List.of(), RefinementClaims.violations(CUBE, broken(null, null)), "setup: the copy is the refinement");
    }

    @Test
    void twoTrianglesSwappedShareNoEdgeWithTheirNeighbours() throws Exception {
        int[] path = path();
        int t = path[3];
        path[3] = path[40];
        path[40] = t;
        List<String> problems = RefinementClaims.violations(CUBE, broken(path, null));
        assertTrue(problems.stream().anyMatch(p -> p.matches("triangles \\d+ and \\d+ of the path share no edge")), problems.toString());
    }

    @Test
    void aTriangleTwiceIsFound() throws Exception {
        int[] path = path();
        path[10] = path[11];
        List<String> problems = RefinementClaims.violations(CUBE, broken(path, null));
        assertTrue(problems.contains("a triangle appears twice in the path"), problems.toString());
    }

    @Test
    void aCentreMovedTowardsACornerNarrowsAnAngle() throws Exception {
        double[] incentres = ((double[]) field(HamiltonianRefinement.refine(CUBE).mesh(), "incentres")).clone();
        int corner = CUBE.fromVertex(CUBE.faceHalfedge(0));
        for (int axis = 0; axis < 3; axis++) {
            incentres[axis] += 0.9 * (CUBE.coordinate(corner, axis) - incentres[axis]);
        }
        List<String> problems = RefinementClaims.violations(CUBE, broken(null, incentres));
        assertTrue(problems.stream().anyMatch(p -> p.startsWith("smallest angle ") && p.contains("is less than half the input's 45")),
                problems.toString());
    }

    @Test
    void theWrongModelIsFoundByItsCountAndArea() throws Exception {
        HalfedgeMesh tetrahedron = HamiltonianRefinementTest.triangles(Solids.tetrahedron());
        List<String> problems = RefinementClaims.violations(tetrahedron, HamiltonianRefinement.refine(CUBE));
        // It threw ArrayIndexOutOfBoundsException, reading the cube's faces in the tetrahedron.
        assertEquals(List.of("58 triangles, expected 5n - 2c = 18", "the refinement is of another model: 12 faces and 8 vertices, not 4 and 4"),
                problems);
    }
}
