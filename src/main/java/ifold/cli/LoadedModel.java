package ifold.cli;

import ifold.mesh.Defect;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.io.MeshFormatException;
import ifold.mesh.io.MeshReaders;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.Map;

/**
 * A model file read and built into a halfedge mesh, with the time each step took. Turns every
 * way that can fail into a {@link UserError} naming the file and, where known, the line.
 *
 * @param inputVertices vertices in the file
 * @param inputFaces faces in the file
 * @param built the halfedge mesh and its repairs
 * @param parseSeconds time to read the file
 * @param buildSeconds time to build the mesh
 */
record LoadedModel(int inputVertices, int inputFaces, MeshBuilder.Result built, double parseSeconds, double buildSeconds) {

    /**
     * Refuses a pipe, a device or a socket before reading it: reading one would wait for ever
     * for a writer, or for an end that never comes.
     */
    static void requireRegularFile(Path file) {
        if (Files.exists(file) && !Files.isDirectory(file) && !Files.isRegularFile(file)) {
            throw new UserError(file + ": not a regular file (a pipe, a device or a socket): iFold reads files");
        }
    }

    static LoadedModel load(Path file, MeshBuilder.Options options) {
        long start = System.nanoTime();
        PolygonSoup soup;
        try {
            if (Files.isDirectory(file)) {
                throw new UserError(file + ": is a folder, expected an .off or .obj file");
            }
            requireRegularFile(file);
            soup = MeshReaders.read(file);
        } catch (MeshFormatException e) {
            throw new UserError(e.getMessage());
        } catch (NoSuchFileException e) {
            throw new UserError(file + ": no such file");
        } catch (AccessDeniedException e) {
            throw new UserError(file + ": permission denied");
        } catch (IOException e) {
            throw new UserError(file + ": cannot read: " + e.getMessage());
        }
        long parsed = System.nanoTime();
        MeshBuilder.Result built;
        try {
            built = MeshBuilder.build(soup, options);
        } catch (InvalidMeshException e) {
            String where = e.sourceLine() > 0 ? file + ":" + e.sourceLine() : file.toString();
            String hint = e.defect().isRepairable() && options.strict() ? " (run without --strict to repair)" : "";
            throw new UserError(where + ": " + e.getMessage() + hint);
        }
        long builtAt = System.nanoTime();
        // The soup is not kept: for big models it is a third of the memory the refinement needs.
        return new LoadedModel(soup.vertexCount(), soup.faceCount(), built, (parsed - start) * 1e-9, (builtAt - parsed) * 1e-9);
    }

    Map<Defect, Integer> repairs() {
        return built.repairs();
    }

    /** One line on {@code err} for each kind of repair made, with its count. */
    /** The repairs made, in one phrase: "dropped 1 zero-area faces, removed 3 unreferenced vertices". */
    String repairsText() {
        java.util.List<String> parts = new java.util.ArrayList<>();
        for (Map.Entry<Defect, Integer> repair : new java.util.TreeMap<>(built.repairs()).entrySet()) {
            parts.add(repair.getKey().describeRepair(repair.getValue()));
        }
        return String.join(", ", parts);
    }

    /**
     * Refuses a model its repairs left without faces, in one line that names the repairs
     * (rather than a line per repair and then the refusal).
     */
    void requireFaces(Path file, String what) {
        if (built.mesh().faceCount() == 0) {
            String repairs = repairsText();
            throw new UserError(file + ": no faces left" + (repairs.isEmpty() ? "" : " after the repairs (" + repairs + ")") + ": " + what);
        }
    }

    void reportRepairs(Path file, PrintWriter err) {
        for (Map.Entry<Defect, Integer> repair : new java.util.TreeMap<>(built.repairs()).entrySet()) {
            err.println("ifold: " + file + ": repaired: " + repair.getKey().describeRepair(repair.getValue()));
        }
        err.flush();
    }
}
