package ifold.cli;

import static ifold.cli.CliTest.assertOneLineError;
import static ifold.cli.CliTest.run;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code ifold check}: an exported wrap checked against its model from the files alone, every
 * truth, the collisions and the layer order; a line a check, exit 0 where all hold and 1 where
 * one does not, and one line for files it cannot read.
 */
class CheckCommandTest {
    @TempDir
    Path dir;

    /** Wraps {@code model} as the user would, its paper written as OBJ and FOLD into the folder. */
    private Path wrapped(Path model) {
        CliTest.Run wrap = run("wrap", model.toString(), "--no-view", "--export-obj", dir.resolve("paper.obj").toString(),
                "--export-fold", dir.resolve("paper.fold").toString());
        assertEquals(0, wrap.code(), wrap.err());
        return dir.resolve("paper.obj");
    }

    @Test
    void theCubesWrapHoldsEveryCheck() throws Exception {
        Path obj = wrapped(Path.of("models", "cube.off"));
        assertTrue(Files.readAllLines(obj).get(0).contains(", a stack of 15 levels"), "the header names the stack");
        Path report = dir.resolve("check.json");
        CliTest.Run check = run("check", "models/cube.off", obj.toString(), "--fold", dir.resolve("paper.fold").toString(), "--report",
                report.toString());
        assertEquals(0, check.code(), check.out() + check.err());
        assertEquals("", check.err());
        String[] lines = check.out().strip().split("\n");
        assertEquals(4, lines.length, check.out());
        assertTrue(lines[0].contains("1 strip, 236 faces of paper") && lines[0].contains("a stack of 15 levels"), lines[0]);
        assertEquals("truths: every one holds (tiled, isometric, not torn, covered, on surface)", lines[1]);
        assertTrue(lines[2].startsWith("collisions: 0 crossing pairs"), lines[2]);
        assertTrue(lines[3].startsWith("layer order: valid"), lines[3]);
        String json = Files.readString(report);
        assertTrue(json.contains("\"truths\": \"hold\"") && json.contains("\"layerOrder\": \"valid\""), json);
    }

    /** Paper of no thickness has its truths checked, not its collisions: every two layers that overlap touch. */
    @Test
    void paperOfNoThicknessIsNotCheckedForCollisions() throws Exception {
        CliTest.Run wrap = run("wrap", "models/cube.off", "--thickness", "0", "--no-view", "--export-obj", dir.resolve("thin.obj").toString());
        assertEquals(0, wrap.code(), wrap.err());
        CliTest.Run check = run("check", "models/cube.off", dir.resolve("thin.obj").toString());
        assertEquals(0, check.code(), check.out() + check.err());
        assertTrue(check.out().contains("truths: every one holds") && check.out().contains("collisions: not checked: paper of no thickness"),
                check.out());
    }

    /** A vertex of the paper moved a fifth of the strip's width: that face is stretched, and the check says so and exits 1. */
    @Test
    void paperMovedAfterTheWrapBreaksATruth() throws Exception {
        Path obj = wrapped(Path.of("models", "cube.off"));
        List<String> lines = new ArrayList<>(Files.readAllLines(obj));
        int vertices = 0;
        for (int i = 0; i < lines.size(); i++) {
            if (lines.get(i).startsWith("v ") && ++vertices == 40) {
                String[] xyz = lines.get(i).split(" ");
                lines.set(i, "v " + (Double.parseDouble(xyz[1]) + 0.05) + " " + xyz[2] + " " + xyz[3]);
            }
        }
        Path moved = dir.resolve("moved.obj");
        Files.write(moved, lines);
        CliTest.Run check = run("check", "models/cube.off", moved.toString());
        assertEquals(UserError.EXIT_CODE, check.code(), check.out());
        assertTrue(check.out().contains("truths: ") && check.out().contains(" isometric ") && check.out().contains("is stretched"), check.out());
        String[] out = check.out().strip().split("\n");
        assertTrue(out[out.length - 1].startsWith("failed: truths"), "the last line says what failed: " + check.out());
    }

