package ifold.scene;

import ifold.mesh.IndexedPolygons;
import ifold.sheet.HostFrame;
import ifold.sheet.Tuck;
import ifold.wrap.Wrap;
import java.util.ArrayList;
import java.util.List;
import org.joml.Quaterniond;
import org.joml.Quaterniondc;
import org.joml.Vector3d;

/**
 * The wrap played fold by fold, then one turn around the result. A movie of a thousand folds
 * cannot show each for long enough to read its caption: the first triangle is shown fold by
 * fold, and each later step is a triangle, or a run of them, wrapped the same way, said so in
 * its caption; every caption stays at least {@link WrapView#CAPTION_SECONDS} at the length it is
 * {@linkplain #pace paced} for.
 */
public final class WrapPlayback implements Animation {
    final Scene scene;

    final Geometry done;

    final Geometry current;

    final WrapView.Strips strips;

    final Wrap.Result result;

    final List<Wrap.Step> steps;

    /** For each step, its place among all path triangles (strips one after another). */
    final int[] triangleOf;

    /** Each strip's face levels, final: found once, not per frame. */
    final int[][] levels;

    final int triangles;

    final double[] centres;

    final double[] normals;

    final Vector3d modelCentre;

    final double modelRadius;

    final int window;

    /** What the final turn starts from: the model turned to show its outer side, where it has one. */
    final Quaterniondc finalFacing;

    final double finalTurn;

    /** The caption once all is folded: what the paper does now. */
    final String ending;

    double shown = -1;

    /** For each step, the position it begins at; the last entry is the end of the folding. */
    double[] stepStart;

    /** For each step, the beat (a caption's time on screen) it is played in. */
    int[] beatOfStep;

    /** Each beat's caption, or null where it is its fold's own. */
    String[] beatCaption;

    /** The positions one beat lasts. */
    double beatLength;

    /** For each path triangle, the positions its folds begin and end at. */
    double[] slotStart;

    double[] slotEnd;

    /** For each path triangle, its first step and the step after its last (none: equal). */
    int[] firstStep;

    int[] endStep;

    /** For each panel of the step diagrams, its first step, and whether it shows that step alone. */
    int[] panelFirst;
    /** Each panel's last path triangle, where it shows triangles' folds together (a run of them past {@link #MOST_PANELS}). */
    int[] panelLastTriangle;

    boolean[] panelIsStep;

    /** For each step, the number of the printed crease it makes (the creasing steps so far, counted from 1). */
    int[] printNumber;
    /** The paper being folded, as it stands at each moment. */
    final PlaybackMesh meshes = new PlaybackMesh(this);
    /** Where the camera looks as the wrap plays. */
    final PlaybackCamera cameraPath = new PlaybackCamera(this);

    WrapPlayback(Scene scene, Geometry done, Geometry current, WrapView.Strips strips, Wrap.Result result, String ending) {
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
                areas[g] = PlaybackMesh.area(mesh, t);
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
        layOutPanels();
        printNumber = new int[steps.size()];
        int creasing = 0;
        for (int j = 0; j < steps.size(); j++) {
            creasing += creases(steps.get(j)) ? 1 : 0;
            printNumber[j] = creasing;
        }
        pace(WrapView.DEFAULT_SECONDS);
    }

