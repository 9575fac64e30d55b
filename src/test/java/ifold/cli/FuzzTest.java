package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * A mutation fuzzer: the project's models and fold scripts, mutated at random (bytes flipped,
 * lines dropped, doubled or cut short, numbers replaced by extreme ones, garbage inserted), and
 * each fed to the command line. Every outcome must be a clean error (one line naming the file,
 * exit 1 or 2, no stack trace) or a verified result (a valid mesh with faces; paper folded
 * without stretching), within seconds. Seeded: the same cases every run; FUZZ_CASES=N (scripts/test -PfuzzCases=N) runs more.
 */
class FuzzTest {
    @TempDir
    Path dir;

    private static final String[] EXTREMES = {"0", "-1", "1e308", "-1e308", "1e-320", "nan", "inf", "-inf", "99999999999999999999",
        "2147483648", "-0", "1e400", "0x10", "", "1.5.2", "3", "100000000"};

    private static int cases() {
        String n = System.getenv("FUZZ_CASES");
        return n == null ? 300 : Integer.parseInt(n);
    }

    static byte[] mutate(byte[] original, Random random) {
        String text = new String(original, StandardCharsets.ISO_8859_1);
        List<String> lines = new ArrayList<>(Arrays.asList(text.split("\n", -1)));
        int mutations = 1 + random.nextInt(3);
        for (int m = 0; m < mutations && !lines.isEmpty(); m++) {
            int i = random.nextInt(lines.size());
            switch (random.nextInt(7)) {
                case 0 -> lines.remove(i);
                case 1 -> lines.add(i, lines.get(i));
                case 2 -> lines.set(i, lines.get(i).substring(0, random.nextInt(lines.get(i).length() + 1)));
                case 3 -> {
                    String[] words = lines.get(i).split(" ", -1);
                    words[random.nextInt(words.length)] = EXTREMES[random.nextInt(EXTREMES.length)];
                    lines.set(i, String.join(" ", words));
                }
                case 4 -> lines.add(i, "garbage " + random.nextInt());
                case 5 -> {
                    char[] chars = lines.get(i).toCharArray();
                    if (chars.length > 0) {
                        chars[random.nextInt(chars.length)] = (char) random.nextInt(256);
                    }
                    lines.set(i, new String(chars));
                }
                default -> lines = lines.subList(0, i); // truncated
            }
        }
        return String.join("\n", lines).getBytes(StandardCharsets.ISO_8859_1);
    }

    private static void assertClean(CliTest.Run run, String what) {
        String err = run.err().strip();
        assertFalse(err.contains("\tat ") || err.contains("internal error") || err.contains("Exception"), what + ": " + err);
        if (run.code() != 0) {
            assertTrue(run.code() == 1 || run.code() == 2, what + ": exit " + run.code());
            String[] lines = err.split("\n");
            // A usage error (exit 2) says how to get help on a line of its own after the error's.
            int last = lines.length > 1 && run.code() == 2 && lines[lines.length - 1].startsWith("Try 'ifold") ? lines.length - 2 : lines.length - 1;
            assertTrue(lines[last].startsWith("ifold: "), what + ": " + err);
        }
    }

    @Test
    void mutatedModelsAndScriptsFailCleanlyOrGiveVerifiedResults() throws Exception {
        List<Path> models = new ArrayList<>();
        for (String name : new String[] {"tetrahedron.off", "cube.off", "triangle.off", "figure3.off", "octahedron.obj", "cube.obj"}) {
            models.add(Path.of("models", name));
        }
        List<Path> scripts = new ArrayList<>();
        try (var files = Files.list(Path.of("models", "scripts"))) {
            files.sorted().forEach(scripts::add);
        }
        Random random = new Random(20261201);
        int errors = 0;
        int verified = 0;
        for (int k = 0; k < cases(); k++) {
            boolean script = k % 3 == 2;
            Path seed = script ? scripts.get(random.nextInt(scripts.size())) : models.get(random.nextInt(models.size()));
            String name = seed.getFileName().toString();
            Path file = dir.resolve("case" + k + name.substring(name.lastIndexOf('.')));
            Files.write(file, mutate(Files.readAllBytes(seed), random));
            String what = "case " + k + " from " + name;
            CliTest.Run run = assertTimeoutPreemptively(Duration.ofSeconds(30), () -> script
                    ? CliTest.run("fold", file.toString(), "--no-view", "--report", dir.resolve("r.json").toString())
                    : CliTest.run("info", file.toString(), "--json"), what + " took too long");
            assertClean(run, what);
            if (run.code() != 0) {
                errors++;
                continue;
            }
            verified++;
            if (script) {
                String report = Files.readString(dir.resolve("r.json"));
                assertTrue(CliTest.number(report, "isometryError") <= 1e-9, what + ": stretched paper: " + report);
                assertTrue(CliTest.number(report, "maxLayers") >= 1, what);
            } else {
                String json = run.out().substring(run.out().indexOf('{'));
                assertTrue(CliTest.number(json, "faces") > 0, what + ": " + json);
                assertTrue(json.contains("\"valid\": true"), what + ": an invalid mesh accepted: " + json);
            }
            Files.deleteIfExists(dir.resolve("r.json"));
        }
        assertEquals(cases(), errors + verified);
        assertTrue(errors > cases() / 10 && verified > cases() / 10, "both outcomes seen: " + errors + " errors, " + verified + " verified");
        System.out.println("fuzz: " + cases() + " cases, " + errors + " clean errors, " + verified + " verified results");
    }

