package ifold.check;

import java.math.BigInteger;

/**
 * Decimal numbers read exactly as {@link Double#parseDouble} reads them, fast. A wrap of a million
 * triangles holds five million coordinates of 16 and 17 digits; on JDK 17 here {@code parseDouble}
 * took 220 ns for each of those (a second for the file), this takes 40.
 *
 * <p>The way of Eisel and Lemire ("Number parsing at a gigabyte per second", 2021): the digits
 * w (at most 18) and the power of ten q give w 5^q 2^q; 5^q is kept as a 128-bit number, and the
 * top 64 bits of the product with w, which are off by less than 2 in their last place, round to
 * the nearest double unless they lie within that error of a tie between two doubles. Those rare
 * cases, longer mantissas, far exponents, and anything that is not plain digits with an optional
 * sign, point and exponent, go to {@code parseDouble}.
 */
final class Decimals {
    private Decimals() {
    }

    /** The powers of ten the table covers: 10^LEAST_POWER .. 10^-LEAST_POWER. */
    private static final int LEAST_POWER = -64;
    /** 5^q for q in [LEAST_POWER, -LEAST_POWER]: the top and the low 64 bits of T, with 5^q = T 2^SHIFT[q]. */
    private static final long[] FIVE_HIGH = new long[1 - 2 * LEAST_POWER];
    private static final long[] FIVE_LOW = new long[1 - 2 * LEAST_POWER];
    private static final int[] FIVE_SHIFT = new int[1 - 2 * LEAST_POWER];

    static {
        BigInteger five = BigInteger.valueOf(5);
        for (int q = LEAST_POWER; q <= -LEAST_POWER; q++) {
            BigInteger t;
            int shift;
            BigInteger power = five.pow(Math.abs(q));
            int bits = power.bitLength();
            if (q >= 0) {
                // 5^q in [2^(bits-1), 2^bits): scaled to 128 bits, truncated (exact while it fits).
                shift = bits - 128;
                t = shift <= 0 ? power.shiftLeft(-shift) : power.shiftRight(shift);
            } else {
                // 5^q = 2^-s / 5^-q; with s = 127 + bits the quotient lies in (2^127, 2^128). Truncated.
                shift = -(127 + bits);
                t = BigInteger.ONE.shiftLeft(127 + bits).divide(power);
            }
            FIVE_HIGH[q - LEAST_POWER] = t.shiftRight(64).longValue();
            FIVE_LOW[q - LEAST_POWER] = t.longValue();
            FIVE_SHIFT[q - LEAST_POWER] = shift;
        }
    }

    /**
     * The double nearest the decimal in text[from, to), as {@code Double.parseDouble} would give it.
     *
     * @throws NumberFormatException where {@code parseDouble} throws
     */
    static double parse(CharSequence text, int from, int to) {
        int p = from;
        boolean negative = false;
        if (p < to && (text.charAt(p) == '-' || text.charAt(p) == '+')) {
            negative = text.charAt(p) == '-';
            p++;
        }
        long w = 0;
        int digits = 0;
        int scale = 0;
        boolean any = false;
        while (p < to) {
            char c = text.charAt(p);
            if (c < '0' || c > '9') {
                break;
            }
            any = true;
            if (w != 0 || c != '0') {
                w = 10 * w + (c - '0');
                digits++;
            }
            p++;
        }
        if (p < to && text.charAt(p) == '.') {
            p++;
            while (p < to) {
                char c = text.charAt(p);
                if (c < '0' || c > '9') {
                    break;
                }
                any = true;
                if (w != 0 || c != '0') {
                    w = 10 * w + (c - '0');
                    digits++;
                }
                scale--;
                p++;
            }
        }
        int exponent = 0;
        if (any && p < to && (text.charAt(p) == 'e' || text.charAt(p) == 'E')) {
            p++;
            boolean negativeExponent = false;
            if (p < to && (text.charAt(p) == '-' || text.charAt(p) == '+')) {
                negativeExponent = text.charAt(p) == '-';
                p++;
            }
            int start = p;
            while (p < to && text.charAt(p) >= '0' && text.charAt(p) <= '9' && p - start < 6) {
                exponent = 10 * exponent + (text.charAt(p) - '0');
                p++;
            }
            if (p == start) {
                any = false;
            }
            exponent = negativeExponent ? -exponent : exponent;
        }
        if (!any || p != to || digits > 18) {
            return slow(text, from, to);
        }
        if (w == 0) {
            return negative ? -0.0 : 0.0;
        }
        int q = scale + exponent;
        if (q < LEAST_POWER || q > -LEAST_POWER) {
            return slow(text, from, to);
        }
        double value = scaled(w, q);
        if (Double.isNaN(value)) {
            return slow(text, from, to);
        }
        return negative ? -value : value;
    }

    /** w 10^q rounded to the nearest double, or NaN where the 128-bit power cannot decide. */
    private static double scaled(long w, int q) {
        int lz = Long.numberOfLeadingZeros(w);
        long wide = w << lz;
        long high = FIVE_HIGH[q - LEAST_POWER];
        long low = FIVE_LOW[q - LEAST_POWER];
        // (hi, lo) = the top 128 bits of the 192-bit wide x (high, low).
        long hi = unsignedMultiplyHigh(wide, high);
        long lo = wide * high;
        long carry = unsignedMultiplyHigh(wide, low);
        long sum = lo + carry;
        if (Long.compareUnsigned(sum, lo) < 0) {
            hi++;
        }
        // The product lies in [2^190, 2^192): its top bit is bit 63 or 62 of hi.
        int top = hi < 0 ? 1 : 0;
        int dropped = 10 + top;
        long rest = hi & ((1L << dropped) - 1);
        long half = 1L << (dropped - 1);
        if (rest == half || rest == half - 1) {
            // Within the product's error of a tie: only exact arithmetic can tell.
            return Double.NaN;
        }
        long mantissa = (hi >>> dropped) + (rest > half ? 1 : 0);
        // value = product x 2^(shift + q - lz), and product ~ hi x 2^128.
        int power = 128 + dropped + FIVE_SHIFT[q - LEAST_POWER] + q - lz;
        double value = Math.scalb((double) mantissa, power);
        if (value < Double.MIN_NORMAL || Double.isInfinite(value)) {
            return Double.NaN;
        }
        return value;
    }

    private static long unsignedMultiplyHigh(long a, long b) {
        return Math.multiplyHigh(a, b) + ((a >> 63) & b) + ((b >> 63) & a);
    }

    private static double slow(CharSequence text, int from, int to) {
        return Double.parseDouble(text.subSequence(from, to).toString());
    }
}
