package ifold.sheet;

import java.util.Arrays;

/**
 * The face to the left of each directed paper edge a → b, kept by a: each vertex has a few
 * slots of its own, side by side in one array, for the edges that leave it (one for each face
 * around it, which on a strip's paper is seldom more than four), and the rare vertex with more
 * keeps the rest in a {@link LongIntMap}.
 *
 * <p>Why not one hash map of all edges, as before: a wrap's sheet has millions of them, and a
 * hash spreads the edges of the faces being folded, which are new and near each other on the
 * sheet, all over a table of tens of megabytes, so nearly every lookup waited on memory (the
 * map's reads and writes were a seventh of the 5,120-triangle icosphere's folding). Kept by
 * vertex, the edges of faces made together lie together, as their vertices were numbered.
 */
final class EdgeFaces {
    /** Slots a vertex has of its own: four (b, face) pairs, eight ints, one cache line of 32 bytes. */
    private static final int SLOTS = 4;
    private static final int EMPTY = -1;

    /** Vertex a's slots are {@code slots[2·SLOTS·a ..]}: each the other end b (or {@link #EMPTY}) and the face. */
    private int[] slots = new int[0];
    /** Per vertex, whether any edge from it is kept in {@link #more}. */
    private boolean[] spilled = new boolean[0];
    private final LongIntMap more = new LongIntMap();

    /** The face to the left of a → b, or {@code missing} if no face has that edge. */
    int get(int a, int b, int missing) {
        if (a < 0 || a >= spilled.length) {
            return missing;
        }
        int at = 2 * SLOTS * a;
        for (int k = 0; k < SLOTS; k++, at += 2) {
            if (slots[at] == b) {
                return slots[at + 1];
            }
        }
        return spilled[a] ? more.get(Sheet.directed(a, b), missing) : missing;
    }

    /** Records face {@code face} to the left of a → b, replacing any face recorded there before. */
    void put(int a, int b, int face) {
        if (a < 0 || b < 0) {
            throw new IllegalArgumentException("vertices are not negative, got " + a + " → " + b);
        }
        if (a >= spilled.length) {
            grow(a);
        }
        int base = 2 * SLOTS * a;
        int free = -1;
        for (int k = 0, at = base; k < SLOTS; k++, at += 2) {
            if (slots[at] == b) {
                slots[at + 1] = face;
                return;
            }
            if (free < 0 && slots[at] == EMPTY) {
                free = at;
            }
        }
        long key = Sheet.directed(a, b);
        if (spilled[a] && more.get(key, EMPTY) != EMPTY) {
            more.put(key, face);
        } else if (free >= 0) {
            slots[free] = b;
            slots[free + 1] = face;
        } else {
            spilled[a] = true;
            more.put(key, face);
        }
    }

    /** Forgets edge a → b; returns the face that was to its left, or {@code missing}. */
    int remove(int a, int b, int missing) {
        if (a < 0 || a >= spilled.length) {
            return missing;
        }
        for (int k = 0, at = 2 * SLOTS * a; k < SLOTS; k++, at += 2) {
            if (slots[at] == b) {
                int face = slots[at + 1];
                slots[at] = EMPTY;
                slots[at + 1] = EMPTY;
                return face;
            }
        }
        return spilled[a] ? more.remove(Sheet.directed(a, b), missing) : missing;
    }

    private void grow(int vertex) {
        int vertices = Math.max(vertex + 1, Math.max(64, spilled.length + (spilled.length >> 1)));
        int old = slots.length;
        slots = Arrays.copyOf(slots, 2 * SLOTS * vertices);
        Arrays.fill(slots, old, slots.length, EMPTY);
        spilled = Arrays.copyOf(spilled, vertices);
    }
}
