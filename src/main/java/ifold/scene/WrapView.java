package ifold.scene;

import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import ifold.sheet.Isometry2;
import ifold.sheet.Sheet;
import ifold.sheet.Tuck;
import ifold.wrap.CoveredPaper;
import ifold.wrap.Wrap;
import ifold.wrap.WrapGeometry;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.List;
import org.joml.Quaterniond;
import org.joml.Quaterniondc;
import org.joml.Vector3d;

/**
 * A wrap on screen: the model, solid in a quiet colour, and the strips laid over it face by
 * face in the order they were folded, the camera following the triangle being wrapped; at the
 * end the camera turns once around the wrapped model. The strips are one mesh whose triangles
 * come in the order their faces were made, so that showing the wrap up to a moment is showing
 * a prefix of it: nothing is rebuilt per frame.
 */
public final class WrapView {
    public static final int MODEL = 0xFF7D8A99;
    private static final int REVEAL_STEPS = 4 * 360;
    private static final int TURN_STEPS = 360;
    /** The part of the final turn over which the camera glides from the last fold's view. */
    private static final double GLIDE = 0.12;

    private WrapView() {
    }

    /** How the paper is drawn: its top side cream, caps grey, its underside blue-grey; no outlines (the faces are many and small). */
    public static final Material PAPER = new Material(PaperView.PAPER, 0xFF8FAACB, true, false);

    /**
     * The paper of the triangle being wrapped: its faces outlined, so that each pass, turn and
     * tucked flap can be told from the next while it is made.
     */
    public static final Material PAPER_FOLDING = new Material(PaperView.PAPER, 0xFF8FAACB, true, true);

    /** The legend's lines for the paper: its two sides in the colours it is drawn in. */
    public static final Scene.Swatch TOP_SIDE = new Scene.Swatch(PaperView.PAPER, "paper, top side");
    public static final Scene.Swatch UNDERSIDE = new Scene.Swatch(PAPER.back(), "paper, underside");

    /** The outline of a face being folded: darker than the paper, quieter than the model's edges. */
    private static final int FACE_EDGE = 0xFF6F7B88;

    /** The wrap's strips and, for each strip and path triangle, how many of the mesh's triangles exist once it is wrapped. */
    public record Strips(SceneMesh mesh, int[][] trianglesAfter) {
    }

    public static Strips strips(Wrap.Result result, List<WrapGeometry> geometries) {
        int total = 0;
        for (WrapGeometry g : geometries) {
            total += g.vertexCount();
        }
        double[] positions = new double[3 * total];
        List<int[]> triangles = new ArrayList<>();
        List<Integer> colors = new ArrayList<>();
        IntList hiddenFrom = new IntList();
        BitSet seams = new BitSet();
        IntList patchOf = new IntList();
        HostPatches patches = new HostPatches(result);
        int[][] after = new int[geometries.size()][];
        int base = 0;
        for (int k = 0; k < geometries.size(); k++) {
            WrapGeometry g = geometries.get(k);
            Wrap.Strip strip = result.strips().get(k);
            System.arraycopy(g.xyz(), 0, positions, 3 * base, 3 * g.vertexCount());
            // Caps come right after the later of the faces they join.
            List<List<Integer>> capsAfter = new ArrayList<>();
            for (int f = 0; f < g.paperFaces().size(); f++) {
                capsAfter.add(new ArrayList<>());
            }
            for (int c = 0; c < g.caps().size(); c++) {
                capsAfter.get(g.capAfter()[c]).add(c);
            }
            // What lies under other paper is not drawn once that paper is there.
            CoveredPaper.Covered covered = CoveredPaper.of(g, result.frames(), strip.sheet().thickness());
            int[] levels = strip.sheet().levels();
            int[] trianglesAtFace = new int[g.paperFaces().size() + 1];
            for (int f = 0; f < g.paperFaces().size(); f++) {
                trianglesAtFace[f] = triangles.size();
                int from = triangles.size();
                int host = g.paperHosts()[f];
                fan(g.paperFaces().get(f), base, PaperView.PAPER, triangles, colors);
                hiddenFrom.add(covered.faceCover()[f], triangles.size() - from); // the face that covers it, for now
                if (!covered.face(f)) {
                    patches.add(host, covered.undersideOut().get(f) ? PAPER.back() : PAPER.front(), covered.areas()[f]);
                }
                patches.layer(host, (levels[f] + 0.5) * strip.sheet().thickness(), triangles.size());
                patchOf.add(host, triangles.size() - from);
                for (int c : capsAfter.get(f)) {
                    from = triangles.size();
                    fan(g.caps().get(c), base, PaperView.CAP, triangles, colors);
                    seams.set(from, triangles.size());
                    hiddenFrom.add(covered.capCover()[c], triangles.size() - from);
                    patchOf.add(host, triangles.size() - from);
                    patches.layer(host, Double.NEGATIVE_INFINITY, triangles.size());
                }
            }
            trianglesAtFace[g.paperFaces().size()] = triangles.size();
            // Covered once the face that covers it is drawn whole.
            for (int t = trianglesAtFace[0]; t < triangles.size(); t++) {
                int cover = hiddenFrom.get(t);
                hiddenFrom.set(t, cover < 0 ? Integer.MAX_VALUE : trianglesAtFace[cover + 1]);
            }
            after[k] = new int[strip.triangles()];
            for (int i = 0; i < strip.triangles(); i++) {
                after[k][i] = trianglesAtFace[strip.facesAfter()[i]];
            }
            base += g.vertexCount();
        }
        int[] flat = new int[3 * triangles.size()];
        for (int t = 0; t < triangles.size(); t++) {
            System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
        }
        int[] colorArray = colors.stream().mapToInt(Integer::intValue).toArray();
        SceneMesh.Layers layers = patches.layers(hiddenFrom.toArray(), seams, patchOf.toArray());
        return new Strips(new SceneMesh(positions, flat, colorArray, new int[0], new int[0], layers), after);
    }

