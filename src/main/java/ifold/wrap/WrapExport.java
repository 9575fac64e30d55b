package ifold.wrap;

import ifold.io.AtomicFile;
import ifold.mesh.PolygonSoup;
import java.io.BufferedWriter;
import java.io.StringWriter;
import java.io.UncheckedIOException;
import java.io.IOException;
import java.io.OutputStreamWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;

/**
 * Writes a wrap as OBJ: each strip an object {@code strip-K} with its own sheet starting at
 * (0, 0); {@code v} in the model's own coordinates, {@code vt} the paper coordinates of the same
 * vertex, the sheet's faces in group {@code paper} and the caps in group {@code cap}. Anyone
 * can check from the file alone that the paper tiles its strip and did not stretch. Written
 * under a temporary name and renamed: a failed export leaves no half-written file.
 */
public final class WrapExport {
    private WrapExport() {
    }

    /**
     * Writes a wrap's strips under a header that names the model, the width, the thickness and
     * the levels of the deepest stack: {@code ifold check} reads the last two from it, as how
     * thick the paper is and how high above the surface it may lie.
     */
    public static void writeObj(Path file, String model, Wrap.Result result, List<PaperInSpace> strips) throws IOException {
        int stack = 0;
        for (Wrap.Strip strip : result.strips()) {
            stack = Math.max(stack, strip.sheet().stackLevels());
        }
        writeObj(file, "iFold wrap of " + model.replace('\n', ' ') + ": " + strips.size() + (strips.size() == 1 ? " strip" : " strips") + ", width " + result.width()
                + ", thickness " + result.thickness() + ", a stack of " + stack + " levels", strips);
    }

    /**
     * The model as an export's header names it: with the point its coordinates are about, where
     * the wrap moved it near its centre ({@code movedBy} not all zero), so that the paper can be
     * put back where the model lies.
     */
    public static String aboutCentre(String model, double[] movedBy) {
        if (movedBy == null || movedBy[0] == 0 && movedBy[1] == 0 && movedBy[2] == 0) {
            return model;
        }
        return model + " (coordinates about (" + movedBy[0] + ", " + movedBy[1] + ", " + movedBy[2]
                + "), near its centre: add that point to place the paper where the model lies)";
    }

    /** Writes folded sheets (a wrap's strips, a fold script's paper) under a header line of their own. */
    public static void writeObj(Path file, String header, List<PaperInSpace> strips) throws IOException {
        AtomicFile.write(file, stream -> {
            Writer out = new BufferedWriter(new OutputStreamWriter(stream, StandardCharsets.UTF_8), 1 << 16);
            writeObj(out, header, strips);
        }, true);
    }

    /** The text {@link #writeObj(Path, String, List)} writes, for a check that reads it without a file. */
    public static String objText(String header, List<PaperInSpace> strips) {
        StringWriter text = new StringWriter();
        try {
            writeObj(text, header, strips);
        } catch (IOException e) {
            throw new UncheckedIOException(e); // a StringWriter does not fail
        }
        return text.toString();
    }

    private static void writeObj(Writer out, String header, List<PaperInSpace> strips) throws IOException {
        out.write("# " + header.replace('\n', ' ') + "\n");
        out.write("# vt holds each vertex's paper coordinates (u, v) on its strip; group cap holds the bent paper at folds\n");
        int base = 0;
        for (int k = 0; k < strips.size(); k++) {
            PaperInSpace strip = strips.get(k);
            out.write("o strip-" + (k + 1) + "\n");
            double[] xyz = strip.xyz();
            double[] uv = strip.uv();
            StringBuilder line = new StringBuilder(64);
            for (int v = 0; v < strip.vertexCount(); v++) {
                line.setLength(0);
                line.append("v ").append(xyz[3 * v]).append(' ').append(xyz[3 * v + 1]).append(' ').append(xyz[3 * v + 2]).append('\n');
                out.write(line.toString());
            }
            for (int v = 0; v < strip.vertexCount(); v++) {
                line.setLength(0);
                line.append("vt ").append(uv[2 * v]).append(' ').append(uv[2 * v + 1]).append('\n');
                out.write(line.toString());
            }
            out.write("g paper\n");
            writeFaces(out, strip.paperFaces(), base);
            out.write("g cap\n");
            writeFaces(out, strip.caps(), base);
            base += strip.vertexCount();
        }
        out.flush();
    }

    /**
     * The folded paper as one mesh, for formats without paper coordinates or groups (PLY, STL,
     * for printing and other tools): each strip's vertices, its paper faces, then its caps, in
     * the order the OBJ numbers them.
     */
    public static PolygonSoup paperMesh(List<PaperInSpace> strips) {
        int vertices = 0;
        int faces = 0;
        for (PaperInSpace strip : strips) {
            vertices += strip.vertexCount();
            faces += strip.paperFaces().size() + strip.caps().size();
        }
        PolygonSoup mesh = new PolygonSoup(vertices, faces, 4 * faces);
        int base = 0;
        for (PaperInSpace strip : strips) {
            double[] xyz = strip.xyz();
            for (int v = 0; v < strip.vertexCount(); v++) {
                mesh.addVertex(xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]);
            }
            for (List<int[]> group : List.of(strip.paperFaces(), strip.caps())) {
                for (int[] loop : group) {
                    int[] shifted = new int[loop.length];
                    for (int k = 0; k < loop.length; k++) {
                        shifted[k] = base + loop[k];
                    }
                    mesh.addFace(shifted, shifted.length, 0);
                }
            }
            base += strip.vertexCount();
        }
        return mesh;
    }

    /**
     * The corners (x, y, z interleaved) of the face the OBJ written of {@code strips} numbers
     * {@code face}, counting its {@code f} lines from 1: each strip's paper faces, then its caps.
     *
     * @throws IllegalArgumentException for a number no face has
     */
    public static double[] faceCorners(List<PaperInSpace> strips, int face) {
        if (face < 1) {
            throw new IllegalArgumentException("the OBJ has no face " + face + ": they count from 1");
        }
        int n = face - 1;
        for (PaperInSpace strip : strips) {
            for (List<int[]> group : List.of(strip.paperFaces(), strip.caps())) {
                if (n < group.size()) {
                    int[] loop = group.get(n);
                    double[] corners = new double[3 * loop.length];
                    for (int k = 0; k < loop.length; k++) {
                        System.arraycopy(strip.xyz(), 3 * loop[k], corners, 3 * k, 3);
                    }
                    return corners;
                }
                n -= group.size();
            }
        }
        throw new IllegalArgumentException("the OBJ has no face " + face);
    }

    private static void writeFaces(Writer out, List<int[]> faces, int base) throws IOException {
        StringBuilder line = new StringBuilder(64);
        for (int[] face : faces) {
            line.setLength(0);
            line.append('f');
            for (int v : face) {
                int index = base + v + 1;
                line.append(' ').append(index).append('/').append(index);
            }
            out.write(line.append('\n').toString());
        }
    }
}