    /** JSON's own ways to go wrong, for FOLD files: a number, a bracket, a quote or a key where another was. */
    private static final String[] JSON_BITS = {"NaN", "1e400", "-1", "1e85", "1e-90", "0", "\"x\"", "null", "[]", "{}", "[", "]", "{", "}",
        ",", ":", "\"", "\"edges_assignment\": [],", "true", "\uFEFF"};

    /** A FOLD file mutated: the line mutations above, or a JSON token put in, replaced or taken out. */
    static byte[] mutateJson(byte[] original, Random random) {
        if (random.nextBoolean()) {
            return mutate(original, random);
        }
        StringBuilder text = new StringBuilder(new String(original, StandardCharsets.UTF_8));
        int mutations = 1 + random.nextInt(3);
        for (int m = 0; m < mutations && text.length() > 0; m++) {
            int at = random.nextInt(text.length());
            String bit = JSON_BITS[random.nextInt(JSON_BITS.length)];
            switch (random.nextInt(3)) {
                case 0 -> text.insert(at, bit);
                case 1 -> {
                    // A number replaced: from a digit to the end of its number.
                    int end = at;
                    while (end < text.length() && "0123456789.eE+-".indexOf(text.charAt(end)) >= 0) {
                        end++;
                    }
                    text.replace(at, Math.max(at + 1, end), bit);
                }
                default -> text.deleteCharAt(at);
            }
        }
        return text.toString().getBytes(StandardCharsets.UTF_8);
    }