    /**
     * What the paper on each host looks like from far away: the host's triangles of the model,
     * raised to the paper's top layer, in the colours of the paper exposed there averaged by
     * area (its top side and its underside). A host is settled once its last face and cap are
     * there: what covers what on it holds from then on.
     */
    private static final class HostPatches {
        private final Wrap.Result result;
        private final double[] red;
        private final double[] green;
        private final double[] blue;
        private final double[] area;
        private final double[] top;
        private final int[] settled;

        HostPatches(Wrap.Result result) {
            this.result = result;
            int hosts = result.frames().length;
            red = new double[hosts];
            green = new double[hosts];
            blue = new double[hosts];
            area = new double[hosts];
            top = new double[hosts];
            java.util.Arrays.fill(top, Double.NEGATIVE_INFINITY);
            settled = new int[hosts];
        }

        void add(int host, int argb, double faceArea) {
            red[host] += faceArea * (argb >> 16 & 0xFF);
            green[host] += faceArea * (argb >> 8 & 0xFF);
            blue[host] += faceArea * (argb & 0xFF);
            area[host] += faceArea;
        }

        /** Paper at {@code height} on {@code host}, its triangles ending at {@code end}. */
        void layer(int host, double height, int end) {
            top[host] = Math.max(top[host], height);
            settled[host] = Math.max(settled[host], end);
        }

        SceneMesh.Layers layers(int[] hiddenFrom, BitSet seams, int[] patchOf) {
            IndexedPolygons mesh = result.mesh();
            int hosts = settled.length;
            int[] start = new int[hosts + 1];
            for (int t = 0; t < mesh.faceCount(); t++) {
                start[result.hostOf()[t] + 1] += area[result.hostOf()[t]] > 0 ? 1 : 0;
            }
            for (int h = 0; h < hosts; h++) {
                start[h + 1] += start[h];
            }
            int count = start[hosts];
            // Neighbour patches share their corners, raised along the mean of their hosts'
            // normals to the highest of their tops: raised each along its own, they would part at
            // every convex edge, the model showing through.
            double[] raise = new double[mesh.vertexCount()];
            double[] normals = new double[3 * mesh.vertexCount()];
            for (int t = 0; t < mesh.faceCount(); t++) {
                int h = result.hostOf()[t];
                if (!(area[h] > 0)) {
                    continue;
                }
                for (int corner = 0; corner < 3; corner++) {
                    int v = mesh.faceVertex(t, corner);
                    raise[v] = Math.max(raise[v], top[h]);
                    for (int axis = 0; axis < 3; axis++) {
                        normals[3 * v + axis] += result.frames()[h].normal()[axis];
                    }
                }
            }
            double[] xyz = new double[3 * mesh.vertexCount()];
            for (int v = 0; v < mesh.vertexCount(); v++) {
                double length = Math.sqrt(normals[3 * v] * normals[3 * v] + normals[3 * v + 1] * normals[3 * v + 1]
                        + normals[3 * v + 2] * normals[3 * v + 2]);
                for (int axis = 0; axis < 3; axis++) {
                    xyz[3 * v + axis] = mesh.coordinate(v, axis) + (length > 0 ? raise[v] * normals[3 * v + axis] / length : 0);
                }
            }
            int[] triangles = new int[3 * count];
            int[] colors = new int[count];
            int[] fill = java.util.Arrays.copyOf(start, hosts);
            for (int t = 0; t < mesh.faceCount(); t++) {
                int h = result.hostOf()[t];
                if (!(area[h] > 0)) {
                    continue; // no paper seen there
                }
                int k = fill[h]++;
                for (int corner = 0; corner < 3; corner++) {
                    triangles[3 * k + corner] = mesh.faceVertex(t, corner);
                }
                colors[k] = 0xFF000000 | (int) Math.round(red[h] / area[h]) << 16 | (int) Math.round(green[h] / area[h]) << 8
                        | (int) Math.round(blue[h] / area[h]);
            }
            SceneMesh patches = new SceneMesh(xyz, triangles, colors, new int[0], new int[0]);
            return new SceneMesh.Layers(hiddenFrom, seams, patchOf, settled, patches, start);
        }
    }

    /** A growing list of ints. */
    private static final class IntList {
        private int[] values = new int[1024];
        private int size;

        /** {@code times} copies of {@code value}. */
        void add(int value, int times) {
            if (size + times > values.length) {
                values = java.util.Arrays.copyOf(values, Math.max(2 * values.length, size + times));
            }
            java.util.Arrays.fill(values, size, size + times, value);
            size += times;
        }

        int get(int i) {
            return values[i];
        }

        void set(int i, int value) {
            values[i] = value;
        }

        int[] toArray() {
            return java.util.Arrays.copyOf(values, size);
        }
    }

    private static void fan(int[] face, int base, int color, List<int[]> triangles, List<Integer> colors) {
        for (int i = 1; i + 1 < face.length; i++) { // faces are convex
            triangles.add(new int[] {base + face[0], base + face[i], base + face[i + 1]});
            colors.add(color);
        }
    }

    /**
     * The animation, four fifths of its length the wrap and the last fifth a turn around the
     * wrapped model. The wrap plays its folds in order: the tail swinging about each new crease
     * (over or under the paper it lands on, or over the edge onto the next triangle), and the
     * tucks turning the excess under along the triangle's edges, the camera following the
     * triangle being wrapped. Triangles already wrapped are a prefix of {@code done}; the one
     * being wrapped, as it stands at the fold shown, and the swinging paper are drawn by
     * {@code current}, rebuilt for each frame (it is a few dozen faces).
     */
    public static Playback animation(Scene scene, Geometry done, Geometry current, Strips strips, Wrap.Result result) {
        return new Playback(scene, done, current, strips, result, null);
    }

