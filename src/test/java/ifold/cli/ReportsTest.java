package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Every key a report holds is documented in docs/reports.md: the reports never say what the docs do not explain. */
class ReportsTest {
    @TempDir
    Path dir;

    /** Keys whose members are named by the data (repair kinds, face sizes, tenths of a script), not by the program. */
    private static final Set<String> OPEN = Set.of("repairs", "faceSizes", "byTenth");

    private static Set<String> keys(String json) throws Exception {
        Set<String> keys = new TreeSet<>();
        List<String> path = new ArrayList<>();
        try (JsonParser parser = new JsonFactory().createParser(json)) {
            int openDepth = -1;
            int depth = 0;
            JsonToken token;
            while ((token = parser.nextToken()) != null) {
                if (token == JsonToken.START_OBJECT || token == JsonToken.START_ARRAY) {
                    depth++;
                } else if (token == JsonToken.END_OBJECT || token == JsonToken.END_ARRAY) {
                    depth--;
                    if (depth < openDepth) {
                        openDepth = -1;
                    }
                } else if (token == JsonToken.FIELD_NAME) {
                    String name = parser.currentName();
                    if (openDepth < 0) {
                        keys.add(name);
                        if (OPEN.contains(name)) {
                            openDepth = depth + 1;
                        }
                    }
                }
            }
        }
        return keys;
    }

    @Test
    void everyKeyOfEveryReportIsDocumented() throws Exception {
        String doc = Files.readString(Path.of("docs", "reports.md"));
        List<String[]> runs = List.of(
                new String[] {"wrap", "models/cube.off", "--no-view", "--export-fold", dir.resolve("a.fold").toString(), "--report", "R"},
                new String[] {"demo", "zigzag", "--no-view", "--export-fold", dir.resolve("b.fold").toString(), "--report", "R"},
                new String[] {"demo", "turn", "--angle", "70", "--no-view", "--report", "R"},
                new String[] {"fold", "models/scripts/pleat20.fold", "--no-view", "--report", "R"});
        int checked = 0;
        for (String[] run : runs) {
            Path report = dir.resolve("r" + checked + ".json");
            String[] args = run.clone();
            for (int i = 0; i < args.length; i++) {
                if (args[i].equals("R")) {
                    args[i] = report.toString();
                }
            }
            CliTest.Run result = CliTest.run(args);
            assertEquals(0, result.code(), result.err());
            for (String key : keys(Files.readString(report))) {
                assertTrue(doc.contains("`" + key + "`"), "docs/reports.md explains " + String.join(" ", run).replace(" R", "")
                        + "'s key " + key);
                checked++;
            }
        }
        for (String[] json : new String[][] {{"info", "models/torus.off", "--json"},
            {"refine", "models/torus.off", "-o", dir.resolve("t.off").toString(), "--json"}}) {
            CliTest.Run result = CliTest.run(json);
            assertEquals(0, result.code(), result.err());
            String out = result.out();
            for (String key : keys(out.substring(out.indexOf('{')))) {
                assertTrue(doc.contains("`" + key + "`"), "docs/reports.md explains " + json[0] + "'s key " + key);
                checked++;
            }
        }
        assertTrue(checked > 80, "keys checked: " + checked);
    }
}
