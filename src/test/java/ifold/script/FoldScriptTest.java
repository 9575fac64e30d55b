package ifold.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.fold.Fold;
import ifold.fold.Folder;
import ifold.fold.Paper;
import ifold.fold.PaperAnalysis;
import ifold.mesh.MeshValidator;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;

class FoldScriptTest {

    private static int errorLine(String text) {
        return assertThrows(FoldScriptException.class, () -> FoldScript.parse(text).play()).line();
    }

    @Test
    void parsesEveryFormOfLine() throws Exception {
        FoldScript script = FoldScript.parse("""
                # comments and blank lines are fine

                paper rectangle 8 2   # trailing comment
                thickness 0
                fold valley 180 paper 4 0 4 2 right
                fold MOUNTAIN 90 points 1 0 0 1 2 0 left
                fold valley 45 point 2.5 0 0 direction 0 1 0 right
                """);
        assertEquals(3, script.steps().size());
        assertEquals(Fold.Kind.MOUNTAIN, script.steps().get(1).kind());
        assertEquals(5, script.steps().get(0).line());
        List<Folder.Prepared> folds = script.play();
        assertEquals(3, folds.size());
        Paper end = folds.get(2).at(1);
        assertTrue(PaperAnalysis.isometryError(end) <= 1e-9);
        assertEquals(16, PaperAnalysis.paperArea(end), 1e-9);
    }

    @Test
    void errorsNameTheLine() {
        assertEquals(2, errorLine("paper strip 10 1\nfold valley 200 paper 5 0 5 1 right\n"));
        assertEquals(2, errorLine("paper strip 10 1\nfold sideways 90 paper 5 0 5 1 right\n"));
        assertEquals(3, errorLine("paper strip 10 1\n\nfold valley 90 paper 5 0 5 1 up\n"));
        assertEquals(2, errorLine("paper strip 10 1\nfold valley 90 paper 5 0 5 1 right extra\n"));
        assertEquals(1, errorLine("paper circle 3\n"));
        assertEquals(1, errorLine("fold valley 90 paper 5 0 5 1 right\n"));
        assertEquals(2, errorLine("paper strip 10 1\nunfold now\n"));
        assertEquals(2, errorLine("paper strip 10 1\nfold valley 90 paper 5 0 5 x right\n"));
        // A line that misses the paper is found when the script plays, and still names its line.
        assertEquals(3, errorLine("paper strip 10 1\nthickness 0.01\nfold valley 180 paper 20 0 20 1 right\n"));
        assertEquals(2, errorLine("paper strip 10 1\nfold valley 180 points 12 0 0 12 1 0 right\n"));
        assertEquals(0, errorLine("# nothing\n"));
    }

    @Test
    void builderMakesTheSameScript() throws Exception {
        FoldScript built = FoldScript.builder().strip(10, 1).thickness(0.02)
                .foldOnPaper(Fold.Kind.VALLEY, 180, 5, 0, 6, 1, Fold.Side.RIGHT).build();
        FoldScript parsed = FoldScript.parse("paper strip 10 1\nthickness 0.02\nfold valley 180 paper 5 0 6 1 right\n");
        Paper a = built.play().get(0).at(1);
        Paper b = parsed.play().get(0).at(1);
        assertEquals(a.vertexCount(), b.vertexCount());
        for (int v = 0; v < a.vertexCount(); v++) {
            assertEquals(a.x(v), b.x(v), 0);
            assertEquals(a.z(v), b.z(v), 0);
        }
    }

    static Stream<String> scripts() throws Exception {
        try (Stream<Path> files = Files.list(Path.of("models", "scripts"))) {
            return files.map(p -> p.getFileName().toString()).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("scripts")
    void exampleScriptsFoldSoundly(String name) throws Exception {
        List<Folder.Prepared> folds = FoldScript.read(Path.of("models", "scripts", name)).play();
        assertTrue(!folds.isEmpty());
        for (Folder.Prepared fold : folds) {
            for (double fraction : new double[] {0.25, 0.5, 1}) {
                Paper paper = fold.at(fraction);
                assertTrue(PaperAnalysis.isometryError(paper) <= 1e-9, name + " is isometric");
            }
            assertEquals(List.of(), MeshValidator.validate(fold.at(1).top()));
        }
    }

    @Test
    void theTurnScriptTurnsTheStripByNinetyDegrees() throws Exception {
        List<Folder.Prepared> folds = FoldScript.read(Path.of("models", "scripts", "strip-turn.fold")).play();
        Paper end = folds.get(0).at(1);
        for (int v = 0; v < end.vertexCount(); v++) {
            if (end.u(v) == 10 && end.v(v) == 0) {
                // The end corner (10, 0) mirrored across the 45-degree line through (5, 0).
                assertEquals(5, end.x(v), 1e-9);
                assertEquals(5, end.y(v), 1e-9);
            }
        }
        assertEquals(2, PaperAnalysis.maxLayers(end));
    }

    @Test
    void quartersHaveFourLayers() throws Exception {
        List<Folder.Prepared> folds = FoldScript.read(Path.of("models", "scripts", "square-quarters.fold")).play();
        Paper end = folds.get(1).at(1);
        assertEquals(4, PaperAnalysis.layersAt(end, 2.5, 2.5, 0));
        assertEquals(100, PaperAnalysis.paperArea(end), 1e-9);
    }

    @Test
    void flapFoldsTurnTheStripBesideItself() throws Exception {
        List<Folder.Prepared> folds = FoldScript.read(Path.of("models", "scripts", "zigzag-turn.fold")).play();
        Paper end = folds.get(1).at(1);
        assertTrue(PaperAnalysis.isometryError(end) <= 1e-12);
        assertEquals(List.of(), MeshValidator.validate(end.top()));
        assertEquals(2, PaperAnalysis.maxLayers(end), "only the turn holds two layers");
        for (int v = 0; v < end.vertexCount(); v++) {
            if (end.u(v) == 12 && end.v(v) == 1) {
                // The strip's end runs back along the band below the first pass, at its height.
                assertEquals(0, end.x(v), 1e-9);
                assertEquals(-1, end.y(v), 1e-9);
                assertEquals(0, end.z(v), 1e-9);
            }
        }
        // The flap form names the side on the sheet: the same folds from the builder.
        List<Folder.Prepared> built = FoldScript.builder().strip(12, 1).thickness(0.02)
                .flap(Fold.Kind.VALLEY, 180, 5, 1, 6, 0, Fold.Side.LEFT)
                .flap(Fold.Kind.MOUNTAIN, 180, 6, 0, 7, 1, Fold.Side.RIGHT).build().play();
        assertEquals(end.vertexCount(), built.get(1).at(1).vertexCount());
        assertEquals(2, errorLine("paper strip 12 1\nfold valley 180 flap 5 1 5 1 left\n"), "a crease needs two points");
    }
}