    /**
     * Adds the wrap's paper to the scene (what the scene holds already, the model or a
     * triangle, stays under it), frames the whole, and returns its playback, whose last caption
     * counts the strips and triangles wrapped.
     */
    public static Playback play(Scene scene, Wrap.Result result, List<WrapGeometry> geometries) {
        return play(scene, result, geometries, null);
    }

    /** As {@link #play(Scene, Wrap.Result, List)}, with {@code ending} the caption once all is folded (null for the count). */
    public static Playback play(Scene scene, Wrap.Result result, List<WrapGeometry> geometries, String ending) {
        Strips strips = strips(result, geometries);
        scene.root().visitGeometry(under -> under.setUnder(true)); // the model, or the triangle, under the paper
        Geometry paper = new Geometry("paper", strips.mesh(), PAPER);
        paper.setHiddenColor(0); // not yet laid: not there
        scene.root().attach(paper);
        Geometry current = new Geometry("folding", strips.mesh(), PAPER_FOLDING);
        scene.root().attach(current);
        scene.frameAll();
        return new Playback(scene, paper, current, strips, result, ending);
    }

    /** The least time a caption stays on screen: long enough to read a line of it. */
    public static final double CAPTION_SECONDS = 1.5;

    /** The length a playback is paced for until {@link Playback#pace} says otherwise: a wrap's two minutes. */
    public static final double DEFAULT_SECONDS = 120;

    /** The height of the frame the triangle being wrapped fills, once the camera has come close to it. */
    static final double CLOSE_FILL = 0.5;

    /**
     * The wrap played fold by fold, then one turn around the result. A movie of a thousand folds
     * cannot show each for long enough to read its caption: the first triangle is shown fold by
     * fold, and each later step is a triangle, or a run of them, wrapped the same way, said so in
     * its caption; every caption stays at least {@link #CAPTION_SECONDS} at the length it is
     * {@linkplain #pace paced} for.
     */
    public static final class Playback implements Animation {
        private final Scene scene;
        private final Geometry done;
        private final Geometry current;
        private final Strips strips;
        private final Wrap.Result result;
        private final List<Wrap.Step> steps;
        /** For each step, its place among all path triangles (strips one after another). */
        private final int[] triangleOf;
        /** Each strip's face levels, final: found once, not per frame. */
        private final int[][] levels;
        private final int triangles;
        private final double[] centres;
        private final double[] normals;
        private final Vector3d modelCentre;
        private final double modelRadius;
        private final int window;
        /** What the final turn starts from: the model turned to show its outer side, where it has one. */
        private final Quaterniondc finalFacing;
        private final double finalTurn;
        /** The caption once all is folded: what the paper does now. */
        private final String ending;
        private double shown = -1;
        /** For each step, the position it begins at; the last entry is the end of the folding. */
        private double[] stepStart;
        /** For each step, the beat (a caption's time on screen) it is played in. */
        private int[] beatOfStep;
        /** Each beat's caption, or null where it is its fold's own. */
        private String[] beatCaption;
        /** The positions one beat lasts. */
        private double beatLength;
        /** For each path triangle, the positions its folds begin and end at. */
        private double[] slotStart;
        private double[] slotEnd;
        /** For each path triangle, its first step and the step after its last (none: equal). */
        private int[] firstStep;
        private int[] endStep;

        Playback(Scene scene, Geometry done, Geometry current, Strips strips, Wrap.Result result, String ending) {
            this.scene = scene;
            this.done = done;
            this.current = current;
            this.strips = strips;
            this.result = result;
            this.ending = ending;
            this.steps = result.steps();
            IndexedPolygons mesh = result.mesh();
            int[] firstOfStrip = new int[result.strips().size()];
            int total = 0;
            for (int k = 0; k < result.strips().size(); k++) {
                firstOfStrip[k] = total;
                total += result.strips().get(k).triangles();
            }
            triangles = total;
            levels = new int[result.strips().size()][];
            for (int k = 0; k < levels.length; k++) {
                levels[k] = result.strips().get(k).sheet().levels();
            }
            triangleOf = new int[steps.size()];
            for (int j = 0; j < steps.size(); j++) {
                triangleOf[j] = firstOfStrip[steps.get(j).strip()] + steps.get(j).pathIndex();
            }
            centres = new double[3 * triangles];
            normals = new double[3 * triangles];
            double[] areas = new double[triangles];
            int g = 0;
            for (Wrap.Strip strip : result.strips()) {
                for (int i = 0; i < strip.triangles(); i++, g++) {
                    int t = strip.firstTriangle() + i;
                    double[] n = result.frames()[result.hostOf()[t]].normal();
                    for (int axis = 0; axis < 3; axis++) {
                        double sum = 0;
                        for (int c = 0; c < 3; c++) {
                            sum += mesh.coordinate(mesh.faceVertex(t, c), axis);
                        }
                        centres[3 * g + axis] = sum / 3;
                        normals[3 * g + axis] = n[axis];
                    }
                    areas[g] = area(mesh, t);
                }
            }
            // An open surface (a lone triangle, a patch) is wrapped on the side its faces face:
            // the final turn starts facing it. A closed one shows every side in turn anyway.
            Vector3d weighted = new Vector3d();
            double area = 0;
            for (int t = 0; t < triangles; t++) {
                double a = areas[t];
                weighted.fma(a, new Vector3d(normals[3 * t], normals[3 * t + 1], normals[3 * t + 2]));
                area += a;
            }
            boolean open = area > 0 && weighted.length() > 0.5 * area;
            finalFacing = open ? Camera.facing(weighted.normalize()) : new Quaterniond();
            finalTurn = open ? 0.3 : 0.6;
            Bounds bounds = scene.bounds();
            modelCentre = bounds.center(new Vector3d());
            modelRadius = bounds.radius();
            // The camera follows a moving average of the triangles, so that it glides rather than jumps.
            window = Math.max(1, triangles / 40);
            firstStep = new int[triangles];
            endStep = new int[triangles];
            for (int j = steps.size() - 1; j >= 0; j--) {
                firstStep[triangleOf[j]] = j;
            }
            for (int j = 0; j < steps.size(); j++) {
                endStep[triangleOf[j]] = j + 1;
            }
            pace(DEFAULT_SECONDS);
        }

