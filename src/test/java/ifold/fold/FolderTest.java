package ifold.fold;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.MeshValidator;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import java.util.TreeSet;
import org.joml.Vector3d;
import org.junit.jupiter.api.Test;

class FolderTest {
    private static final double T = 0.01;

    /** A fold along the vertical line x = c, the side x > c moving (right, looking along +y). */
    private static Fold atX(Fold.Kind kind, double degrees, double c, Fold.Side side) {
        return Fold.through(kind, degrees, new Vector3d(c, 0, 0), new Vector3d(c, 1, 0), side);
    }

    /** Every invariant a folded paper must keep. */
    static void assertSound(Paper paper) throws Exception {
        assertTrue(PaperAnalysis.isometryError(paper) <= 1e-9, "isometric: " + PaperAnalysis.isometryError(paper));
        for (int v = 0; v < paper.vertexCount(); v++) {
            assertTrue(Double.isFinite(paper.x(v) + paper.y(v) + paper.z(v)), "vertex " + v + " is finite");
        }
        assertEquals(List.of(), MeshValidator.validate(paper.top()), "the top is a valid mesh");
        assertEquals(List.of(), MeshValidator.validate(paper.bottom()), "so is the bottom");
    }

    /** The distinct heights of the paper faces (caps left out), rounded to 1e-12. */
    private static TreeSet<Double> layerHeights(Paper paper) {
        TreeSet<Double> heights = new TreeSet<>();
        for (int f = 0; f < paper.faceCount(); f++) {
            if (!paper.isCap(f)) {
                for (int v : paper.face(f)) {
                    heights.add(Math.rint(paper.height(v) * 1e12) / 1e12);
                }
            }
        }
        return heights;
    }

    @Test
    void valleyFoldLaysTheMovingHalfOneThicknessAbove() throws Exception {
        Paper strip = Paper.strip(10, 1, T);
        Paper folded = Folder.fold(strip, atX(Fold.Kind.VALLEY, 180, 5, Fold.Side.RIGHT));
        assertSound(folded);
        assertEquals(new TreeSet<>(List.of(0.0, T)), layerHeights(folded));
        // The far corner (10, 0) lands over (0, 0), one thickness up.
        int corner = -1;
        for (int v = 0; v < folded.vertexCount(); v++) {
            if (folded.u(v) == 10 && folded.v(v) == 0) {
                corner = v;
            }
        }
        assertEquals(0, folded.x(corner), 1e-12);
        assertEquals(0, folded.y(corner), 1e-12);
        assertEquals(T, folded.z(corner), 1e-12);
        assertEquals(2, PaperAnalysis.layersAt(folded, 2.5, 0.5, 0));
        assertEquals(10, PaperAnalysis.paperArea(folded), 1e-12);
        assertEquals(1, folded.creaseCount());
        assertEquals(2, PaperAnalysis.maxLayers(folded));
    }

    @Test
    void mountainFoldGoesUnder() throws Exception {
        Paper folded = Folder.fold(Paper.strip(10, 1, T), atX(Fold.Kind.MOUNTAIN, 180, 5, Fold.Side.RIGHT));
        assertSound(folded);
        assertEquals(new TreeSet<>(List.of(-T, 0.0)), layerHeights(folded));
    }

    @Test
    void squareFoldedInHalfTwiceHasFourLayersOneThicknessApart() throws Exception {
        Paper square = Paper.square(2, T);
        Paper once = Folder.fold(square, atX(Fold.Kind.VALLEY, 180, 1, Fold.Side.RIGHT));
        // Fold the other way through both layers: along y = 1, the top half moving.
        Paper twice = Folder.fold(once, Fold.through(Fold.Kind.VALLEY, 180, new Vector3d(0, 1, 0), new Vector3d(1, 1, 0),
                Fold.Side.LEFT));
        assertSound(twice);
        assertEquals(new TreeSet<>(List.of(0.0, T, 2 * T, 3 * T)), layerHeights(twice));
        assertEquals(4, PaperAnalysis.layersAt(twice, 0.5, 0.5, 0));
        assertEquals(4, PaperAnalysis.maxLayers(twice));
        assertEquals(4, PaperAnalysis.paperArea(twice), 1e-12);
    }

    @Test
    void foldThroughCornersMakesNoNewVertices() throws Exception {
        Paper square = Paper.square(2, 0);
        Paper folded = Folder.fold(square, Fold.through(Fold.Kind.VALLEY, 180, new Vector3d(0, 0, 0), new Vector3d(2, 2, 0),
                Fold.Side.RIGHT));
        assertSound(folded);
        assertEquals(4, folded.vertexCount(), "the diagonal passes through two corners: nothing to split, no thickness");
        assertEquals(2, folded.faceCount());
        assertEquals(2, PaperAnalysis.layersAt(folded, 1.0, 1.5, 0), "the lower right half now lies over the upper left");
        assertEquals(0, PaperAnalysis.layersAt(folded, 1.5, 1.0, 0));
    }

    @Test
    void foldAlongAnExistingEdgeUsesIt() throws Exception {
        // Two squares side by side, sharing the edge x = 1.
        double[] xyz = {0, 0, 0, 1, 0, 0, 2, 0, 0, 2, 1, 0, 1, 1, 0, 0, 1, 0};
        double[] uv = {0, 0, 1, 0, 2, 0, 2, 1, 1, 1, 0, 1};
        List<int[]> faces = new ArrayList<>(List.of(new int[] {0, 1, 4, 5}, new int[] {1, 2, 3, 4}));
        Paper paper = new Paper(xyz, uv, faces, new boolean[2], T, new Vector3d(0, 0, 1), List.of());
        Paper folded = Folder.fold(paper, atX(Fold.Kind.VALLEY, 180, 1, Fold.Side.RIGHT));
        assertSound(folded);
        assertEquals(6 + 2 + 2, folded.vertexCount(), "no splits: the six vertices, a clone and a half-way clone of each end of the edge");
        assertEquals(2 + 2, folded.faceCount(), "the two squares and the two facets of the cap");
    }

