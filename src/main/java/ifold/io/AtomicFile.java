package ifold.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AccessDeniedException;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.DirectoryNotEmptyException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.time.Instant;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * Writes a file all or nothing: the content goes to a hidden temporary file beside it, which is
 * renamed over the target (atomically where the file system can) only once it is whole. On any
 * failure the temporary file is deleted and an existing target is left as it was, so a failed
 * or killed run never leaves a half-written output.
 */
public final class AtomicFile {
    private AtomicFile() {
    }

    /** What goes into the file. */
    public interface Content {
        void writeTo(OutputStream out) throws IOException;
    }

    /**
     * @param durable force the content to disk before the rename, so that not even a crash of
     *     the machine soon after can leave an empty file; frames of a movie skip it for speed
     */
    public static void write(Path file, Content content, boolean durable) throws IOException {
        Path named = file.toAbsolutePath();
        Path target = destination(named);
        if (Files.exists(target) && !Files.isRegularFile(target)) {
            // A device, a pipe or a socket (or a link to one): renaming over it would replace it
            // with a plain file, and /dev/full with a PDF.
            throw new IOException(named + ": not a regular file (a device, a pipe or a folder): iFold writes plain files");
        }
        Path temp;
        synchronized (IN_FLIGHT) {
            if (shuttingDown) {
                throw new IOException(named + ": not written: iFold is stopping");
            }
            try {
                temp = createTemporary(target);
            } catch (IOException e) {
                // Name the file the user asked for, not the temporary one beside it.
                throw new IOException(named + ": " + reason(e), e);
            }
            register(temp);
        }
        try {
            try (FileChannel channel = FileChannel.open(temp, StandardOpenOption.WRITE)) {
                OutputStream out = Channels.newOutputStream(channel);
                content.writeTo(out);
                out.flush();
                if (durable) {
                    channel.force(true);
                }
            }
            try {
                Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
            }
            WRITTEN.add(named);
        } catch (IOException e) {
            discard(temp, e);
            // Name the file the user asked for, not the temporary one beside it.
            throw new IOException(named + ": " + reason(e), e);
        } catch (RuntimeException | Error e) {
            discard(temp, e);
            throw e;
        } finally {
            cancelDeleteOnStop(temp);
        }
    }

    /** Why a write failed, in words, without the temporary file's name. */
    /**
     * Where a write of {@code file} (absolute) lands: the file itself, or where a symbolic link
     * there points, followed to the end. The rename would otherwise put a plain file in the
     * link's place and leave the file it points to as it was, where every other program writes
     * through the link.
     */
    static Path destination(Path file) throws IOException {
        Path target = file;
        for (int hops = 0; Files.isSymbolicLink(target); hops++) {
            if (hops == 40) {
                throw new IOException(file + ": too many levels of symbolic links");
            }
            Path parent = target.getParent();
            target = parent.resolve(Files.readSymbolicLink(target)).normalize();
        }
        return target;
    }