    /**
     * The FOLD import and the wrap, fuzzed as the models and scripts are: crease patterns iFold
     * wrote (of the example scripts and of the turn gadget) mutated and folded, and small models
     * mutated and wrapped. Each ends in one clean error line, or in paper that is not stretched,
     * covers what it wraps and has at least the layers any strip must (FUZZ_CASES scales them
     * too: a third of it each, at least 30).
     */
    @Test
    void mutatedFoldFilesAndWrappedModelsFailCleanlyOrGiveVerifiedResults() throws Exception {
        List<Path> patterns = new ArrayList<>();
        try (var files = Files.list(Path.of("models", "scripts"))) {
            for (Path script : files.sorted().toList()) {
                Path pattern = dir.resolve(script.getFileName().toString().replace(".fold", "-cp.fold"));
                assertEquals(0, CliTest.run("fold", script.toString(), "--no-view", "--export-fold", pattern.toString()).code(), "setup");
                patterns.add(pattern);
            }
        }
        Path turn = dir.resolve("turn-cp.fold");
        assertEquals(0, CliTest.run("demo", "turn", "--angle", "60", "--no-view", "--export-fold", turn.toString()).code(), "setup");
        patterns.add(turn);
        Path[] models = {Path.of("models", "tetrahedron.off"), Path.of("models", "cube.off"), Path.of("models", "triangle.off")};
        Random random = new Random(20261203);
        int cases = Math.max(30, cases() / 3);
        int[] errors = new int[2];
        int[] verified = new int[2];
        for (int k = 0; k < 2 * cases; k++) {
            boolean wrap = k % 2 == 1;
            Path seed = wrap ? models[random.nextInt(models.length)] : patterns.get(random.nextInt(patterns.size()));
            String name = seed.getFileName().toString();
            Path file = dir.resolve("case" + k + name.substring(name.lastIndexOf('.')));
            Files.write(file, wrap ? mutate(Files.readAllBytes(seed), random) : mutateJson(Files.readAllBytes(seed), random));
            String what = "case " + k + " from " + name;
            Path report = dir.resolve("r.json");
            CliTest.Run run = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> wrap
                    ? CliTest.run("wrap", file.toString(), "--no-view", "--report", report.toString())
                    : CliTest.run("fold", file.toString(), "--no-view", "--report", report.toString()), what + " took too long");
            assertClean(run, what);
            int kind = wrap ? 1 : 0;
            if (run.code() != 0) {
                errors[kind]++;
                continue;
            }
            verified[kind]++;
            String json = Files.readString(report);
            assertTrue(CliTest.number(json, "isometryError") <= 1e-9, what + ": stretched paper: " + json);
            assertTrue(CliTest.number(json, "maxLayers") >= 1, what + ": " + json);
            if (wrap) {
                assertTrue(CliTest.number(json, "coverage") >= 1 - 1e-6, what + ": not covered: " + json);
                assertTrue(json.contains("\"layersAtLeast\""), what);
            }
            Files.deleteIfExists(report);
        }
        for (int kind = 0; kind < 2; kind++) {
            assertTrue(errors[kind] > 0 && verified[kind] > 0, (kind == 0 ? "FOLD files" : "wraps") + ": both outcomes seen: "
                    + errors[kind] + " errors, " + verified[kind] + " verified");
        }
        System.out.println("fuzz: " + cases + " FOLD files (" + errors[0] + " clean errors, " + verified[0] + " verified), " + cases
                + " wraps (" + errors[1] + " clean errors, " + verified[1] + " verified)");
    }

    /**
     * Movie and frame options at random, good and bad (sizes, rates, lengths, formats): each run
     * is a clean error naming the option, or a movie or frames of the size and count asked.
     */
    @Test
    void moviesWithOptionsAtRandomFailCleanlyOrAreWhole() throws Exception {
        String display = System.getenv("DISPLAY");
        org.junit.jupiter.api.Assumptions.assumeTrue(display != null && !display.isEmpty(), "no X display (run the tests under xvfb-run)");
        // Good values and bad, a good one three times in four: most runs then fail at one option.
        String[][] sizes = {{"64x36", "16x16", "48x64"}, {"15x16", "0x0", "100000x100000", "8193x16", "64x", "x36", "64*36", "-64x36"}};
        String[][] rates = {{"1", "5", "12", ""}, {"0", "-3", "241", "x", "1e9"}};
        String[][] lengths = {{"0.5", "0.2", "1", ""}, {"0", "-1", "nan", "Infinity", "3601", "1e9", "x"}};
        String[][] outputs = {{"m.mp4", "m.gif", "frames", "m.MP4"}, {"m.avi", "m"}};
        Random random = new Random(20261204);
        int errors = 0;
        int made = 0;
        for (int k = 0; k < 24; k++) {
            Path out = Files.createDirectory(dir.resolve("movie" + k));
            String output = pick(outputs, random);
            List<String> args = new ArrayList<>(List.of("demo", "zigzag", output.equals("frames") ? "--frames" : "--movie",
                    out.resolve(output).toString()));
            String size = pick(sizes, random);
            String fps = pick(rates, random);
            String seconds = pick(lengths, random);
            for (String[] option : new String[][] {{"--size", size}, {"--fps", fps}, {"--seconds", seconds}}) {
                if (!option[1].isEmpty()) {
                    args.add(option[0]);
                    args.add(option[1]);
                }
            }
            String what = "case " + k + ": " + String.join(" ", args.subList(2, args.size()));
            CliTest.Run run = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> CliTest.run(args.toArray(String[]::new)),
                    what + " took too long");
            assertClean(run, what);
            if (run.code() != 0) {
                errors++;
                assertTrue(run.err().contains("option --") || run.err().contains("--movie"), what + ": names the option: " + run.err());
                try (var files = Files.list(out)) {
                    assertEquals(List.of(), files.map(Path::toString).toList(), what + ": nothing left");
                }
                continue;
            }
            made++;
            assertTrue(run.out().contains("wrote "), what + ": " + run.out());
            Path written = out.resolve(output);
            if (output.equals("frames")) {
                try (var files = Files.list(written)) {
                    assertTrue(files.allMatch(p -> p.getFileName().toString().matches("frame_\\d{5}\\.png")), what);
                }
            } else {
                assertTrue(Files.size(written) > 0, what);
            }
        }
        assertTrue(errors > 0 && made > 0, "both outcomes seen: " + errors + " errors, " + made + " made");
        System.out.println("fuzz: 24 movie and frame runs, " + errors + " clean errors, " + made + " made");
    }

    /** A good value three times in four, else a bad one. */
    private static String pick(String[][] goodAndBad, Random random) {
        String[] from = goodAndBad[random.nextInt(4) < 3 ? 0 : 1];
        return from[random.nextInt(from.length)];
    }
}
