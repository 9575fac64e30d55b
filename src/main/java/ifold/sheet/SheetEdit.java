package ifold.sheet;

import ifold.geom.IntList;
import ifold.sheet.Sheet.Crease;
import ifold.sheet.Sheet.Placement;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * An edit of the paper already laid, as a fold of it makes: cut faces along a line, then
 * move some of them to a host (the same one, reflected, or another) over or under the paper
 * there. Every face it cuts or moves is journaled with its loop, pose and host before, for
 * the animation.
 */
public final class SheetEdit {
    private final Sheet sheet;
    private final int facesBefore;
    /** The faces made before the edit that it changed, each noted once (the set of them in {@link #noted}). */
    private final IntList changedFaces = new IntList();
    private final LongIntMap noted = new LongIntMap(3);
    private final List<int[]> loopsBefore = new ArrayList<>();
    private final List<Isometry2> posesBefore = new ArrayList<>();
    private final IntList hostsBefore = new IntList();
    private final LongIntMap splitOfEdge = new LongIntMap(3);

    /** Faces whose shape changed (cut, or made by a cut): their relations are checked again. */
    private final Set<Integer> reshaped = new HashSet<>();

    /** For each face made by a cut, the face it was cut from. */
    private final IntList parents = new IntList();

    /** Whether a cut ran along a line on the sheet rather than on a host. */
    private boolean sheetCut;

    SheetEdit(Sheet sheet) {
        this.sheet = sheet;
        this.facesBefore = sheet.loops.size();
    }

    /**
     * What the edit did.
     *
     * @param facesBefore the faces before it: those from it on were cut off by it
     * @param changed the faces there before that it cut or moved
     * @param loopsBefore their loops before
     * @param posesBefore their poses before
     * @param hostsBefore their hosts before
     * @param parents for each face made by the edit (facesBefore, facesBefore + 1, ...), the
     *     face there before that it was cut from
     */
    public record Journal(int facesBefore, int[] changed, int[][] loopsBefore, Isometry2[] posesBefore, int[] hostsBefore,
            int[] parents) {
        /** The face there before the edit that face g was cut from (g itself if it was there). */
        public int parentOf(int g) {
            return g < facesBefore ? g : parents[g - facesBefore];
        }
    }

    public Journal journal() {
        return new Journal(facesBefore, changedFaces.toArray(), loopsBefore.toArray(new int[0][]), posesBefore.toArray(new Isometry2[0]),
                hostsBefore.toArray(), parents.toArray());
    }

    private void note(int f) {
        if (f < facesBefore && noted.get(f, -1) < 0) {
            noted.put(f, changedFaces.size());
            changedFaces.add(f);
            loopsBefore.add(sheet.loops.get(f));
            posesBefore.add(sheet.poseOf.get(f));
            hostsBefore.add(sheet.hostOf[f]);
        }
    }

    /**
     * Cuts the faces on {@code host} that the directed line through (px, py) with direction
     * (dx, dy), in the host's frame, crosses.
     *
     * @return the faces of the host right of the line, after cutting
     */
    public int[] cutOnHost(int host, double px, double py, double dx, double dy) {
        Stack stack = sheet.stacks.get(host);
        if (stack == null) {
            return new int[0];
        }
        double length = Math.hypot(dx, dy);
        double nx = dy / length; // right of the direction
        double ny = -dx / length;
        double c = nx * px + ny * py;
        return cut(Arrays.copyOf(stack.faces, stack.count), nx, ny, c, false);
    }

    /**
     * Cuts every face the directed line through paper points (u1, v1) and (u2, v2) crosses,
     * wherever it lies.
     *
     * @return the faces right of the line on the sheet (seen from its top), after cutting
     */
    public int[] cutOnSheet(double u1, double v1, double u2, double v2) {
        double du = u2 - u1;
        double dv = v2 - v1;
        double length = Math.hypot(du, dv);
        double nu = dv / length;
        double nv = -du / length;
        double c = nu * u1 + nv * v1;
        sheetCut = true;
        int[] all = new int[sheet.loops.size()];
        for (int f = 0; f < all.length; f++) {
            all[f] = f;
        }
        return cut(all, nu, nv, c, true);
    }

