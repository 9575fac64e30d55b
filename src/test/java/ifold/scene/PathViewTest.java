package ifold.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

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
        SceneMesh mesh = PathView.mesh(refineIcosahedron());
        int[] colors = mesh.triangleColors();
        assertEquals(Colormap.turbo(0.08), colors[0]);
        assertEquals(Colormap.turbo(0.92), colors[colors.length - 1]);
        assertNotEquals(colors[0], colors[colors.length - 1]);
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
