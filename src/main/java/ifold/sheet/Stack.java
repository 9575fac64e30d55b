package ifold.sheet;

import java.util.Arrays;
import java.util.List;
import java.util.Set;

/**
 * The faces of a sheet resting on one host and their order: which of its overlapping faces lies
 * above which (pairs above << 32 | below), each face's level once found, and a grid of where
 * they lie once there are many.
 */
final class Stack {
    /** From how many faces a stack finds the faces a new one overlaps through a grid rather than by looking at all. */
    static final int GRID_FROM = 32;
    private final Sheet sheet;
    int[] faces = new int[8];
    int count;
    /** Pairs (above << 32 | below) of overlapping faces. */
    LongList above = new LongList();
    int[] levels;
    int top = -1;

    /**
     * The faces by where they lie, once the stack is big enough. A face that moves or leaves
     * stays listed where it was ({@link #near} passes over it, and the faces it finds are
     * only candidates): the grid is made again once those are as many as the faces, not at
     * each tuck, which cost a big host's every face each time.
     */
    FaceGrid grid;

    /** The faces listed in the grid since it was made, those gone or moved since included. */
    int gridListed;

    void add(int f) {
        if (count == faces.length) {
            faces = Arrays.copyOf(faces, 2 * count);
        }
        sheet.slotOf[f] = count;
        faces[count++] = f;
        levels = null;
        if (grid != null) {
            grid.add(f, sheet.placedFaces.polygon(f));
            gridListed++;
        }
    }

    void remove(Set<Integer> gone) {
        // Marked by face, not looked up in the set: a tuck's flap leaves a stack of thousands,
        // and a boxed lookup for each of them was a fiftieth of the icosphere's folding.
        int stamp = sheet.nextMark();
        int[] goneMark = sheet.goneMark;
        for (int f : gone) {
            goneMark[f] = stamp;
        }
        int n = 0;
        for (int i = 0; i < count; i++) {
            if (goneMark[faces[i]] != stamp) {
                sheet.slotOf[faces[i]] = n;
                faces[n++] = faces[i];
            }
        }
        count = n;
        levels = null;
    }

    /**
     * The places in the stack, in order, of the faces that may overlap face f (listed in the
     * grid cells its polygon meets): all of them while the stack is small.
     */
    int[] near(int f) {
        return near(sheet.placedFaces.polygon(f), f);
    }

    /**
     * The places in the stack, in order, of the faces that may overlap a polygon (x y each, on the
     * host's frame), face {@code f} left out (-1: none).
     */
    int[] near(double[] polygon, int f) {
        if (grid != null && gridListed > 2 * count + GRID_FROM) {
            grid = null; // more listed faces gone or moved than there are faces
        }
        if (count >= GRID_FROM && grid == null) {
            double[][] polygons = new double[count][];
            for (int i = 0; i < count; i++) {
                polygons[i] = sheet.placedFaces.polygon(faces[i]);
            }
            grid = new FaceGrid(FaceGrid.cellFor(polygons, count, 2 * sheet.width));
            for (int i = 0; i < count; i++) {
                grid.add(faces[i], polygons[i]);
            }
            gridListed = count;
        }
        int[] listed = grid == null ? null : grid.near(polygon);
        if (listed != null) {
            // Faces that left the stack stay listed: only those still in it, by their place.
            int[] slots = new int[listed.length];
            int n = 0;
            for (int g : listed) {
                if (g != f && sheet.slotOf[g] < count && faces[sheet.slotOf[g]] == g) {
                    slots[n++] = sheet.slotOf[g];
                }
            }
            slots = Arrays.copyOf(slots, n);
            Arrays.sort(slots);
            return slots;
        }
        int[] all = new int[count];
        int n = 0;
        for (int i = 0; i < count; i++) {
            if (faces[i] != f) {
                all[n++] = i;
            }
        }
        return n == count ? all : Arrays.copyOf(all, n);
    }
    Stack(Sheet sheet) {
        this.sheet = sheet;
    }

    /**
     * The stack's relations by face: for each, the faces directly below it ({@code byUpper}) or
     * directly above it, in the order the relations were made.
     */
    static Related related(Stack stack, boolean byUpper) {
        return new Related(stack, byUpper);
    }

    /**
     * A stack's relations by face, one way, as arrays by the faces' places in the stack
     * (compressed rows): a tuck and a landing walk a few of them from a hinge or a strip, and a
     * map of boxed lists of them all, made at each, was a twentieth of what a wrap allocated
     * (the 5,000-triangle torus: 0.84 of 16 GB).
     */
    static final class Related {
        /**
         * The stack's faces by place when these were found, and where each one's run of others
         * starts. A face's place is looked up in the sheet and checked against them, and only
         * where it has moved since (a tuck's flap left the stack, and the tuck reads these then)
         * in a map of them all, made then: made at every tuck and landing, that map was a
         * fiftieth of the 5,120-triangle icosphere's folding.
         */
        private final int[] faces;
        private final Sheet sheet;
        private LongIntMap slots;
        private final int[] start;
        private final int[] others;

        /** No relations. */
        static final Related NONE = new Related();

        private Related() {
            faces = new int[0];
            sheet = null;
            start = new int[1];
            others = new int[0];
        }