        /**
         * Lays the folds out for a playback of {@code seconds}, so that each caption stays at least
         * {@link #CAPTION_SECONDS}: where there is time, the first triangle fold by fold and each
         * later one a step; where there is not, the later ones in runs ("triangles 12-20 of 58:
         * each wrapped as triangle 1"), or, on a lone triangle, its folds in runs.
         */
        public void pace(double seconds) {
            if (!(seconds > 0)) {
                throw new IllegalArgumentException("seconds must be positive, got " + seconds);
            }
            int n = steps.size();
            stepStart = new double[n + 1];
            beatOfStep = new int[n];
            slotStart = new double[triangles];
            slotEnd = new double[triangles];
            if (n == 0) {
                beatCaption = new String[0];
                beatLength = REVEAL_STEPS;
                return;
            }
            double folding = seconds * REVEAL_STEPS / (REVEAL_STEPS + TURN_STEPS);
            int most = Math.max(1, (int) Math.floor(folding / CAPTION_SECONDS + 1e-9));
            // Each beat: its triangles (from, to) or, for a beat of folds, -1 and its steps.
            List<int[]> beats = new ArrayList<>();
            List<String> captions = new ArrayList<>();
            List<Integer> withSteps = new ArrayList<>();
            for (int t = 0; t < triangles; t++) {
                if (endStep[t] > firstStep[t]) {
                    withSteps.add(t);
                }
            }
            if (withSteps.size() == 1) {
                int per = (n + most - 1) / most;
                for (int j = 0; j < n; j += per) {
                    int end = Math.min(n, j + per);
                    beats.add(new int[] {-1, j, end});
                    captions.add(per == 1 ? null : describeStep(j) + (end - j == 1 ? " (fold " + end : " (folds " + (j + 1) + "\u2013" + end)
                            + " of " + n + ")");
                }
            } else {
                int first = withSteps.get(0);
                int detailed = endStep[first] - firstStep[first];
                boolean detail = detailed + 1 <= most;
                List<Integer> grouped = detail ? withSteps.subList(1, withSteps.size()) : withSteps;
                if (detail) {
                    for (int j = firstStep[first]; j < endStep[first]; j++) {
                        beats.add(new int[] {-1, j, j + 1});
                        captions.add(null);
                    }
                }
                int room = Math.max(1, most - beats.size());
                List<List<Integer>> runs = runs(grouped, room);
                for (List<Integer> run : runs) {
                    beats.add(new int[] {run.get(0), run.get(run.size() - 1)});
                    captions.add(describeRun(run, detail));
                }
            }
            beatLength = (double) REVEAL_STEPS / beats.size();
            beatCaption = captions.toArray(new String[0]);
            for (int b = 0; b < beats.size(); b++) {
                int[] beat = beats.get(b);
                double start = b * beatLength;
                if (beat[0] == -1) {
                    int count = beat[2] - beat[1];
                    for (int j = beat[1]; j < beat[2]; j++) {
                        stepStart[j] = start + beatLength * (j - beat[1]) / count;
                        beatOfStep[j] = b;
                    }
                    continue;
                }
                // A run of triangles: each an equal share of the beat, each fold an equal share of its triangle's.
                List<Integer> inRun = new ArrayList<>();
                for (int t = beat[0]; t <= beat[1]; t++) {
                    if (endStep[t] > firstStep[t]) {
                        inRun.add(t);
                    }
                }
                double share = beatLength / inRun.size();
                for (int r = 0; r < inRun.size(); r++) {
                    int t = inRun.get(r);
                    int count = endStep[t] - firstStep[t];
                    for (int j = firstStep[t]; j < endStep[t]; j++) {
                        stepStart[j] = start + share * (r + (double) (j - firstStep[t]) / count);
                        beatOfStep[j] = b;
                    }
                }
            }
            stepStart[n] = REVEAL_STEPS;
            for (int t = 0; t < triangles; t++) {
                if (endStep[t] > firstStep[t]) {
                    slotStart[t] = stepStart[firstStep[t]];
                    slotEnd[t] = stepStart[endStep[t]];
                }
            }
            shown = -1;
        }

        /** The triangles in runs of equal length, as few as fit in {@code room} beats, a run never crossing from one strip to the next. */
        private List<List<Integer>> runs(List<Integer> grouped, int room) {
            for (int per = Math.max(1, (grouped.size() + room - 1) / room);; per++) {
                List<List<Integer>> runs = new ArrayList<>();
                List<Integer> run = new ArrayList<>();
                for (int t : grouped) {
                    if (!run.isEmpty() && (run.size() == per || steps.get(firstStep[t]).strip() != steps.get(firstStep[run.get(0)]).strip())) {
                        runs.add(run);
                        run = new ArrayList<>();
                    }
                    run.add(t);
                }
                if (!run.isEmpty()) {
                    runs.add(run);
                }
                if (runs.size() <= room || per >= grouped.size()) {
                    return runs;
                }
            }
        }

