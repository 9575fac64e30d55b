package ifold.mesh.io;

import ifold.io.Workers;
import ifold.mesh.PolygonSoup;
import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.MappedByteBuffer;
import java.nio.channels.FileChannel;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.util.List;
import java.util.concurrent.Future;

/**
 * Reads a big OBJ file on every core ({@link Workers}), or says that it cannot: the OBJ
 * counterpart of {@link ParallelOffReader}, with its gates and its cuts.
 *
 * <p>An OBJ statement is a line, unless a backslash continues it, and its first token says
 * what it is. So the file is cut at line breaks into pieces, and each piece's line breaks,
 * {@code v} statements (vertices) and {@code f} statements (faces, and the references after
 * them: corners) are counted in parallel by a plain scan of bytes. The running totals tell
 * every piece the number of its first line and the index of its first vertex, which is where
 * its vertices go in the one shared array and what its negative indices count back from.
 * Then the pieces are parsed in parallel by {@link ObjReader} itself, faces into a soup per
 * piece, sized exactly by the counts, which are joined in order; the positive indices are
 * checked on the joined soup as the whole-file reader checks them.
 *
 * <p>Anything unusual — a line continued by a backslash, binary bytes, MSVC's {@code 1.#INF},
 * counts that disagree, any error at all — gives up and leaves the file to the whole-file
 * reader, which reads it, or refuses it with its own message naming the line, exactly as it
 * always has: errors never depend on the number of threads.
 */
final class ParallelObjReader {
    private ParallelObjReader() {
    }

    /**
     * The soup of {@code file}, read in parallel; null where the file is small, where there is
     * one thread, or where it is anything but a plain, valid OBJ file up to its positive
     * indices: then read it with the whole-file reader.
     *
     * @throws MeshFormatException for a face that names a vertex past the last, as the
     *     whole-file reader says it
     */
    static PolygonSoup read(Path file) throws IOException, MeshFormatException {
        int threads = ParallelOffReader.threadsFor(file);
        if (threads == 0) {
            return null;
        }
        try (FileChannel channel = FileChannel.open(file, StandardOpenOption.READ)) {
            long size = channel.size();
            long textStart = textStart(channel);
            if (textStart < 0) {
                return null;
            }
            long[] cuts = ParallelOffReader.cuts(channel, textStart, size, threads * ParallelOffReader.PIECES_PER_THREAD);
            int pieces = cuts.length - 1;
            List<Future<Count>> counting = ParallelOffReader.eachPiece(cuts, (k, from, to) -> count(channel, from, to));
            int[] firstLine = new int[pieces];
            int[] firstVertex = new int[pieces + 1];
            int[] faces = new int[pieces];
            int[] corners = new int[pieces];
            long line = 1;
            long vertexCount = 0;
            long faceCount = 0;
            long cornerCount = 0;
            boolean plain = true;
            for (int k = 0; k < pieces; k++) {
                Count count = Workers.await(counting.get(k));
                plain &= count.plain;
                firstLine[k] = (int) Math.min(line, Integer.MAX_VALUE);
                firstVertex[k] = (int) Math.min(vertexCount, Integer.MAX_VALUE);
                faces[k] = (int) Math.min(count.faces, Integer.MAX_VALUE);
                corners[k] = (int) Math.min(count.corners, Integer.MAX_VALUE);
                line += count.lineBreaks;
                vertexCount += count.vertices;
                faceCount += count.faces;
                cornerCount += count.corners;
            }
            // No faces is an error, and the limits are those of a soup's arrays: the
            // whole-file reader says what is wrong.
            if (!plain || faceCount == 0 || line > Integer.MAX_VALUE || 3 * vertexCount > Integer.MAX_VALUE - 8
                    || faceCount + 1 > Integer.MAX_VALUE - 8 || cornerCount > Integer.MAX_VALUE - 8) {
                return null;
            }
            firstVertex[pieces] = (int) vertexCount;
            double[] coordinates = new double[3 * (int) vertexCount];
            List<Future<PolygonSoup>> parsing = ParallelOffReader.eachPiece(cuts, (k, from, to) -> {
                ByteTokenizer tokens = ByteTokenizer.region(file, new ParallelOffReader.PieceStream(channel, from, to), from,
                        firstLine[k], true);
                try {
                    return ObjReader.readStatements(tokens, coordinates, firstVertex[k], firstVertex[k + 1], faces[k], corners[k]);
                } catch (MeshFormatException e) {
                    return null; // read whole, to be refused with the whole-file reader's message
                }
            });
            List<PolygonSoup> faceParts = ParallelOffReader.awaitPieces(parsing);
            if (faceParts == null) {
                return null;
            }
            PolygonSoup soup = PolygonSoup.joined(coordinates, (int) vertexCount, faceParts);
            ObjReader.checkIndices(soup, file);
            return soup;
        }
    }

