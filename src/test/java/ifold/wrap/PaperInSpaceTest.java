package ifold.wrap;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Polycubes;
import ifold.refine.HamiltonianRefinement;
import java.util.List;
import org.junit.jupiter.api.Test;

class PaperInSpaceTest {
    /**
     * Faces are cut on a thread of their own ahead of the placing where there are two threads
     * (PaperInSpace's PiecesAhead): the paper comes out the same to the bit as cut and placed
     * one by one. The L polycube's concave edges cut hundreds of its faces into pieces, and its
     * sheet has several batches of faces.
     */
    @Test
    void thePaperIsPlacedTheSameWhetherItsFacesAreCutAheadOrNot() throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(Polycubes.surface(Polycubes.l()), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        HamiltonianRefinement.Result refinement = ifold.job.WrapPath.of(mesh).refinement();
        Wrap.Result result = Wrap.wrap(refinement, new Wrap.Options(Double.NaN, Double.NaN));
        Wrap.Strip strip = result.strips().get(0);
        PaperInSpace alone = placed(strip, result, "1");
        PaperInSpace ahead = placed(strip, result, "2");
        assertTrue(strip.sheet().faceCount() > 4 * 512, "setup: batches of faces " + strip.sheet().faceCount());
        int cut = 0;
        for (int f = 0; f < alone.sheetFaceCount(); f++) {
            cut += alone.pieceStart()[f + 1] - alone.pieceStart()[f] > 1 ? 1 : 0;
        }
        assertTrue(cut > 100, "setup: faces cut into pieces " + cut);
        assertArrayEquals(alone.xyz(), ahead.xyz());
        assertArrayEquals(alone.uv(), ahead.uv());
        assertArrayEquals(alone.pieceStart(), ahead.pieceStart());
        assertArrayEquals(alone.paperHosts(), ahead.paperHosts());
        assertArrayEquals(alone.capAfter(), ahead.capAfter());
        assertArrayEquals(alone.creep().vertices(), ahead.creep().vertices());
        assertArrayEquals(alone.creep().from(), ahead.creep().from());
        assertSame(alone.paperFaces(), ahead.paperFaces());
        assertSame(alone.caps(), ahead.caps());
    }

    private static PaperInSpace placed(Wrap.Strip strip, Wrap.Result result, String threads) {
        String old = System.getProperty("ifold.threads");
        System.setProperty("ifold.threads", threads);
        try {
            return PaperInSpace.of(strip.sheet(), result.frames());
        } finally {
            if (old == null) {
                System.clearProperty("ifold.threads");
            } else {
                System.setProperty("ifold.threads", old);
            }
        }
    }

    private static void assertSame(List<int[]> expected, List<int[]> actual) {
        assertEquals(expected.size(), actual.size());
        for (int k = 0; k < expected.size(); k++) {
            assertArrayEquals(expected.get(k), actual.get(k), "polygon " + k);
        }
    }
}
