package ifold.job;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What each figure of a report means and in what unit, for people reading it in the window. The
 * meanings are the tables of {@code docs/reports.md}, which the build copies beside this class:
 * one text for the reader of the docs and the reader of the window, so that the two cannot say
 * different things (and {@code ReportsTest} already holds the docs to every key a report writes).
 */
public final class ReportGlossary {
    /** The section of the docs that explains the figures several reports share. */
    static final String SHARED = "shared";

    /** What a figure is measured in. */
    public enum Unit {
        NONE(""), LENGTH("model units"), AREA("square model units"), DEGREES("°"), SECONDS("s"), MILLISECONDS("ms"),
        THICKNESSES("thicknesses T");

        private final String symbol;

        Unit(String symbol) {
            this.symbol = symbol;
        }

        /** How the unit is written after a figure's name, "" for none. */
        public String symbol() {
            return symbol;
        }
    }

    // Named by the figure's own name, wherever it is: the reports use each of these words for one kind of measure.
    private static final Set<String> LENGTHS = Set.of("width", "widestWidth", "thickness", "length", "stripLength", "stripWidth",
            "paperOutside", "farthestFromSurface", "creep", "farthestFromTriangle", "overhang", "insideFacesLength", "alongEdgesLength");
    private static final Set<String> AREAS = Set.of("surfaceArea", "paperArea", "paperOutsideArea", "triangleArea");
    private static final Set<String> ANGLES = Set.of("angle", "measuredAngle", "targetAngle", "angleSumDegrees",
            "minAngleInDegrees", "minAngleOutDegrees");

    private static final Pattern HEADING = Pattern.compile("^## (.*)$");
    private static final Pattern ROW = Pattern.compile("^\\| (`[^|]*`) \\| (.*) \\|$");
    private static final Pattern KEY = Pattern.compile("`([A-Za-z.]+)`");

    private static volatile ReportGlossary packaged;

    /** Section ("wrap", "demo zigzag", "shared", ...) → key as written in its table → meaning. */
    private final Map<String, Map<String, String>> sections;

    private ReportGlossary(Map<String, Map<String, String>> sections) {
        this.sections = sections;
    }

    /** The glossary of the docs built into the program. */
    public static ReportGlossary packaged() {
        ReportGlossary glossary = packaged;
        if (glossary == null) {
            try (InputStream in = ReportGlossary.class.getResourceAsStream("reports.md")) {
                if (in == null) {
                    throw new IllegalStateException("reports.md is missing beside " + ReportGlossary.class.getName()
                            + ": the build copies it from docs/");
                }
                glossary = parse(new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
            packaged = glossary;
        }
        return glossary;
    }

    /**
     * Reads the tables of a reports.md: each {@code ## } heading starts a section, named by its
     * command without "ifold" and "--json" ("## `ifold demo zigzag`" is "demo zigzag"), "shared"
     * for the figures several reports share, "view" for the window's view of a model; each row
     * {@code | `a`, `b` | meaning |} gives a and b that meaning, backquotes dropped.
     */
    public static ReportGlossary parse(String markdown) {
        Map<String, Map<String, String>> sections = new LinkedHashMap<>();
        Map<String, String> rows = null;
        for (String line : (Iterable<String>) markdown.lines()::iterator) {
            Matcher heading = HEADING.matcher(line);
            if (heading.matches()) {
                rows = new HashMap<>();
                sections.put(sectionName(heading.group(1)), rows);
                continue;
            }
            Matcher row = ROW.matcher(line.strip());
            if (rows != null && row.matches()) {
                String meaning = row.group(2).replace("`", "").strip();
                Matcher key = KEY.matcher(row.group(1));
                while (key.find()) {
                    rows.put(key.group(1), meaning);
                }
            }
        }
        return new ReportGlossary(sections);
    }

    private static String sectionName(String heading) {
        String text = heading.replace("`", "").strip();
        if (text.startsWith("ifold ")) {
            return text.substring("ifold ".length()).replace(" --json", "").strip();
        }
        String lower = text.toLowerCase(Locale.ROOT);
        return lower.startsWith("figures several reports share") ? SHARED : lower.startsWith("the window's view") ? "view" : lower;
    }

    /**
     * What the figure at {@code path} of a report of {@code section} means: the row of its own
     * path ({@code collisions.pairs}, or at the top level its name) in the section's table or
     * in the shared one, else the row of the figure it is in ({@code strips.1.length} is
     * explained by {@code strips}: the wrap's {@code length} is the strips' sum, not one
     * strip's).
     */
    public Optional<String> meaning(String section, String path) {
        List<String> names = new ArrayList<>();
        for (String name : path.split("\\.")) {
            if (!name.isEmpty() && !name.chars().allMatch(Character::isDigit)) {
                names.add(name);
            }
        }
        for (int end = names.size(); end > 0; end--) {
            Optional<String> meaning = row(section, String.join(".", names.subList(0, end)));
            if (meaning.isPresent()) {
                return meaning;
            }
        }
        return Optional.empty();
    }

    /**
     * The section's row for the key, where it says what the key is; a row that says "as above"
     * is the shared table's, one that says "as for wrap" the wrap's ("as for wrap: the area..."
     * says it itself). A key the section does not list is only the shared table's: the wrap's
     * same word may mean another thing.
     */
    private Optional<String> row(String section, String key) {
        String own = sections.getOrDefault(section, Map.of()).get(key);
        if (own != null && own.startsWith(AS_FOR_WRAP + ": ")) {
            return Optional.of(own.substring(AS_FOR_WRAP.length() + 2));
        }
        if (own != null && !own.isEmpty() && !own.startsWith("as above") && !own.startsWith(AS_FOR_WRAP)) {
            return Optional.of(own);
        }
        String shared = sections.getOrDefault(SHARED, Map.of()).get(key);
        if (shared != null) {
            return Optional.of(shared);
        }
        String wrap = own != null ? sections.getOrDefault("wrap", Map.of()).get(key) : null;
        return wrap != null && !wrap.isEmpty() && !wrap.startsWith("as above") ? Optional.of(wrap) : Optional.empty();
    }

    private static final String AS_FOR_WRAP = "as for wrap";

    /** The unit of the figure at {@code path} (its own name decides; the phases of {@code seconds} are seconds). */
    public static Unit unit(String path) {
        String[] names = path.split("\\.");
        String name = names[names.length - 1];
        if (name.chars().allMatch(Character::isDigit) && names.length > 1) {
            name = names[names.length - 2];
        }
        if (names[0].equals("seconds") || name.equals("seconds")) {
            return Unit.SECONDS;
        }
        if (name.equals("millisecondsPerFold")) {
            return Unit.MILLISECONDS;
        }
        if (names[0].equals("collisions") && name.equals("deepest")) {
            return Unit.THICKNESSES;
        }
        if (names.length > 1 && names[names.length - 2].equals("minAngles")) {
            return Unit.DEGREES;
        }
        if (LENGTHS.contains(name)) {
            return Unit.LENGTH;
        }
        if (AREAS.contains(name)) {
            return Unit.AREA;
        }
        return ANGLES.contains(name) ? Unit.DEGREES : Unit.NONE;
    }
}