        /** A run's caption: "triangles 12-20 of 58: each wrapped as triangle 1". */
        private String describeRun(List<Integer> run, boolean afterDetail) {
            Wrap.Step first = steps.get(firstStep[run.get(0)]);
            Wrap.Step last = steps.get(firstStep[run.get(run.size() - 1)]);
            String strip = result.strips().size() > 1 ? "strip " + (first.strip() + 1) + ", " : "";
            String which = run.size() == 1 ? "triangle " + (first.pathIndex() + 1)
                    : "triangles " + (first.pathIndex() + 1) + "\u2013" + (last.pathIndex() + 1);
            String how = !afterDetail ? "zig-zag passes, turns and tucks"
                    : (run.size() == 1 ? "wrapped as triangle 1" : "each wrapped as triangle 1") + (result.strips().size() > 1 ? " of strip 1" : "");
            return strip + which + " of " + first.pathLength() + ": " + how;
        }

        private String describeStep(int j) {
            Wrap.Step step = steps.get(j);
            return (result.strips().size() > 1 ? "strip " + (step.strip() + 1) + ", " : "") + step.describe();
        }

        /** The beat shown at a position of the folding. */
        private int beatAt(double position) {
            return beatOfStep[(int) Math.floor(along(position))];
        }

        @Override
        public int stepCount() {
            return REVEAL_STEPS + TURN_STEPS;
        }

        /** The position at which the first {@code folds} steps of the wrap are made and the next has not begun. */
        public double positionAfter(int folds) {
            return steps.isEmpty() ? 0 : stepStart[Math.max(0, Math.min(folds, steps.size()))];
        }

        /** The position half way round the final turn: the wrapped model seen from behind. */
        public double halfTurn() {
            return REVEAL_STEPS + TURN_STEPS / 2.0;
        }

        /** The step (fold) shown at a position, with how far it has gone. */
        private double along(double position) {
            int n = steps.size();
            if (position >= REVEAL_STEPS) {
                return n;
            }
            int j = java.util.Arrays.binarySearch(stepStart, 0, n, position);
            j = j >= 0 ? j : -j - 2;
            j = Math.max(0, Math.min(n - 1, j));
            double length = stepStart[j + 1] - stepStart[j];
            return j + (length > 0 ? Math.min(1, (position - stepStart[j]) / length) : 0);
        }

        @Override
        public void apply(double position) {
            if (position == shown) {
                return;
            }
            shown = position;
            Camera camera = scene.camera();
            if (position >= REVEAL_STEPS || steps.isEmpty()) {
                done.setRevealed(Geometry.ALL);
                current.setMesh(EMPTY);
                camera.frame(modelCentre, modelRadius);
                double angle = Math.toRadians((position - REVEAL_STEPS) * 360.0 / TURN_STEPS);
                Quaterniond turn = new Quaterniond().rotateX(-0.5).rotateY(finalTurn + Math.max(0, angle)).mul(finalFacing);
                camera.setOrientation(turn);
                // The first moments of the turn glide from where the camera followed the last fold.
                double glide = steps.isEmpty() ? 1 : (position - REVEAL_STEPS) / (GLIDE * TURN_STEPS);
                if (glide < 1) {
                    Camera last = new Camera();
                    if (triangles > 2) {
                        last.frame(modelCentre, WIDE * modelRadius);
                        last.setOrientation(closeOrientation(triangleOf[steps.size() - 1]));
                    } else {
                        follow(last, triangles, underAt(steps.size()));
                    }
                    double b = smooth(Math.max(0, glide));
                    camera.setOrientation(new Quaterniond(last.orientation()).slerp(turn, b));
                    camera.setTarget(new Vector3d(last.target()).lerp(camera.target(), b));
                    camera.setDistance(last.distance() + b * (camera.distance() - last.distance()));
                    camera.setSceneRadius(Math.max(last.sceneRadius(), camera.sceneRadius()));
                }
                return;
            }
            double along = along(position);
            int j = Math.min(steps.size() - 1, (int) Math.floor(along));
            double fraction = along - j;
            Wrap.Step step = steps.get(j);
            Wrap.Strip strip = result.strips().get(step.strip());
            int i = step.pathIndex();
            int k = step.strip();
            // Triangles wrapped before this one are done; this one is drawn as it stands.
            int doneTriangles = i > 0 ? strips.trianglesAfter()[k][i - 1] : k > 0 ? last(strips.trianglesAfter()[k - 1]) : 0;
            done.setRevealed(doneTriangles);
            int firstFace = i > 0 ? strip.facesAfter()[i - 1] : 0;
            current.setMesh(currentMesh(strip, step, j, firstFace, fraction));
            if (triangles > 2) {
                frameTriangle(camera, position, triangleOf[j]);
            } else {
                follow(camera, triangleOf[j] + Math.min(1, (j + fraction - firstStepOf(j)) / Math.max(1, stepsOf(j))), underAt(along));
            }
        }

        /** The whole model's view, in model radii: the model with a margin, the caption's band included. */
        private static final double WIDE = 1.15;

        /**
         * Frames triangle t while its folds are made: close, the triangle filling
         * {@link #CLOSE_FILL} of the frame's height (its folds are a few pixels wide when the
         * whole model is in view), easing out to the whole model at the start and end of its
         * time, so that each triangle is seen first where it lies on the model and the camera
         * turns from one to the next at a distance.
         */
        private void frameTriangle(Camera camera, double position, int t) {
            double start = slotStart[t];
            double end = slotEnd[t];
            double ease = Math.min(0.25 * (end - start), 0.5 * beatLength);
            double in = smooth(Math.max(0, Math.min(1, (position - start) / ease)));
            double out = smooth(Math.max(0, Math.min(1, (end - position) / ease)));
            double close = Math.min(in, out);
            Quaterniondc facing = closeOrientation(t);
            // Between two triangles the camera looks half way between their faces.
            int other = position - start < end - position ? t - 1 : t + 1;
            Quaterniond wide = new Quaterniond(facing);
            if (other >= 0 && other < triangles && endStep[other] > firstStep[other]) {
                wide = new Quaterniond(facing).slerp(closeOrientation(other), 0.5);
            }
            Camera near = new Camera();
            near.setOrientation(facing);
            Vector3d centre = new Vector3d(centres[3 * t], centres[3 * t + 1], centres[3 * t + 2]);
            near.setTarget(centre);
            near.setDistance(closeDistance(t, facing, near.fovY()));
            camera.frame(modelCentre, WIDE * modelRadius);
            double far = camera.distance();
            camera.setTarget(new Vector3d(modelCentre).lerp(centre, close));
            // Zoomed at an even pace: the distance changes by equal ratios, not equal lengths.
            camera.setDistance(far * Math.pow(near.distance() / far, close));
            camera.setOrientation(wide.slerp(facing, close, new Quaterniond()));
            camera.setSceneRadius(3 * modelRadius);
        }

