package ifold.foldfile;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * What a FOLD file says of one piece of paper, read and checked before anything is folded: its
 * key frame's vertices (2D: a crease pattern; 3D: a folded form, such as the FOLD repository's
 * box), edges with their assignments and fold angles, faces, face orders; and where the file
 * holds a folded state of its crease pattern as well (a {@code foldedForm} frame in
 * {@code file_frames}, as iFold writes), that state's vertices, face orders and levels. Every
 * index is checked against what it indexes; a key of the wrong kind is refused naming it.
 *
 * @param vertices each vertex's coordinates, 2 or 3 numbers
 * @param flat whether the key frame is a crease pattern (every z zero)
 * @param edges each edge's two vertices
 * @param assignments each edge's assignment, one of B M V F U C J ('U' where none is given)
 * @param angles each edge's fold angle in degrees, NaN where none is given
 * @param faces each face's vertices, or null where the file gives none
 * @param faceOrders the key frame's face orders [f, g, s], or an empty list
 * @param folded the folded state's vertices (3 numbers each), or null where the file holds none
 * @param foldedOrders the folded state's face orders, or an empty list
 * @param levels each face's level in its stack ({@code faces_ifold:level}), or null
 * @param facing each face's side out, +1 where its own normal (its corners counter-clockwise on
 *     the paper) points away from the surface it rests on, -1 where towards
 *     ({@code faces_ifold:facing}), or null
 * @param thickness the paper's ({@code frame_ifold:thickness}), or NaN
 * @param foldedForm whether the key frame says it is a folded form ({@code frame_classes}), its
 *     vertices where the paper lies folded even where they are 2D (a flat folded state)
 * @param unfolded the key frame's {@code vertices_flatUnfoldCoords} (where a folded form's
 *     vertices lie on the paper), or null
 */
