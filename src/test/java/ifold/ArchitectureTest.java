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
    private static final List<String> CORE = List.of("mesh", "geom", "refine", "fold", "zigzag", "script", "scene", "image", "io");
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
}