        /** How triangle t is looked at close up: facing the viewer, tilted a little, as the whole model's view is. */
        private Quaterniondc closeOrientation(int t) {
            Vector3d normal = new Vector3d(normals[3 * t], normals[3 * t + 1], normals[3 * t + 2]).normalize();
            return new Quaterniond().rotateX(-0.25).mul(Camera.facing(normal));
        }

        /**
         * The distance at which triangle t, seen turned by {@code facing}, is {@link #CLOSE_FILL}
         * of the frame's height, and at most seven tenths of a 16:9 frame's width.
         */
        private double closeDistance(int t, Quaterniondc facing, double fovY) {
            IndexedPolygons mesh = result.mesh();
            int face = triangleFace(t);
            double top = Double.NEGATIVE_INFINITY;
            double bottom = Double.POSITIVE_INFINITY;
            double left = Double.POSITIVE_INFINITY;
            double right = Double.NEGATIVE_INFINITY;
            for (int c = 0; c < 3; c++) {
                int v = mesh.faceVertex(face, c);
                Vector3d p = new Vector3d(mesh.coordinate(v, 0), mesh.coordinate(v, 1), mesh.coordinate(v, 2))
                        .sub(centres[3 * t], centres[3 * t + 1], centres[3 * t + 2]);
                facing.transform(p);
                top = Math.max(top, p.y);
                bottom = Math.min(bottom, p.y);
                left = Math.min(left, p.x);
                right = Math.max(right, p.x);
            }
            double tan = Math.tan(fovY / 2);
            double distance = Math.max((top - bottom) / (2 * CLOSE_FILL * tan), (right - left) / (2 * 0.7 * tan * 16 / 9.0));
            return Math.max(distance, 1e-9 * modelRadius);
        }

        /** The refined mesh's face of path triangle t (strips one after another). */
        private int triangleFace(int t) {
            int g = t;
            for (Wrap.Strip strip : result.strips()) {
                if (g < strip.triangles()) {
                    return strip.firstTriangle() + g;
                }
                g -= strip.triangles();
            }
            throw new IllegalArgumentException("no path triangle " + t);
        }

        /**
         * How far the camera has turned to look from below at a position along the folds (0 to
         * 1): on a lone triangle, its tucks fold the excess under it, out of sight from above,
         * so the camera turns under for them, easing in half a fold before and out half a fold
         * after (the last stays under until the final turn).
         * A polyhedron hides its tucks in the solid; the camera stays outside.
         */
        private double underAt(double along) {
            if (triangles != 1) {
                return 0;
            }
            double under = 0;
            int n = steps.size();
            for (int j = 0; j < n; j++) {
                if (steps.get(j).kind() != Wrap.Kind.TUCK) {
                    continue;
                }
                double rise = (along - (j - 0.5)) / 0.5;
                // After the last tuck the camera stays under to the end of its caption: the final
                // turn glides up from there.
                double fall = j == n - 1 ? 1 : ((j + 1.5) - along) / 0.5;
                under = Math.max(under, smooth(Math.max(0, Math.min(1, Math.min(rise, fall)))));
            }
            return under;
        }

        private static double smooth(double t) {
            return t * t * (3 - 2 * t);
        }

        private static int last(int[] a) {
            return a[a.length - 1];
        }

        private int firstStepOf(int j) {
            int first = j;
            while (first > 0 && triangleOf[first - 1] == triangleOf[j]) {
                first--;
            }
            return first;
        }

        private int stepsOf(int j) {
            int first = firstStepOf(j);
            int end = j;
            while (end < steps.size() && triangleOf[end] == triangleOf[j]) {
                end++;
            }
            return end - first;
        }

        private void follow(Camera camera, double at, double under) {
            Vector3d centre = new Vector3d();
            Vector3d normal = new Vector3d();
            double weights = 0;
            int middle = (int) Math.floor(at);
            for (int t = Math.max(0, middle - window); t <= Math.min(triangles - 1, middle + window + 1); t++) {
                double weight = window + 1 - Math.abs(t + 0.5 - at);
                if (weight <= 0) {
                    continue;
                }
                centre.fma(weight, new Vector3d(centres[3 * t], centres[3 * t + 1], centres[3 * t + 2]));
                normal.fma(weight, new Vector3d(normals[3 * t], normals[3 * t + 1], normals[3 * t + 2]));
                weights += weight;
            }
            int here = Math.min(triangles - 1, Math.max(0, middle));
            if (weights == 0) {
                centre.set(centres[3 * here], centres[3 * here + 1], centres[3 * here + 2]);
            } else {
                centre.div(weights);
            }
            if (normal.length() < 1e-9) {
                normal.set(normals[3 * here], normals[3 * here + 1], normals[3 * here + 2]);
            }
            normal.normalize();
            // Aim between the model's centre and the triangle, close enough to see the fold and
            // far enough to see where on the model it is; the triangle faces the viewer.
            // The whole model stays in the picture, with a margin (the caption's band included):
            // the aim leans 0.3 of the way towards the triangle, and the view holds 0.3 more than
            // the model, so the model's sphere never leaves it; the triangle faces the viewer.
            // A lone triangle or two are the model.
            Vector3d target = new Vector3d(modelCentre).lerp(centre, triangles <= 2 ? 0.6 : 0.3);
            camera.frame(target, (triangles <= 2 ? 1.15 : 1.38) * modelRadius);
            camera.setSceneRadius(3 * modelRadius);
            camera.setOrientation(new Quaterniond().rotateX(-0.25 - under * (Math.PI - 0.9)).mul(Camera.facing(normal)));
        }

