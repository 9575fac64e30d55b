import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * The README's comparison of the two methods, from one run: each model wrapped the zig-zag way
 * and by the hinge strip through the real command line (a fresh JVM a run, the median of RUNS
 * runs' wall time), its figures read from the report each run writes.
 * Usage: java -cp 'build/install/ifold/lib/*' bench/Methods.java IFOLD RUNS NAME=MODEL ...
 */
public final class Methods {
    public static void main(String[] args) throws Exception {
        String ifold = args[0];
        int runs = Integer.parseInt(args[1]);
        Path dir = Files.createTempDirectory("methods");
        System.out.println("| model | method | L/w | paper efficiency | most layers | creases inside faces | folds | crossing pairs (coplanar) | seconds |");
        System.out.println("|---|---|---|---|---|---|---|---|---|");
        for (int i = 2; i < args.length; i++) {
            String name = args[i].substring(0, args[i].indexOf('='));
            String model = args[i].substring(args[i].indexOf('=') + 1);
            for (String method : new String[] {"zigzag", "hinge"}) {
                double[] seconds = new double[runs];
                Map<String, Double> figures = null;
                String refused = null;
                for (int r = 0; r < runs; r++) {
                    Path report = dir.resolve("r.json");
                    Files.deleteIfExists(report);
                    ProcessBuilder run = new ProcessBuilder(ifold, "wrap", model, "--method", method, "--no-view", "--report",
                            report.toString()).redirectErrorStream(true);
                    long start = System.nanoTime();
                    Process process = run.start();
                    String out = new String(process.getInputStream().readAllBytes());
                    int code = process.waitFor();
                    seconds[r] = (System.nanoTime() - start) * 1e-9;
                    if (code != 0) {
                        refused = out.strip().lines().reduce((a, b) -> b).orElse("");
                        break;
                    }
                    figures = read(report);
                }
                if (refused != null) {
                    System.out.printf(Locale.ROOT, "| %s | %s | refused: %s | | | | | | |%n", name, method, refused);
                    continue;
                }
                Arrays.sort(seconds);
                double median = runs % 2 == 1 ? seconds[runs / 2] : (seconds[runs / 2 - 1] + seconds[runs / 2]) / 2;
                System.out.printf(Locale.ROOT, "| %s | %s | %,.1f | %.3f | %d | %,d | %,d | %,d (%,d) | %.2f |%n", name, method,
                        figures.get("strips.0.lengthOverWidth"), figures.get("paperEfficiency"), figures.get("maxLayers").intValue(),
                        figures.get("creases.insideFaces").intValue(), folds(figures), figures.getOrDefault("collisions.pairs", -1.0).intValue(),
                        figures.getOrDefault("collisions.coplanarPairs", -1.0).intValue(), median);
            }
        }
    }

    /** Every fold of the strip but its end: the report's folds by kind. */
    private static int folds(Map<String, Double> figures) {
        int folds = 0;
        for (Map.Entry<String, Double> figure : figures.entrySet()) {
            if (figure.getKey().startsWith("folds.")) {
                folds += figure.getValue().intValue();
            }
        }
        return folds;
    }

    /** The report's numbers by their dotted path ("strips.0.length"). */
    private static Map<String, Double> read(Path report) throws Exception {
        Map<String, Double> numbers = new HashMap<>();
        try (JsonParser parser = new JsonFactory().createParser(report.toFile())) {
            parser.nextToken();
            value(parser, "", numbers);
        }
        return numbers;
    }

    /** The value the parser is at, under {@code path}: its numbers into {@code numbers}. */
    private static void value(JsonParser parser, String path, Map<String, Double> numbers) throws Exception {
        JsonToken token = parser.currentToken();
        if (token == JsonToken.START_OBJECT) {
            while (parser.nextToken() == JsonToken.FIELD_NAME) {
                String name = parser.currentName();
                parser.nextToken();
                value(parser, path.isEmpty() ? name : path + "." + name, numbers);
            }
        } else if (token == JsonToken.START_ARRAY) {
            int i = 0;
            while (parser.nextToken() != JsonToken.END_ARRAY) {
                value(parser, path + "." + i++, numbers);
            }
        } else if (token == JsonToken.VALUE_NUMBER_INT || token == JsonToken.VALUE_NUMBER_FLOAT) {
            numbers.put(path, parser.getDoubleValue());
        }
    }
}
