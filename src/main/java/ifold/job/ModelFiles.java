package ifold.job;

import ifold.mesh.Defect;
import ifold.mesh.InvalidMeshException;
import ifold.mesh.MeshBuilder;
import ifold.mesh.PolygonSoup;
import ifold.mesh.io.MeshFormatException;
import ifold.mesh.io.MeshReaders;
import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;

/**
 * Model files read and built into halfedge meshes, for every front end: each way that fails
 * is one line naming the file (and the line, where known), the same on the command line and in
 * the window, which add only their own hint for strict mode.
 */
public final class ModelFiles {
    private ModelFiles() {
    }

    /**
     * A model read and built, with the time each step took.
     *
     * @param inputVertices vertices in the file
     * @param inputFaces faces in the file
     * @param read the format read (its soup is dropped: null)
     * @param built the halfedge mesh and its repairs
     */
    public record Loaded(int inputVertices, int inputFaces, MeshReaders.Read read, MeshBuilder.Result built, double parseSeconds,
            double buildSeconds) {
        public Map<Defect, Integer> repairs() {
            return built.repairs();
        }


        /**
         * The refusal of a model its repairs left without faces, in one line that names the
         * repairs, or null where faces are left: there is nothing to {@code what} ("wrap").
         */
        public String noFacesLeft(Path file, String what) {
            return ModelFiles.noFacesLeft(file, built, what);
        }
    }

    /** The repairs made, in one phrase: "dropped 1 zero-area faces, removed 3 unreferenced vertices". */
    public static String repairsText(Map<Defect, Integer> repairs) {
        List<String> parts = new ArrayList<>();
        for (Map.Entry<Defect, Integer> repair : new TreeMap<>(repairs).entrySet()) {
            parts.add(repair.getKey().describeRepair(repair.getValue()));
        }
        return String.join(", ", parts);
    }

    /** A line for each kind of repair made, with its count: "models/x.off: repaired: dropped 1 zero-area face". */
    public static List<String> repairNotes(Path file, Map<Defect, Integer> repairs) {
        List<String> notes = new ArrayList<>();
        for (Map.Entry<Defect, Integer> repair : new TreeMap<>(repairs).entrySet()) {
            notes.add(file + ": repaired: " + repair.getKey().describeRepair(repair.getValue()));
        }
        return notes;
    }

    /**
     * The refusal of a model its repairs left without faces, in one line that names the repairs
     * (rather than a line per repair and then the refusal), or null where faces are left.
     *
     * @param what what there is none of to do: "nothing to wrap"
     */
    public static String noFacesLeft(Path file, MeshBuilder.Result built, String what) {
        if (built.mesh().faceCount() > 0) {
            return null;
        }
        String repairs = repairsText(built.repairs());
        return file + ": no faces left" + (repairs.isEmpty() ? "" : " after the repairs (" + repairs + ")") + ": " + what;
    }

    /** A model file that cannot be read or built. */
    public static final class LoadFailure extends Exception {
        private static final long serialVersionUID = 1L;
        private final boolean repairable;

        LoadFailure(String message, boolean repairable) {
            super(message);
            this.repairable = repairable;
        }

        /** Whether strict mode refused what the builder would have repaired: a front end says how to let it. */
        public boolean repairable() {
            return repairable;
        }
    }

    /**
     * Refuses what is not a file to read before reading it: a folder, or a pipe, a device or a
     * socket, whose reading would wait for ever for a writer, or for an end that never comes.
     * Null where {@code file} may be read (or does not exist: reading it says so).
     */
    public static String notAFile(Path file) {
        if (Files.isDirectory(file)) {
            return file + ": is a folder, expected a file";
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            return file + ": not a regular file (a pipe, a device or a socket): iFold reads files";
        }
        return null;
    }

    /** Reads {@code file} into a soup. */
    public static PolygonSoup read(Path file) throws LoadFailure {
        return readDescribed(file).soup();
    }

    /** Reads {@code file} into a soup, with the format read. */
    public static MeshReaders.Read readDescribed(Path file) throws LoadFailure {
        if (Files.isDirectory(file)) {
            throw new LoadFailure(file + ": is a folder, expected a model file", false);
        }
        String refusal = notAFile(file);
        if (refusal != null) {
            throw new LoadFailure(refusal, false);
        }
        try {
            return MeshReaders.readDescribed(file);
        } catch (MeshFormatException e) {
            throw new LoadFailure(e.getMessage(), false);
        } catch (IOException e) {
            throw new LoadFailure(readError(file, e), false);
        }
    }

    /** Builds the soup read from {@code file}. */
    public static MeshBuilder.Result build(Path file, PolygonSoup soup, MeshBuilder.Options options) throws LoadFailure {
        try {
            return MeshBuilder.build(soup, options);
        } catch (InvalidMeshException e) {
            String where = e.sourceLine() > 0 ? file + ":" + e.sourceLine() : file.toString();
            throw new LoadFailure(where + ": " + e.getMessage(), e.defect().isRepairable() && options.strict());
        }
    }

    /** Reads and builds {@code file}. */
    public static Loaded load(Path file, MeshBuilder.Options options) throws LoadFailure {
        return load(file, options, JobWatcher.NONE);
    }

    /** Reads and builds {@code file}, the stage told to {@code watcher}, which may stop it between reading and building. */
    public static Loaded load(Path file, MeshBuilder.Options options, JobWatcher watcher) throws LoadFailure {
        watcher.stage("reading " + file.getFileName());
        long start = System.nanoTime();
        MeshReaders.Read read = readDescribed(file);
        PolygonSoup soup = read.soup();
        long parsed = System.nanoTime();
        watcher.stopIfAsked();
        MeshBuilder.Result built = build(file, soup, options);
        long builtAt = System.nanoTime();
        // The soup is not kept: for big models it is a third of the memory the refinement needs.
        return new Loaded(soup.vertexCount(), soup.faceCount(), new MeshReaders.Read(null, read.format(), read.weldedCorners()), built,
                (parsed - start) * 1e-9, (builtAt - parsed) * 1e-9);
    }

    /**
     * Reads and builds {@code file} for a job that looks at its surface: the stage told, a stop
     * looked for between reading and building, a model its repairs left without faces refused
     * ("nothing to {@code what}"), and a note for each kind of repair made.
     */
    public static Loaded loadSurface(Path file, MeshBuilder.Options options, String what, JobWatcher watcher) throws LoadFailure {
        Loaded loaded = load(file, options, watcher);
        String refusal = loaded.noFacesLeft(file, "nothing to " + what);
        if (refusal != null) {
            throw new LoadFailure(refusal, false);
        }
        for (String note : repairNotes(file, loaded.repairs())) {
            watcher.note(note);
        }
        return loaded;
    }

    /** What went wrong reading {@code file}, in one line. */
    public static String readError(Path file, IOException e) {
        if (e instanceof NoSuchFileException) {
            return file + ": no such file";
        }
        if (e instanceof AccessDeniedException) {
            return file + ": permission denied";
        }
        return file + ": cannot read: " + e.getMessage();
    }
}