        /**
         * The triangle being wrapped at step j: its faces as they stand then (the final state with
         * the tucks after step j undone), and the paper in motion: the tail swinging about its new
         * crease, or the flap of a tuck turning under.
         */
        private SceneMesh currentMesh(Wrap.Strip strip, Wrap.Step step, int j, int firstFace, double fraction) {
            Sheet sheet = strip.sheet();
            int end = step.facesAfter();
            int count = end - firstFace;
            int[][] loops = new int[count][];
            Isometry2[] poses = new Isometry2[count];
            for (int f = firstFace; f < end; f++) {
                loops[f - firstFace] = sheet.loop(f);
                poses[f - firstFace] = sheet.pose(f);
            }
            // Undo the tucks of this triangle after the one shown.
            int lastStep = j;
            while (lastStep + 1 < steps.size() && triangleOf[lastStep + 1] == triangleOf[j]) {
                lastStep++;
            }
            for (int q = lastStep; q > j; q--) {
                Tuck tuck = steps.get(q).tuck();
                if (tuck == null) {
                    continue;
                }
                for (int c = 0; c < tuck.changed().length; c++) {
                    int f = tuck.changed()[c];
                    if (f >= firstFace && f < end) {
                        loops[f - firstFace] = tuck.loopsBefore()[c];
                        poses[f - firstFace] = tuck.posesBefore()[c];
                    }
                }
            }
            // A tuck being shown: its faces are cut already, and the flap turns from where it lay
            // (its reflection back over the tuck line) to under the paper.
            java.util.Set<Integer> turning = new java.util.HashSet<>();
            Tuck shownTuck = step.kind() == Wrap.Kind.TUCK ? step.tuck() : null;
            if (shownTuck != null) {
                Isometry2 back = Isometry2.reflection(shownTuck.px(), shownTuck.py(), shownTuck.dx(), shownTuck.dy());
                for (int f : shownTuck.moved()) {
                    if (f >= firstFace && f < end) {
                        turning.add(f);
                        poses[f - firstFace] = back.after(poses[f - firstFace]);
                    }
                }
            }
            int[] levels = this.levels[step.strip()];
            double thickness = sheet.thickness();
            List<double[]> points = new ArrayList<>();
            List<int[]> triangles = new ArrayList<>();
            List<Integer> colors = new ArrayList<>();
            List<Integer> edges = new ArrayList<>();
            HostFrame frame = shownTuck != null ? result.frames()[shownTuck.host()] : null;
            for (int f = firstFace; f < end; f++) {
                int[] loop = loops[f - firstFace];
                Isometry2 pose = poses[f - firstFace];
                double height = (levels[f] + 0.5) * thickness;
                HostFrame on = result.frames()[sheet.host(f)];
                double[][] corners = new double[loop.length][];
                for (int c = 0; c < loop.length; c++) {
                    double u = sheet.u(loop[c]);
                    double v = sheet.v(loop[c]);
                    double[] point = new double[3];
                    on.toSpace(pose.x(u, v), pose.y(u, v), height, point, 0);
                    if (turning.contains(f)) {
                        point = turnAbout(point, frame, shownTuck.px(), shownTuck.py(), shownTuck.dx(), shownTuck.dy(), Math.PI * fraction);
                    }
                    corners[c] = point;
                }
                // Counter-clockwise on the sheet; a mirrored pose shows its underside, drawn as such.
                int base = points.size();
                addPolygon(corners, PaperView.PAPER, points, triangles, colors);
                for (int c = 0; c < corners.length; c++) {
                    edges.add(base + c);
                    edges.add(base + (c + 1) % corners.length);
                }
            }
            if (step.tail() != null && step.kind() != Wrap.Kind.END) {
                addTail(sheet, step.strip(), step.tail(), fraction, points, triangles, colors);
            }
            double[] positions = new double[3 * points.size()];
            for (int p = 0; p < points.size(); p++) {
                System.arraycopy(points.get(p), 0, positions, 3 * p, 3);
            }
            int[] flat = new int[3 * triangles.size()];
            for (int t = 0; t < triangles.size(); t++) {
                System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
            }
            int[] edgeColors = new int[edges.size() / 2];
            java.util.Arrays.fill(edgeColors, FACE_EDGE);
            return new SceneMesh(positions, flat, colors.stream().mapToInt(Integer::intValue).toArray(),
                    edges.stream().mapToInt(Integer::intValue).toArray(), edgeColors);
        }