    /**
     * Lays the folds out for a playback of {@code seconds}, so that each caption stays at least
     * {@link WrapView#CAPTION_SECONDS}: where there is time, the first triangle fold by fold and each
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
            beatLength = WrapView.REVEAL_STEPS;
            return;
        }
        double folding = seconds * WrapView.REVEAL_STEPS / (WrapView.REVEAL_STEPS + WrapView.TURN_STEPS);
        int most = Math.max(1, (int) Math.floor(folding / WrapView.CAPTION_SECONDS + 1e-9));
        // Each beat: its triangles (from, to) or, for a beat of folds, -1 and its steps.
        List<int[]> beats = new ArrayList<>();
        List<String> captions = new ArrayList<>();
        List<Integer> withSteps = new ArrayList<>();
        for (int t = 0; t < triangles; t++) {
            if (endStep[t] > firstStep[t]) {
                withSteps.add(t);
            }
        }
        if (result.method() == Wrap.Method.HINGE) {
            // The hinge strip's passes fold once or twice each: every fold its own beat where there
            // is time, else runs of passes, each said by its folds.
            if (n <= most) {
                for (int j = 0; j < n; j++) {
                    beats.add(new int[] {-1, j, j + 1});
                    captions.add(null);
                }
            } else {
                for (List<Integer> run : runs(withSteps, most)) {
                    beats.add(new int[] {run.get(0), run.get(run.size() - 1)});
                    captions.add(describeRun(run, true));
                }
            }
        } else if (withSteps.size() == 1) {
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
        beatLength = (double) WrapView.REVEAL_STEPS / beats.size();
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
        stepStart[n] = WrapView.REVEAL_STEPS;
        for (int t = 0; t < triangles; t++) {
            if (endStep[t] > firstStep[t]) {
                slotStart[t] = stepStart[firstStep[t]];
                slotEnd[t] = stepStart[endStep[t]];
            }
        }
        shown = -1;
    }

    /** The triangles in runs of equal length, as few as fit in {@code room} beats, a run never crossing from one strip to the next. */
    List<List<Integer>> runs(List<Integer> grouped, int room) {
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
    String describeRun(List<Integer> run, boolean afterDetail) {
        Wrap.Step first = steps.get(firstStep[run.get(0)]);
        Wrap.Step last = steps.get(firstStep[run.get(run.size() - 1)]);
        String strip = result.strips().size() > 1 ? "strip " + (first.strip() + 1) + ", " : "";
        String which = run.size() == 1 ? result.unit() + " " + (first.pathIndex() + 1)
                : result.units() + " " + (first.pathIndex() + 1) + "\u2013" + (last.pathIndex() + 1);
        if (result.method() == Wrap.Method.HINGE) {
            return strip + which + " of " + first.pathLength() + ":" + kinds(firstStep[run.get(0)], endStep[run.get(run.size() - 1)]);
        }
        String how = !afterDetail ? "zig-zag passes, turns and tucks"
                : (run.size() == 1 ? "wrapped as triangle 1" : "each wrapped as triangle 1") + (result.strips().size() > 1 ? " of strip 1" : "");
        return strip + which + " of " + first.pathLength() + ": " + how;
    }

    /**
     * Whether a step leaves a crease the printed pattern numbers: not the strip's end, nor a
     * crossing onto another host in the same plane (the paper runs on flat there: the print draws
     * it as the edge of a face, no fold).
     */
    private boolean creases(Wrap.Step step) {
        if (step.kind().crease() == null) {
            return false;
        }
        if (step.kind() == Wrap.Kind.EDGE_CROSSING && step.tail() != null) {
            double[] a = result.frames()[step.tail().hostBefore()].normal();
            double[] b = result.frames()[step.tail().hostAfter()].normal();
            return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] < 1 - 1e-12;
        }
        return true;
    }

    /** The folds of steps {@code from} to {@code to} by kind: " 3 turn folds, 2 tucks". */
    private String kinds(int from, int to) {
        int[] kinds = new int[Wrap.Kind.values().length];
        int flat = 0;
        for (int j = from; j < to; j++) {
            Wrap.Step step = steps.get(j);
            if (step.kind() == Wrap.Kind.EDGE_CROSSING && !creases(step)) {
                flat++; // on over a side into the next piece of a face: no fold
            } else {
                kinds[step.kind().ordinal()]++;
            }
        }
        StringBuilder text = new StringBuilder();
        String separator = " ";
        if (flat > 0) {
            text.append(separator).append(flat).append(flat == 1 ? " time on flat over a side" : " times on flat over a side");
            separator = ", ";
        }
        for (Wrap.Kind kind : Wrap.Kind.values()) {
            int n = kinds[kind.ordinal()];
            if (kind == Wrap.Kind.END && n > 0) {
                // Not a fold to count: where the strip stops.
                text.append(separator).append(n == 1 ? "the strip's end" : n + " ends of strips");
                separator = ", ";
            } else if (n > 0) {
                String word = switch (kind) {
                    case ZIGZAG_TURN -> n == 1 ? "turn fold" : "turn folds";
                    case TURN_GADGET -> n == 1 ? "gadget fold" : "gadget folds";
                    case EDGE_CROSSING -> result.method() == Wrap.Method.HINGE ? (n == 1 ? "fold over an edge" : "folds over edges")
                            : n == 1 ? "crossing to the next triangle" : "crossings to the next triangle";
                    case OVERLAP -> n == 1 ? "overlap" : "overlaps";
                    case TUCK -> n == 1 ? "tuck" : "tucks";
                    case END -> throw new AssertionError("said above");
                    case DIAGONAL_TURN -> n == 1 ? "turn along a square's diagonal" : "turns along squares' diagonals";
                };
                text.append(separator).append(n).append(' ').append(word);
                separator = ", ";
            }
        }
        return text.toString();
    }

