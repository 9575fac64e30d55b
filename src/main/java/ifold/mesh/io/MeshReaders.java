package ifold.mesh.io;

import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.file.Path;
import java.util.Locale;

/** Reads a model file by the extension of its name: {@code .off}, {@code .obj}, {@code .ply} or {@code .stl}, in any case. */
public final class MeshReaders {
    private MeshReaders() {
    }

    /**
     * A model file read.
     *
     * @param format the format in words, as {@code ifold info} names it: "OFF", "OBJ", "binary
     *     little-endian PLY", "ASCII STL"
     * @param weldedCorners corners of an STL file that were welded into a vertex already read (STL
     *     repeats each vertex in every triangle), or -1 for formats that share vertices
     */
    public record Read(PolygonSoup soup, String format, long weldedCorners) {
    }

    /** As {@link #readDescribed}, the soup alone. */
    public static PolygonSoup read(Path file) throws MeshFormatException, IOException {
        return readDescribed(file).soup();
    }

    /**
     * Reads {@code file} with {@link OffReader}, {@link ObjReader}, {@link PlyReader} or {@link StlReader}.
     *
     * @throws MeshFormatException for a file that the chosen reader refuses, and (with line 0)
     *         for a name that ends in none of the extensions
     * @throws IOException when the file cannot be read
     */
    public static Read readDescribed(Path file) throws MeshFormatException, IOException {
        String name = lowerCaseName(file);
        if (name.endsWith(".off")) {
            return new Read(OffReader.read(file), "OFF", -1);
        }
        if (name.endsWith(".obj")) {
            return new Read(ObjReader.read(file), "OBJ", -1);
        }
        if (name.endsWith(".ply")) {
            PlyReader.Result ply = PlyReader.readWithCounts(file);
            String format = switch (ply.format()) {
                case ASCII -> "ASCII PLY";
                case BINARY_LITTLE_ENDIAN -> "binary little-endian PLY";
                case BINARY_BIG_ENDIAN -> "binary big-endian PLY";
            };
            return new Read(ply.soup(), format, -1);
        }
        if (name.endsWith(".stl")) {
            StlReader.Result stl = StlReader.readWithCounts(file);
            return new Read(stl.soup(), stl.binary() ? "binary STL" : "ASCII STL", stl.welded());
        }
        throw new MeshFormatException(file, 0, "unsupported file type: expected a name ending in .off, .obj, .ply or .stl");
    }

    /** The extensions of the files {@link #read} reads, without their dot. */
    public static final java.util.List<String> EXTENSIONS = java.util.List.of("off", "obj", "ply", "stl");

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