    private static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException missing) {
            // The folder may be there and take no file (/proc).
            Path folder = missing.getFile() == null ? null : Path.of(missing.getFile()).getParent();
            return folder != null && Files.isDirectory(folder) ? "cannot create a file in that folder" : "no such folder";
        }
        if (e instanceof FileSystemException fse && fse.getReason() != null) {
            return fse.getReason();
        }
        String message = e.getMessage();
        return message == null || message.isBlank() ? e.getClass().getSimpleName() : message.replaceAll("\\S*\\.tmp\\b", "").strip();
    }

    private static void discard(Path temp, Throwable failure) {
        try {
            Files.deleteIfExists(temp);
        } catch (IOException | RuntimeException cleanup) {
            failure.addSuppressed(cleanup);
        }
    }

    /**
     * Temporary files being written now, and other files of this run's (locks): Ctrl-C or
     * SIGTERM mid-write takes them back. Each with how many times it is registered: two holds
     * on one file (a lock, and another export in this JVM refused it) take two releases.
     */
    private static final Map<Path, Integer> IN_FLIGHT = new ConcurrentHashMap<>();

    /**
     * Programs writing some of them (ffmpeg): stopped before the files are taken back, or one
     * would write its file again once it is deleted.
     */
    private static final Map<Path, Process> WRITERS = new ConcurrentHashMap<>();

    /** The files this run has written whole, in order: what an interrupted run leaves. */
    private static final java.util.List<Path> WRITTEN = java.util.Collections.synchronizedList(new java.util.ArrayList<>());

    /**
     * The files this run has written whole so far (renamed into place), in order, and still
     * there: a file written and taken back since (the window's check writes the wrap into a
     * folder of its own and deletes it) is no file left, and an interrupted run named one.
     */
    public static java.util.List<Path> written() {
        synchronized (WRITTEN) {
            return WRITTEN.stream().filter(Files::exists).toList();
        }
    }

    /** Folders this run made for its files, removed on a stop where nothing whole was left in them. */
    private static final java.util.List<Path> FOLDERS = new java.util.ArrayList<>();

    /**
     * Makes the folder {@code dir} for this run's files, to be removed when the JVM stops (at the
     * end of any run, Ctrl-C or SIGTERM) if it holds nothing whole then: made and registered in
     * one step, so that no stop between the two can leave an empty folder behind.
     *
     * @throws IOException if the JVM is stopping already (nothing is made), or the folder cannot be made
     */
    public static void createFolderRemovedIfEmptyOnStop(Path dir) throws IOException {
        synchronized (IN_FLIGHT) {
            if (shuttingDown) {
                throw new IOException("not made: iFold is stopping");
            }
            Files.createDirectory(dir);
            FOLDERS.add(dir);
        }
    }

    /** Set once the JVM shuts down: no new file is begun after the unfinished ones are taken back. */
    private static boolean shuttingDown;

    /** Whether the JVM is shutting down (Ctrl-C, SIGTERM): what is whole stays, nothing new is begun. */
    public static boolean stopping() {
        synchronized (IN_FLIGHT) {
            return shuttingDown;
        }
    }

    static {
        try {
            Runtime.getRuntime().addShutdownHook(new Thread(() -> {
                synchronized (IN_FLIGHT) {
                    shuttingDown = true;
                    for (Process writer : WRITERS.values()) {
                        writer.destroyForcibly();
                    }
                    for (Process writer : WRITERS.values()) {
                        try {
                            writer.waitFor(2, TimeUnit.SECONDS);
                        } catch (InterruptedException e) {
                            break; // exiting anyway
                        }
                    }
                    for (Path temp : IN_FLIGHT.keySet()) {
                        try {
                            deleteWithContents(temp);
                        } catch (IOException e) {
                            // Exiting anyway; the next run that writes there sweeps it.
                        }
                    }
                    for (Path folder : FOLDERS) {
                        try {
                            Files.deleteIfExists(folder); // fails, as it should, where whole files stay in it
                        } catch (IOException e) {
                            // Something whole was written there: it stays.
                        }
                    }
                }
            }, "discard unfinished files"));
        } catch (IllegalStateException e) {
            shuttingDown = true; // first used while the JVM stops: nothing new is begun
        }
    }

    /** Makes a file of this run's, such as a lock or a temporary file, and says where it is. */
    public interface Creation {
        Path create() throws IOException;
    }

    /**
     * Makes a file by {@code creation}, a file of no use once this run stops (a lock, a
     * temporary file), to be deleted should the JVM stop (Ctrl-C, SIGTERM) before
     * {@link #cancelDeleteOnStop}: made and registered in one step, so that no stop between the
     * two can leave it behind.
     *
     * @return the file made
     * @throws IOException if the JVM is stopping already (nothing is made), or as creation throws
     */
    public static Path createDeletedOnStop(Creation creation) throws IOException {
        synchronized (IN_FLIGHT) {
            if (shuttingDown) {
                throw new IOException("not written: iFold is stopping");
            }
            Path made = creation.create();
            register(made);
            return made;
        }
    }

    /** {@code file} is to stay, or is gone already: a stop no longer deletes it. */
    public static void cancelDeleteOnStop(Path file) {
        Integer left = IN_FLIGHT.computeIfPresent(file, (path, holds) -> holds > 1 ? holds - 1 : null);
        if (left == null) {
            WRITERS.remove(file);
        }
    }

    /** Whether a stop would delete {@code file}: for tests. */
    static boolean deletedOnStop(Path file) {
        return IN_FLIGHT.containsKey(file);
    }

    private static void register(Path file) {
        IN_FLIGHT.merge(file, 1, Integer::sum);
    }

    /**
     * A file being written in steps (a movie, frame by frame): its content goes to a hidden
     * temporary file beside the target, renamed over it by {@link #commit()}. {@link #close()}
     * without a commit deletes it, and so does the JVM's shutdown (Ctrl-C, SIGTERM) while it is
     * pending: an interrupted export leaves no half-written file.
     *
     * <p>Where another program writes the file ({@link #beginForProgram}), it writes it inside
     * a hidden folder of its own beside the target: a program that outlives iFold cannot then
     * make the file again once it is taken back, as its folder is gone.
     */
    public static final class Pending implements AutoCloseable {
        /** The file as the user named it, and where it is written: where a link there points. */
        private final Path named;
        private final Path target;
        /** What a stop takes back: the temporary file, or the folder it is in. */
        private final Path temp;
        private final Path path;
        private boolean done;

        private Pending(Path named, boolean forProgram) throws IOException {
            this.named = named;
            this.target = destination(named);
            try {
                this.temp = createDeletedOnStop(() -> forProgram ? createTemporaryFolder(target) : createTemporary(target));
            } catch (IOException e) {
                // Name the file the user asked for, not the temporary one beside it.
                throw new IOException(named + ": " + reason(e), e);
            }
            this.path = forProgram ? temp.resolve(target.getFileName()) : temp;
        }

        /** The temporary file to write to. */
        public Path path() {
            return path;
        }

        /**
         * {@code writer}, another program, writes the temporary file: a stop (Ctrl-C, SIGTERM)
         * kills it before taking the file back; one under way already kills it now.
         */
        public void writtenBy(Process writer) {
            synchronized (IN_FLIGHT) {
                if (shuttingDown) {
                    writer.destroyForcibly();
                    return;
                }
                WRITERS.put(temp, writer);
            }
        }

        /** Renames the whole file over the target. */
        public void commit() throws IOException {
            try {
                Files.move(path, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(path, target, StandardCopyOption.REPLACE_EXISTING);
            }
            WRITTEN.add(named);
            if (!temp.equals(path)) {
                try {
                    deleteWithContents(temp);
                } catch (IOException e) {
                    // The movie is whole where it belongs; the next run that writes there sweeps the folder.
                }
            }
            finish();
        }

        /** Deletes the temporary file unless it was committed. */
        @Override
        public void close() {
            if (!done) {
                try {
                    deleteWithContents(temp);
                } catch (IOException e) {
                    // A stop still deletes it; else the next run that writes there sweeps it.
                    return;
                }
                finish();
            }
        }

        private void finish() {
            done = true;
            cancelDeleteOnStop(temp);
        }
    }

    /** Deletes a file, or a folder with the files in it. */
    private static void deleteWithContents(Path file) throws IOException {
        for (int attempt = 0; ; attempt++) {
            if (Files.isDirectory(file, LinkOption.NOFOLLOW_LINKS)) {
                try (DirectoryStream<Path> files = Files.newDirectoryStream(file)) {
                    for (Path inside : files) {
                        Files.deleteIfExists(inside);
                    }
                }
            }
            try {
                Files.deleteIfExists(file);
                return;
            } catch (DirectoryNotEmptyException e) {
                // A writer made a file in it since it was listed: once more.
                if (attempt == 3) {
                    throw e;
                }
            }
        }
    }

    /** When this process started: temporary files older than that are no run's now. */
    private static final long STARTED = ProcessHandle.current().info().startInstant().map(Instant::toEpochMilli)
            .orElse(System.currentTimeMillis());

    /**
     * Removes the temporary files that writing {@code dir/name} would make, older than this
     * process: left by a run that was killed before it could take them back (SIGKILL, a power
     * cut). A running export's own are younger than the run, and stay.
     */
    public static void sweepStale(Path dir, String name) {
        String base = "." + (name.length() > 200 ? name.substring(0, 200) : name) + ".";
        sweepStale(dir, glob(base) + "*.tmp", Pattern.quote(base) + "[0-9a-f]+\\.tmp");
    }

    /** As {@link #sweepStale(Path, String)}, for every file in {@code dir} matching {@code glob} and {@code regex}. */
    public static void sweepStale(Path dir, String glob, String regex) {
        Pattern pattern = Pattern.compile(regex);
        try (DirectoryStream<Path> files = Files.newDirectoryStream(dir, glob)) {
            for (Path file : files) {
                if (!pattern.matcher(file.getFileName().toString()).matches()) {
                    continue;
                }
                try {
                    if (Files.getLastModifiedTime(file).toMillis() < STARTED - 1000) {
                        deleteWithContents(file);
                    }
                } catch (IOException e) {
                    // Someone else's, or gone already: leave it.
                }
            }
        } catch (IOException | RuntimeException e) {
            // Sweeping is a courtesy: the write itself goes on.
        }
    }

    private static String glob(String literal) {
        StringBuilder glob = new StringBuilder();
        for (char c : literal.toCharArray()) {
            if ("*?[]{}\\".indexOf(c) >= 0) {
                glob.append('\\');
            }
            glob.append(c);
        }
        return glob.toString();
    }

    /** Begins a file written in steps; see {@link Pending}. */
    public static Pending begin(Path file) throws IOException {
        return new Pending(file.toAbsolutePath(), false);
    }

    /** Begins a file that another program (ffmpeg) writes, in a hidden folder of its own; see {@link Pending}. */
    public static Pending beginForProgram(Path file) throws IOException {
        return new Pending(file.toAbsolutePath(), true);
    }

    /**
     * Creates an empty, uniquely named hidden file beside {@code target}. Files.createTempFile
     * would make it readable by its owner only, and the rename would carry that over.
     */
    private static Path createTemporary(Path target) throws IOException {
        return createTemporary(target, false);
    }

    /** Creates an empty, uniquely named hidden folder beside {@code target}, named as its temporary files are. */
    private static Path createTemporaryFolder(Path target) throws IOException {
        return createTemporary(target, true);
    }

    private static Path createTemporary(Path target, boolean folder) throws IOException {
        Path dir = target.getParent();
        String name = target.getFileName().toString();
        // Keeps the temporary name within the usual 255-byte limit.
        String base = "." + (name.length() > 200 ? name.substring(0, 200) : name) + ".";
        sweepStale(dir, name);
        for (int attempt = 0; ; attempt++) {
            Path temp = dir.resolve(base + Long.toHexString(ThreadLocalRandom.current().nextLong()) + ".tmp");
            try {
                return folder ? Files.createDirectory(temp) : Files.createFile(temp);
            } catch (FileAlreadyExistsException e) {
                if (attempt == 10) {
                    throw e;
                }
            }
        }
    }
}