    String describeStep(int j) {
        Wrap.Step step = steps.get(j);
        return (result.strips().size() > 1 ? "strip " + (step.strip() + 1) + ", " : "") + step.describe();
    }

    /** The beat shown at a position of the folding. */
    int beatAt(double position) {
        return beatOfStep[(int) Math.floor(along(position))];
    }

    public int stepCount() {
        return WrapView.REVEAL_STEPS + WrapView.TURN_STEPS;
    }

    /**
     * The folds of step diagrams: each fold of a path of one or two triangles (the demos) and of
     * the hinge strip; for a longer zig-zag path, each fold of its first triangle, then each
     * later triangle, its passes, gadgets, crossing and tucks in one panel.
     */
    @Override
    public int foldCount() {
        return panelFirst.length;
    }

    @Override
    public double foldStart(int k) {
        if (steps.isEmpty()) {
            return 0;
        }
        return k >= panelFirst.length ? stepStart[steps.size()] : stepStart[panelFirst[k]];
    }

    /**
     * A panel of one fold: the number the printed crease pattern gives its crease (the creasing
     * folds counted in order, as the FOLD file's foldStep); blank where it folds nothing (the
     * strip's end). A panel of a triangle: "T" and the triangle's number on its path.
     */
    @Override
    public String foldLabel(int k) {
        int alone = stepOfPanel(k);
        if (alone >= 0) {
            return !creases(steps.get(alone)) ? "" : Integer.toString(printNumber[alone]);
        }
        // A run's first; its caption says where it ends.
        return (result.method() == Wrap.Method.HINGE ? "P" : "T") + (triangleOf[panelFirst[k]] + 1);
    }

    @Override
    public boolean foldIsGroup(int k) {
        return k >= 0 && k < panelFirst.length && !panelIsStep[k];
    }

    /** The step a panel shows alone, or -1 where it shows a triangle's folds together. */
    private int stepOfPanel(int k) {
        return k >= 0 && k < panelFirst.length && panelIsStep[k] ? panelFirst[k] : -1;
    }

    /**
     * The panels of the step diagrams: for each, its first step and whether it shows that step
     * alone (else the steps of its triangle).
     */
    private void layOutPanels() {
        List<Integer> first = new ArrayList<>();
        List<Boolean> alone = new ArrayList<>();
        List<Integer> last = new ArrayList<>();
        List<Integer> withSteps = new ArrayList<>();
        for (int t = 0; t < triangles; t++) {
            if (endStep[t] > firstStep[t]) {
                withSteps.add(t);
            }
        }
        // The hinge strip folds once or twice a pass, each fold worth a panel of its own where
        // they are few enough to print; the zig-zag's first triangle fold by fold, then a panel a
        // triangle; past MOST_PANELS, the rest in runs of triangles (a 1,000-page book helps no one).
        boolean everyFold = triangles <= 2 || result.method() == Wrap.Method.HINGE && steps.size() <= MOST_PANELS;
        int from = 0;
        if (!everyFold && !withSteps.isEmpty() && result.method() != Wrap.Method.HINGE) {
            int t = withSteps.get(0);
            for (int j = firstStep[t]; j < endStep[t]; j++) {
                first.add(j);
                alone.add(true);
                last.add(t);
            }
            from = 1;
        }
        if (everyFold) {
            for (int t : withSteps) {
                for (int j = firstStep[t]; j < endStep[t]; j++) {
                    first.add(j);
                    alone.add(true);
                    last.add(t);
                }
            }
        } else {
            int rest = withSteps.size() - from;
            int room = Math.max(1, MOST_PANELS - first.size());
            int per = (rest + room - 1) / room;
            for (int i = from; i < withSteps.size(); i += per) {
                first.add(firstStep[withSteps.get(i)]);
                alone.add(false);
                last.add(withSteps.get(Math.min(withSteps.size(), i + per) - 1));
            }
        }
        panelFirst = first.stream().mapToInt(Integer::intValue).toArray();
        panelLastTriangle = last.stream().mapToInt(Integer::intValue).toArray();
        panelIsStep = new boolean[alone.size()];
        for (int k = 0; k < panelIsStep.length; k++) {
            panelIsStep[k] = alone.get(k);
        }
    }