    /**
     * Cuts those of {@code faces} that the line n·p = c crosses (p in their host's frame, or
     * on the sheet): each keeps its near side, a new face takes the far side.
     *
     * @return the faces beyond the line, after cutting
     */
    private int[] cut(int[] faces, double nx, double ny, double c, boolean onSheet) {
        IntList beyond = new IntList();
        IntList split = new IntList(); // each face split, then the part cut off it
        for (int f : faces) {
            double[] range = range(f, nx, ny, c, onSheet);
            if (range[1] <= sheet.tolerance) {
                continue;
            }
            note(f);
            if (range[0] >= -sheet.tolerance) {
                beyond.add(f);
                continue;
            }
            int g = split(f, nx, ny, c, onSheet, splitOfEdge, this);
            split.add(f);
            split.add(g);
            beyond.add(g);
        }
        // Each new part inherits its face's relations, in one pass over each stack's (a cut
        // across a deep stack splits thousands of faces); those that no longer overlap are
        // dropped later. The parts by face in an array of the sheet's, not a map of boxed
        // numbers: a wrap cuts stacks of thousands of relations hundreds of thousands of times.
        int[] partOf = sheet.partOfFace();
        Set<Integer> hosts = new java.util.LinkedHashSet<>();
        for (int k = 0; k < split.size(); k += 2) {
            partOf[split.get(k)] = split.get(k + 1);
            hosts.add(sheet.hostOf[split.get(k)]);
        }
        try {
            for (int host : hosts) {
                Stack stack = sheet.stacks.get(host);
                LongList inherited = new LongList();
                for (int r = 0; r < stack.above.size(); r++) {
                    long pair = stack.above.get(r);
                    int upper = partOf[(int) (pair >>> 32)];
                    int lower = partOf[(int) pair];
                    if (upper >= 0) {
                        inherited.add(((long) upper << 32) | (pair & 0xffffffffL));
                    }
                    if (lower >= 0) {
                        inherited.add((pair & ~0xffffffffL) | lower);
                    }
                    if (upper >= 0 && lower >= 0) {
                        inherited.add(((long) upper << 32) | lower);
                    }
                }
                stack.above.addAll(inherited);
            }
        } finally {
            for (int k = 0; k < split.size(); k += 2) {
                partOf[split.get(k)] = -1;
            }
        }
        return beyond.toArray();
    }

    private double[] range(int f, double nx, double ny, double c, boolean onSheet) {
        int[] loop = sheet.loops.get(f);
        Isometry2 pose = sheet.poseOf.get(f);
        double min = Double.POSITIVE_INFINITY;
        double max = Double.NEGATIVE_INFINITY;
        for (int v : loop) {
            double d = onSheet ? nx * sheet.u(v) + ny * sheet.v(v) - c : nx * pose.x(sheet.u(v), sheet.v(v)) + ny * pose.y(sheet.u(v), sheet.v(v)) - c;
            min = Math.min(min, d);
            max = Math.max(max, d);
        }
        return new double[] {min, max};
    }

    /** Marks the paper edges between {@code moving} faces and the rest as creases of {@code kind}, where they are not creases already. */
    public void crease(Set<Integer> moving, Crease kind) {
        int value = kind.ordinal() + Sheet.CREASES.length * sheet.creasingFolds++;
        for (int f : moving) {
            int[] loop = sheet.loops.get(f);
            for (int i = 0; i < loop.length; i++) {
                int a = loop[i];
                int b = loop[(i + 1) % loop.length];
                int across = sheet.faceOfEdge.get(b, a, -1);
                if (across >= 0 && !moving.contains(across) && sheet.creases.get(Sheet.undirected(a, b), -1) < 0) {
                    sheet.creases.put(Sheet.undirected(a, b), value);
                }
            }
        }
    }

    /**
     * Moves {@code faces}, all resting on one host, to {@code toHost} (which may be the same):
     * each pose is composed with {@code frameChange}, which maps the old host's frame to the
     * new one's. Their order among themselves is kept, or reversed where the change mirrors
     * (the paper turned over); where they overlap paper already on the new host they land
     * {@code placement} it.
     */
    public void move(Set<Integer> faces, int toHost, Isometry2 frameChange, Placement placement) {
        move(faces, toHost, frameChange, placement, null, null);
    }

