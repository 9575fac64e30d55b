package ifold.mesh.io;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/** Reads a model file by the extension of its name: {@code .off}, {@code .obj} or {@code .stl}, in any case. */
public final class MeshReaders {
    private MeshReaders() {
    }

    /**
     * Reads {@code file} with {@link OffReader}, {@link ObjReader} or {@link StlReader}.
     *
     * @throws MeshFormatException for a file that the chosen reader refuses, and (with line 0)
     *         for a name that ends in neither extension
     * @throws IOException when the file cannot be read
     */
    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        String name = lowerCaseName(file);
        if (name.endsWith(".off")) {
            return OffReader.read(file);
        }
        if (name.endsWith(".obj")) {
            return ObjReader.read(file);
        }
        if (name.endsWith(".stl")) {
            return StlReader.read(file);
        }
        throw new MeshFormatException(file, 0, "unsupported file type: expected a name ending in .off, .obj or .stl");
    }

    /** The extensions of the files {@link #read} reads, without their dot. */
    public static final java.util.List<String> EXTENSIONS = java.util.List.of("off", "obj", "stl");

    /** Whether {@link #read} reads a file of this name (a model, not a fold script or FOLD file). */
    public static boolean isModel(Path file) {
        String name = lowerCaseName(file);
        return EXTENSIONS.stream().anyMatch(extension -> name.endsWith("." + extension));
    }

    static String lowerCaseName(Path file) {
        Path name = file.getFileName();
        return name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
    }
}