    /**
     * Where the text of the file starts: past a UTF-8 byte order mark, which the tokenizer
     * skips; -1 for a UTF-16 or UTF-32 one, which it refuses.
     */
    private static long textStart(FileChannel channel) throws IOException {
        ByteBuffer mark = ByteBuffer.allocate(3);
        while (mark.hasRemaining() && channel.read(mark, mark.position()) > 0) {
            // a read may return fewer bytes than asked
        }
        int n = mark.position();
        int b0 = n > 0 ? mark.get(0) & 0xFF : -1;
        int b1 = n > 1 ? mark.get(1) & 0xFF : -1;
        int b2 = n > 2 ? mark.get(2) & 0xFF : -1;
        if ((b0 == 0xFF && b1 == 0xFE) || (b0 == 0xFE && b1 == 0xFF)) {
            return -1;
        }
        return b0 == 0xEF && b1 == 0xBB && b2 == 0xBF ? 3 : 0;
    }

    /**
     * A piece counted: its line breaks, {@code v} and {@code f} statements, the references
     * after its {@code f}s, and whether it holds only what the counting understands.
     */
    private record Count(long lineBreaks, long vertices, long faces, long corners, boolean plain) {
    }

    /**
     * Counts the line breaks (CR, LF or CRLF), vertices, faces and corners in [from, to), as
     * {@link ByteTokenizer} splits an OBJ file, by its classes of bytes: {@code #} starts a
     * comment, space, tab, vertical tab and form feed separate tokens, and so does a backslash,
     * which also continues the statement on the next line when nothing but blanks and a
     * comment follow it. A statement is a vertex when its first token is {@code v}, a face
     * when it is {@code f} (or the old {@code fo}), and each later token of a face is a
     * corner. A continued line, control bytes (binary content for the tokenizer) and a
     * {@code #} right after a point (MSVC's {@code 1.#INF}, one token to the tokenizer) make
     * the piece not plain.
     */
    private static Count count(FileChannel channel, long from, long to) throws IOException {
        MappedByteBuffer map = channel.map(FileChannel.MapMode.READ_ONLY, from, to - from);
        int n = (int) (to - from);
        long breaks = 0;
        long vertices = 0;
        long faces = 0;
        long corners = 0;
        boolean comment = false;
        boolean afterCr = false;
        boolean continuation = false;
        // The line being scanned: inside a token or not, tokens started, its first token's
        // length and first two bytes, and whether that token made it a face.
        boolean inToken = false;
        int tokens = 0;
        int firstLength = 0;
        byte first0 = 0;
        byte first1 = 0;
        boolean face = false;
        byte previous = '\n';
        for (int i = 0; i < n; i++) {
            byte c = map.get(i);
            byte kind = c == '\\' ? ByteTokenizer.SPACE : ByteTokenizer.CLASSES[c & 0xFF];
            if (kind == ByteTokenizer.PART) {
                afterCr = false;
                if (!comment) {
                    if (!inToken) {
                        inToken = true;
                        tokens++;
                        continuation = false;
                        if (face) {
                            corners++;
                        }
                    }
                    if (tokens == 1) {
                        if (firstLength == 0) {
                            first0 = c;
                        } else if (firstLength == 1) {
                            first1 = c;
                        }
                        firstLength++;
                    }
                }
                previous = c;
                continue;
            }
            // Any other byte ends a token: where it is the first, it says what the statement is.
            if (inToken && tokens == 1) {
                if (isVertex(firstLength, first0)) {
                    vertices++;
                } else if (isFace(firstLength, first0, first1)) {
                    faces++;
                    face = true;
                }
            }
            inToken = false;
            if (kind == ByteTokenizer.SPACE) {
                afterCr = false;
                continuation |= c == '\\' && !comment;
            } else if (kind == ByteTokenizer.LF && afterCr) {
                afterCr = false; // the LF of a CRLF: one line break
            } else if (kind == ByteTokenizer.LF || kind == ByteTokenizer.CR) {
                if (continuation) {
                    return new Count(breaks, vertices, faces, corners, false);
                }
                breaks++;
                tokens = 0;
                firstLength = 0;
                face = false;
                comment = false;
                afterCr = kind == ByteTokenizer.CR;
            } else if (kind == ByteTokenizer.HASH) {
                afterCr = false;
                if (!comment && previous == '.') {
                    return new Count(breaks, vertices, faces, corners, false);
                }
                comment = true;
            } else if (!comment || c == 0) { // binary content; in a comment only a NUL is
                return new Count(breaks, vertices, faces, corners, false);
            }
            previous = c;
        }
        if (inToken && tokens == 1) {
            // The last line of the file, without a line break, is one token: a bare "v" or "f",
            // an error the parser reports, but counted as it parses it.
            if (isVertex(firstLength, first0)) {
                vertices++;
            } else if (isFace(firstLength, first0, first1)) {
                faces++;
            }
        }
        return new Count(breaks, vertices, faces, corners, true);
    }

    /** Whether a statement whose first token has {@code length} bytes and starts with {@code first0} is a vertex, as {@link ObjReader} reads it. */
    private static boolean isVertex(int length, byte first0) {
        return length == 1 && first0 == 'v';
    }

    /** Whether a statement whose first token has {@code length} bytes and starts with {@code first0 first1} is a face: "f", or the old "fo". */
    private static boolean isFace(int length, byte first0, byte first1) {
        return first0 == 'f' && (length == 1 || length == 2 && first1 == 'o');
    }
}
