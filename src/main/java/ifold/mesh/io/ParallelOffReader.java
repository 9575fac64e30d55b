package ifold.mesh.io;

import ifold.io.Workers;
import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Future;

/**
 * Reads a big OFF file on every core ({@link Workers}), or says that it cannot.
 *
 * <p>OFF records are found by counting: after the header, the first V non-blank lines are the
 * vertices and the next F the faces, as long as every face is written on one line, which is
 * how every writer writes them. So the file is cut at line breaks into pieces, each piece's
 * line breaks and non-blank lines are counted in parallel (a plain scan of bytes), and the
 * running totals tell every piece the number of its first line and of its first record. Then
 * the pieces are parsed in parallel by {@link OffReader} itself, vertices straight into one
 * array, faces into a soup per piece, which are joined in order.
 *
 * <p>Anything unusual — a face over several lines, counts that disagree, binary bytes, MSVC's
 * {@code 1.#INF}, any error at all — gives up and leaves the file to the whole-file reader,
 * which reads it, or refuses it with its own message naming the line, exactly as it always
 * has: errors never depend on the number of threads.
 */
final class ParallelOffReader {
    /** Files smaller than this are read whole: a second thread does not pay for itself. */
    static final long MIN_BYTES = 1 << 22;

    /**
     * The fewest threads it reads with unless {@code ifold.threads} asks: on two cores it is
     * slower in a fresh JVM (bench/run: 0.36 s against 0.24 s read whole for 1.4M triangles,
     * though 1.4 times as fast once warm), as the compiler threads warming the parser up take
     * the second core.
     */
    static final int MIN_THREADS = 3;

    /** Pieces per thread: enough to even out pieces that parse at different speeds. */
    static final int PIECES_PER_THREAD = 4;

    private ParallelOffReader() {
    }

