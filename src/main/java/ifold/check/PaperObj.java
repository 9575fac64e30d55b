package ifold.check;

import java.util.Arrays;

/**
 * The paper of an exported wrap, read from its OBJ text alone: vertices, faces (in file order,
 * each a paper face or a cap) and their triangles (fans of the convex faces).
 *
 * <p>The format is what {@code ifold wrap --export-obj} writes: objects {@code o strip-K}, each with
 * {@code v x y z} lines, {@code vt u v} lines (paper coordinates, not needed here and not parsed),
 * and faces {@code f v/vt ...} in groups {@code g paper} and {@code g cap}. Indices may be
 * negative (relative), as OBJ allows. Normals, materials and smoothing groups are ignored.
 */
final class PaperObj {
    /** Vertex positions, x y z interleaved, in file order (0-based: OBJ vertex k is k - 1). */
    final double[] xyz;
    /** Face f's corners are corner[faceStart[f] .. faceStart[f + 1]) (0-based vertex indices). */
    final int[] faceStart;
    final int[] corner;
    /** Whether face f is a cap (group {@code cap}), else paper. */
    final boolean[] cap;
    /** The line face f is on (1-based), for messages. */
    final int[] line;
    /** Triangle t's corners are vertices tri[3t], tri[3t + 1], tri[3t + 2]: fans (c0, ci, ci+1) of each face. */
    final int[] tri;
    /** The face (0-based, file order) each triangle belongs to. */
    final int[] triFace;
    /** The number of {@code o} objects (strips). */
    final int strips;

    private PaperObj(double[] xyz, int[] faceStart, int[] corner, boolean[] cap, int[] line, int strips) {
        this.xyz = xyz;
        this.faceStart = faceStart;
        this.corner = corner;
        this.cap = cap;
        this.line = line;
        this.strips = strips;
        int faces = faceCount();
        int triangles = 0;
        for (int f = 0; f < faces; f++) {
            triangles += faceStart[f + 1] - faceStart[f] - 2;
        }
        tri = new int[3 * triangles];
        triFace = new int[triangles];
        int t = 0;
        for (int f = 0; f < faces; f++) {
            int first = faceStart[f];
            for (int c = first + 1; c + 1 < faceStart[f + 1]; c++) {
                tri[3 * t] = corner[first];
                tri[3 * t + 1] = corner[c];
                tri[3 * t + 2] = corner[c + 1];
                triFace[t++] = f;
            }
        }
    }

    int faceCount() {
        return faceStart.length - 1;
    }

    int vertexCount() {
        return xyz.length / 3;
    }

    int triangleCount() {
        return triFace.length;
    }