    @Test
    void partialFoldTurnsByTheAngle() throws Exception {
        Folder.Prepared prepared = Folder.prepare(Paper.strip(10, 1, 0), atX(Fold.Kind.VALLEY, 90, 5, Fold.Side.RIGHT));
        Paper standing = prepared.at(1);
        assertSound(standing);
        int corner = -1;
        for (int v = 0; v < standing.vertexCount(); v++) {
            if (standing.u(v) == 10 && standing.v(v) == 1) {
                corner = v;
            }
        }
        assertEquals(5, standing.x(corner), 1e-12);
        assertEquals(5, standing.z(corner), 1e-12, "turned up by 90 degrees");
        Paper flat = prepared.at(0);
        assertEquals(10, flat.x(corner), 0, "at the start of the animation nothing has moved");
    }

    @Test
    void foldThenUnfoldRestoresTheSheet() throws Exception {
        Paper strip = Paper.strip(10, 1, T);
        Folder.Prepared prepared = Folder.prepare(strip, atX(Fold.Kind.VALLEY, 180, 3.7, Fold.Side.RIGHT));
        Paper folded = prepared.at(1);
        Paper unfolded = prepared.at(0);
        assertSound(folded);
        for (int v = 0; v < unfolded.vertexCount(); v++) {
            assertEquals(unfolded.u(v), unfolded.x(v), 1e-12);
            assertEquals(unfolded.v(v), unfolded.y(v), 1e-12);
            assertEquals(0, unfolded.z(v), 1e-12);
        }
    }

    @Test
    void badFoldsAreRefused() {
        Paper strip = Paper.strip(10, 1, T);
        assertThrows(FoldException.class, () -> Folder.fold(strip, atX(Fold.Kind.VALLEY, 0, 5, Fold.Side.RIGHT)));
        assertThrows(FoldException.class, () -> Folder.fold(strip, atX(Fold.Kind.VALLEY, 181, 5, Fold.Side.RIGHT)));
        FoldException misses = assertThrows(FoldException.class, () -> Folder.fold(strip, atX(Fold.Kind.VALLEY, 180, 12, Fold.Side.RIGHT)));
        assertTrue(misses.getMessage().contains("nothing moves"), misses.getMessage());
        assertThrows(FoldException.class, () -> Folder.fold(strip, atX(Fold.Kind.VALLEY, 180, -2, Fold.Side.RIGHT)));
        assertThrows(FoldException.class, () -> Folder.fold(strip, new Fold(Fold.Kind.VALLEY, 90, new Vector3d(5, 0, 0),
                new Vector3d(0, 0, 1), Fold.Side.RIGHT)));
    }

    @Test
    void hundredRollingFoldsStaySound() throws Exception {
        // Roll a strip up from its end: each fold lays the growing stack over the next unit.
        Paper paper = Paper.strip(110, 1, 0.001);
        for (int k = 1; k <= 100; k++) {
            paper = Folder.fold(paper, atX(k % 2 == 0 ? Fold.Kind.VALLEY : Fold.Kind.VALLEY, 180, 110 - k, Fold.Side.RIGHT));
            assertEquals(List.of(), MeshValidator.validate(paper.top()), "after fold " + k);
            assertTrue(PaperAnalysis.isometryError(paper) <= 1e-9, "isometric after fold " + k);
        }
        assertSound(paper);
        assertEquals(101, PaperAnalysis.layersAt(paper, 9.5, 0.5, 0));
        TreeSet<Double> expected = new TreeSet<>();
        for (int k = 0; k <= 100; k++) {
            expected.add(Math.rint(k * 0.001 * 1e12) / 1e12);
        }
        assertEquals(expected, layerHeights(paper), "101 layers, exactly one thickness apart");
        assertEquals(110, PaperAnalysis.paperArea(paper), 1e-9);
    }

    @Test
    void randomFoldsOnASquareStaySound() throws Exception {
        Random random = new Random(11);
        for (int trial = 0; trial < 20; trial++) {
            Paper paper = Paper.square(4, T);
            for (int k = 0; k < 4; k++) {
                // A line through a point of the paper's current shadow, in a random direction.
                double angle = random.nextDouble() * Math.PI;
                int v = random.nextInt(paper.vertexCount());
                Vector3d through = new Vector3d(paper.x(v), paper.y(v), 0).lerp(new Vector3d(0.7, 0.9, 0), 0.5);
                Fold fold = new Fold(random.nextBoolean() ? Fold.Kind.VALLEY : Fold.Kind.MOUNTAIN, 180, through,
                        new Vector3d(Math.cos(angle), Math.sin(angle), 0), random.nextBoolean() ? Fold.Side.LEFT : Fold.Side.RIGHT);
                try {
                    paper = Folder.fold(paper, fold);
                } catch (FoldException e) {
                    continue; // the line missed what is left of the paper: a clear refusal is fine
                }
                assertSound(paper);
                assertEquals(16, PaperAnalysis.paperArea(paper), 1e-9);
            }
        }
    }
}
