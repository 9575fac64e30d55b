package ifold.wrap;

import ifold.mesh.GridSquares;
import java.util.Arrays;

/**
 * The tour a hinge strip follows over a closed surface of squares: it crosses every side of
 * every square exactly once, so it passes through every square exactly twice. On a closed
 * surface each square has four sides, each shared with one other square, so the squares and
 * their sides make a graph in which every square has four ends of sides: an Euler circuit of
 * that graph, one per component, is such a tour (Hierholzer's walk).
 *
 * <p>Whatever the circuit, each square's two passes are one of three kinds, all of which the
 * strip, one square wide, covers with exactly two layers and no gap: two straight passes
 * crossing (each covers the square), or two turns at opposite corners (a turn folds the
 * square's paper along the diagonal away from its corner, two layers over the half at the
 * corner, and the other turn's corner is the opposite one, its half the other half). So the
 * strip is twice the surface's area, and nowhere more than two layers thick: the bounds
 * Benbernou, Demaine, Demaine and Lubiw prove for their universal hinge strip on any grid
 * polyhedron of sphere topology (here of any genus, the circuit needing only a connected
 * closed surface). The walk goes straight on where it can, so that it turns, and creases
 * inside squares, less.
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

    /** The tour of every component of {@code squares}, a closed surface: components in the order of their first squares. */
    public static HingeTour of(GridSquares squares) {
        int n = squares.count();
        int passes = 2 * n;
        int[] square = new int[passes];
        int[] entry = new int[passes];
        int[] exit = new int[passes];
        int[] componentStart = new int[squares.components() + 1];
        boolean[] used = new boolean[4 * n];
        int[] firstOf = new int[squares.components()];
        Arrays.fill(firstOf, -1);
        for (int q = n - 1; q >= 0; q--) {
            firstOf[squares.component(q)] = q;
        }
        int at = 0;
        // Hierholzer's walk, iterative: a stack of the sides crossed (as 4 q + k, the square and
        // side it was entered by, q and k of the far square), each popped onto the circuit once
        // its square has no side left to leave by.
        int[] stack = new int[passes + 1];
        int[] circuit = new int[passes + 1];
        for (int c = 0; c < squares.components(); c++) {
            componentStart[c] = at;
            int top = 0;
            int length = 0;
            stack[top++] = 4 * firstOf[c] + 3; // as if entered by side 3: the walk leaves by side 1 first
            while (top > 0) {
                int arrival = stack[top - 1];
                int q = arrival / 4;
                int in = arrival % 4;
                int out = -1;
                for (int turn : new int[] {2, 1, 3, 0}) { // straight on first
                    int k = (in + turn) % 4;
                    if (!used[4 * q + k]) {
                        out = k;
                        break;
                    }
                }
                if (out < 0) {
                    circuit[length++] = stack[--top];
                    continue;
                }
                int p = squares.across(q, out);
                int j = squares.acrossSide(q, out);
                used[4 * q + out] = true;
                used[4 * p + j] = true;
                stack[top++] = 4 * p + j;
            }
            // The circuit comes out backwards, the starting entry last: crossings x_1 … x_m in
            // order are circuit[length - 2] down to circuit[0]; pass i lies between crossing i
            // and crossing i + 1 (the last between x_m and x_1, where the strip's two ends meet).
            int m = length - 1;
            for (int i = 0; i < m; i++) {
                int arrival = circuit[m - 1 - i];
                int next = circuit[(m - 2 - i + m) % m];
                int q = arrival / 4;
                square[at] = q;
                entry[at] = arrival % 4;
                int p = next / 4;
                exit[at] = squares.acrossSide(p, next % 4);
                if (squares.across(p, next % 4) != q) {
                    throw new IllegalStateException("the tour's crossings do not follow one another at square " + q);
                }
                at++;
            }
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
