package ifold.mesh.io;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/** Reads a model file by the extension of its name: {@code .off} or {@code .obj}, in any case. */
public final class MeshReaders {
    private MeshReaders() {
    }

    /**
     * Reads {@code file} with {@link OffReader} or {@link ObjReader}.
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
        throw new MeshFormatException(file, 0, "unsupported file type: expected a name ending in .off or .obj");
    }

    static String lowerCaseName(Path file) {
        Path name = file.getFileName();
        return name == null ? "" : name.toString().toLowerCase(Locale.ROOT);
    }
}
