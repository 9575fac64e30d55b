package ifold.mesh;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;

/** A grid polyhedron's lattice squares: found at the lattice its corners lie on, paired side by side, and what is not one refused. */
class GridSquaresTest {
    /** A box of a × b × c (six rectangles, as a user's model has them), at {@code scale}. */
    static HalfedgeMesh box(double a, double b, double c) throws InvalidMeshException {
        PolygonSoup soup = new PolygonSoup();
        double[][] p = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
        for (double[] q : p) {
            soup.addVertex(q[0], q[1], q[2]);
        }
        int[][] faces = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
        for (int[] f : faces) {
            soup.addFace(f, 4, 0);
        }
        return MeshBuilder.build(soup, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    static HalfedgeMesh polycube(List<int[]> cubes) throws InvalidMeshException {
        return MeshBuilder.build(Polycubes.surface(cubes), MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
    }

    @Test
    void aBoxOfRectanglesIsCutIntoItsLatticeSquares() throws Exception {
        HalfedgeMesh mesh = box(2, 1, 1);
        assertEquals(12, mesh.faceCount(), "setup: six rectangles, two triangles each");
        GridSquares squares = GridSquares.of(mesh, Double.NaN);
        assertEquals(1, squares.spacing(), 1e-15);
        assertEquals(10, squares.count());
        assertEquals(1, squares.components());
        assertPaired(squares);
        // Half the side: four times the squares.
        GridSquares halves = GridSquares.of(mesh, 0.5);
        assertEquals(40, halves.count());
        assertPaired(halves);
    }

    @Test
    void theLatticeIsTheLargestEveryCornerLiesOn() throws Exception {
        // Corners at 0, 1 and 1.5 along z: a lattice of halves, 3 × 2 × 3 squares along the box.
        GridSquares squares = GridSquares.of(box(1, 1, 1.5), Double.NaN);
        assertEquals(0.5, squares.spacing(), 1e-15);
        assertEquals(2 * 4 + 4 * 6, squares.count());
        assertPaired(squares);
    }

    @Test
    void aPolycubesSquaresFaceOutwardAndMeetTwoAnEdge() throws Exception {
        GridSquares squares = GridSquares.of(polycube(Polycubes.plus()), Double.NaN);
        assertEquals(Polycubes.surface(Polycubes.plus()).faceCount(), squares.count());
        assertPaired(squares);
        // Each square's corners are counter-clockwise seen from outside: its normal along +axis × sign.
        for (int q = 0; q < squares.count(); q++) {
            double[] n = new double[3];
            for (int k = 0; k < 4; k++) {
                int l = (k + 1) % 4;
                for (int a = 0; a < 3; a++) {
                    int y = (a + 1) % 3;
                    int z = (a + 2) % 3;
                    n[a] += (squares.corner(q, k, y) - squares.corner(q, l, y)) * (squares.corner(q, k, z) + squares.corner(q, l, z));
                }
            }
            assertEquals(squares.sign(q), Math.signum(n[squares.axis(q)]), "square " + q + " faces its sign");
        }
    }

    @Test
    void whatIsNotAClosedGridPolyhedronIsRefusedNamingWhy() throws Exception {
        HalfedgeMesh tetrahedron = MeshBuilder.build(ifold.mesh.io.OffReader.read(java.nio.file.Path.of("models/tetrahedron.off")),
                MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        GridSquares.NotGrid slanted = assertThrows(GridSquares.NotGrid.class, () -> GridSquares.of(tetrahedron, Double.NaN));
        assertTrue(slanted.getMessage().contains("not square to the axes"), slanted.getMessage());
        GridSquares.NotGrid off = assertThrows(GridSquares.NotGrid.class, () -> GridSquares.of(box(1, 1, Math.sqrt(0.5)), Double.NaN));
        assertTrue(off.getMessage().contains("no lattice"), off.getMessage());
        PolygonSoup one = new PolygonSoup();
        one.addVertex(0, 0, 0);
        one.addVertex(1, 0, 0);
        one.addVertex(1, 1, 0);
        one.addVertex(0, 1, 0);
        one.addFace(new int[] {0, 1, 2, 3}, 4, 0);
        HalfedgeMesh square = MeshBuilder.build(one, MeshBuilder.Options.REPAIR_TRIANGULATE).mesh();
        GridSquares.NotGrid open = assertThrows(GridSquares.NotGrid.class, () -> GridSquares.of(square, Double.NaN));
        assertTrue(open.getMessage().contains("open at"), open.getMessage());
        GridSquares.NotGrid thirds = assertThrows(GridSquares.NotGrid.class, () -> GridSquares.of(box(2, 1, 1), 0.3));
        assertTrue(thirds.getMessage().contains("must divide"), thirds.getMessage());
    }

    @Test
    void solidsMeetingAlongAnEdgeOrAtACornerAloneAreRefused() throws Exception {
        // Paper wrapping both would pass through itself where they meet.
        GridSquares.NotGrid edge = assertThrows(GridSquares.NotGrid.class,
                () -> GridSquares.of(polycube(List.of(new int[] {0, 0, 0}, new int[] {1, 1, 0})), Double.NaN));
        assertTrue(edge.getMessage().contains("more than two squares on it"), edge.getMessage());
        GridSquares.NotGrid corner = assertThrows(GridSquares.NotGrid.class,
                () -> GridSquares.of(polycube(List.of(new int[] {0, 0, 0}, new int[] {1, 1, 1})), Double.NaN));
        assertTrue(corner.getMessage().contains("more than one fan"), corner.getMessage());
        // Setup: joined by a face, the same cubes make one closed surface.
        assertEquals(10, GridSquares.of(polycube(List.of(new int[] {0, 0, 0}, new int[] {1, 0, 0})), Double.NaN).count());
    }

    /** Every side is shared with one other square, which runs along it the other way. */
    static void assertPaired(GridSquares squares) {
        for (int q = 0; q < squares.count(); q++) {
            for (int k = 0; k < 4; k++) {
                int p = squares.across(q, k);
                int j = squares.acrossSide(q, k);
                assertEquals(q, squares.across(p, j));
                assertEquals(k, squares.acrossSide(p, j));
                for (int a = 0; a < 3; a++) {
                    assertEquals(squares.corner(q, k, a), squares.corner(p, (j + 1) % 4, a), 1e-12);
                    assertEquals(squares.corner(q, (k + 1) % 4, a), squares.corner(p, j, a), 1e-12);
                }
            }
        }
    }
}