    /**
     * The soup of {@code file}, read in parallel; null where the file is small, where there is
     * one thread, or where it is anything but a plain, valid OFF file: then read it with the
     * whole-file reader.
     */
    static PolygonSoup read(Path file) throws IOException {
        int threads = threadsFor(file);
        if (threads == 0) {
            return null;
        }
        OffReader.Preamble preamble;
        try {
            preamble = OffReader.preamble(file);
        } catch (MeshFormatException e) {
            return null;
        }
        if (preamble == null || (long) preamble.vertexCount() + preamble.faceCount() > Integer.MAX_VALUE
                || 3L * preamble.vertexCount() > Integer.MAX_VALUE - 8) {
            return null;
        }
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = channel.size();
            long[] cuts = cuts(channel, preamble.recordsOffset(), size, threads * PIECES_PER_THREAD);
            int pieces = cuts.length - 1;
            List<Future<Count>> counting = eachPiece(cuts, (k, from, to) -> count(channel, from, to));
            int[] firstLine = new int[pieces];
            int[] firstRecord = new int[pieces + 1];
            long line = preamble.recordsLine();
            long records = 0;
            boolean plain = true;
            for (int k = 0; k < pieces; k++) {
                Count count = Workers.await(counting.get(k));
                plain &= count.plain;
                firstLine[k] = (int) Math.min(line, Integer.MAX_VALUE);
                firstRecord[k] = (int) Math.min(records, Integer.MAX_VALUE);
                line += count.lineBreaks;
                records += count.records;
            }
            if (!plain || records != (long) preamble.vertexCount() + preamble.faceCount() || line > Integer.MAX_VALUE) {
                return null;
            }
            firstRecord[pieces] = (int) records;
            double[] coordinates = new double[3 * preamble.vertexCount()];
            List<Future<PolygonSoup>> parsing = eachPiece(cuts, (k, from, to) -> {
                ByteTokenizer tokens = ByteTokenizer.region(file, new PieceStream(channel, from, to), from, firstLine[k], false);
                try {
                    return OffReader.readRecords(tokens, preamble, coordinates, firstRecord[k], firstRecord[k + 1]);
                } catch (MeshFormatException e) {
                    return null; // read whole, to be refused with the whole-file reader's message
                }
            });
            List<PolygonSoup> faces = awaitPieces(parsing);
            return faces == null ? null : PolygonSoup.joined(coordinates, preamble.vertexCount(), faces);
        }
    }

    /** What is done with piece k of a file, the bytes [from, to). */
    interface PieceTask<T> {
        T run(int k, long from, long to) throws Exception;
    }

    /** {@code task} on each piece between the cuts, on the workers; their results in order. */
    static <T> List<Future<T>> eachPiece(long[] cuts, PieceTask<T> task) {
        List<Future<T>> results = new ArrayList<>();
        for (int k = 0; k + 1 < cuts.length; k++) {
            int piece = k;
            long from = cuts[k];
            long to = cuts[k + 1];
            results.add(Workers.pool().submit(() -> task.run(piece, from, to)));
        }
        return results;
    }

    /**
     * The soups of the pieces, in order, once all are parsed; null as soon as one gave up (the
     * file is then read whole), the others left to finish: not interrupted, as an interrupt
     * closes the channel they share.
     */
    static List<PolygonSoup> awaitPieces(List<Future<PolygonSoup>> parsing) throws IOException {
        List<PolygonSoup> soups = new ArrayList<>();
        for (Future<PolygonSoup> piece : parsing) {
            PolygonSoup soup = Workers.await(piece);
            if (soup == null) {
                for (Future<PolygonSoup> rest : parsing) {
                    rest.cancel(false);
                }
                return null;
            }
            soups.add(soup);
        }
        return soups;
    }

    /**
     * How many threads to read {@code file} with in pieces, or 0 where it is to be read whole:
     * where it is no regular file, is smaller than {@code ifold.parallelReadBytes} (default
     * {@link #MIN_BYTES}), or there are fewer threads than {@link #MIN_THREADS} (2 where
     * {@code ifold.threads} asks for them).
     */
    static int threadsFor(Path file) throws IOException {
        int threads = Workers.threads();
        if (threads < (System.getProperty("ifold.threads") != null ? 2 : MIN_THREADS) || !Files.isRegularFile(file)
                || Files.size(file) < Long.getLong("ifold.parallelReadBytes", MIN_BYTES)) {
            return 0;
        }
        return threads;
    }

    /**
     * Where to cut [from, size) into about {@code pieces} pieces: each cut just after a line
     * break (after the LF of a CRLF, never between its two bytes).
     */
    static long[] cuts(FileChannel channel, long from, long size, int pieces) throws IOException {
        long[] cuts = new long[pieces + 1];
        cuts[0] = from;
        int n = 1;
        ByteBuffer window = ByteBuffer.allocate(1 << 16);
        for (int k = 1; k < pieces; k++) {
            long target = Math.max(cuts[n - 1], from + (size - from) * k / pieces);
            long cut = nextLineStart(channel, target, size, window);
            if (cut > cuts[n - 1] && cut < size) {
                cuts[n++] = cut;
            }
        }
        cuts[n++] = size;
        return java.util.Arrays.copyOf(cuts, n);
    }

    /** The offset just after the first line break at or after {@code at}, or {@code size}. */
    private static long nextLineStart(FileChannel channel, long at, long size, ByteBuffer window) throws IOException {
        long position = at;
        while (position < size) {
            window.clear();
            int n = channel.read(window, position);
            if (n <= 0) {
                return size;
            }
            byte[] b = window.array();
            for (int i = 0; i < n; i++) {
                if (b[i] == '\n') {
                    return position + i + 1;
                }
                if (b[i] == '\r') {
                    // The LF of a CRLF goes with its CR; it may lie in the next window.
                    if (i + 1 < n) {
                        return position + i + 1 + (b[i + 1] == '\n' ? 1 : 0);
                    }
                    ByteBuffer next = ByteBuffer.allocate(1);
                    boolean lf = channel.read(next, position + i + 1) == 1 && next.get(0) == '\n';
                    return position + i + 1 + (lf ? 1 : 0);
                }
            }
            position += n;
        }
        return size;
    }

    /** A piece counted: its line breaks, its non-blank lines, and whether it holds only what the counting understands. */
    private record Count(long lineBreaks, long records, boolean plain) {
    }

    /**
     * Counts the line breaks (CR, LF or CRLF) and the lines with a token in [from, to), as
     * {@link ByteTokenizer} splits them, by its classes of bytes: {@code #} starts a comment,
     * space, tab, vertical tab and form feed separate tokens. Control bytes (binary content
     * for the tokenizer) and a {@code #} right after a point (MSVC's {@code 1.#INF}, one token
     * to the tokenizer) make the piece not plain.
     */
    private static Count count(FileChannel channel, long from, long to) throws IOException {
        java.nio.MappedByteBuffer map = channel.map(FileChannel.MapMode.READ_ONLY, from, to - from);
        int n = (int) (to - from);
        long breaks = 0;
        long records = 0;
        boolean token = false;
        boolean comment = false;
        boolean afterCr = false;
        byte previous = '\n';
        for (int i = 0; i < n; i++) {
            byte c = map.get(i);
            byte kind = ByteTokenizer.CLASSES[c & 0xFF];
            if (kind == ByteTokenizer.PART) {
                afterCr = false;
                token |= !comment;
            } else if (kind == ByteTokenizer.SPACE) {
                afterCr = false;
            } else if (kind == ByteTokenizer.LF && afterCr) {
                afterCr = false; // the LF of a CRLF: one line break
            } else if (kind == ByteTokenizer.LF || kind == ByteTokenizer.CR) {
                breaks++;
                if (token) {
                    records++;
                }
                token = false;
                comment = false;
                afterCr = kind == ByteTokenizer.CR;
            } else if (kind == ByteTokenizer.HASH) {
                afterCr = false;
                if (!comment && previous == '.') {
                    return new Count(breaks, records, false);
                }
                comment = true;
            } else if (!comment || c == 0) { // binary content; in a comment only a NUL is
                return new Count(breaks, records, false);
            }
            previous = c;
        }
        if (token) {
            records++; // the last line of the file, without a line break
        }
        return new Count(breaks, records, true);
    }

    /** The bytes of [from, to) of a file, read at their positions so that pieces share one channel. */
    static final class PieceStream extends InputStream {
        private final FileChannel channel;
        private long position;
        private final long end;

        PieceStream(FileChannel channel, long from, long to) {
            this.channel = channel;
            this.position = from;
            this.end = to;
        }

        @Override
        public int read(byte[] b, int off, int len) throws IOException {
            if (position >= end) {
                return -1;
            }
            int n = channel.read(ByteBuffer.wrap(b, off, (int) Math.min(len, end - position)), position);
            if (n > 0) {
                position += n;
            }
            return n;
        }

        @Override
        public int read() throws IOException {
            byte[] one = new byte[1];
            return read(one, 0, 1) == 1 ? one[0] & 0xFF : -1;
        }
    }
}