    /**
     * Tucks {@code faces}, resting on one host, under across the fold line (nx, ny)·p = c, their
     * layers nesting about the line, and not around a strip crossing it to another host
     * ({@link TuckPlacement#tuckUnder}).
     */
    public void tuckUnder(Set<Integer> faces, Isometry2 reflection, double nx, double ny, double c) {
        TuckPlacement.tuckUnder(this, sheet, faces, reflection, nx, ny, c);
    }

    /**
     * As {@link #move(Set, int, Isometry2, Placement)}; with a {@code tuckPlace} (not null),
     * a tuck ({@link #tuckUnder}), placed as {@link TuckPlacement#placeTucked} says, with the stack's
     * levels before the move {@code levelBefore} (by face: read for the stack's faces only).
     */
    void move(Set<Integer> faces, int toHost, Isometry2 frameChange, Placement placement, TuckPlacement.TuckPlace tuckPlace,
            int[] levelBefore) {
        if (faces.isEmpty()) {
            return;
        }
        int fromHost = sheet.hostOf[faces.iterator().next()];
        Stack from = sheet.stacks.get(fromHost);
        boolean mirrors = frameChange.mirrors();
        // The relations that stay are kept in the stack's own list, in their order: a new list of
        // them at each tuck was a fortieth of what the 5,000-triangle torus allocated.
        LongList kept = from.above;
        int keptCount = 0;
        LongList carried = new LongList();
        // Marks by face, not set lookups: a stack folded again and again holds many relations.
        // (Kept by the sheet and told apart by a count, not cleared: a tuck must not cost the
        // whole sheet.)
        int moves = sheet.nextMark();
        for (int f : faces) {
            sheet.mark[f] = moves;
        }
        int cut = sheet.nextMark();
        for (int f : reshaped) {
            sheet.cutMark[f] = cut;
        }
        // A cut along a line on the sheet can take away paper that lay between two faces that
        // stay, wherever they lie: their order, implied through it, is then recorded itself.
        Map<Integer, List<Integer>> stayingAbove = new HashMap<>();
        Map<Integer, List<Integer>> stayingBelow = new HashMap<>();
        for (int r = 0; r < from.above.size(); r++) {
            long pair = from.above.get(r);
            int upper = (int) (pair >>> 32);
            int lower = (int) pair;
            boolean upperMoves = sheet.mark[upper] == moves;
            boolean lowerMoves = sheet.mark[lower] == moves;
            if (upperMoves != lowerMoves) {
                if (sheetCut) {
                    (upperMoves ? stayingBelow : stayingAbove).computeIfAbsent(upperMoves ? upper : lower, k -> new ArrayList<>())
                            .add(upperMoves ? lower : upper);
                }
                continue; // they lay side by side before; where the moved paper lands is decided below
            }
            if ((sheet.cutMark[upper] == cut || sheet.cutMark[lower] == cut) && !sheet.placedFaces.overlap(upper, lower)) {
                continue; // a face cut by the line keeps only the relations of the part that overlaps
            }
            if (upperMoves) {
                carried.add(mirrors ? ((long) lower << 32) | upper : pair);
            } else {
                kept.set(keptCount++, pair); // never ahead of r: the list read is the one written
            }
        }
        kept.truncate(keptCount);
        for (Map.Entry<Integer, List<Integer>> entry : stayingAbove.entrySet()) {
            for (int upper : entry.getValue()) {
                for (int lower : stayingBelow.getOrDefault(entry.getKey(), List.of())) {
                    if (sheet.placedFaces.overlap(upper, lower)) {
                        kept.add(((long) upper << 32) | lower);
                    }
                }
            }
        }
        from.remove(faces);
        for (int f : faces) {
            note(f);
            if (sheet.hostOf[f] != fromHost) {
                throw new IllegalArgumentException("the faces moved together must rest on one host");
            }
            sheet.poseOf.set(f, frameChange.after(sheet.poseOf.get(f)));
            sheet.hostOf[f] = toHost;
            sheet.placedFaces.forget(f);
        }
        Stack to = sheet.stacks.computeIfAbsent(toHost, h -> new Stack(sheet));
        if (tuckPlace != null) {
            TuckPlacement.placeTucked(sheet, faces, to, carried, tuckPlace, levelBefore);
            to.levels = null;
            from.levels = null;
            return;
        }
        // Each moved face lands over (or under) the faces it overlaps, unless a moved face it
        // rests on, and that holds all of it, lies between: the order is then implied, and a
        // stack folded again and again would otherwise hold every pair of its layers.
        Map<Integer, List<Integer>> between = new HashMap<>();
        for (int r = 0; r < carried.size(); r++) {
            long pair = carried.get(r);
            int upper = (int) (pair >>> 32);
            int lower = (int) pair;
            if (placement == Placement.OVER) {
                between.computeIfAbsent(upper, k -> new ArrayList<>()).add(lower);
            } else {
                between.computeIfAbsent(lower, k -> new ArrayList<>()).add(upper);
            }
        }
        // A face there already that the moved face overlaps too, lying directly between and
        // holding all of where the two overlap, implies the order as well: paper folded onto a
        // pile lands on its top layer, not on each, or a pleat of n folds would hold n²
        // relations and each fold cost what the pile holds. (The order is kept where the
        // face between later leaves: see stayingAbove.)
        Between direct = new Between(to.above, placement);
        for (int f : faces) {
            int holds = sheet.placedFaces.nextHoldsStamp();
            for (int i = 0; i < to.count; i++) {
                int g = to.faces[i];
                // First the cheap cases, without even asking whether f and g overlap: a face
                // directly on f's side of g that holds all of g, or all of f, holds all of
                // where they overlap. Each fold of a pleat lands on a pile whose every layer
                // holds the one below: asked of each pair of layers, the pile of n folds cost
                // n² overlaps (24 s for 10,000 creases).
                boolean implied = false;
                for (int k = direct.start(g); k < direct.end(g) && !implied; k++) {
                    int h = direct.face(k);
                    implied = sheet.placedFaces.holdsFace(h, g) || sheet.placedFaces.holdsAll(h, f, holds);
                }
                if (implied || !sheet.placedFaces.overlap(f, g)) {
                    continue;
                }
                for (int h : between.getOrDefault(f, List.of())) {
                    if (sheet.placedFaces.contains(h, f) && sheet.placedFaces.overlap(h, g)) {
                        implied = true;
                        break;
                    }
                }
                for (int k = direct.start(g); k < direct.end(g) && !implied; k++) {
                    int h = direct.face(k);
                    implied = sheet.placedFaces.overlap(f, h) && sheet.placedFaces.holdsOverlap(h, f, g);
                }
                if (!implied) {
                    to.above.add(placement == Placement.OVER ? ((long) f << 32) | g : ((long) g << 32) | f);
                }
            }
        }
        to.above.addAll(carried);
        for (int f : faces) {
            to.add(f);
        }
        to.levels = null;
        from.levels = null;
    }