        private Related(Stack stack, boolean byUpper) {
            // In compressed rows by the faces' places in the stack, each face's run in the order
            // the relations were made; the places looked up by face, not in the sheet, whose
            // places change once a tuck's flap has left the stack (and the tuck reads these then).
            int n = stack.count;
            int[] slotOf = stack.sheet.slotOf;
            this.faces = Arrays.copyOf(stack.faces, n);
            this.sheet = stack.sheet;
            int relations = stack.above.size();
            start = new int[n + 1];
            for (int r = 0; r < relations; r++) {
                long pair = stack.above.get(r);
                int key = byUpper ? (int) (pair >>> 32) : (int) pair;
                if (slotOf[key] >= n || stack.faces[slotOf[key]] != key) {
                    throw new IllegalStateException("a relation of face " + key + ", which is not in its stack");
                }
                start[slotOf[key] + 1]++;
            }
            for (int i = 0; i < n; i++) {
                start[i + 1] += start[i];
            }
            others = new int[relations];
            int[] fill = Arrays.copyOf(start, n);
            for (int r = 0; r < relations; r++) {
                long pair = stack.above.get(r);
                others[fill[slotOf[byUpper ? (int) (pair >>> 32) : (int) pair]]++] = byUpper ? (int) pair : (int) (pair >>> 32);
            }
        }

        /** The faces directly below (or above) face f: none where f has no relation this way. */
        List<Integer> of(int f) {
            int slot = slot(f);
            if (slot < 0) {
                return List.of();
            }
            int from = start[slot];
            int to = start[slot + 1];
            return new java.util.AbstractList<>() {
                @Override
                public Integer get(int index) {
                    return others[from + index];
                }

                @Override
                public int size() {
                    return to - from;
                }
            };
        }

        /** Face f's place in the stack when these were found, or -1 where it was not in it. */
        private int slot(int f) {
            if (faces.length == 0) {
                return -1;
            }
            // Any place holding f among these faces is its place then: each is in it once.
            int now = f < sheet.slotOf.length ? sheet.slotOf[f] : -1;
            if (now >= 0 && now < faces.length && faces[now] == f) {
                return now;
            }
            if (slots == null) {
                slots = new LongIntMap();
                for (int i = 0; i < faces.length; i++) {
                    slots.put(faces[i], i);
                }
            }
            return slots.get(f, -1);
        }
    }

    /**
     * The level of each face of the stack, by its place in it (0 on the surface: the longest chain
     * of faces below it), found again only after a change.
     */
    int[] findLevels() {
        if (levels != null) {
            return levels;
        }
        // Faces by their place in the stack, and the relations as arrays (compressed rows): a
        // stack folded over and over holds hundreds of thousands of them.
        int n = count;
        if (sheet.placeInStack.length < sheet.loops.size()) {
            sheet.placeInStack = new int[Math.max(sheet.loops.size(), 2 * sheet.placeInStack.length)];
        }
        int[] index = sheet.placeInStack; // only the stack's own faces are read, and all are written first
        for (int i = 0; i < n; i++) {
            index[faces[i]] = i;
        }
        int relations = above.size();
        // The working arrays are the sheet's, kept from call to call: the levels are found again
        // after every change of a stack, and new arrays each time were the most of a wrap's
        // allocation (0.9 of 12 GB on the 5,000-triangle torus).
        int[] uppers = sheet.levelScratch(0, relations);
        int[] lowers = sheet.levelScratch(1, relations);
        int[] below = sheet.levelScratch(2, n); // how many faces lie directly below each, still to place
        int[] start = sheet.levelScratch(3, n + 1);
        Arrays.fill(below, 0, n, 0);
        Arrays.fill(start, 0, n + 1, 0);
        for (int r = 0; r < relations; r++) {
            long pair = above.get(r);
            uppers[r] = index[(int) (pair >>> 32)];
            lowers[r] = index[(int) pair];
            below[uppers[r]]++;
            start[lowers[r] + 1]++;
        }
        for (int i = 0; i < n; i++) {
            start[i + 1] += start[i];
        }
        int[] fill = sheet.levelScratch(4, n);
        System.arraycopy(start, 0, fill, 0, n);
        int[] over = sheet.levelScratch(5, relations);
        for (int r = 0; r < relations; r++) {
            over[fill[lowers[r]]++] = uppers[r];
        }
        int[] level = new int[faces.length];
        int[] queue = sheet.levelScratch(6, n);
        int head = 0;
        int tail = 0;
        for (int i = 0; i < n; i++) {
            if (below[i] == 0) {
                queue[tail++] = i;
            }
        }
        while (head < tail) {
            int i = queue[head++];
            for (int k = start[i]; k < start[i + 1]; k++) {
                int upper = over[k];
                level[upper] = Math.max(level[upper], level[i] + 1);
                if (--below[upper] == 0) {
                    queue[tail++] = upper;
                }
            }
        }
        if (tail != n) {
            throw new IllegalStateException("the stack on host has a cycle: a face lies above itself");
        }
        int highest = -1;
        for (int i = 0; i < n; i++) {
            highest = Math.max(highest, level[i]);
        }
        top = highest;
        levels = level;
        return levels;
    }
}
