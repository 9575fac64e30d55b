package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.io.MeshReaders;
import java.nio.file.Path;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/** Paper placed in space with its faces placed in shares by host on several threads: the same, to the bit, as on one. */
class PaperInSpaceTest {

    /**
     * figure3 has concave edges where faces are placed in pieces, paper that creeps and pieces
     * torn apart where a wall ends: the shares' vertices, pieces, sides and caps are put back in
     * the order one builder makes them.
     */
    @ParameterizedTest
    @ValueSource(ints = {2, 3, 7})
    void facesPlacedInSharesAreTheFacesPlacedInOne(int shards) throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(MeshReaders.read(Path.of("models", "figure3.off")), MeshBuilder.Options.REPAIR_TRIANGULATE)
                .mesh();
        Wrap.Result result = Wrap.wrap(ifold.job.WrapPath.of(mesh).refinement(), new Wrap.Options(Double.NaN, Double.NaN));
        Wrap.Strip strip = result.strips().get(0);
        PaperInSpace one = PaperInSpace.of(strip.sheet(), result.frames(), 1);
        PaperInSpace shared = PaperInSpace.of(strip.sheet(), result.frames(), shards);
        // What makes the shares' order matter is there: pieces, creep, and caps within faces.
        assertTrue(one.paperFaces().size() > one.sheetFaceCount(), "faces placed in pieces");
        assertTrue(one.creep().vertices().length > 100, "paper that creeps");
        assertArrayEquals(one.xyz(), shared.xyz());
        assertArrayEquals(one.uv(), shared.uv());
        assertArrayEquals(one.pieceStart(), shared.pieceStart());
        assertArrayEquals(one.paperHosts(), shared.paperHosts());
        assertEquals(one.paperFaces().size(), shared.paperFaces().size());
        for (int k = 0; k < one.paperFaces().size(); k++) {
            assertArrayEquals(one.paperFaces().get(k), shared.paperFaces().get(k), "paper face " + k);
        }
        assertEquals(one.caps().size(), shared.caps().size());
        for (int k = 0; k < one.caps().size(); k++) {
            assertArrayEquals(one.caps().get(k), shared.caps().get(k), "cap " + k);
        }
        assertArrayEquals(one.capAfter(), shared.capAfter());
        assertArrayEquals(one.creep().vertices(), shared.creep().vertices());
        assertArrayEquals(one.creep().from(), shared.creep().from());
    }
}
