package ifold.mesh.io;

import ch.randelshofer.fastdoubleparser.JavaDoubleParser;

/**
 * Numbers in the bytes of a model file, parsed in place: decimals as {@link Double#parseDouble}
 * reads them, bit for bit, and integers.
 *
 * <p>Decimals go through fastdoubleparser (Werner Randelshofer's port of Lemire's fast_float):
 * in {@code bench/run} it parsed the 2.1M coordinates of a 72 MB OFF file in 38 ms against
 * 46 ms for the Eisel-Lemire parser iFold had before, which it replaces. It reads Java's
 * syntax, which is more than a model file may hold: {@code NaN}, {@code Infinity}, hexadecimal
 * ({@code 0x1p3}) and the suffixes {@code d} and {@code f} are refused here before it sees them.
 */
final class DecimalParser {
    private DecimalParser() {
    }

    /**
     * Parses b[from .. to) as a decimal number {@code [+-]digits[.digits][(e|E)[+-]digits]}
     * (digits may be missing on one side of the point), with exactly the result of
     * {@link Double#parseDouble}.
     *
     * @return the value, which is infinite when it overflows a double and a zero of the same
     *         sign when it underflows; NaN when the text is not a decimal number (this includes
     *         "NaN", "Infinity", hexadecimal forms and Java's suffixes)
     */
    static double parseDouble(byte[] b, int from, int to) {
        if (from == to) {
            return Double.NaN;
        }
        // A plain decimal starts with a sign, a digit or a point and ends with a digit or a
        // point; of what Java reads besides, only hexadecimal passes that, and it has an x.
        byte first = b[from];
        byte last = b[to - 1];
        if (!(isDigit(last) || last == '.') || !(isDigit(first) || first == '.' || first == '-' || first == '+')) {
            return Double.NaN;
        }
        int zero = first == '-' || first == '+' ? from + 1 : from;
        if (zero + 1 < to && (b[zero + 1] == 'x' || b[zero + 1] == 'X')) {
            return Double.NaN;
        }
        try {
            return JavaDoubleParser.parseDouble(b, from, to - from);
        } catch (NumberFormatException e) {
            return Double.NaN;
        }
    }

    private static boolean isDigit(byte c) {
        return c >= '0' && c <= '9';
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
