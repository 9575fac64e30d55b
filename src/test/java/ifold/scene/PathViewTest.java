package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.mesh.HalfedgeMesh;
import ifold.mesh.MeshBuilder;
import ifold.mesh.Solids;
import ifold.refine.HamiltonianRefinement;
import org.junit.jupiter.api.Test;

class PathViewTest {

    private static HamiltonianRefinement.Result refineIcosahedron() throws Exception {
        HalfedgeMesh mesh = MeshBuilder.build(Solids.icosahedron(), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        return HamiltonianRefinement.refine(mesh);
    }

    private static int brightness(int argb) {
        return ((argb >>> 16) & 0xff) + ((argb >>> 8) & 0xff) + (argb & 0xff);
    }

    @Test
    void thePathIsADottedCurveAndDenseMeshesKeepTheirTree() throws Exception {
        HamiltonianRefinement.Result refinement = refineIcosahedron();
        SceneMesh mesh = PathView.mesh(refinement);
        int curve = 0;
        for (int color : mesh.edgeColors()) {
            curve += color == PathView.PATH_CURVE ? 1 : 0;
        }
        // 98 incentres and 97 edge middles: 195 points; each cut of the corners doubles them (the
        // ends kept), 780 in all, and every other of the 779 pieces is drawn.
        assertEquals(390, curve);
        SceneMesh dense = PathView.mesh(refinement, PathView.Colors.DARKNESS, true);
        int[] counts = PathView.edgeKindCounts(dense);
        assertEquals(2 * 19, counts[0], "the tree is kept: two halves of each tree edge");
        assertEquals(0, counts[1], "the Steiner edges are left out");
        for (int color : dense.edgeColors()) {
            assertTrue(color != PathView.PATH_CURVE, "and the path's curve: its colours show it");
        }
    }

    @Test
    void edgesAreSortedIntoTreeNewAndOriginal() throws Exception {
        SceneMesh mesh = PathView.mesh(refineIcosahedron());
        int[] counts = PathView.edgeKindCounts(mesh);
        // 19 tree edges, each split: 2 tree segments per tree edge (incentre-midpoint-incentre).
        assertEquals(2 * 19, counts[0]);
        // Spokes: 3 per face.
        assertEquals(3 * 20, counts[1]);
        // The 30 original edges, 19 of them split in two halves.
        assertEquals(30 + 19, counts[2]);
        assertEquals(98, mesh.triangleCount());
    }

    @Test
    void coloursRunAlongThePathAndRevealCountsTriangles() throws Exception {
        SceneMesh rainbow = PathView.mesh(refineIcosahedron(), PathView.Colors.RAINBOW, false);
        assertEquals(Colormap.turbo(0.08), rainbow.triangleColors()[0]);
        assertEquals(Colormap.turbo(0.92), rainbow.triangleColors()[rainbow.triangleCount() - 1]);
        // By default darker and darker along the path, as the seed's Figure 10.
        SceneMesh mesh = PathView.mesh(refineIcosahedron());
        int[] colors = mesh.triangleColors();
        for (int t = 1; t < colors.length; t++) {
            assertTrue(brightness(colors[t]) <= brightness(colors[t - 1]), "triangle " + t + " is no lighter than the one before");
        }
        assertTrue(brightness(colors[0]) - brightness(colors[colors.length - 1]) > 400, "from light to dark");
        Geometry geometry = new Geometry("path", mesh, Material.FACE_COLORS);
        Player player = new Player(PathView.reveal(geometry), 10);
        assertEquals(0, geometry.revealed());
        player.togglePlaying();
        player.advance(5);
        assertEquals(49, geometry.revealed());
        player.advance(100);
        assertEquals(98, geometry.revealed());
        player.step(-1);
        assertEquals(97, geometry.revealed());
        player.restart();
        assertEquals(0, geometry.revealed());
    }
}
