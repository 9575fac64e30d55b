package ifold;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/** The package layout is the architecture: the geometry core never reaches GL, AWT or the shells. */
class ArchitectureTest {
    private static final Path SOURCES = Path.of("src", "main", "java", "ifold");
    private static final List<String> CORE = List.of("mesh", "geom", "refine", "sheet", "wrap", "script", "fold", "scene", "image", "io", "job", "check");
    private static final List<String> FORBIDDEN = List.of("com.jogamp", "java.awt", "javax.swing", "javax.imageio",
            "ifold.render", "ifold.cli", "ifold.view", "ifold.ui", "com.formdev");

    @Test
    void coreImportsNoGlNoAwtNoShell() throws IOException {
        assertTrue(Files.isDirectory(SOURCES), "setup: tests run in the project folder");
        List<String> offences = new ArrayList<>();
        int checked = 0;
        for (String pkg : CORE) {
            Path dir = SOURCES.resolve(pkg);
            if (!Files.isDirectory(dir)) {
                continue;
            }
            try (Stream<Path> files = Files.walk(dir)) {
                for (Path file : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                    checked++;
                    for (String line : Files.readAllLines(file)) {
                        String trimmed = line.trim();
                        if (!trimmed.startsWith("import ")) {
                            continue;
                        }
                        for (String forbidden : FORBIDDEN) {
                            if (trimmed.contains(" " + forbidden + ".") || trimmed.contains(" static " + forbidden + ".")) {
                                offences.add(file + ": " + trimmed);
                            }
                        }
                    }
                }
            }
        }
        assertTrue(checked > 10, "setup: found the core sources, got " + checked);
        assertEquals(List.of(), offences);
    }

    /**
     * The table of packages in docs/architecture.md is the map: every import of one iFold
     * package from another (and of JOML, JOGL, picocli) must be allowed by its row's "may
     * import" column, so the document and the code cannot drift apart.
     */
    @Test
    void importsFollowTheTableOfPackages() throws IOException {
        java.util.Map<String, String> allowed = new java.util.LinkedHashMap<>();
        java.util.regex.Pattern row = java.util.regex.Pattern.compile("^\\| `ifold\\.([a-z.]+)` \\|.*\\| ([^|]+) \\|$");
        for (String line : Files.readAllLines(Path.of("docs", "architecture.md"))) {
            java.util.regex.Matcher m = row.matcher(line.trim());
            if (m.matches()) {
                allowed.put(m.group(1), m.group(2).trim());
            }
        }
        assertTrue(allowed.size() > 8, "setup: read the table, got " + allowed.keySet());
        List<String> offences = new ArrayList<>();
        try (Stream<Path> files = Files.walk(SOURCES)) {
            for (Path file : (Iterable<Path>) files.filter(p -> p.toString().endsWith(".java"))::iterator) {
                String pkg = SOURCES.relativize(file.getParent()).toString().replace('/', '.');
                String rule = allowed.get(pkg);
                if (rule == null) {
                    offences.add(file + ": package ifold." + pkg + " is not in the table");
                    continue;
                }
                if (rule.equals("everything")) {
                    continue;
                }
                for (String line : Files.readAllLines(file)) {
                    String trimmed = line.trim();
                    if (!trimmed.startsWith("import ")) {
                        continue;
                    }
                    String name = trimmed.replace("import static ", "").replace("import ", "").replace(";", "");
                    boolean ok;
                    if (name.startsWith("ifold.")) {
                        String target = name.substring(6);
                        ok = target.startsWith(pkg + ".") || allowedPackage(rule, target, allowed.keySet());
                    } else if (name.startsWith("org.joml.")) {
                        ok = rule.contains("JOML");
                    } else if (name.startsWith("com.jogamp.")) {
                        ok = rule.contains("JOGL");
                    } else if (name.startsWith("picocli.")) {
                        ok = rule.contains("picocli");
                    } else if (name.startsWith("com.fasterxml.jackson.")) {
                        ok = rule.contains("jackson");
                    } else if (name.startsWith("ch.randelshofer.fastdoubleparser.")) {
                        ok = rule.contains("fastdoubleparser");
                    } else if (name.startsWith("org.tinfour.")) {
                        ok = rule.contains("Tinfour");
                    } else if (name.startsWith("com.formdev.flatlaf.")) {
                        ok = rule.contains("FlatLaf");
                    } else if (name.startsWith("java.awt.") || name.startsWith("javax.swing.")) {
                        // Only the shells that draw may: the window, and render's text and pictures.
                        ok = rule.contains("AWT");
                    } else {
                        ok = name.startsWith("java.") || name.startsWith("javax.") || name.startsWith("org.w3c.");
                    }
                    if (!ok) {
                        offences.add(file + ": " + trimmed + " (may import: " + rule + ")");
                    }
                }
            }
        }
        assertEquals(List.of(), offences);
    }

    /** Whether {@code target} (a class below ifold.) lies in a package the rule names, as `name`. */
    private static boolean allowedPackage(String rule, String target, java.util.Set<String> packages) {
        String owner = "";
        for (String pkg : packages) {
            if (target.startsWith(pkg + ".") && pkg.length() > owner.length()) {
                owner = pkg;
            }
        }
        return !owner.isEmpty() && rule.contains("`" + owner + "`");
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
