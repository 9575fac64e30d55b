package ifold.wrap;

import ifold.mesh.GridSquares;
import java.util.Arrays;

/**
 * The tour a hinge strip follows over a closed surface of squares: it crosses every side of
 * every square exactly once, so it passes through every square exactly twice. On a closed
 * surface each square has four sides, each shared with one other square, so the squares and
 * their sides make a graph in which every square has four ends of sides: an Euler circuit of
 * that graph, one per component, is such a tour.
 *
 * <p>Whatever the circuit, each square's two passes are one of three kinds, all of which the
 * strip, one square wide, covers with exactly two layers and no gap: two straight passes
 * crossing (each covers the square), or two turns at opposite corners (a turn folds the
 * square's paper along the diagonal away from its corner, two layers over the half at the
 * corner, and the other turn's corner is the opposite one, its half the other half). So the
 * strip is twice the surface's area, and nowhere more than two layers thick: the bounds
 * Benbernou, Demaine, Demaine and Lubiw prove for their universal hinge strip on any grid
 * polyhedron of sphere topology (here of any genus, the circuit needing only a connected
 * closed surface).
 */
public final class HingeTour {
    /** Per pass, in the order of the tour: the square passed through, the side it enters by, the side it leaves by. */
    private final int[] square;
    private final int[] entry;
    private final int[] exit;
    /** Where each component's passes begin, and the total at the end. */
    private final int[] componentStart;

    private HingeTour(int[] square, int[] entry, int[] exit, int[] componentStart) {
        this.square = square;
        this.entry = entry;
        this.exit = exit;
        this.componentStart = componentStart;
    }

    /**
     * The tour of every component of {@code squares}, a closed surface: components in the order
     * of their first squares. Every square begins as a crossing, its two passes straight on, and
     * then the strip runs in rings, straight on from side to opposite side all round; where two
     * rings that are not yet one cross, the square's passes turn instead (two turns at opposite
     * corners), which joins them into one. So the tour turns in as few squares as rings joined by
     * crossings allow: the rings less one.
     */
    public static HingeTour of(GridSquares squares) {
        int n = squares.count();
        // The ring of each square's two directions: 2 q for its sides 0 and 2, 2 q + 1 for 1 and 3.
        int[] ring = new int[2 * n];
        Arrays.fill(ring, -1);
        int rings = 0;
        for (int start = 0; start < 2 * n; start++) {
            if (ring[start] >= 0) {
                continue;
            }
            int q = start / 2;
            int in = start % 2;
            while (ring[2 * q + in % 2] < 0) {
                ring[2 * q + in % 2] = rings;
                int out = (in + 2) % 4;
                int next = squares.across(q, out);
                in = squares.acrossSide(q, out);
                q = next;
            }
            rings++;
        }
        // A square whose two rings are not yet one turns, and joins them.
        int[] parent = ifold.geom.UnionFind.pieces(rings);
        boolean[] turning = new boolean[n];
        for (int q = 0; q < n; q++) {
            int a = ifold.geom.UnionFind.find(parent, ring[2 * q]);
            int b = ifold.geom.UnionFind.find(parent, ring[2 * q + 1]);
            if (a != b) {
                ifold.geom.UnionFind.union(parent, a, b);
                turning[q] = true;
            }
        }
        int passes = 2 * n;
        int[] square = new int[passes];
        int[] entry = new int[passes];
        int[] exit = new int[passes];
        int[] componentStart = new int[squares.components() + 1];
        int[] firstOf = new int[squares.components()];
        Arrays.fill(firstOf, -1);
        for (int q = n - 1; q >= 0; q--) {
            firstOf[squares.component(q)] = q;
        }
        int at = 0;
        for (int c = 0; c < squares.components(); c++) {
            componentStart[c] = at;
            int q = firstOf[c];
            int in = 0;
            do {
                // A turning square pairs side 0 with 1 and 2 with 3: turns at corners 1 and 3, opposite.
                int out = turning[q] ? in ^ 1 : (in + 2) % 4;
                square[at] = q;
                entry[at] = in;
                exit[at] = out;
                at++;
                int next = squares.across(q, out);
                in = squares.acrossSide(q, out);
                q = next;
            } while (!(q == firstOf[c] && in == 0) && at < passes);
        }
        componentStart[squares.components()] = at;
        if (at != passes) {
            throw new IllegalStateException("the tour passes " + at + " times, not twice through each of " + n + " squares");
        }
        return new HingeTour(square, entry, exit, componentStart);
    }

    /** The passes of all components. */
    public int passes() {
        return square.length;
    }

    public int square(int pass) {
        return square[pass];
    }

    public int entry(int pass) {
        return entry[pass];
    }

    public int exit(int pass) {
        return exit[pass];
    }

    /** Whether the pass turns (enters and leaves by sides that meet at a corner) rather than going straight through. */
    public boolean turns(int pass) {
        return (exit[pass] - entry[pass] + 4) % 2 != 0;
    }

    /** Whether a turning pass turns left as the square is seen from outside: it leaves by the side after the one it enters by. */
    public boolean turnsLeft(int pass) {
        return (exit[pass] - entry[pass] + 4) % 4 == 3;
    }

    public int components() {
        return componentStart.length - 1;
    }

    /** The first pass of component c; {@code componentStart(components())} is the number of passes. */
    public int componentStart(int c) {
        return componentStart[c];
    }

    /** The turning passes. */
    public int turnCount() {
        int turns = 0;
        for (int i = 0; i < square.length; i++) {
            turns += turns(i) ? 1 : 0;
        }
        return turns;
    }
}