    /**
     * Cuts face f along the line n·p = c: f keeps the part on the near side, a new face the
     * part beyond, which is returned. Each crossing edge gets one new vertex, shared with the
     * face across it on the sheet, which is given the vertex too so that no edge of the sheet
     * ends in the middle of another.
     */
    private int split(int f, double nx, double ny, double c, boolean onSheet, LongIntMap splitOfEdge, SheetEdit edit) {
        int[] loop = sheet.loops.get(f);
        Isometry2 pose = sheet.poseOf.get(f);
        int n = loop.length;
        double[] d = new double[n];
        for (int i = 0; i < n; i++) {
            int v = loop[i];
            d[i] = onSheet ? nx * sheet.u(v) + ny * sheet.v(v) - c : nx * pose.x(sheet.u(v), sheet.v(v)) + ny * pose.y(sheet.u(v), sheet.v(v)) - c;
        }
        int[] withSplits = new int[2 * n];
        int[] side = new int[2 * n];
        int m = 0;
        for (int i = 0; i < n; i++) {
            int j = (i + 1) % n;
            withSplits[m] = loop[i];
            side[m++] = d[i] > sheet.tolerance ? 1 : d[i] < -sheet.tolerance ? -1 : 0;
            if ((d[i] > sheet.tolerance && d[j] < -sheet.tolerance) || (d[i] < -sheet.tolerance && d[j] > sheet.tolerance)) {
                int a = loop[i];
                int b = loop[j];
                int split = splitOfEdge.get(Sheet.undirected(a, b), -1);
                if (split < 0) {
                    double t = d[i] / (d[i] - d[j]);
                    split = sheet.addVertex(sheet.u(a) + t * (sheet.u(b) - sheet.u(a)), sheet.v(a) + t * (sheet.v(b) - sheet.v(a)));
                    splitOfEdge.put(Sheet.undirected(a, b), split);
                    insertAcross(a, b, split, edit);
                }
                withSplits[m] = split;
                side[m++] = 0;
            }
        }
        int[] near = new int[m];
        int[] far = new int[m];
        int nearCount = 0;
        int farCount = 0;
        for (int i = 0; i < m; i++) {
            if (side[i] <= 0) {
                near[nearCount++] = withSplits[i];
            }
            if (side[i] >= 0) {
                far[farCount++] = withSplits[i];
            }
        }
        sheet.unregister(f);
        sheet.loops.set(f, Arrays.copyOf(near, nearCount));
        sheet.placedFaces.forget(f);
        sheet.register(f);
        int g = sheet.loops.size();
        sheet.loops.add(Arrays.copyOf(far, farCount));
        sheet.poseOf.add(pose);
        sheet.ensureFaceCapacity(g + 1);
        sheet.hostOf[g] = sheet.hostOf[f];
        sheet.originOf[g] = sheet.originOf[f];
        sheet.register(g);
        edit.reshaped.add(f);
        edit.reshaped.add(g);
        edit.parents.add(f < edit.facesBefore ? f : edit.parents.get(f - edit.facesBefore));
        sheet.stacks.get(sheet.hostOf[f]).add(g);
        return g;
    }

