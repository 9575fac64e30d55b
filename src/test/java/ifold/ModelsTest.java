package ifold;

import static org.junit.jupiter.api.Assertions.assertEquals;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Solids;
import ifold.mesh.Topology;
import ifold.mesh.io.MeshReaders;
import ifold.refine.HamiltonianRefinement;
import ifold.refine.RefinementClaims;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/** The models in models/ are what the generator makes, load strictly, and refine with every claim kept. */
class ModelsTest {

    static Stream<Arguments> models() {
        return Stream.of("off", "obj").flatMap(ext -> Stream.of(
                Arguments.of("tetrahedron." + ext, Solids.tetrahedron(), 0, 0),
                Arguments.of("cube." + ext, Solids.cube(), 0, 0),
                Arguments.of("octahedron." + ext, Solids.octahedron(), 0, 0),
                Arguments.of("icosahedron." + ext, Solids.icosahedron(), 0, 0),
                Arguments.of("torus." + ext, Solids.torus(3, 1, 24, 12), 1, 0),
                Arguments.of("triangle." + ext, Solids.triangle(), 0, 1),
                Arguments.of("figure3." + ext, Solids.figure3(), 0, 1)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("models")
    void modelLoadsStrictlyAndRefines(String file, PolygonSoup expected, int genus, int boundaryLoops) throws Exception {
        PolygonSoup soup = MeshReaders.read(Path.of("models", file));
        assertEquals(expected.vertexCount(), soup.vertexCount());
        assertEquals(expected.faceCount(), soup.faceCount());
        for (int v = 0; v < soup.vertexCount(); v++) {
            for (int axis = 0; axis < 3; axis++) {
                assertEquals(expected.coordinate(v, axis), soup.coordinate(v, axis), "vertex " + v);
            }
        }
        HalfedgeMesh mesh = MeshBuilder.build(soup, new MeshBuilder.Options(true, true)).mesh();
        assertEquals(List.of(), MeshValidator.validate(mesh));
        Topology topology = Topology.of(mesh);
        assertEquals(genus, topology.genus());
        assertEquals(boundaryLoops, topology.boundaryLoops());
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(5 * mesh.faceCount() - 2, result.mesh().faceCount());
        assertEquals(List.of(), RefinementClaims.violations(mesh, result));
    }
}
