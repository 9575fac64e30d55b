package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** {@code ifold fold}: the exported OBJ passes the isometry check read back from the file itself. */
class FoldCommandTest {
    @TempDir
    Path dir;

    @Test
    void exportedObjIsIsometricAndNamesItsCaps() throws Exception {
        Path obj = dir.resolve("pleat.obj");
        Path report = dir.resolve("pleat.json");
        CliTest.Run run = CliTest.run("fold", "models/scripts/pleat20.fold", "--no-view", "--export-obj", obj.toString(),
                "--report", report.toString());
        assertEquals(0, run.code(), run.err());
        ObjReadBack back = ObjReadBack.read(obj);
        assertEquals(21, back.paperFaces(), "21 pieces of strip");
        assertEquals(40, back.capFaces(), "two facets for each of 20 folds");
        assertTrue(back.worstIsometry() <= 1e-9, "isometric as written: " + back.worstIsometry());
        String json = Files.readString(report);
        assertTrue(json.contains("\"maxLayers\": 21"), json);
        assertTrue(json.contains("\"folds\": 20"), json);
        assertTrue(run.out().contains("20 folds, 21 layers at most"), run.out());
    }

    @Test
    void scriptErrorsNameFileAndLineAndWriteNothing() throws Exception {
        Path script = Files.writeString(dir.resolve("bad.fold"), "paper strip 10 1\nthickness 0.01\nfold valley 180 paper 30 0 30 1 right\n");
        Path obj = dir.resolve("out.obj");
        CliTest.Run run = CliTest.run("fold", script.toString(), "--no-view", "--export-obj", obj.toString());
        assertEquals(UserError.EXIT_CODE, run.code());
        assertTrue(run.err().contains("bad.fold:3: paper point (30, 0) is not on the paper"), run.err());
        assertFalse(Files.exists(obj));
        CliTest.Run missing = CliTest.run("fold", dir.resolve("none.fold").toString(), "--no-view");
        assertTrue(missing.err().contains("no such file"), missing.err());
        CliTest.Run badOption = CliTest.run("fold", script.toString(), "--export-obj", dir.resolve("x.stl").toString());
        assertTrue(badOption.err().contains("--export-obj"), badOption.err());
    }

    @Test
    void foldsThatHalveThePaperAgainAndAgainStopAtTheLimitOfFaces() throws Exception {
        StringBuilder script = new StringBuilder("paper square 1024\nthickness 0.0001\n");
        double x = 1024;
        double y = 1024;
        for (int k = 0; k < 25; k++) {
            if (k % 2 == 0) {
                x /= 2;
                script.append("fold valley 180 points ").append(x).append(" 0 0 ").append(x).append(" 1 0 right\n");
            } else {
                y /= 2;
                script.append("fold valley 180 points 0 ").append(y).append(" 0 1 ").append(y).append(" 0 left\n");
            }
        }
        Path file = Files.writeString(dir.resolve("halve.fold"), script.toString());
        Path obj = dir.resolve("out.obj");
        long start = System.nanoTime();
        CliTest.Run run = CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "1000", "--export-obj", obj.toString());
        CliTest.assertOneLineError(run, "halve.fold:12: fold 10", "more than the 1000 allowed", "--max-faces");
        assertTrue((System.nanoTime() - start) * 1e-9 < 30, "refused in bounded time");
        assertFalse(Files.exists(obj));
        CliTest.assertOneLineError(CliTest.run("fold", file.toString(), "--no-view", "--max-faces", "0"), "--max-faces");
    }

    @Test
    void aCreasePatternExportedAsFoldFoldsBackToTheSamePattern() throws Exception {
        for (String name : new String[] {"square-quarters", "pleat20", "zigzag-turn"}) {
            Path pattern = dir.resolve(name + ".cp.fold");
            Path first = dir.resolve(name + ".json");
            Path second = dir.resolve(name + ".back.json");
            assertEquals(0, CliTest.run("fold", "models/scripts/" + name + ".fold", "--no-view", "--export-fold", pattern.toString(),
                    "--report", first.toString()).code());
            CliTest.Run back = CliTest.run("fold", pattern.toString(), "--no-view", "--export-fold", dir.resolve("again.fold").toString(),
                    "--report", second.toString());
            assertEquals(0, back.code(), name + ": " + back.err());
            String a = Files.readString(first);
            String b = Files.readString(second);
            for (String key : new String[] {"mountains", "valleys", "maxLayers"}) {
                assertEquals(CliTest.number(a, key), CliTest.number(b, key), 0, name + ": " + key);
            }
        }
        // Two folds along the diagonals, the second through both layers: its line comes out a
        // valley on one layer and a mountain on the other, and folds back the way that makes both.
        Path diagonals = Files.writeString(dir.resolve("diagonals.fold"),
                "paper square 10\nfold valley 180 paper 0 0 10 10 left\nfold valley 180 paper 10 0 5 5 right\n");
        Path diagonalsPattern = dir.resolve("diagonals-cp.fold");
        Path diagonalsReport = dir.resolve("diagonals.json");
        assertEquals(0, CliTest.run("fold", diagonals.toString(), "--no-view", "--export-fold", diagonalsPattern.toString(),
                "--report", diagonalsReport.toString()).code());
        Path diagonalsBack = dir.resolve("diagonals-back.json");
        CliTest.Run back = CliTest.run("fold", diagonalsPattern.toString(), "--no-view", "--export-fold",
                dir.resolve("diagonals-again.fold").toString(), "--report", diagonalsBack.toString());
        assertEquals(0, back.code(), back.err());
        for (String key : new String[] {"mountains", "valleys", "maxLayers"}) {
            assertEquals(CliTest.number(Files.readString(diagonalsReport), key), CliTest.number(Files.readString(diagonalsBack), key), 0,
                    "diagonals: " + key);
        }
        // A pattern whose creases cannot be folded line by line in the order of its edges (the
        // zig-zag's tucks come between its turns) is refused, saying so.
        Path zigzag = dir.resolve("zigzag.fold");
        assertEquals(0, CliTest.run("demo", "zigzag", "--no-view", "--export-fold", zigzag.toString()).code());
        CliTest.assertOneLineError(CliTest.run("fold", zigzag.toString(), "--no-view"), "cannot be folded one crease line at a time");
        Path broken = Files.writeString(dir.resolve("broken.fold"), "{\"vertices_coords\": [[0, 0], [1, 0]],\n \"edges_vertices\": [[0, 1]");
        CliTest.assertOneLineError(CliTest.run("fold", broken.toString(), "--no-view"), "broken.fold", "JSON");
    }
}