    /** Gives the face across edge a → b (the one holding b → a) the vertex m between b and a. */
    private void insertAcross(int a, int b, int m, SheetEdit edit) {
        int g = sheet.faceOfEdge.get(b, a, -1);
        if (g < 0) {
            return; // the strip's own border
        }
        edit.note(g);
        int[] loop = sheet.loops.get(g);
        int[] longer = new int[loop.length + 1];
        int k = 0;
        for (int i = 0; i < loop.length; i++) {
            longer[k++] = loop[i];
            if (loop[i] == b && loop[(i + 1) % loop.length] == a) {
                longer[k++] = m;
            }
        }
        sheet.faceOfEdge.remove(b, a, -1);
        sheet.faceOfEdge.put(b, m, g);
        sheet.faceOfEdge.put(m, a, g);
        sheet.loops.set(g, longer);
        sheet.placedFaces.forget(g);
        int crease = sheet.creases.remove(Sheet.undirected(a, b), -1);
        if (crease >= 0) {
            sheet.creases.put(Sheet.undirected(a, m), crease);
            sheet.creases.put(Sheet.undirected(m, b), crease);
        }
    }

    /**
     * The faces of a stack directly over each (for paper landing over it) or directly under
     * each (landing under), from its relations, as compressed rows by face.
     */
    private final class Between {
        private final int[] start;
        private final int[] faces;

        Between(LongList above, Placement placement) {
            int relations = above.size();
            start = new int[sheet.loops.size() + 1];
            faces = new int[relations];
            for (int r = 0; r < relations; r++) {
                start[from(above.get(r), placement) + 1]++;
            }
            for (int f = 0; f < sheet.loops.size(); f++) {
                start[f + 1] += start[f];
            }
            int[] fill = Arrays.copyOf(start, sheet.loops.size());
            for (int r = 0; r < relations; r++) {
                long pair = above.get(r);
                int f = from(pair, placement);
                faces[fill[f]++] = placement == Placement.OVER ? (int) (pair >>> 32) : (int) pair;
            }
        }

        /** The face a relation is listed under: its lower face for paper landing over, its upper one for paper landing under. */
        private static int from(long pair, Placement placement) {
            return placement == Placement.OVER ? (int) pair : (int) (pair >>> 32);
        }

        int start(int g) {
            return start[g];
        }

        int end(int g) {
            return start[g + 1];
        }

        int face(int k) {
            return faces[k];
        }
    }
}
