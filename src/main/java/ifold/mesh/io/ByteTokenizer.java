package ifold.mesh.io;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * Splits a text model file into whitespace-separated tokens, straight from bytes: the one
 * tokenizer behind {@link OffReader} and {@link ObjReader}.
 *
 * <p>{@link #advance()} reports a token, an end of line or the end of the file, so a reader can
 * work by lines (OBJ statements, OFF vertex records) or across them (OFF face records). A
 * token lives in {@link #buffer()} between {@link #tokenStart()} and {@link #tokenEnd()} until
 * the next call; nothing is allocated per token. {@code #} starts a comment wherever a token
 * could start or end, CR, LF and CRLF all end a line, and a NUL or other control byte stops
 * the read as binary content.
 *
 * <p>Numbers are parsed in place by {@link DecimalParser}.
 */
final class ByteTokenizer implements Closeable {
    /** What {@link #advance()} found. */
    static final int EOF = -1;
    static final int EOL = 0;
    static final int TOKEN = 1;

    /** Refill size; also the longest token accepted, which keeps garbage input from growing memory. */
    static final int BUFFER_SIZE = 1 << 16;

    // Byte classes: what each byte value means to the tokenizer (and to the counting of
    // ParallelOffReader and ParallelObjReader, which must split lines exactly as it does).
    static final byte PART = 0;
    static final byte SPACE = 1;
    static final byte LF = 2;
    static final byte CR = 3;
    static final byte HASH = 4;
    static final byte BINARY = 5;
    private static final byte BACKSLASH = 6;

    /** The class of each byte value, by {@code b & 0xFF}; where a backslash is a byte like any other (OFF). Never written after the class is loaded. */
    static final byte[] CLASSES = new byte[256];

    static {
        for (int b = 0; b < 32; b++) {
            CLASSES[b] = BINARY;
        }
        CLASSES[0x7F] = BINARY;
        CLASSES[' '] = SPACE;
        CLASSES['\t'] = SPACE;
        CLASSES[0x0B] = SPACE; // vertical tab and form feed are whitespace to C's isspace, so some writers emit them
        CLASSES[0x0C] = SPACE;
        CLASSES['\n'] = LF;
        CLASSES['\r'] = CR;
        CLASSES['#'] = HASH;
    }

    private final Path file;
    private final InputStream in;
    /** Byte classes in use: {@link #CLASSES}, or a copy where a backslash continues a line. */
    private final byte[] classes;
    /** Bytes buf[pos .. limit) are read from the file but not yet consumed. */
    private final byte[] buf = new byte[BUFFER_SIZE];
    private int pos;
    private int limit;
    /** Where in the file buf[0] lies. */
    private long bufferOffset;
    private boolean endOfInput;
    /** The line pos is on, 1-based. */
    private int line = 1;
    /** A CR just ended a line, so an LF right after it belongs to the same line break. */
    private boolean afterCr;
    /** A backslash was seen since the last token; the next line break only continues the line. */
    private boolean continuation;

    private int tokenStart;
    private int tokenEnd;
    private int tokenLine;
    /** The line of the last token, kept across ends of line to report where a file stops. */
    private int lastTokenLine;

    /**
     * Opens {@code file} for reading. Rejects an empty file, and UTF-16 or UTF-32 content by its
     * byte order mark; skips a UTF-8 byte order mark.
     *
     * @param backslashContinuesLine whether a backslash before a line break joins two lines (OBJ)
     */
    static ByteTokenizer open(Path file, boolean backslashContinuesLine) throws IOException, MeshFormatException {
        InputStream in = Files.newInputStream(file);
        try {
            ByteTokenizer tokenizer = new ByteTokenizer(file, in, backslashContinuesLine);
            tokenizer.start();
            return tokenizer;
        } catch (IOException | MeshFormatException | RuntimeException e) {
            in.close();
            throw e;
        }
    }

    /**
     * A tokenizer over part of a file that starts at the beginning of line {@code firstLine}
     * at file offset {@code offset}: {@code in} gives its bytes (a file of its own, no byte
     * order mark). For reading a file in pieces.
     *
     * @param backslashContinuesLine as for {@link #open}: the same as the whole file is read with
     */
    static ByteTokenizer region(Path file, InputStream in, long offset, int firstLine, boolean backslashContinuesLine) {
        ByteTokenizer tokenizer = new ByteTokenizer(file, in, backslashContinuesLine);
        tokenizer.bufferOffset = offset;
        tokenizer.line = firstLine;
        return tokenizer;
    }

    private ByteTokenizer(Path file, InputStream in, boolean backslashContinuesLine) {
        this.file = file;
        this.in = in;
        if (backslashContinuesLine) {
            classes = CLASSES.clone();
            classes['\\'] = BACKSLASH;
        } else {
            classes = CLASSES;
        }
    }

    private void start() throws IOException, MeshFormatException {
        if (!fill(0)) {
            throw new MeshFormatException(file, 0, "empty file");
        }
        // Three bytes decide the marks looked for (UTF-32's start with them or with NULs).
        while (limit < 3 && fill(0)) {
            // keep reading
        }
        int b0 = limit > 0 ? buf[0] & 0xFF : -1;
        int b1 = limit > 1 ? buf[1] & 0xFF : -1;
        int b2 = limit > 2 ? buf[2] & 0xFF : -1;
        if ((b0 == 0xFF && b1 == 0xFE) || (b0 == 0xFE && b1 == 0xFF)) {
            throw binary(1);
        }
        if (b0 == 0xEF && b1 == 0xBB && b2 == 0xBF) {
            pos = 3; // a UTF-8 mark is harmless: the rest is still text
        }
    }

    /**
     * Moves to the next token, end of line or end of file. Comments and blank space are
     * skipped; each end of line is reported once, so blank lines come back as repeated EOLs.
     */
    int advance() throws IOException, MeshFormatException {
        for (;;) {
            if (pos == limit && !fill(limit)) {
                return EOF;
            }
            int b = buf[pos] & 0xFF;
            switch (classes[b]) {
                case SPACE:
                    pos++;
                    afterCr = false;
                    break;
                case LF:
                    pos++;
                    if (afterCr) {
                        afterCr = false; // the LF of a CRLF: the CR already ended the line
                        break;
                    }
                    line++;
                    if (continuation) {
                        continuation = false;
                        break;
                    }
                    return EOL;
                case CR:
                    pos++;
                    afterCr = true;
                    line++;
                    if (continuation) {
                        continuation = false;
                        break;
                    }
                    return EOL;
                case HASH:
                    afterCr = false;
                    skipComment();
                    break;
                case BACKSLASH:
                    pos++;
                    afterCr = false;
                    continuation = true;
                    break;
                case BINARY:
                    throw binary(line);
                default:
                    afterCr = false;
                    continuation = false;
                    scanToken();
                    return TOKEN;
            }
        }
    }

    /** Skips to the end of the line, leaving the line break itself for {@link #advance()}. */
    private void skipComment() throws IOException, MeshFormatException {
        for (;;) {
            while (pos < limit) {
                byte c = classes[buf[pos] & 0xFF];
                if (c == LF || c == CR) {
                    return;
                }
                // A comment is free text, but a NUL still means the file is not text at all.
                if (buf[pos] == 0) {
                    throw binary(line);
                }
                pos++;
            }
            if (!fill(limit)) {
                return;
            }
        }
    }

    /** Reads the token starting at pos; on return it lies in buf[tokenStart .. tokenEnd). */
    private void scanToken() throws IOException, MeshFormatException {
        tokenStart = pos;
        tokenLine = line;
        lastTokenLine = line;
        pos++;
        for (;;) {
            while (pos < limit) {
                byte c = classes[buf[pos] & 0xFF];
                if (c == PART) {
                    pos++;
                } else if (c == HASH && isMsvcNonFinite()) {
                    // "1.#IND", "-1.#INF": MSVC's NaN and infinity. Keeping them whole lets the
                    // number parser reject them instead of reading "1." and hiding the comment.
                    pos++;
                } else if (c == BINARY) {
                    // Caught here, not at the next advance(), so that "O\0F\0F\0" (UTF-16)
                    // is reported as such rather than as a bad token "O".
                    throw binary(line);
                } else {
                    tokenEnd = pos;
                    return;
                }
            }
            if (!fill(tokenStart)) {
                tokenEnd = pos;
                return;
            }
        }
    }

    /** Whether the token so far ends in a digit and a point, as MSVC prints "1.#INF". */
    private boolean isMsvcNonFinite() {
        return pos - tokenStart >= 2 && buf[pos - 1] == '.' && buf[pos - 2] >= '0' && buf[pos - 2] <= '9';
    }

    /**
     * Reads more bytes, keeping buf[keepFrom .. limit) at the start of the buffer.
     *
     * @return false at the end of the file
     */
    private boolean fill(int keepFrom) throws IOException, MeshFormatException {
        if (endOfInput) {
            return false;
        }
        int keep = limit - keepFrom;
        if (keepFrom > 0) {
            bufferOffset += keepFrom;
            System.arraycopy(buf, keepFrom, buf, 0, keep);
            pos -= keepFrom;
            tokenStart -= keepFrom;
            limit = keep;
        }
        if (limit == buf.length) {
            throw new MeshFormatException(file, line, "a token longer than " + BUFFER_SIZE
                    + " bytes: binary or UTF-16 content, expected a text OFF/OBJ file");
        }
        int n;
        do {
            n = in.read(buf, limit, buf.length - limit);
        } while (n == 0);
        if (n < 0) {
            endOfInput = true;
            return false;
        }
        limit += n;
        return true;
    }

    /** Skips the rest of the current line, tokens included, up to but not past its end. */
    int skipLine() throws IOException, MeshFormatException {
        int t;
        do {
            t = advance();
        } while (t == TOKEN);
        return t;
    }

    /** Moves to the next token, passing over ends of line; returns TOKEN or EOF. */
    int advanceAcrossLines() throws IOException, MeshFormatException {
        int t;
        do {
            t = advance();
        } while (t == EOL);
        return t;
    }

    /**
     * Right after {@link #advance()} reported an end of line: the file offset where the next
     * line begins (past the LF of a CRLF) and that line's number.
     */
    long nextLineOffset() throws IOException, MeshFormatException {
        if (afterCr && (pos < limit || fill(limit)) && buf[pos] == '\n') {
            pos++;
            afterCr = false;
        }
        return bufferOffset + pos;
    }

    /** The line {@link #advance()} is on: after an end of line, the next one. */
    int line() {
        return line;
    }

    byte[] buffer() {
        return buf;
    }

    int tokenStart() {
        return tokenStart;
    }

    int tokenEnd() {
        return tokenEnd;
    }

    /** The line of the current token. */
    int tokenLine() {
        return tokenLine;
    }

    /** The line of the last token read, or 1 if none: where a truncated file stops. */
    int lastTokenLine() {
        return lastTokenLine > 0 ? lastTokenLine : 1;
    }

    /** Whether the current token is exactly the ASCII text {@code s}. */
    boolean tokenIs(String s) {
        int n = tokenEnd - tokenStart;
        if (n != s.length()) {
            return false;
        }
        for (int i = 0; i < n; i++) {
            if (buf[tokenStart + i] != s.charAt(i)) {
                return false;
            }
        }
        return true;
    }

    /** The current token parsed as a decimal number; see {@link DecimalParser#parseDouble}. */
    double tokenDouble() {
        return DecimalParser.parseDouble(buf, tokenStart, tokenEnd);
    }

    /** The current token parsed as an integer; see {@link DecimalParser#parseLong}. */
    long tokenLong() {
        return DecimalParser.parseLong(buf, tokenStart, tokenEnd);
    }

    /**
     * The current token as a finite double, or an exception naming the {@code what} (a noun
     * such as "coordinate") that was expected.
     * NaN, infinities in any spelling and numbers too large for a double are refused.
     */
    double finiteDouble(String what) throws MeshFormatException {
        double value = DecimalParser.parseDouble(buf, tokenStart, tokenEnd);
        if (Double.isFinite(value)) {
            return value;
        }
        throw notFinite(what);
    }

    /** The error for a token that did not parse to a finite double: says whether it was a number at all. */
    private MeshFormatException notFinite(String what) {
        String text = tokenText();
        if (isNonFiniteSpelling(text)) {
            return error(tokenLine, what + " '" + text + "' is not a finite number");
        }
        if (Double.isInfinite(DecimalParser.parseDouble(buf, tokenStart, tokenEnd))) {
            return error(tokenLine, what + " '" + text + "' is not a finite number (too large for a double)");
        }
        return error(tokenLine, "expected a " + what + ", found '" + text + "'");
    }

    /** NaN and infinity as C libraries, Java and MSVC print them. */
    private static boolean isNonFiniteSpelling(String text) {
        String t = text.toLowerCase(java.util.Locale.ROOT);
        if (t.startsWith("+") || t.startsWith("-")) {
            t = t.substring(1);
        }
        return t.equals("nan") || t.startsWith("nan(") || t.equals("inf") || t.equals("infinity")
                || t.contains(".#");
    }

    /** The current token as text for a message: at most 40 characters, control bytes escaped. */
    String tokenText() {
        StringBuilder text = new StringBuilder();
        int n = Math.min(tokenEnd - tokenStart, 40);
        for (int i = 0; i < n; i++) {
            int b = buf[tokenStart + i] & 0xFF;
            if (b < 32 || b >= 127) {
                text.append(String.format("\\x%02X", b));
            } else {
                text.append((char) b);
            }
        }
        if (tokenEnd - tokenStart > n) {
            text.append("...");
        }
        return text.toString();
    }

    MeshFormatException error(int atLine, String problem) {
        return new MeshFormatException(file, atLine, problem);
    }

    private MeshFormatException binary(int atLine) {
        return new MeshFormatException(file, atLine, "binary or UTF-16 content, expected a text OFF/OBJ file");
    }

    @Override
    public void close() throws IOException {
        in.close();
    }
}