    /** The most panels a wrap's step diagrams get: 40 pages of six. */
    static final int MOST_PANELS = 240;

    /**
     * A fold's crease, where its panel shows one fold: a fold of the tail across the strip where
     * it lay before (over: a valley seen from outside the host, the side its normal points to), or
     * a tuck's line along its host's edge (its flap goes under: a mountain from outside). A panel
     * of a whole triangle has none.
     */
    @Override
    public FoldLine foldLine(int k) {
        int j = stepOfPanel(k);
        if (j < 0) {
            return null;
        }
        Wrap.Step step = steps.get(j);
        double[] from = new double[3];
        double[] to = new double[3];
        if (step.tail() != null) {
            Wrap.TailMove tail = step.tail();
            double w = result.strips().get(step.strip()).sheet().width();
            HostFrame frame = result.frames()[tail.hostBefore()];
            frame.toSpace(tail.before().x(tail.u0(), 0), tail.before().y(tail.u0(), 0), 0, from, 0);
            frame.toSpace(tail.before().x(tail.u1(), w), tail.before().y(tail.u1(), w), 0, to, 0);
            return new FoldLine(from, to, tail.over(), frame.normal().clone());
        }
        if (step.tuck() != null) {
            Tuck tuck = step.tuck();
            HostFrame frame = result.frames()[tuck.host()];
            frame.toSpace(tuck.px(), tuck.py(), 0, from, 0);
            frame.toSpace(tuck.px() + tuck.dx(), tuck.py() + tuck.dy(), 0, to, 0);
            return new FoldLine(from, to, false, frame.normal().clone());
        }
        return null;
    }

    /** The way the paper a lone fold moves travels, for its panel's arrow. */
    @Override
    public double[][] foldPath(int k) {
        int j = stepOfPanel(k);
        if (j < 0) {
            return null;
        }
        Wrap.Step step = steps.get(j);
        Wrap.Strip strip = result.strips().get(step.strip());
        int i = step.pathIndex();
        return meshes.flapPath(strip, step, j, i > 0 ? strip.facesAfter()[i - 1] : 0);
    }

    /**
     * A demo's panel, as the movie says it; a wrap's panel of one fold of its first triangle, that
     * fold's own words; a wrap's panel of a triangle, its folds by kind.
     */
    @Override
    public String foldCaption(int k) {
        if (triangles <= 2) {
            return describe((foldStart(k) + foldStart(k + 1)) / 2);
        }
        int alone = stepOfPanel(k);
        if (alone >= 0) {
            if (!creases(steps.get(alone))) {
                return describeStep(alone); // it folds nothing: not one of its triangle's folds
            }
            // Its place among its triangle's folds, counted as the print numbers them.
            int t = triangleOf[alone];
            int before = firstStep[t] > 0 ? printNumber[firstStep[t] - 1] : 0;
            return String.format(java.util.Locale.ROOT, "%s (fold %d of %d)", describeStep(alone), printNumber[alone] - before,
                    printNumber[endStep[t] - 1] - before);
        }
        int first = panelFirst[k];
        int t = triangleOf[first];
        int lastTriangle = panelLastTriangle[k];
        StringBuilder text = new StringBuilder(t == lastTriangle
                ? String.format(java.util.Locale.ROOT, "%s %d of %d:", result.unit(), t + 1, triangles)
                : String.format(java.util.Locale.ROOT, "%s %d\u2013%d of %d:", result.units(), t + 1, lastTriangle + 1, triangles));
        int from = firstStep[t];
        int to = endStep[lastTriangle];
        text.append(kinds(from, to));
        // Which of the printed creases they are: the triangles' creasing folds run one after another.
        int low = from > 0 ? printNumber[from - 1] + 1 : 1;
        int high = printNumber[to - 1];
        if (high >= low) {
            text.append(low == high ? String.format(java.util.Locale.ROOT, " (crease %d on the print)", low)
                    : String.format(java.util.Locale.ROOT, " (creases %d\u2013%d on the print)", low, high));
        }
        return text.toString();
    }

