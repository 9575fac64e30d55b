package ifold.refine;

/**
 * A set of edges as a bit array, with the number of members before each 64-bit word kept
 * alongside, so that an edge's rank (its index among the members) takes one look-up and a
 * bit count, and selecting the k-th member a binary search over the words: the midpoints of
 * the refinement are numbered by the rank of their edge without an array as long as the edges.
 */
final class EdgeSet {
    private final long[] bits;
    /** before[w] = members in words 0 .. w - 1. */
    private final int[] before;
    private final int size;

    EdgeSet(boolean[] members) {
        bits = new long[(members.length + 63) >>> 6];
        for (int e = 0; e < members.length; e++) {
            if (members[e]) {
                bits[e >>> 6] |= 1L << (e & 63);
            }
        }
        before = new int[bits.length + 1];
        for (int w = 0; w < bits.length; w++) {
            before[w + 1] = before[w] + Long.bitCount(bits[w]);
        }
        size = before[bits.length];
    }

    int size() {
        return size;
    }

    boolean contains(int e) {
        return (bits[e >>> 6] & (1L << (e & 63))) != 0;
    }

    /** The number of members below {@code e}. */
    int rank(int e) {
        int w = e >>> 6;
        return before[w] + Long.bitCount(bits[w] & ((1L << (e & 63)) - 1));
    }

    /** The member of rank {@code k}, {@code 0 <= k < size()}. */
    int select(int k) {
        int lo = 0;
        int hi = bits.length - 1;
        while (lo < hi) { // the last word w with before[w] <= k
            int mid = (lo + hi + 1) >>> 1;
            if (before[mid] <= k) {
                lo = mid;
            } else {
                hi = mid - 1;
            }
        }
        long word = bits[lo];
        for (int skip = k - before[lo]; skip > 0; skip--) {
            word &= word - 1; // drop the lowest member
        }
        return (lo << 6) + Long.numberOfTrailingZeros(word);
    }
}
