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
            assertTrue(lines[lines.length - 1].startsWith("ifold: "), what + ": " + err);
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
}
