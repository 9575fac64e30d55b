package ifold.job;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/** Which kind of file holds folds: a fold script, or a FOLD crease pattern. */
public final class Scripts {
    private Scripts() {
    }

    /** Whether the file is FOLD (JSON) rather than a fold script: its first character that is not white space is '{'. */
    public static boolean isFoldFile(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] head = in.readNBytes(4096);
            for (byte b : head) {
                if (!Character.isWhitespace(b)) {
                    return b == '{';
                }
            }
            return false;
        }
    }
}
