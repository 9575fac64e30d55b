package ifold.scene;

import ifold.fold.Folder;
import ifold.fold.Paper;
import ifold.fold.PaperMotion;
import java.util.ArrayList;
import java.util.List;

/** Paper on screen: its faces (caps in grey), outlined, with the creases in red; and folds as animations. */
public final class PaperView {
    public static final int PAPER = 0xFFF4F1EA;
    public static final int CAP = 0xFF9A9A9A;
    public static final int CREASE = 0xFFB03030;

    private PaperView() {
    }

    /** How the paper is drawn: face colours (paper or cap) on the front, a blue-grey back. */
    public static final Material MATERIAL = new Material(PAPER, 0xFF8FAACB, true, true);

    public static SceneMesh mesh(Paper paper) {
        double[] positions = new double[3 * paper.vertexCount()];
        for (int v = 0; v < paper.vertexCount(); v++) {
            positions[3 * v] = paper.x(v);
            positions[3 * v + 1] = paper.y(v);
            positions[3 * v + 2] = paper.z(v);
        }
        List<int[]> triangles = new ArrayList<>();
        List<Integer> colors = new ArrayList<>();
        List<Long> edgeKeys = new ArrayList<>();
        for (int f = 0; f < paper.faceCount(); f++) {
            int[] face = paper.face(f);
            for (int i = 1; i + 1 < face.length; i++) { // faces are convex: a fan will do
                triangles.add(new int[] {face[0], face[i], face[i + 1]});
                colors.add(paper.isCap(f) ? CAP : PAPER);
            }
            if (!paper.isCap(f)) {
                for (int i = 0; i < face.length; i++) {
                    int a = face[i];
                    int b = face[(i + 1) % face.length];
                    edgeKeys.add(((long) Math.min(a, b) << 32) | Math.max(a, b));
                }
            }
        }
        int[] flat = new int[3 * triangles.size()];
        for (int t = 0; t < triangles.size(); t++) {
            System.arraycopy(triangles.get(t), 0, flat, 3 * t, 3);
        }
        long[] keys = edgeKeys.stream().mapToLong(Long::longValue).toArray();
        int[] edges = SceneMesh.uniqueEdges(keys, keys.length);
        java.util.Set<Long> creases = new java.util.HashSet<>();
        for (int[] crease : paper.creaseEdges()) {
            creases.add(((long) Math.min(crease[0], crease[1]) << 32) | Math.max(crease[0], crease[1]));
        }
        int[] edgeColors = new int[edges.length / 2];
        for (int e = 0; e < edgeColors.length; e++) {
            long key = ((long) edges[2 * e] << 32) | edges[2 * e + 1];
            edgeColors[e] = creases.contains(key) ? CREASE : SceneMesh.EDGE_COLOR;
        }
        return new SceneMesh(positions, flat, colors.stream().mapToInt(Integer::intValue).toArray(), edges, edgeColors);
    }

    /** Plays folds one after another, each swinging from 0 to its angle over one step. */
    public static Animation folding(Geometry geometry, Paper start, List<Folder.Prepared> folds) {
        return playing(geometry, start, folds, null);
    }

    /**
     * Plays paper motions (folds, presses) one after another, one a step; the status line shows
     * each one's description if {@code descriptions} is given.
     */
    public static Animation playing(Geometry geometry, Paper start, List<? extends PaperMotion> folds, List<String> descriptions) {
        return new Animation() {
            @Override
            public int stepCount() {
                return folds.size();
            }

            @Override
            public void apply(double position) {
                geometry.setMesh(mesh(at(position)));
            }

            private Paper at(double position) {
                if (folds.isEmpty()) {
                    return start;
                }
                int k = Math.min((int) Math.floor(position), folds.size() - 1);
                return folds.get(k).at(Math.max(0, Math.min(1, position - k)));
            }

            @Override
            public String describe(double position) {
                int k = Math.min((int) Math.floor(position), Math.max(0, folds.size() - 1));
                String step = String.format(java.util.Locale.ROOT, "step %d of %d (%.0f %%)", Math.min(k + 1, folds.size()),
                        folds.size(), 100 * Math.max(0, Math.min(1, position - k)));
                if (descriptions == null) {
                    return step.replace("step", "fold");
                }
                return folds.isEmpty() ? step : step + ": " + descriptions.get(k);
            }
        };
    }
}