    /**
     * The wrap moves a model far from the origin near it, and its paper with it; the header says
     * where: checked against the model where it lies, the paper is on it. Without the header's
     * point, the same paper lies nowhere near the model.
     */
    @Test
    void paperOfAModelMovedNearTheOriginIsCheckedWhereTheModelLies() throws Exception {
        List<String> far = new ArrayList<>();
        List<String> cube = Files.readAllLines(Path.of("models", "cube.off"));
        for (int i = 0; i < cube.size(); i++) {
            String[] p = cube.get(i).trim().split("\\s+");
            far.add(i >= 2 && i < 10 ? (Double.parseDouble(p[0]) + 1000) + " " + (Double.parseDouble(p[1]) + 5000) + " " + p[2] : cube.get(i));
        }
        Path model = dir.resolve("far.off");
        Files.write(model, far);
        Path obj = wrapped(model);
        String header = Files.readAllLines(obj).get(0);
        assertTrue(header.contains("coordinates about (1000.0, 5000.0, 0.0)"), header);
        assertEquals(0, run("check", model.toString(), obj.toString()).code());
        List<String> lines = new ArrayList<>(Files.readAllLines(obj));
        lines.set(0, header.replaceAll(" \\(coordinates about [^)]*\\)[^)]*\\)", ""));
        Files.write(obj, lines);
        CliTest.Run unmoved = run("check", model.toString(), obj.toString());
        assertEquals(UserError.EXIT_CODE, unmoved.code(), unmoved.out());
        assertTrue(unmoved.out().contains("covered") && unmoved.out().contains("on surface"), unmoved.out());
    }

    @Test
    void filesItCannotReadAreOneLine() throws Exception {
        Path obj = wrapped(Path.of("models", "cube.off"));
        assertOneLineError(run("check", "models/cube.off", dir.resolve("none.obj").toString()), "none.obj: no such file");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--stack", "-1"), "option --stack");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--thickness", "-0.1"), "option --thickness");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--thickness", "NaN"), "option --thickness");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--samples", "-1"), "option --samples");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--report", dir.resolve("r.txt").toString()), "option --report");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--fold", obj.toString()), "paper.obj:1:1: not a FOLD file");
        Path bare = dir.resolve("bare.obj");
        List<String> lines = new ArrayList<>(Files.readAllLines(obj));
        lines.set(0, "# paper of somewhere");
        Files.write(bare, lines);
        assertOneLineError(run("check", "models/cube.off", bare.toString()), "bare.obj: its first line names no thickness", "give --thickness");
        assertOneLineError(run("check", "models/cube.off", bare.toString(), "--thickness", "0.003"), "names no stack", "give --stack");
        assertEquals(0, run("check", "models/cube.off", bare.toString(), "--thickness", "0.0029462782549439476", "--stack", "15").code());
        Path junk = dir.resolve("junk.obj");
        Files.writeString(junk, "v 1 2\n");
        assertOneLineError(run("check", "models/cube.off", junk.toString(), "--thickness", "0.01", "--stack", "3"), "junk.obj: line 1");
        // Paper whose stack stands higher than the model is big: no wrap's, and its creep zones would take the check for ever.
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--thickness", "1"), "option --thickness", "16.0 high, higher than the model");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--stack", "2147483647"), "option --stack");
        assertOneLineError(run("check", "models/cube.off", obj.toString(), "--samples", "2147483647"), "option --samples", "0 to 10,000,000");
        Path thick = dir.resolve("thick.obj");
        Files.writeString(thick, Files.readString(obj).replace("thickness 0.0029462782549439476", "thickness 0.5"));
        assertOneLineError(run("check", "models/cube.off", thick.toString()), "thick.obj: a stack of 15 levels of paper 0.5 thick");
        Path empty = dir.resolve("empty.obj");
        Files.writeString(empty, "");
        assertOneLineError(run("check", "models/cube.off", empty.toString()), "empty.obj: the file is empty");
        Path binary = dir.resolve("binary.obj");
        Files.write(binary, new byte[] {(byte) 0xff, (byte) 0xfe, 0, 1, (byte) 0x80});
        assertOneLineError(run("check", "models/cube.off", binary.toString()), "binary.obj: not a text file");
        Path cut = dir.resolve("cut.obj");
        String text = Files.readString(obj);
        Files.writeString(cut, text.substring(0, text.indexOf("\nvt ")));
        assertOneLineError(run("check", "models/cube.off", cut.toString()), "cut.obj: no faces of paper");
        Path shortFold = dir.resolve("short.fold");
        String fold = Files.readString(dir.resolve("paper.fold"));
        Files.writeString(shortFold, fold.substring(0, fold.length() / 2));
        CliTest.Run truncated = run("check", "models/cube.off", obj.toString(), "--fold", shortFold.toString());
        assertOneLineError(truncated, "short.fold:", "not a FOLD file");
        assertTrue(!truncated.err().contains("[Source"), "no parser's inner words: " + truncated.err());
    }
}