record FoldInput(double[][] vertices, boolean flat, int[][] edges, char[] assignments, double[] angles, int[][] faces,
        List<int[]> faceOrders, double[][] folded, List<int[]> foldedOrders, int[] levels, int[] facing, double thickness,
        boolean foldedForm, double[][] unfolded) {

    /** The most vertices, edges or faces read: beyond, a file is refused before it fills memory. */
    static final int MOST_ITEMS = 2_000_000;

    static FoldInput read(Map<String, Object> fold) throws CreasePattern.Refused {
        double[][] vertices = numbers(fold, "vertices_coords", 2, 3, true);
        boolean flat = true;
        for (int i = 0; i < vertices.length; i++) {
            for (double c : vertices[i]) {
                if (!Double.isFinite(c)) {
                    throw new CreasePattern.Refused("vertex " + i + ": vertices_coords must hold finite numbers");
                }
            }
            flat &= vertices[i].length == 2 || vertices[i][2] == 0;
        }
        int n = vertices.length;
        int[][] edges = indices(fold, "edges_vertices", n, "vertices", 2, 2, false);
        char[] assignments = new char[edges.length];
        java.util.Arrays.fill(assignments, 'U');
        if (fold.containsKey("edges_assignment")) {
            List<?> given = list(fold, "edges_assignment", edges.length);
            for (int e = 0; e < edges.length; e++) {
                if (!(given.get(e) instanceof String text) || text.length() != 1 || "BMVFUCJbmvfucj".indexOf(text.charAt(0)) < 0) {
                    throw new CreasePattern.Refused("edge " + e + ": edges_assignment gives it " + text(given.get(e))
                            + ", not one of B, M, V, F, U, C or J");
                }
                assignments[e] = Character.toUpperCase(((String) given.get(e)).charAt(0));
                if (assignments[e] == 'C') {
                    throw new CreasePattern.Refused("edge " + e + " is C, a cut: iFold folds paper in one piece, its outline B; a cut"
                            + " is two border edges, one a side, with vertices of their own");
                }
            }
        }
        double[] angles = new double[edges.length];
        java.util.Arrays.fill(angles, Double.NaN);
        if (fold.containsKey("edges_foldAngle")) {
            List<?> given = list(fold, "edges_foldAngle", edges.length);
            for (int e = 0; e < edges.length; e++) {
                Object angle = given.get(e);
                if (angle == null) {
                    continue;
                }
                if (!(angle instanceof Number number) || !Double.isFinite(number.doubleValue()) || Math.abs(number.doubleValue()) > 180) {
                    throw new CreasePattern.Refused("edge " + e + ": edges_foldAngle gives it " + text(angle)
                            + ", not a number of degrees from -180 to 180");
                }
                angles[e] = number.doubleValue();
            }
        }
        int[][] faces = fold.containsKey("faces_vertices") ? indices(fold, "faces_vertices", n, "vertices", 3, Integer.MAX_VALUE, false) : null;
        List<int[]> faceOrders = faces == null ? List.of() : orders(fold, faces.length);
        double[][] folded = null;
        List<int[]> foldedOrders = List.of();
        int[] levels = null;
        int[] facing = null;
        double thickness = Double.NaN;
        if (fold.containsKey("frame_ifold:thickness")) {
            if (!(fold.get("frame_ifold:thickness") instanceof Number t) || !(t.doubleValue() >= 0) || !Double.isFinite(t.doubleValue())) {
                throw new CreasePattern.Refused("frame_ifold:thickness gives " + text(fold.get("frame_ifold:thickness"))
                        + ", not a thickness of zero or more");
            }
            thickness = t.doubleValue();
        }
        if (fold.get("file_frames") instanceof List<?> frames) {
            for (Object item : frames) {
                if (item instanceof Map<?, ?> frame && frame.get("frame_classes") instanceof List<?> classes && classes.contains("foldedForm")
                        && frame.containsKey("vertices_coords") && faces != null) {
                    @SuppressWarnings("unchecked")
                    Map<String, Object> state = (Map<String, Object>) frame;
                    folded = numbers(state, "vertices_coords", 3, 3, false);
                    if (folded.length != n) {
                        throw new CreasePattern.Refused(String.format(Locale.ROOT, "file_frames: the folded state has %d vertices for the"
                                + " crease pattern's %d", folded.length, n));
                    }
                    for (int i = 0; i < n; i++) {
                        for (double c : folded[i]) {
                            if (!Double.isFinite(c)) {
                                throw new CreasePattern.Refused("file_frames: vertex " + i + " of the folded state is not finite");
                            }
                        }
                    }
                    foldedOrders = orders(state, faces.length);
                    if (state.get("faces_ifold:facing") instanceof List<?> sides && sides.size() == faces.length) {
                        facing = new int[faces.length];
                        for (int f = 0; f < facing.length; f++) {
                            if (!(sides.get(f) instanceof Number side) || Math.abs(side.doubleValue()) != 1) {
                                throw new CreasePattern.Refused("file_frames: faces_ifold:facing gives face " + f + " " + text(sides.get(f))
                                        + ", not 1 or -1");
                            }
                            facing[f] = side.intValue();
                        }
                    }
                    if (state.get("faces_ifold:level") instanceof List<?> given && given.size() == faces.length) {
                        levels = new int[faces.length];
                        for (int f = 0; f < levels.length; f++) {
                            if (!(given.get(f) instanceof Number level) || level.doubleValue() < 0 || level.doubleValue() != Math.rint(level.doubleValue())
                                    || level.doubleValue() > MOST_ITEMS) {
                                throw new CreasePattern.Refused("file_frames: faces_ifold:level gives face " + f + " " + text(given.get(f))
                                        + ", not a level");
                            }
                            levels[f] = level.intValue();
                        }
                    }
                    break;
                }
            }
        }
        boolean foldedForm = fold.get("frame_classes") instanceof List<?> classes && classes.contains("foldedForm");
        double[][] unfolded = null;
        if (foldedForm && fold.containsKey("vertices_flatUnfoldCoords")) {
            unfolded = numbers(fold, "vertices_flatUnfoldCoords", 2, 3, true);
            if (unfolded.length != n) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "vertices_flatUnfoldCoords has %d vertices for %d", unfolded.length,
                        n));
            }
        }
        return new FoldInput(vertices, flat, edges, assignments, angles, faces, faceOrders, folded, foldedOrders, levels, facing,
                thickness, foldedForm, unfolded);
    }

    private static List<?> list(Map<String, Object> fold, String key, int size) throws CreasePattern.Refused {
        if (!(fold.get(key) instanceof List<?> list)) {
            throw new CreasePattern.Refused(key + " must be a list");
        }
        if (list.size() != size) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s must give each edge its value: it has %d for %d edges", key,
                    list.size(), size));
        }
        return list;
    }

    /** {@code key}'s lists of {@code least} to {@code most} numbers; refused where missing (if {@code required}) or malformed. */
    private static double[][] numbers(Map<String, Object> fold, String key, int least, int most, boolean required) throws CreasePattern.Refused {
        if (!(fold.get(key) instanceof List<?> list) || list.isEmpty()) {
            throw new CreasePattern.Refused("no " + key + ": a FOLD file to fold needs vertices_coords and edges_vertices (or faces_vertices)");
        }
        if (list.size() > MOST_ITEMS) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s holds %,d entries, more than the %,d iFold reads", key, list.size(),
                    MOST_ITEMS));
        }
        double[][] points = new double[list.size()][];
        for (int i = 0; i < points.length; i++) {
            if (!(list.get(i) instanceof List<?> coords) || coords.size() < least || coords.size() > most) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s must be a list of lists of %d%s numbers: entry %d is %s", key,
                        least, least == most ? "" : " or " + most, i, text(list.get(i))));
            }
            points[i] = new double[coords.size()];
            for (int k = 0; k < coords.size(); k++) {
                if (!(coords.get(k) instanceof Number number)) {
                    throw new CreasePattern.Refused(key + " must be a list of lists of numbers: entry " + i + " holds " + text(coords.get(k)));
                }
                points[i][k] = number.doubleValue();
            }
        }
        return points;
    }

    /** {@code key}'s lists of indices into {@code count} {@code what}, {@code least} to {@code most} each, none repeated in a list. */
    private static int[][] indices(Map<String, Object> fold, String key, int count, String what, int least, int most, boolean empty)
            throws CreasePattern.Refused {
        if (!(fold.get(key) instanceof List<?> list) || (list.isEmpty() && !empty)) {
            throw new CreasePattern.Refused("no " + key + ": a FOLD file to fold needs vertices_coords and edges_vertices");
        }
        if (list.size() > MOST_ITEMS) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s holds %,d entries, more than the %,d iFold reads", key, list.size(),
                    MOST_ITEMS));
        }
        int[][] result = new int[list.size()][];
        String item = key.substring(0, key.indexOf('_') - 1);
        for (int i = 0; i < result.length; i++) {
            if (!(list.get(i) instanceof List<?> given) || given.size() < least || given.size() > most) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s %d: %s must name %s %s", item, i, key,
                        least == most ? "two" : "at least " + least, what));
            }
            result[i] = new int[given.size()];
            for (int k = 0; k < given.size(); k++) {
                if (!(given.get(k) instanceof Number number) || number.doubleValue() != Math.rint(number.doubleValue())
                        || number.doubleValue() < 0 || number.doubleValue() >= count) {
                    throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s %d: %s names %s, not one of the %,d %s", item, i, key,
                            text(given.get(k)), count, what));
                }
                result[i][k] = number.intValue();
                for (int j = 0; j < k; j++) {
                    if (result[i][j] == result[i][k]) {
                        throw new CreasePattern.Refused(String.format(Locale.ROOT, "%s %d: %s names vertex %d twice", item, i, key,
                                result[i][k]));
                    }
                }
            }
        }
        return result;
    }

    /** A frame's {@code faceOrders}: [f, g, s], faces within range, s one of -1, 0, +1. */
    private static List<int[]> orders(Map<String, Object> frame, int faces) throws CreasePattern.Refused {
        if (!frame.containsKey("faceOrders")) {
            return List.of();
        }
        if (!(frame.get("faceOrders") instanceof List<?> list)) {
            throw new CreasePattern.Refused("faceOrders must be a list");
        }
        List<int[]> orders = new ArrayList<>();
        for (int i = 0; i < list.size(); i++) {
            if (!(list.get(i) instanceof List<?> order) || order.size() != 3) {
                throw new CreasePattern.Refused("faceOrders entry " + i + " must be [f, g, s]");
            }
            int[] o = new int[3];
            for (int k = 0; k < 3; k++) {
                if (!(order.get(k) instanceof Number number) || number.doubleValue() != Math.rint(number.doubleValue())) {
                    throw new CreasePattern.Refused("faceOrders entry " + i + " must be [f, g, s] of whole numbers");
                }
                o[k] = number.intValue();
            }
            if (o[0] < 0 || o[0] >= faces || o[1] < 0 || o[1] >= faces || Math.abs(o[2]) > 1) {
                throw new CreasePattern.Refused(String.format(Locale.ROOT, "faceOrders entry %d: [%d, %d, %d] names a face that is not one"
                        + " of the %d, or a side not -1, 0 or 1", i, o[0], o[1], o[2], faces));
            }
            orders.add(o);
        }
        return orders;
    }

    /** A value as a message quotes it. */
    static String text(Object value) {
        if (value instanceof String s) {
            return "\"" + (s.length() > 20 ? s.substring(0, 20) + "…" : s) + "\"";
        }
        if (value instanceof Number number) {
            return CreasePattern.fmt(number.doubleValue());
        }
        if (value instanceof List<?>) {
            return "a list";
        }
        if (value instanceof Map<?, ?>) {
            return "an object";
        }
        return String.valueOf(value);
    }
}
