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
    private static final List<String> CORE = List.of("mesh", "geom", "refine", "sheet", "wrap", "script", "scene", "image", "io");
    private static final List<String> FORBIDDEN = List.of("com.jogamp", "java.awt", "javax.swing", "javax.imageio",
            "ifold.render", "ifold.cli", "ifold.view");

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
