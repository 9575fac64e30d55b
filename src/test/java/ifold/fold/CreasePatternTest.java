package ifold.fold;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.script.ScriptFolding;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Crease patterns of many parallel creases fold at a cost that grows with the creases, not with their cube. */
class CreasePatternTest {
    @TempDir
    Path dir;

    /**
     * A FOLD file of {@code n} parallel creases, mountain and valley in turn, across a strip
     * n + 1 long and 10 wide: it folds into a pile of n + 1 layers, each fold landing on the pile.
     */
    static Path parallelCreases(Path dir, int n) throws Exception {
        StringBuilder vertices = new StringBuilder();
        StringBuilder edges = new StringBuilder();
        StringBuilder assignments = new StringBuilder();
        for (int k = 0; k <= n + 1; k++) {
            vertices.append(k == 0 ? "" : ", ").append('[').append(k).append(", 0], [").append(k).append(", 10]");
        }
        // Vertex 2k is (k, 0), 2k + 1 is (k, 10): the border along both long sides, the two ends, then the creases.
        for (int k = 0; k <= n; k++) {
            edges.append(k == 0 ? "" : ", ").append('[').append(2 * k).append(", ").append(2 * k + 2).append("], [")
                    .append(2 * k + 1).append(", ").append(2 * k + 3).append(']');
            assignments.append(k == 0 ? "" : ", ").append("\"B\", \"B\"");
        }
        edges.append(", [0, 1], [").append(2 * n + 2).append(", ").append(2 * n + 3).append(']');
        assignments.append(", \"B\", \"B\"");
        for (int k = 1; k <= n; k++) {
            edges.append(", [").append(2 * k).append(", ").append(2 * k + 1).append(']');
            assignments.append(k % 2 == 1 ? ", \"V\"" : ", \"M\"");
        }
        return Files.writeString(dir.resolve("parallel" + n + ".fold"), "{\"frame_classes\": [\"creasePattern\"],\n \"vertices_coords\": ["
                + vertices + "],\n \"edges_vertices\": [" + edges + "],\n \"edges_assignment\": [" + assignments + "]}\n");
    }

    /**
     * Each fold lands on the pile's top layer: the order of the pile is n relations, not one
     * for every pair of layers (n² / 2: 80,000 here), which every later fold would walk.
     */
    @Test
    void aPileOfParallelFoldsKeepsOneRelationALayer() throws Exception {
        int n = 400;
        CreasePattern pattern = CreasePattern.read(parallelCreases(dir, n));
        assertEquals(n, pattern.lines().size(), "setup: one line a crease");
        CreasePattern.Folding folding = pattern.fold(new long[n], ScriptFolding.DEFAULT_MAX_FACES);
        assertEquals(n + 1, folding.result().sheet().faceCount());
        assertEquals(n + 1, folding.result().sheet().stackLevels(), "a pile of n + 1 layers");
        int relations = folding.result().sheet().orderRelations();
        assertTrue(relations <= 2 * n, "relations: " + relations);
    }

    /** 2,000 parallel creases folded in 77 s (cubic: 500 took 3.5 s); now in a few seconds. */
    @Test
    void twoThousandParallelCreasesFoldInSeconds() throws Exception {
        int n = 2000;
        CreasePattern pattern = CreasePattern.read(parallelCreases(dir, n));
        long start = System.nanoTime();
        CreasePattern.Folding folding = pattern.fold(new long[n], ScriptFolding.DEFAULT_MAX_FACES);
        double seconds = (System.nanoTime() - start) * 1e-9;
        assertEquals(n + 1, folding.result().sheet().stackLevels());
        assertTrue(seconds < 20, "folded in " + seconds + " s");
    }
}
