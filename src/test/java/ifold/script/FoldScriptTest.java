package ifold.script;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import ifold.wrap.WrapAnalysis;
import ifold.wrap.PaperInSpace;
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
        assertEquals(FoldScript.Kind.MOUNTAIN, script.steps().get(1).kind());
        assertEquals(5, script.steps().get(0).line());
        ScriptFolding.Result folded = script.play();
        assertEquals(3, folded.steps().size());
        assertTrue(isometryError(folded) <= 1e-9);
        assertEquals(3, folded.frames().length, "the table, the part turned down and the part turned up");
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

    private static double isometryError(ScriptFolding.Result result) {
        return WrapAnalysis.isometryError(PaperInSpace.of(result.sheet(), result.frames()), result.sheet().width());
    }

    @Test
    void builderMakesTheSameScript() throws Exception {
        FoldScript built = FoldScript.builder().strip(10, 1).thickness(0.02)
                .foldOnPaper(FoldScript.Kind.VALLEY, 180, 5, 0, 6, 1, FoldScript.Side.RIGHT).build();
        FoldScript parsed = FoldScript.parse("paper strip 10 1\nthickness 0.02\nfold valley 180 paper 5 0 6 1 right\n");
        PaperInSpace a = PaperInSpace.of(built.play().sheet(), built.play().frames());
        PaperInSpace b = PaperInSpace.of(parsed.play().sheet(), parsed.play().frames());
        assertEquals(a.vertexCount(), b.vertexCount());
        for (int k = 0; k < a.xyz().length; k++) {
            assertEquals(a.xyz()[k], b.xyz()[k], 0);
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
        ScriptFolding.Result folded = FoldScript.read(Path.of("models", "scripts", name)).play();
        assertTrue(!folded.steps().isEmpty());
        assertTrue(isometryError(folded) <= 1e-9, name + " is isometric");
    }

    @Test
    void theTurnScriptTurnsTheStripByNinetyDegrees() throws Exception {
        ScriptFolding.Result folded = FoldScript.read(Path.of("models", "scripts", "strip-turn.fold")).play();
        PaperInSpace geometry = PaperInSpace.of(folded.sheet(), folded.frames());
        int found = 0;
        for (int v = 0; v < geometry.vertexCount(); v++) {
            if (geometry.uv()[2 * v] == 10 && geometry.uv()[2 * v + 1] == 0) {
                // The end corner (10, 0) mirrored across the 45-degree line through (5, 0).
                assertEquals(5, geometry.xyz()[3 * v], 1e-9);
                assertEquals(5, geometry.xyz()[3 * v + 1], 1e-9);
                found++;
            }
        }
        assertEquals(1, found);
        assertEquals(2, WrapAnalysis.maxLayers(folded.sheet(), folded.frames().length));
    }

    @Test
    void quartersHaveFourLayers() throws Exception {
        ScriptFolding.Result folded = FoldScript.read(Path.of("models", "scripts", "square-quarters.fold")).play();
        assertEquals(4, WrapAnalysis.maxLayers(folded.sheet(), folded.frames().length));
        assertEquals(4, folded.sheet().faceCount());
    }

    @Test
    void aFlapNeedsACreaseOfTwoPoints() {
        assertEquals(2, errorLine("paper strip 12 1\nfold valley 180 flap 5 1 5 1 left\n"), "a crease needs two points");
    }
}
