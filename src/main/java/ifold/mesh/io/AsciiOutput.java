package ifold.mesh.io;

import java.io.IOException;
import java.io.OutputStream;
import ifold.io.AtomicFile;
import java.nio.file.Path;

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

    /** Writes {@code file} all or nothing, forced to disk (see {@link AtomicFile}). */
    static void writeAtomically(Path file, Content content) throws IOException {
        AtomicFile.write(file, stream -> {
            AsciiOutput out = new AsciiOutput(stream);
            content.writeTo(out);
            out.flush();
        }, true);
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
     * same bits: integral values as integers ("-0" keeps the sign of zero), others as the
     * shortest decimal that round-trips.
     */
    void writeDouble(double value) throws IOException {
        if (value == 0) {
            writeAscii(Double.doubleToRawLongBits(value) < 0 ? "-0" : "0");
        } else if (value == Math.rint(value) && Math.abs(value) < EXACT_LONGS) {
            writeLong((long) value);
        } else {
            // The shortest digits that read back as the same double (Schubfach, jackson-core's
            // writer): exact as Double.toString, and a good deal faster.
            String text = com.fasterxml.jackson.core.io.NumberOutput.toString(value, true);
            ensure(LONGEST);
            for (int i = 0; i < text.length(); i++) {
                buf[size++] = (byte) text.charAt(i);
            }
        }
    }
}
