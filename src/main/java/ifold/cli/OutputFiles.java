package ifold.cli;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

/** Checks on output paths, made before any work so that a bad option fails at once. */
final class OutputFiles {
    private OutputFiles() {
    }

    /**
     * Refuses {@code file} unless its name ends in one of {@code extensions} and its folder
     * exists and can be written.
     */
    static void checkWritableFile(Path file, String option, String... extensions) {
        if (file.toString().isBlank()) {
            throw UserError.usage("option " + option + ": no file named");
        }
        if (Files.isDirectory(file)) {
            throw UserError.usage("option " + option + ": " + file + " is a folder");
        }
        if (Files.exists(file) && !Files.isRegularFile(file)) {
            throw UserError.usage("option " + option + ": " + file + " is not a regular file (a device, a pipe or a socket):"
                    + " iFold writes plain files");
        }
        String name = file.getFileName() == null ? "" : file.getFileName().toString().toLowerCase(Locale.ROOT);
        boolean known = false;
        for (String extension : extensions) {
            known |= name.endsWith(extension);
        }
        if (!known) {
            throw UserError.usage("option " + option + ": " + file + " must end in " + String.join(" or ", extensions));
        }
        Path folder = file.toAbsolutePath().getParent();
        if (folder == null || !Files.isDirectory(folder)) {
            throw UserError.usage("option " + option + ": folder " + folder + " does not exist");
        }
        if (!Files.isWritable(folder)) {
            throw UserError.usage("option " + option + ": folder " + folder + " is not writable");
        }
        // A folder can say it is writable and take no file (/proc, to root): found now, not after the wrap.
        try {
            Files.delete(Files.createTempFile(folder, ".ifold-", ".probe"));
        } catch (java.io.IOException e) {
            throw UserError.usage("option " + option + ": cannot create a file in folder " + folder);
        }
    }
}