        /**
         * The tail beyond its new crease, two widths of it, swinging from where it would run on
         * unfolded to where the fold lays it: a turn about the crease line in space.
         */
        private void addTail(Sheet sheet, int strip, Wrap.TailMove move, double fraction, List<double[]> points, List<int[]> triangles,
                List<Integer> colors) {
            double w = sheet.width();
            double[][] paper = {{move.u0(), 0}, {move.u0() + 2 * w, 0}, {move.u1() + 2 * w, w}, {move.u1(), w}};
            HostFrame before = result.frames()[move.hostBefore()];
            HostFrame after = result.frames()[move.hostAfter()];
            double height = (topLevel(sheet, levels[strip], move.hostBefore()) + 1.5) * sheet.thickness();
            double[][] from = new double[4][3];
            double[][] to = new double[4][3];
            for (int c = 0; c < 4; c++) {
                before.toSpace(move.before().x(paper[c][0], paper[c][1]), move.before().y(paper[c][0], paper[c][1]), height, from[c], 0);
                after.toSpace(move.after().x(paper[c][0], paper[c][1]), move.after().y(paper[c][0], paper[c][1]), height, to[c], 0);
            }
            // The axis: the crease, where both placements agree; the angle: between the tail piece's
            // direction across the axis before and after.
            Vector3d a = new Vector3d(from[0][0], from[0][1], from[0][2]);
            Vector3d axis = new Vector3d(from[3][0], from[3][1], from[3][2]).sub(a).normalize();
            Vector3d out0 = new Vector3d(from[1][0], from[1][1], from[1][2]).sub(a);
            out0.fma(-out0.dot(axis), axis).normalize();
            Vector3d out1 = new Vector3d(to[1][0], to[1][1], to[1][2]).sub(new Vector3d(to[0][0], to[0][1], to[0][2]));
            out1.fma(-out1.dot(axis), axis).normalize();
            double angle = Math.atan2(new Vector3d(out0).cross(out1).dot(axis), out0.dot(out1));
            if (Math.abs(Math.abs(angle) - Math.PI) < 1e-6) {
                // A flat fold: swing over (towards the triangle's outside) or under, as the fold says.
                Vector3d up = new Vector3d(before.normal()[0], before.normal()[1], before.normal()[2]);
                double sign = new Vector3d(axis).cross(out0).dot(up) > 0 ? 1 : -1;
                angle = move.over() ? sign * Math.PI : -sign * Math.PI;
            }
            double[][] corners = new double[4][];
            for (int c = 0; c < 4; c++) {
                corners[c] = rotate(from[c], a, axis, angle * fraction);
            }
            addPolygon(corners, PaperView.CAP, points, triangles, colors);
        }

        /** The area of triangle t of the mesh. */
        private static double area(IndexedPolygons mesh, int t) {
            double[] e1 = new double[3];
            double[] e2 = new double[3];
            for (int axis = 0; axis < 3; axis++) {
                double o = mesh.coordinate(mesh.faceVertex(t, 0), axis);
                e1[axis] = mesh.coordinate(mesh.faceVertex(t, 1), axis) - o;
                e2[axis] = mesh.coordinate(mesh.faceVertex(t, 2), axis) - o;
            }
            double x = e1[1] * e2[2] - e1[2] * e2[1];
            double y = e1[2] * e2[0] - e1[0] * e2[2];
            double z = e1[0] * e2[1] - e1[1] * e2[0];
            return Math.sqrt(x * x + y * y + z * z) / 2;
        }

        private int topLevel(Sheet sheet, int[] levels, int host) {
            int top = -1;
            for (int f : sheet.facesOn(host)) {
                top = Math.max(top, levels[f]);
            }
            return top;
        }

        @Override
        public String describe(double position) {
            if (position >= REVEAL_STEPS || steps.isEmpty()) {
                int strips = result.strips().size();
                return ending != null ? ending : "wrapped: " + strips + (strips == 1 ? " strip" : " strips") + " over " + triangles
                        + (triangles == 1 ? " triangle" : " triangles");
            }
            int beat = beatAt(position);
            // On a lone triangle the camera turns under for the tucks: what is seen is the underside.
            double middle = along(beat * beatLength + beatLength / 2);
            String below = underAt(middle) > 0.5 ? " (seen from below)" : "";
            if (beatCaption[beat] != null) {
                // A beat of several folds is seen from below all through only where each is a tuck.
                boolean tucks = triangles == 1;
                for (int j = 0; j < steps.size() && tucks; j++) {
                    tucks = beatOfStep[j] != beat || steps.get(j).kind() == Wrap.Kind.TUCK;
                }
                return beatCaption[beat] + (tucks ? below : "");
            }
            int j = Math.min(steps.size() - 1, (int) Math.floor(along(position)));
            return describeStep(j) + below;
        }
    }

    private static final SceneMesh EMPTY = new SceneMesh(new double[0], new int[0], new int[0], new int[0], new int[0]);

    private static void addPolygon(double[][] corners, int color, List<double[]> points, List<int[]> triangles, List<Integer> colors) {
        int base = points.size();
        for (double[] corner : corners) {
            points.add(corner);
        }
        for (int c = 1; c + 1 < corners.length; c++) {
            triangles.add(new int[] {base, base + c, base + c + 1});
            colors.add(color);
        }
    }

    /** A point turned by {@code angle} about the line through (px, py) with direction (dx, dy) in a triangle's frame, at height 0. */
    private static double[] turnAbout(double[] point, HostFrame frame, double px, double py, double dx, double dy, double angle) {
        double[] a = new double[3];
        frame.toSpace(px, py, 0, a, 0);
        double[] b = new double[3];
        frame.toSpace(px + dx, py + dy, 0, b, 0);
        Vector3d axis = new Vector3d(b[0] - a[0], b[1] - a[1], b[2] - a[2]).normalize();
        return rotate(point, new Vector3d(a[0], a[1], a[2]), axis, angle);
    }

    /** Rodrigues: p turned by {@code angle} about the axis through {@code origin}. */
    private static double[] rotate(double[] p, Vector3d origin, Vector3d axis, double angle) {
        Vector3d v = new Vector3d(p[0], p[1], p[2]).sub(origin);
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        Vector3d cross = new Vector3d(axis).cross(v);
        double dot = axis.dot(v);
        Vector3d r = new Vector3d(v).mul(c).fma(s, cross).fma(dot * (1 - c), axis).add(origin);
        return new double[] {r.x, r.y, r.z};
    }

}
