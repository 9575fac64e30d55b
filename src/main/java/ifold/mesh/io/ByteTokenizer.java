package ifold.mesh.io;

import java.io.Closeable;
import java.io.IOException;
import java.io.InputStream;
import java.math.BigInteger;
import java.nio.charset.StandardCharsets;
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
 * <p>Numbers are parsed in place: see {@link #parseDecimal} and {@link #parseLong}.
 */
final class ByteTokenizer implements Closeable {
    /** What {@link #advance()} found. */
    static final int EOF = -1;
    static final int EOL = 0;
    static final int TOKEN = 1;

    /** Refill size; also the longest token accepted, which keeps garbage input from growing memory. */
    static final int BUFFER_SIZE = 1 << 16;

    // Byte classes: what each byte value means to the tokenizer.
    private static final byte PART = 0;
    private static final byte SPACE = 1;
    private static final byte LF = 2;
    private static final byte CR = 3;
    private static final byte HASH = 4;
    private static final byte BINARY = 5;
    private static final byte BACKSLASH = 6;

    private static final byte[] CLASSES = new byte[256];

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

    /** Exact powers of ten as doubles: 10^0 .. 10^22 are all representable without rounding. */
    private static final double[] POWERS_OF_TEN = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    };

    private final Path file;
    private final InputStream in;
    /** Byte classes in use: {@link #CLASSES}, or a copy where a backslash continues a line. */
    private final byte[] classes;
    /** Bytes buf[pos .. limit) are read from the file but not yet consumed. */
    private final byte[] buf = new byte[BUFFER_SIZE];
    private int pos;
    private int limit;
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

    /** The current token parsed as a decimal number; see {@link #parseDecimal}. */
    double tokenDouble() {
        return parseDecimal(buf, tokenStart, tokenEnd);
    }

    /** The current token parsed as an integer; see {@link #parseLong}. */
    long tokenLong() {
        return parseLong(buf, tokenStart, tokenEnd);
    }

    /**
     * The current token as a finite double, or an exception naming the {@code what} (a noun
     * such as "coordinate") that was expected.
     * NaN, infinities in any spelling and numbers too large for a double are refused.
     */
    double finiteDouble(String what) throws MeshFormatException {
        double value = parseDecimal(buf, tokenStart, tokenEnd);
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
        if (Double.isInfinite(parseDecimal(buf, tokenStart, tokenEnd))) {
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

    /**
     * Parses b[from .. to) as a decimal number {@code [+-]digits[.digits][(e|E)[+-]digits]}
     * (digits may be missing on one side of the point), with exactly the result of
     * {@link Double#parseDouble}.
     *
     * <p>The digits become an integer w of at most 19 significant digits and a power of ten q.
     * Short coordinates take Clinger's fast path: a w below 2^53 and a power of ten up to 10^22
     * are both exact doubles, so one multiplication or division rounds once, correctly. Other
     * values of up to 19 digits, which is what a shortest round-trip printer such as
     * {@link Double#toString} writes for most doubles, go through {@link #eiselLemire}. Only
     * a longer mantissa (zeros after the 19th digit aside), an exponent beyond 99999 or a rare
     * case Eisel-Lemire cannot decide reach {@code Double.parseDouble}. The first two paths
     * allocate nothing.
     *
     * @return the value, which is infinite when it overflows a double and a zero of the same
     *         sign when it underflows; NaN when the text is not a decimal number (this includes
     *         "NaN", "inf" and hexadecimal forms)
     */
    static double parseDecimal(byte[] b, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (b[i] == '-' || b[i] == '+')) {
            negative = b[i] == '-';
            i++;
        }
        // Unsigned: 19 digits can pass 2^63, never 2^64.
        long mantissa = 0;
        int significantDigits = 0;
        int digits = 0;
        int exponent = 0;
        boolean exact = true; // false once a non-zero digit did not fit into the mantissa
        for (; i < to; i++) {
            int d = b[i] - '0';
            if (d < 0 || d > 9) {
                break;
            }
            digits++;
            if (mantissa == 0 && d == 0) {
                continue; // leading zeros carry no precision
            }
            if (significantDigits < MAX_MANTISSA_DIGITS) {
                mantissa = 10 * mantissa + d;
                significantDigits++;
            } else {
                // A dropped zero only scales, so "1000...0" of any length stays on a fast path.
                exponent++;
                exact &= d == 0;
            }
        }
        if (i < to && b[i] == '.') {
            i++;
            for (; i < to; i++) {
                int d = b[i] - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                digits++;
                if (mantissa == 0 && d == 0) {
                    exponent--;
                    continue;
                }
                if (significantDigits < MAX_MANTISSA_DIGITS) {
                    mantissa = 10 * mantissa + d;
                    significantDigits++;
                    exponent--;
                } else {
                    exact &= d == 0;
                }
            }
        }
        if (digits == 0) {
            return Double.NaN;
        }
        if (i < to && (b[i] == 'e' || b[i] == 'E')) {
            i++;
            boolean negativeExponent = false;
            if (i < to && (b[i] == '-' || b[i] == '+')) {
                negativeExponent = b[i] == '-';
                i++;
            }
            int exponentStart = i;
            int explicit = 0;
            for (; i < to; i++) {
                int d = b[i] - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                // Beyond this any double is 0 or infinite; the slow path decides which.
                if (explicit < 100_000) {
                    explicit = 10 * explicit + d;
                } else {
                    exact = false;
                }
            }
            if (i == exponentStart) {
                return Double.NaN;
            }
            exponent += negativeExponent ? -explicit : explicit;
        }
        if (i != to) {
            return Double.NaN;
        }
        if (!exact) {
            return slowParse(b, from, to);
        }
        if (mantissa == 0) {
            return negative ? -0.0 : 0.0;
        }
        if (mantissa >>> 53 == 0 && exponent >= -22 && exponent <= 22) {
            double value = exponent >= 0
                    ? mantissa * POWERS_OF_TEN[exponent]
                    : mantissa / POWERS_OF_TEN[-exponent];
            return negative ? -value : value;
        }
        long bits = eiselLemire(mantissa, exponent);
        if (bits == UNDECIDED) {
            return slowParse(b, from, to);
        }
        return Double.longBitsToDouble(negative ? bits | Long.MIN_VALUE : bits);
    }

    /** The most significant digits {@link #parseDecimal} keeps: 10^19 - 1 &lt; 2^64. */
    private static final int MAX_MANTISSA_DIGITS = 19;
    /** The decimal exponents {@link PowersOfFive} covers; outside them w * 10^q is 0 or infinite for any w. */
    static final int MIN_EXPONENT_10 = -342;
    static final int MAX_EXPONENT_10 = 308;
    /** {@link #eiselLemire}'s answer when the truncated product cannot tell how to round. */
    static final long UNDECIDED = -1;
    private static final long INFINITY_BITS = 0x7FF0_0000_0000_0000L;

    /**
     * The bits of the double nearest to w * 10^q (ties to even), positive; or {@link #UNDECIDED}.
     * This is the Eisel-Lemire algorithm (D. Lemire, "Number Parsing at a Gigabyte per
     * Second", Software: Practice and Experience 51(8), 2021, Algorithm 1; the same as
     * fast_float's {@code compute_float}, Go's {@code eiselLemire64} and Rust's
     * {@code core::num::dec2flt::lemire}).
     *
     * <p>w is shifted until its top bit is set and multiplied by the 128-bit approximation of
     * 5^q (the factor 2^q only moves the binary exponent). The top 54 or 55 bits of the product
     * hold the 53-bit significand and a rounding bit, and the bits below them say whether the
     * truncation of 5^q or of the product could have changed those: only when they are all
     * ones after the refined product, outside the exponents where the product is exact, is the
     * answer left to the slow path.
     *
     * @param w the decimal significand, unsigned and not 0
     * @param q the power of ten
     */
    static long eiselLemire(long w, int q) {
        if (q < MIN_EXPONENT_10) {
            return 0; // w * 10^q < 2^64 * 10^-343 < 2^-1076: rounds to zero
        }
        if (q > MAX_EXPONENT_10) {
            return INFINITY_BITS; // w * 10^q >= 10^309
        }
        int leadingZeros = Long.numberOfLeadingZeros(w);
        w <<= leadingZeros;
        int index = 2 * (q - MIN_EXPONENT_10);
        long powerHigh = PowersOfFive.TABLE[index];
        long high = unsignedMultiplyHigh(w, powerHigh);
        long low = w * powerHigh;
        // 55 bits are needed (52 stored, the implicit one, a rounding bit and one the leading
        // bit may lose); when the 9 below them are all ones, a carry from the product with the
        // low word of 5^q could still change them.
        if ((high & 0x1FF) == 0x1FF) {
            long secondHigh = unsignedMultiplyHigh(w, PowersOfFive.TABLE[index + 1]);
            low += secondHigh;
            if (Long.compareUnsigned(secondHigh, low) > 0) {
                high++;
            }
        }
        // All ones might still be a carry short of the truth. Not for q in [0, 55], where 5^q fits
        // in 128 bits and the product is exact, nor for q in [-27, -1], where 5^-q fits in 64 bits
        // and the paper shows the 128-bit reciprocal suffices.
        if (low == -1 && (q < -27 || q > 55)) {
            return UNDECIDED;
        }
        int upperBit = (int) (high >>> 63);
        int shift = upperBit + 9;
        long significand = high >>> shift; // 54 bits: 53 and a rounding bit
        // floor(log2(10^q)) + 63 is where the product's top bit sits; 217706 / 2^16 ~ log2(10).
        int exponent2 = ((217706 * q) >> 16) + 63 + upperBit - leadingZeros + 1023;
        if (exponent2 <= 0) {
            // Subnormal or zero. q <= -308 here, where no tie is possible (see below), so
            // rounding up on the rounding bit is rounding to nearest.
            if (-exponent2 + 1 >= 64) {
                return 0;
            }
            significand >>>= -exponent2 + 1;
            significand += significand & 1;
            significand >>>= 1;
            // Rounding up to 2^52 gives the smallest normal, whose bits are the same 2^52.
            return significand;
        }
        // Rounding up on the rounding bit is wrong only for a tie on an even significand. A tie
        // is a dyadic fraction with 54 significant bits: for q > 0 the odd part 5^q must fit in
        // them (q <= 23), for q < 0 w must be 5^-q times 2^53 or more (q >= -4); and the product
        // then has nothing but zeros below the rounding bit.
        if (Long.compareUnsigned(low, 1) <= 0 && q >= -4 && q <= 23 && (significand & 3) == 1
                && significand << shift == high) {
            significand &= ~1L;
        }
        significand += significand & 1;
        significand >>>= 1;
        if (significand >= 1L << 53) {
            // Rounded up past the top: 1.111..1 became 10.000..0.
            significand = 1L << 52;
            exponent2++;
        }
        if (exponent2 >= 0x7FF) {
            return INFINITY_BITS;
        }
        return (long) exponent2 << 52 | (significand & ~(1L << 52));
    }

    /** The high 64 bits of the unsigned 128-bit product a * b (Math.unsignedMultiplyHigh arrived in Java 18). */
    private static long unsignedMultiplyHigh(long a, long b) {
        return Math.multiplyHigh(a, b) + ((a >> 63) & b) + ((b >> 63) & a);
    }

    /**
     * 5^q for q in [{@link #MIN_EXPONENT_10}, {@link #MAX_EXPONENT_10}] as 128-bit significands
     * with the top bit set, high word then low word, exactly fast_float's
     * {@code power_of_five_128}. A holder class, so that files of short numbers never build it.
     */
    static final class PowersOfFive {
        static final long[] TABLE = new long[2 * (MAX_EXPONENT_10 - MIN_EXPONENT_10 + 1)];

        static {
            for (int q = MIN_EXPONENT_10; q <= MAX_EXPONENT_10; q++) {
                BigInteger power = BigInteger.valueOf(5).pow(Math.abs(q));
                BigInteger entry;
                if (q >= 0) {
                    // 5^q shifted to 128 bits, truncated: exact up to 5^55.
                    int excess = power.bitLength() - 128;
                    entry = excess > 0 ? power.shiftRight(excess) : power.shiftLeft(-excess);
                } else {
                    // The reciprocal 2^b / 5^-q plus one, truncated to 128 bits, with z the bit
                    // length of 5^-q: for q >= -27 (5^-q < 2^64) b = z + 127 makes it exactly
                    // 128 bits wide, so the entry is the reciprocal rounded up; below, b =
                    // 2z + 128 and the truncation drops the extra bits. These are the paper's
                    // and fast_float's definitions, and the error analysis depends on them.
                    int z = power.bitLength();
                    int b = q >= -27 ? z + 127 : 2 * z + 128;
                    entry = BigInteger.ONE.shiftLeft(b).divide(power).add(BigInteger.ONE);
                    entry = entry.shiftRight(Math.max(0, entry.bitLength() - 128));
                }
                int index = 2 * (q - MIN_EXPONENT_10);
                TABLE[index] = entry.shiftRight(64).longValue();
                TABLE[index + 1] = entry.longValue();
            }
        }
    }

    private static double slowParse(byte[] b, int from, int to) {
        // The text is known to be plain decimal, which Double.parseDouble reads the same way.
        return Double.parseDouble(new String(b, from, to - from, StandardCharsets.ISO_8859_1));
    }

    /** Returned by {@link #parseLong} for text that is not an integer. */
    static final long NOT_AN_INTEGER = Long.MIN_VALUE;
    /** Returned by {@link #parseLong} for an integer of more than 18 digits. */
    static final long TOO_LARGE = Long.MAX_VALUE;

    /**
     * Parses b[from .. to) as a decimal integer {@code [+-]digits}.
     *
     * @return the value; {@link #NOT_AN_INTEGER} for other text; {@link #TOO_LARGE} when the
     *         digits (leading zeros aside) are more than 18, whatever the sign
     */
    static long parseLong(byte[] b, int from, int to) {
        int i = from;
        boolean negative = false;
        if (i < to && (b[i] == '-' || b[i] == '+')) {
            negative = b[i] == '-';
            i++;
        }
        if (i == to) {
            return NOT_AN_INTEGER;
        }
        long value = 0;
        int significantDigits = 0;
        for (; i < to; i++) {
            int d = b[i] - '0';
            if (d < 0 || d > 9) {
                return NOT_AN_INTEGER;
            }
            if (value != 0 || d != 0) {
                if (++significantDigits > 18) {
                    // Finish checking the syntax, so that "1234567890123456789x" is not "too large".
                    for (i++; i < to; i++) {
                        if (b[i] < '0' || b[i] > '9') {
                            return NOT_AN_INTEGER;
                        }
                    }
                    return TOO_LARGE;
                }
                value = 10 * value + d;
            }
        }
        return negative ? -value : value;
    }
}
