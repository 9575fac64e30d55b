package ifold.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import ifold.job.ReportGlossary;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
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

    /**
     * A report of each command, as its section of docs/reports.md names it (after a # what
     * tells two runs of one command apart), and its JSON.
     */
    private Map<String, String> reports() throws Exception {
        Map<String, String[]> runs = new LinkedHashMap<>();
        runs.put("wrap", new String[] {"wrap", "models/cube.off", "--no-view", "--export-fold", dir.resolve("a.fold").toString(), "--export-obj",
            dir.resolve("cube.obj").toString(), "--report", "R"});
        runs.put("wrap#thin", new String[] {"wrap", "models/cube.off", "--thickness", "0", "--no-view", "--report", "R"});
        runs.put("wrap#hinge", new String[] {"wrap", "models/cube.off", "--method", "hinge", "--no-view", "--report", "R"});
        runs.put("demo zigzag", new String[] {"demo", "zigzag", "--no-view", "--export-fold", dir.resolve("b.fold").toString(), "--report", "R"});
        runs.put("demo turn", new String[] {"demo", "turn", "--angle", "70", "--no-view", "--report", "R"});
        runs.put("fold", new String[] {"fold", "models/scripts/pleat20.fold", "--no-view", "--report", "R"});
        runs.put("check", new String[] {"check", "models/cube.off", dir.resolve("cube.obj").toString(), "--fold", dir.resolve("a.fold").toString(),
            "--report", "R"});
        runs.put("info", new String[] {"info", "models/torus.off", "--json"});
        runs.put("refine", new String[] {"refine", "models/torus.off", "-o", dir.resolve("t.off").toString(), "--json"});
        Map<String, String> reports = new LinkedHashMap<>();
        for (Map.Entry<String, String[]> run : runs.entrySet()) {
            Path report = dir.resolve("r" + reports.size() + ".json");
            String[] args = run.getValue().clone();
            for (int i = 0; i < args.length; i++) {
                if (args[i].equals("R")) {
                    args[i] = report.toString();
                }
            }
            CliTest.Run result = CliTest.run(args);
            assertEquals(0, result.code(), result.err());
            String json = Files.exists(report) ? Files.readString(report) : result.out().substring(result.out().indexOf('{'));
            reports.put(run.getKey(), json);
        }
        return reports;
    }

    @Test
    void everyKeyOfEveryReportIsDocumented() throws Exception {
        String doc = Files.readString(Path.of("docs", "reports.md"));
        int checked = 0;
        for (Map.Entry<String, String> report : reports().entrySet()) {
            for (String key : keys(report.getValue())) {
                assertTrue(doc.contains("`" + key + "`"), "docs/reports.md explains " + report.getKey() + "'s key " + key);
                checked++;
            }
        }
        assertTrue(checked > 80, "keys checked: " + checked);
    }

    /** Every figure's path in a report, lists' items numbered from 1 as the window shows them. */
    private static List<String> leaves(String json) throws Exception {
        List<String> leaves = new ArrayList<>();
        List<String> path = new ArrayList<>();
        List<Integer> items = new ArrayList<>(); // per open container: -1 for an object, else the next item's number
        try (JsonParser parser = new JsonFactory().createParser(json)) {
            JsonToken token;
            while ((token = parser.nextToken()) != null) {
                boolean inList = !items.isEmpty() && items.get(items.size() - 1) >= 0;
                if (token == JsonToken.FIELD_NAME) {
                    path.set(path.size() - 1, parser.currentName());
                    continue;
                }
                if (inList && token != JsonToken.END_ARRAY) {
                    int next = items.get(items.size() - 1);
                    path.set(path.size() - 1, Integer.toString(next));
                    items.set(items.size() - 1, next + 1);
                }
                if (token == JsonToken.START_OBJECT || token == JsonToken.START_ARRAY) {
                    items.add(token == JsonToken.START_ARRAY ? 1 : -1);
                    path.add("");
                } else if (token == JsonToken.END_OBJECT || token == JsonToken.END_ARRAY) {
                    items.remove(items.size() - 1);
                    path.remove(path.size() - 1);
                } else {
                    leaves.add(String.join(".", path));
                }
            }
        }
        return leaves;
    }

    /**
     * The window explains every figure of every report, with the words of docs/reports.md as
     * built into the program (as they are now, not a copy left from another build); a report
     * of one kind never borrows the wrap's meaning of a word it does not list.
     */
    @Test
    void everyFigureOfEveryReportHasItsMeaningInTheWindow() throws Exception {
        ReportGlossary packaged = ReportGlossary.packaged();
        ReportGlossary docs = ReportGlossary.parse(Files.readString(Path.of("docs", "reports.md")));
        int checked = 0;
        for (Map.Entry<String, String> report : reports().entrySet()) {
            for (String leaf : leaves(report.getValue())) {
                String section = report.getKey().split("#")[0];
                Optional<String> meaning = packaged.meaning(section, leaf);
                assertTrue(meaning.isPresent() && !meaning.get().isBlank(), report.getKey() + "'s " + leaf + " has a meaning");
                assertEquals(docs.meaning(section, leaf), meaning, leaf);
                checked++;
            }
        }
        assertTrue(checked > 150, "figures checked: " + checked);
        assertEquals(Optional.empty(), packaged.meaning("demo turn", "deepestLayers"), "not the wrap's");
        assertTrue(packaged.meaning("wrap", "strips.1.length").orElseThrow().startsWith("per strip"), "a strip's length is the strips' row");
        assertTrue(packaged.meaning("wrap", "length").orElseThrow().startsWith("Σ L"));
        assertTrue(packaged.meaning("demo zigzag", "paperOutsideArea").orElseThrow().startsWith("paper area whose shadow falls outside the triangle"));
        assertEquals(packaged.meaning("wrap", "isometryError"), packaged.meaning("demo zigzag", "isometryError"), "as above: the shared row");
        assertTrue(packaged.meaning("wrap", "collisions.pairs").orElseThrow().contains("cross deeper than"));
        assertTrue(packaged.meaning("wrap", "collisions.notChecked").orElseThrow().startsWith("why the paper was not checked"));
    }
}