    /** The position at which the first {@code folds} steps of the wrap are made and the next has not begun. */
    public double positionAfter(int folds) {
        return steps.isEmpty() ? 0 : stepStart[Math.max(0, Math.min(folds, steps.size()))];
    }

    /** The position half way round the final turn: the wrapped model seen from behind. */
    public double halfTurn() {
        return WrapView.REVEAL_STEPS + WrapView.TURN_STEPS / 2.0;
    }

    /** The step (fold) shown at a position, with how far it has gone. */
    double along(double position) {
        int n = steps.size();
        if (position >= WrapView.REVEAL_STEPS) {
            return n;
        }
        int j = java.util.Arrays.binarySearch(stepStart, 0, n, position);
        j = j >= 0 ? j : -j - 2;
        j = Math.max(0, Math.min(n - 1, j));
        double length = stepStart[j + 1] - stepStart[j];
        return j + (length > 0 ? Math.min(1, (position - stepStart[j]) / length) : 0);
    }

    public void apply(double position) {
        if (position == shown) {
            return;
        }
        shown = position;
        Camera camera = scene.camera();
        if (position >= WrapView.REVEAL_STEPS || steps.isEmpty()) {
            done.setRevealed(Geometry.ALL);
            current.setMesh(WrapView.EMPTY);
            camera.frame(modelCentre, modelRadius);
            double angle = Math.toRadians((position - WrapView.REVEAL_STEPS) * 360.0 / WrapView.TURN_STEPS);
            Quaterniond turn = new Quaterniond().rotateX(-0.5).rotateY(finalTurn + Math.max(0, angle)).mul(finalFacing);
            camera.setOrientation(turn);
            // The first moments of the turn glide from where the camera followed the last fold.
            double glide = steps.isEmpty() ? 1 : (position - WrapView.REVEAL_STEPS) / (WrapView.GLIDE * WrapView.TURN_STEPS);
            if (glide < 1) {
                Camera last = new Camera();
                if (triangles > 2) {
                    last.frame(modelCentre, PlaybackCamera.WIDE * modelRadius);
                    last.setOrientation(cameraPath.closeOrientation(triangleOf[steps.size() - 1]));
                } else {
                    cameraPath.follow(last, triangles, cameraPath.underAt(steps.size()));
                }
                double b = PlaybackCamera.smooth(Math.max(0, glide));
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
        current.setMesh(meshes.currentMesh(strip, step, j, firstFace, fraction));
        if (triangles > 2) {
            cameraPath.frameTriangle(camera, position, triangleOf[j]);
        } else {
            cameraPath.follow(camera, triangleOf[j] + Math.min(1, (j + fraction - firstStepOf(j)) / Math.max(1, stepsOf(j))), cameraPath.underAt(along));
        }
    }

    static int last(int[] a) {
        return a[a.length - 1];
    }

    int firstStepOf(int j) {
        int first = j;
        while (first > 0 && triangleOf[first - 1] == triangleOf[j]) {
            first--;
        }
        return first;
    }

    int stepsOf(int j) {
        int first = firstStepOf(j);
        int end = j;
        while (end < steps.size() && triangleOf[end] == triangleOf[j]) {
            end++;
        }
        return end - first;
    }

    public String describe(double position) {
        if (position >= WrapView.REVEAL_STEPS || steps.isEmpty()) {
            int strips = result.strips().size();
            if (ending != null) {
                return ending;
            }
            String strip = strips + (strips == 1 ? " strip" : " strips");
            if (result.method() == Wrap.Method.HINGE) {
                return "wrapped: " + strip + " over " + triangles / 2 + " squares, each passed twice: two layers everywhere";
            }
            return "wrapped: " + strip + " over " + triangles + (triangles == 1 ? " triangle" : " triangles");
        }
        int beat = beatAt(position);
        // On a lone triangle the camera turns under for the tucks: what is seen is the underside.
        double middle = along(beat * beatLength + beatLength / 2);
        String below = cameraPath.underAt(middle) > 0.5 ? " (seen from below)" : "";
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
