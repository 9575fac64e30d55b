package ifold.refine;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.MeshValidator;
import ifold.mesh.PolygonSoup;
import ifold.mesh.Topology;
import ifold.mesh.io.MeshFormatException;
import ifold.mesh.io.MeshReaders;
import ifold.testing.SharedMeshes;
import java.io.IOException;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

/** Every real model in ../shared/meshes/valid refines and keeps every claim. */
class SharedMeshRefinementTest {

    static Stream<String> valid() {
        return SharedMeshes.names("valid");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("valid")
    void refinesAndKeepsEveryClaim(String name) throws IOException, MeshFormatException, InvalidMeshException {
        assumeTrue(SharedMeshes.present(), "../shared/meshes is absent");
        PolygonSoup soup = MeshReaders.read(SharedMeshes.ROOT.resolve("valid").resolve(name));
        MeshBuilder.Result built = MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE);
        HalfedgeMesh mesh = built.mesh();
        assertEquals(List.of(), MeshValidator.validate(mesh));
        HamiltonianRefinement.Result result = HamiltonianRefinement.refine(mesh);
        assertEquals(List.of(), RefinementClaims.violations(mesh, result));
        assertEquals(Topology.of(mesh).components(), result.componentCount());
        if (mesh.faceCount() <= 20_000) {
            // The refined triangles form the same surface: rebuild them strictly and compare.
            MeshBuilder.Result rebuilt = MeshBuilder.build(result.mesh(), new MeshBuilder.Options(true, false));
            Topology before = Topology.of(mesh);
            Topology after = Topology.of(rebuilt.mesh());
            assertEquals(List.of(), MeshValidator.validate(rebuilt.mesh()));
            assertEquals(before.genus(), after.genus());
            assertEquals(before.boundaryLoops(), after.boundaryLoops());
            assertEquals(before.eulerCharacteristic(), after.eulerCharacteristic());
        }
    }
}