    /**
     * Reads the OBJ text of folded paper.
     *
     * @throws IllegalArgumentException naming the line: a face outside an object or outside the
     *     groups {@code paper} and {@code cap}, with fewer than 3 corners, or naming a vertex not
     *     read so far; a group other than those two; a vertex that is not three finite numbers
     */
    static PaperObj read(CharSequence objText) {
        String text = objText.toString();
        Doubles xyz = new Doubles();
        Ints faceStart = new Ints();
        Ints corner = new Ints();
        Ints line = new Ints();
        boolean[] cap = new boolean[64];
        faceStart.add(0);
        int strips = 0;
        int group = -1;
        int length = text.length();
        int lineNo = 0;
        int start = 0;
        while (start < length) {
            lineNo++;
            int end = text.indexOf('\n', start);
            int next = end < 0 ? length : end + 1;
            end = end < 0 ? length : end;
            if (end > start && text.charAt(end - 1) == '\r') {
                end--;
            }
            int p = skipSpace(text, start, end);
            if (p < end && text.charAt(p) == 'v' && p + 1 < end && text.charAt(p + 1) == 't') {
                // Paper coordinates: most of the file, and nothing to check collisions with.
                start = next;
                continue;
            }
            if (p < end) {
                char c0 = text.charAt(p);
                char c1 = p + 1 < end ? text.charAt(p + 1) : ' ';
                boolean word = c1 == ' ' || c1 == '\t';
                if (c0 == 'v' && word) {
                    for (int k = 0; k < 3; k++) {
                        p = skipSpace(text, p + (k == 0 ? 1 : 0), end);
                        int q = tokenEnd(text, p, end);
                        require(q > p, lineNo, "a vertex needs x y z");
                        double value;
                        try {
                            value = Decimals.parse(text, p, q);
                        } catch (NumberFormatException e) {
                            throw new IllegalArgumentException("line " + lineNo + ": not a number: '" + text.subSequence(p, q) + "'", e);
                        }
                        require(Double.isFinite(value), lineNo, "a vertex coordinate is not finite");
                        xyz.add(value);
                        p = q;
                    }
                } else if (c0 == 'o' && word) {
                    strips++;
                } else if (c0 == 'g' && word) {
                    int q = skipSpace(text, p + 1, end);
                    String name = text.subSequence(q, tokenEnd(text, q, end)).toString();
                    require(name.equals("paper") || name.equals("cap"), lineNo, "the groups are paper and cap, not '" + name + "'");
                    group = name.equals("cap") ? 1 : 0;
                } else if (c0 == 'f' && word) {
                    require(strips > 0, lineNo, "a face before any 'o' strip");
                    require(group >= 0, lineNo, "a face before any 'g paper' or 'g cap'");
                    int corners = 0;
                    int vertices = xyz.size() / 3;
                    p = skipSpace(text, p + 1, end);
                    while (p < end) {
                        int q = tokenEnd(text, p, end);
                        corner.add(vertexIndex(text, p, q, vertices, lineNo));
                        corners++;
                        p = skipSpace(text, q, end);
                    }
                    require(corners >= 3, lineNo, "a face needs 3 or more corners");
                    int f = faceStart.size() - 1;
                    if (f == cap.length) {
                        cap = Arrays.copyOf(cap, 2 * f);
                    }
                    cap[f] = group == 1;
                    faceStart.add(corner.size());
                    line.add(lineNo);
                }
                // vt, vn, s, usemtl, comments: nothing to check collisions with.
            }
            start = next;
        }
        int faces = faceStart.size() - 1;
        return new PaperObj(xyz.toArray(), faceStart.toArray(), corner.toArray(), Arrays.copyOf(cap, faces), line.toArray(), strips);
    }

    private static int skipSpace(String text, int p, int end) {
        while (p < end && (text.charAt(p) == ' ' || text.charAt(p) == '\t')) {
            p++;
        }
        return p;
    }

    private static int tokenEnd(String text, int p, int end) {
        while (p < end && text.charAt(p) != ' ' && text.charAt(p) != '\t') {
            p++;
        }
        return p;
    }

    /** The vertex of corner token [p, q) ("k", "k/t", "k//n", "k/t/n"), 0-based; OBJ counts only vertices read so far. */
    private static int vertexIndex(String text, int p, int q, int vertices, int lineNo) {
        boolean negative = p < q && text.charAt(p) == '-';
        int i = negative ? p + 1 : p;
        long k = 0;
        int digits = 0;
        while (i < q && text.charAt(i) != '/') {
            char c = text.charAt(i);
            if (c < '0' || c > '9' || digits == 11) {
                require(false, lineNo, "not a vertex index: '" + text.substring(p, q) + "'");
            }
            k = 10 * k + (c - '0');
            digits++;
            i++;
        }
        if (digits == 0) {
            require(false, lineNo, "not a vertex index: '" + text.substring(p, q) + "'");
        }
        long v = negative ? vertices - k : k - 1;
        if (k == 0 || v < 0 || v >= vertices) {
            require(false, lineNo, "vertex " + text.substring(p, i) + " is not among the " + vertices + " read so far");
        }
        return (int) v;
    }

    private static void require(boolean condition, int lineNo, String message) {
        if (!condition) {
            throw new IllegalArgumentException("line " + lineNo + ": " + message);
        }
    }

    /** A growable list of doubles. */
    static final class Doubles {
        private double[] items = new double[48];
        private int size;

        void add(double value) {
            if (size == items.length) {
                items = Arrays.copyOf(items, 2 * size);
            }
            items[size++] = value;
        }

        int size() {
            return size;
        }

        double get(int i) {
            return items[i];
        }

        double[] toArray() {
            return Arrays.copyOf(items, size);
        }
    }
}
