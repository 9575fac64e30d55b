package ifold;

import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.classes;
import static com.tngtech.archunit.lang.syntax.ArchRuleDefinition.noClasses;
import static com.tngtech.archunit.library.dependencies.SlicesRuleDefinition.slices;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.base.DescribedPredicate;
import com.tngtech.archunit.core.domain.JavaClass;
import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.core.importer.ImportOption;
import com.tngtech.archunit.lang.ArchRule;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * The package layout is the architecture, read from the compiled classes by ArchUnit (so a
 * class named in full in the code, not imported, counts as a dependency too): the table of
 * docs/architecture.md is the rule for every package, no two packages depend on each other
 * round a cycle, the geometry core never reaches GL, AWT, Swing or the shells, and the window's
 * model draws nothing.
 */
class ArchitectureTest {
    private static final Path SOURCES = Path.of("src", "main", "java", "ifold");

    /** The core: geometry, meshes, the refinement, the fold engine, the planner, scripts, the FOLD format, the checks. */
    static final String[] CORE = {"ifold.geom..", "ifold.mesh..", "ifold.refine..", "ifold.sheet..", "ifold.wrap..", "ifold.script..",
        "ifold.foldfile..", "ifold.check..", "ifold.io.."};

    /** The libraries the table names, by the packages they hold. */
    private static final Map<String, List<String>> LIBRARIES = Map.of(
            "JOML", List.of("org.joml"),
            "JOGL", List.of("com.jogamp", "jogamp"),
            "picocli", List.of("picocli"),
            "jackson", List.of("com.fasterxml.jackson"),
            "fastdoubleparser", List.of("ch.randelshofer.fastdoubleparser"),
            "Tinfour", List.of("org.tinfour"),
            "FlatLaf", List.of("com.formdev.flatlaf"),
            "PDFBox", List.of("org.apache.pdfbox"),
            "AWT", List.of("java.awt", "javax.swing", "javax.imageio", "sun.awt"));

    private static JavaClasses main;

    static JavaClasses mainClasses() {
        if (main == null) {
            main = new ClassFileImporter().withImportOption(ImportOption.Predefined.DO_NOT_INCLUDE_TESTS).importPackages("ifold");
        }
        return main;
    }

    /** The table of docs/architecture.md: package (without "ifold.") → its "may import" column. */
    static Map<String, String> table() throws IOException {
        Map<String, String> allowed = new LinkedHashMap<>();
        Pattern row = Pattern.compile("^\\| `ifold\\.([a-z.]+)` \\|.*\\| ([^|]+) \\|$");
        for (String line : Files.readAllLines(Path.of("docs", "architecture.md"))) {
            Matcher m = row.matcher(line.trim());
            if (m.matches()) {
                allowed.put(m.group(1), m.group(2).trim());
            }
        }
        return allowed;
    }

    /**
     * What a package whose row says {@code rule} may depend on: itself, the iFold packages the
     * rule names in backquotes (each exactly: naming `mesh` does not allow `mesh.io`), the
     * libraries it names, and the JDK but AWT, Swing and ImageIO unless it names AWT.
     */
    static DescribedPredicate<JavaClass> mayUse(String pkg, String rule) {
        Set<String> packages = new HashSet<>();
        packages.add("ifold." + pkg);
        Matcher named = Pattern.compile("`([a-z.]+)`").matcher(rule);
        while (named.find()) {
            packages.add("ifold." + named.group(1));
        }
        List<String> libraries = new ArrayList<>();
        LIBRARIES.forEach((name, prefixes) -> {
            if (rule.contains(name)) {
                libraries.addAll(prefixes);
            }
        });
        return DescribedPredicate.describe("in " + packages + ", " + libraries + " or the JDK", target -> {
            String name = target.getPackageName();
            if (name.equals("ifold") || name.startsWith("ifold.")) {
                return packages.contains(name);
            }
            for (String library : libraries) {
                if (name.equals(library) || name.startsWith(library + ".")) {
                    return true;
                }
            }
            for (String drawing : LIBRARIES.get("AWT")) {
                if (name.equals(drawing) || name.startsWith(drawing + ".")) {
                    return false;
                }
            }
            return name.isEmpty() || name.startsWith("java.") || name.startsWith("javax.") || name.startsWith("org.w3c.");
        });
    }

