package ifold.testing;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.stream.Stream;

/**
 * The third-party models in {@code ../shared/meshes} beside the project. A user's clone has no
 * such folder: tests that use it skip (through assumptions) rather than fail.
 */
public final class SharedMeshes {
    public static final Path ROOT = Path.of("..", "shared", "meshes");

    private SharedMeshes() {
    }

    public static boolean present() {
        return Files.isDirectory(ROOT.resolve("valid")) && Files.isDirectory(ROOT.resolve("invalid"));
    }

    /** The files of {@code valid/} or {@code invalid/}, sorted; empty when the folder is absent. */
    public static List<Path> files(String kind) {
        Path dir = ROOT.resolve(kind);
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> files = Files.list(dir)) {
            return files.filter(Files::isRegularFile).sorted().toList();
        } catch (IOException e) {
            throw new IllegalStateException(e);
        }
    }

    /** File names for parameterised tests; when the folder is absent, one name that says so, for a test that then skips. */
    public static Stream<String> names(String kind) {
        List<Path> files = files(kind);
        return files.isEmpty() ? Stream.of("(../shared/meshes absent)") : files.stream().map(p -> p.getFileName().toString());
    }
}
