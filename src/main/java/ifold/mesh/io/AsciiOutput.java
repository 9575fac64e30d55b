package ifold.mesh.io;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.channels.Channels;
import java.nio.channels.FileChannel;
import java.nio.file.AtomicMoveNotSupportedException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.nio.file.StandardOpenOption;
import java.util.concurrent.ThreadLocalRandom;

/**
 * ASCII text into a 1 MiB byte buffer, for the writers: integers by hand, doubles so that they
 * read back bit for bit. Also the atomic write both writers go through.
 */
final class AsciiOutput {
    private static final int BUFFER_SIZE = 1 << 20;
    /** Room for the longest thing written in one go: a long, or a double as Double.toString prints it. */
    private static final int LONGEST = 32;

    /** The 2^53 bound: integral doubles below it are exactly the longs of the same value. */
    private static final double EXACT_LONGS = 9007199254740992.0;

    private final OutputStream out;
    private final byte[] buf = new byte[BUFFER_SIZE];
    private int size;

    private AsciiOutput(OutputStream out) {
        this.out = out;
    }

    /** What a writer puts into the file. */
    interface Content {
        void writeTo(AsciiOutput out) throws IOException;
    }

    /**
     * Writes {@code file} all or nothing: the content goes to a temporary file in the same
     * directory, is forced to disk, and is then renamed over {@code file} (atomically where the
     * file system can). On any failure, including an exception thrown by {@code content}, the
     * temporary file is deleted and an existing {@code file} is left as it was.
     */
    static void writeAtomically(Path file, Content content) throws IOException {
        Path target = file.toAbsolutePath();
        Path temp = createTemporary(target);
        try {
            try (FileChannel channel = FileChannel.open(temp, StandardOpenOption.WRITE)) {
                AsciiOutput out = new AsciiOutput(Channels.newOutputStream(channel));
                content.writeTo(out);
                out.flush();
                // Without this a crash soon after the rename can leave an empty file behind it.
                channel.force(true);
            }
            try {
                Files.move(temp, target, StandardCopyOption.ATOMIC_MOVE, StandardCopyOption.REPLACE_EXISTING);
            } catch (AtomicMoveNotSupportedException e) {
                Files.move(temp, target, StandardCopyOption.REPLACE_EXISTING);
            }
        } catch (IOException | RuntimeException | Error e) {
            try {
                Files.deleteIfExists(temp);
            } catch (IOException | RuntimeException cleanup) {
                e.addSuppressed(cleanup);
            }
            throw e;
        }
    }

    /**
     * Creates an empty, uniquely named hidden file beside {@code target}. Files.createTempFile
     * would make it readable by its owner only, and the rename would carry that over.
     */
    private static Path createTemporary(Path target) throws IOException {
        Path dir = target.getParent();
        String name = target.getFileName().toString();
        // Keeps the temporary name within the usual 255-byte limit.
        String base = "." + (name.length() > 200 ? name.substring(0, 200) : name) + ".";
        for (int attempt = 0; ; attempt++) {
            Path temp = dir.resolve(base + Long.toHexString(ThreadLocalRandom.current().nextLong()) + ".tmp");
            try {
                return Files.createFile(temp);
            } catch (FileAlreadyExistsException e) {
                if (attempt == 10) {
                    throw e;
                }
            }
        }
    }

    private void ensure(int room) throws IOException {
        if (size + room > buf.length) {
            flush();
        }
    }

    private void flush() throws IOException {
        out.write(buf, 0, size);
        size = 0;
    }

    void writeByte(int b) throws IOException {
        if (size == buf.length) {
            flush();
        }
        buf[size++] = (byte) b;
    }

    /** Writes ASCII text; for headers and comments, not the hot path. */
    void writeAscii(String text) throws IOException {
        for (int i = 0; i < text.length(); i++) {
            writeByte(text.charAt(i));
        }
    }

    void writeLong(long value) throws IOException {
        ensure(LONGEST);
        if (value < 0) {
            buf[size++] = '-';
            if (value == Long.MIN_VALUE) {
                writeAscii("9223372036854775808");
                return;
            }
            value = -value;
        }
        // Digits come out last first: count them, then fill from the right.
        int digits = 1;
        for (long rest = value / 10; rest != 0; rest /= 10) {
            digits++;
        }
        int i = size + digits;
        size = i;
        do {
            long quotient = value / 10;
            buf[--i] = (byte) ('0' + (value - 10 * quotient));
            value = quotient;
        } while (value != 0);
    }

    /**
     * Writes a finite double so that {@link Double#parseDouble} and the readers give back the
     * same bits: integral values as integers ("-0" keeps the sign of zero), others through
     * {@link Double#toString(double)}, whose digits always round-trip.
     */
    void writeDouble(double value) throws IOException {
        if (value == 0) {
            writeAscii(Double.doubleToRawLongBits(value) < 0 ? "-0" : "0");
        } else if (value == Math.rint(value) && Math.abs(value) < EXACT_LONGS) {
            writeLong((long) value);
        } else {
            String text = Double.toString(value);
            ensure(LONGEST);
            for (int i = 0; i < text.length(); i++) {
                buf[size++] = (byte) text.charAt(i);
            }
        }
    }
}