    /**
     * Every class of every package depends only on what its row of the table allows: the
     * document and the code cannot drift apart.
     */
    @Test
    void everyPackageDependsOnlyOnWhatTheTableAllows() throws IOException {
        Map<String, String> table = table();
        assertTrue(table.size() > 8, "setup: read the table, got " + table.keySet());
        Set<String> packages = new TreeSet<>();
        for (JavaClass c : mainClasses()) {
            packages.add(c.getPackageName().equals("ifold") ? "" : c.getPackageName().substring("ifold.".length()));
        }
        packages.remove("");
        assertTrue(packages.size() > 8, "setup: imported the main classes, got " + packages);
        assertEquals(Set.of(), new TreeSet<>(org.junit.jupiter.api.Assertions.assertDoesNotThrow(() -> {
            Set<String> missing = new TreeSet<>(packages);
            missing.removeAll(table.keySet());
            return missing;
        })), "every package has its row");
        for (Map.Entry<String, String> row : table.entrySet()) {
            if (row.getValue().equals("everything")) {
                continue;
            }
            classes().that().resideInAPackage("ifold." + row.getKey())
                    .should().onlyDependOnClassesThat(mayUse(row.getKey(), row.getValue()))
                    .allowEmptyShould(true)
                    .check(mainClasses());
        }
    }

    @Test
    void noPackagesDependOnEachOtherRoundACycle() {
        slices().matching("ifold.(**)").should().beFreeOfCycles().check(mainClasses());
    }

    /** The rule the table implies, said once more on its own: the core draws nothing and knows no shell. */
    static ArchRule coreDrawsNothing() {
        return noClasses().that().resideInAnyPackage(CORE)
                .should().dependOnClassesThat().resideInAnyPackage("java.awt..", "javax.swing..", "javax.imageio..", "com.jogamp..",
                        "ifold.render..", "ifold.ui..", "ifold.cli..");
    }

    @Test
    void theCoreDrawsNothingAndKnowsNoShell() {
        coreDrawsNothing().check(mainClasses());
    }

    /** The window's model is the window without Swing: it neither draws nor renders, so it can be tested without a display. */
    @Test
    void theWindowsModelNeitherDrawsNorRenders() {
        noClasses().that().resideInAPackage("ifold.ui.model")
                .should().dependOnClassesThat().resideInAnyPackage("java.awt..", "javax.swing..", "com.jogamp..", "ifold.render..", "ifold.ui")
                .check(mainClasses());
    }

    /**
     * The rules fail when they should: a class of the core that draws with AWT and calls the
     * renderer (test code, in package ifold.geom, named in full rather than imported) breaks
     * both the core's rule and its row of the table.
     */
    @Test
    void aForbiddenDependencyFailsTheRules() throws Exception {
        JavaClasses offender = new ClassFileImporter().importClasses(Class.forName("ifold.geom.DrawsOnTheSide"));
        AssertionError core = assertThrows(AssertionError.class, () -> coreDrawsNothing().check(offender));
        assertTrue(core.getMessage().contains("java.awt.geom.Point2D") && core.getMessage().contains("ifold.render.FrameExport"),
                core.getMessage());
        AssertionError row = assertThrows(AssertionError.class, () -> classes().that().resideInAPackage("ifold.geom")
                .should().onlyDependOnClassesThat(mayUse("geom", table().get("geom"))).check(offender));
        assertTrue(row.getMessage().contains("ifold.render.FrameExport"), row.getMessage());
        classes().that().resideInAPackage("ifold.render")
                .should().onlyDependOnClassesThat(mayUse("render", table().get("render")))
                .check(new ClassFileImporter().importClasses(ifold.render.FrameExport.class));
    }

    /**
     * JOML 1.10.8's {@code Quaterniond.rotationX} builds (sin, 0, cos, 0): not a turn about x but
     * one of 180 degrees about a tilted axis, which turned every camera upside down. The fix is
     * {@code new Quaterniond().rotateX(a)}; this keeps the broken call out.
     */
    @Test
    void nobodyCallsJomlsBrokenQuaternionRotationX() throws IOException {
        assertTrue(new org.joml.Quaterniond().rotateX(0.3).w > 0.98, "setup: rotateX is a turn about x");
        List<String> offences = new ArrayList<>();
        try (Stream<Path> files = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                for (String line : Files.readAllLines(file)) {
                    if (line.contains("Quaterniond().rotationX(")) {
                        offences.add(file + ": " + line.trim());
                    }
                }
            }
        }
        assertEquals(List.of(), offences);
    }
}
