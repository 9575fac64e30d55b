package ifold.mesh.io;

import ifold.io.AtomicFile;
import ifold.io.Workers;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.concurrent.Future;

/**
 * ASCII text into a 1 MiB byte buffer, for the writers: integers by hand, doubles so that they
 * read back bit for bit. Also the atomic write both writers go through.
 *
 * <p>The vertex and face lines of a big model are formatted in blocks on every core
 * ({@link #writeLines}) and written in order by one thread: formatting doubles is most of the
 * cost of a write, and each block comes out the same whatever thread formats it, so the file
 * is the same byte for byte whatever the number of threads.
 */
final class AsciiOutput {
    private static final int BUFFER_SIZE = 1 << 20;
    /** Room for the longest thing written in one go: a long, or a double as Double.toString prints it. */
    private static final int LONGEST = 32;

    /** The 2^53 bound: integral doubles below it are exactly the longs of the same value. */
    private static final double EXACT_LONGS = 9007199254740992.0;

    /** Lines formatted together by one thread: a block of vertex lines is about 1 MB. */
    static final int BLOCK_LINES = 1 << 14;
    /** A block's first buffer, doubled as it needs: faces' lines fit, vertices' take one doubling at most. */
    private static final int BLOCK_CAPACITY = 1 << 19;

    /** Where full buffers go; null for a block, whose buffer grows instead. */
    private final OutputStream out;
    private byte[] buf;
    private int size;

    private AsciiOutput(OutputStream out) {
        this.out = out;
        this.buf = new byte[BUFFER_SIZE];
    }

    /** A block of lines in memory. */
    private AsciiOutput(int capacity) {
        this.out = null;
        this.buf = new byte[capacity];
    }

    /** Writes line {@code i} of a run of lines. */
    interface Lines {
        void write(AsciiOutput out, int i) throws IOException;
    }

    /**
     * Writes lines 0 .. count - 1, formatted in blocks of {@link #BLOCK_LINES} on
     * {@link Workers#threads()} threads and written in order. A failure in any block is thrown
     * as the sequential write would throw it: the blocks are taken in order, so the first
     * failing line's exception comes out.
     */
    void writeLines(int count, Lines lines) throws IOException {
        int threads = Workers.threads();
        if (threads == 1 || count <= BLOCK_LINES) {
            for (int i = 0; i < count; i++) {
                lines.write(this, i);
            }
            return;
        }
        flush(); // what is buffered comes before the blocks
        ArrayDeque<Future<AsciiOutput>> pending = new ArrayDeque<>();
        int next = 0;
        try {
            while (next < count || !pending.isEmpty()) {
                // A few blocks ahead of the writer: enough to keep every thread busy, few enough to bound memory.
                while (next < count && pending.size() < 2 * threads) {
                    int from = next;
                    int to = Math.min(count, from + BLOCK_LINES);
                    pending.add(Workers.pool().submit(() -> {
                        AsciiOutput block = new AsciiOutput(BLOCK_CAPACITY);
                        for (int i = from; i < to; i++) {
                            lines.write(block, i);
                        }
                        return block;
                    }));
                    next = to;
                }
                AsciiOutput block = Workers.await(pending.poll());
                out.write(block.buf, 0, block.size);
            }
        } finally {
            for (Future<AsciiOutput> block : pending) {
                block.cancel(true);
            }
        }
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
        if (out == null) {
            buf = java.util.Arrays.copyOf(buf, 2 * buf.length);
            return;
        }
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
        if (value >= 0 && value <= Integer.MAX_VALUE) {
            writeInt((int) value); // indices and counts: int arithmetic is much the cheaper
            return;
        }
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

    /** The tens and the ones digit of 0 .. 99, for writing two digits per division. */
    private static final byte[] TENS = new byte[100];
    private static final byte[] ONES = new byte[100];

    static {
        for (int i = 0; i < 100; i++) {
            TENS[i] = (byte) ('0' + i / 10);
            ONES[i] = (byte) ('0' + i % 10);
        }
    }

    /** Writes a value of 0 or more: the face lines of a big model are mostly these. */
    private void writeInt(int value) throws IOException {
        ensure(LONGEST);
        int digits = value < 10 ? 1 : value < 100 ? 2 : value < 1000 ? 3 : value < 10_000 ? 4 : value < 100_000 ? 5
                : value < 1_000_000 ? 6 : value < 10_000_000 ? 7 : value < 100_000_000 ? 8 : value < 1_000_000_000 ? 9 : 10;
        int i = size + digits;
        size = i;
        while (value >= 100) {
            int quotient = value / 100;
            int pair = value - 100 * quotient;
            buf[--i] = ONES[pair];
            buf[--i] = TENS[pair];
            value = quotient;
        }
        if (value >= 10) {
            buf[--i] = ONES[value];
            buf[--i] = TENS[value];
        } else {
            buf[--i] = (byte) ('0' + value);
        }
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
