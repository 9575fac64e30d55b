package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.math.BigDecimal;
import java.math.BigInteger;
import java.math.MathContext;
import java.math.RoundingMode;
import java.nio.charset.StandardCharsets;
import java.util.Locale;
import java.util.Random;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

/**
 * {@link DecimalParser#parseDouble} against {@link Double#parseDouble}, bit for bit, on the
 * texts printers write and on the cases that break fast parsers: ties, subnormals, the ends
 * of the power table, long mantissas. {@link ByteTokenizerTest} covers the syntax.
 */
class DecimalParsingTest {
    private static double parse(String s) {
        byte[] b = ("xx" + s + "yy").getBytes(StandardCharsets.ISO_8859_1);
        return DecimalParser.parseDouble(b, 2, b.length - 2);
    }

    private static void assertSameAsJdk(String s) {
        double expected = Double.parseDouble(s);
        double actual = parse(s);
        if (Double.doubleToRawLongBits(expected) != Double.doubleToRawLongBits(actual)) {
            // Compared first, so that millions of passing checks build no messages.
            assertEquals(expected, actual, s);
            assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                    s + " (sign of zero)");
        }
    }

    private static final MathContext SEVENTEEN_DIGITS = new MathContext(17, RoundingMode.HALF_EVEN);

    /** A finite double from random bits: every exponent, subnormals included, about equally likely. */
    private static double randomFinite(Random random) {
        double d;
        do {
            d = Double.longBitsToDouble(random.nextLong());
        } while (!Double.isFinite(d));
        return d;
    }

    @Test
    void parsesRandomBitPatterns() {
        // Every exponent, subnormals included; Java 17's toString and parseDouble are slow on
        // these, hence fewer than of the others.
        Random random = new Random(2021);
        for (int n = 0; n < 500_000; n++) {
            double x = randomFinite(random);
            assertSameAsJdk(Double.toString(x));
            if (n % 20 == 0) {
                assertSameAsJdk(String.format(Locale.ROOT, "%.15e", x));
            }
            if (n % 100 == 0) {
                assertSameAsJdk(new BigDecimal(x).round(SEVENTEEN_DIGITS).toString());
            }
        }
    }

    @Test
    void parsesRandomCoordinates() {
        Random random = new Random(1300);
        for (int n = 0; n < 1_300_000; n++) {
            double x = random.nextDouble() * 20 - 10;
            assertSameAsJdk(Double.toString(x));
            if (n % 20 == 0) {
                assertSameAsJdk(new BigDecimal(x).round(SEVENTEEN_DIGITS).toString());
                assertSameAsJdk(String.format(Locale.ROOT, "%.17g", x));
                assertSameAsJdk(String.format(Locale.ROOT, "%.15e", x));
            }
        }
    }

    @Test
    void parsesDecimalFractions() {
        // k / 10^n, both as the double nearest to it prints and as the exact text "k e-n".
        Random random = new Random(10);
        for (int n = 0; n < 300_000; n++) {
            int k = random.nextInt(1_000_000_000);
            int digits = random.nextInt(26);
            assertSameAsJdk(Double.toString(-k / Math.pow(10, digits)));
            assertSameAsJdk(k + "e-" + digits);
        }
    }

    @Test
    void roundsTiesToEven() {
        // Exact midpoints between neighbouring doubles that fit in 19 digits: an odd 54-bit
        // number o times 2^t, written as w * 10^q. For q >= 0, o = 5^q * m; for q < 0,
        // w = o * 5^-q * 2^(t - q). Each also one unit below and above in the last digit.
        Random random = new Random(53);
        BigInteger limit = BigInteger.TEN.pow(19);
        int ties = 0;
        for (int q = -4; q <= 23; q++) {
            BigInteger five = BigInteger.valueOf(5).pow(Math.abs(q));
            for (int n = 0; n < 2000; n++) {
                BigInteger w;
                if (q >= 0) {
                    // m odd with 5^q * m of 54 bits, then w = m * 2^s for a few s
                    BigInteger low = BigInteger.ONE.shiftLeft(53).divide(five).add(BigInteger.ONE);
                    BigInteger high = BigInteger.ONE.shiftLeft(54).subtract(BigInteger.ONE).divide(five);
                    if (high.compareTo(low) < 0) {
                        break; // 5^q alone has more than 54 bits
                    }
                    BigInteger m = low.add(new BigInteger(64, random).mod(high.subtract(low).add(BigInteger.ONE)))
                            .setBit(0);
                    if (m.multiply(five).bitLength() != 54) {
                        continue;
                    }
                    w = m.shiftLeft(random.nextInt(12));
                } else {
                    BigInteger o = new BigInteger(53, random).setBit(53).setBit(0);
                    w = o.multiply(five).shiftLeft(random.nextInt(3));
                }
                if (w.compareTo(limit) >= 0) {
                    continue;
                }
                String tie = w + "e" + q;
                // Check the setup: the text is exactly halfway between two doubles.
                if (n < 20) {
                    BigDecimal exact = new BigDecimal(w, -q);
                    double below = new BigDecimal(Double.parseDouble(tie)).compareTo(exact) < 0
                            ? Double.parseDouble(tie) : Math.nextDown(Double.parseDouble(tie));
                    BigDecimal mid = new BigDecimal(below).add(new BigDecimal(Math.nextUp(below)))
                            .divide(BigDecimal.valueOf(2));
                    assertEquals(0, mid.compareTo(exact), tie + " is a tie");
                }
                assertSameAsJdk(tie);
                assertSameAsJdk("-" + tie);
                assertSameAsJdk(w.subtract(BigInteger.ONE) + "e" + q);
                assertSameAsJdk(w.add(BigInteger.ONE) + "e" + q);
                ties++;
            }
        }
        assertTrue(ties > 25_000, "ties tested: " + ties);
    }

    @Test
    void parsesNearMidpointsAtEveryMagnitude() {
        // The midpoint between x and the next double, cut to 17, 18 and 19 digits both ways:
        // texts within a few units of the 19th digit of a rounding boundary.
        Random random = new Random(1075);
        for (int n = 0; n < 8_000; n++) {
            double x = Math.abs(randomFinite(random));
            if (x == Double.MAX_VALUE) {
                continue;
            }
            BigDecimal mid = new BigDecimal(x).add(new BigDecimal(Math.nextUp(x))).divide(BigDecimal.valueOf(2));
            for (int digits = 17; digits <= 19; digits++) {
                assertSameAsJdk(mid.round(new MathContext(digits, RoundingMode.FLOOR)).toString());
                assertSameAsJdk(mid.round(new MathContext(digits, RoundingMode.CEILING)).toString());
            }
            assertSameAsJdk(mid.toString()); // hundreds of digits: the slow path
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {
        // subnormals and the normal boundary
        "4.9e-324", "4.9406564584124654e-324", "2.4703282292062327e-324", "2.4703282292062328e-324",
        "2.2250738585072011e-308", "2.2250738585072012e-308", "2.2250738585072013e-308",
        "2.2250738585072014e-308", "2.225073858507201e-308", "2.2250738585072009e-308",
        "-2.2250738585072014e-308", "1e-310", "9.99999999999999999e-311", "4.4501477170144023e-308",
        // the largest double and just past it
        "1.7976931348623157e308", "1.7976931348623158e308", "1.7976931348623158079e308",
        "1.797693134862315807e308", "-1.7976931348623157e308", "179769313486231570000000000000000e276",
        // ties and their neighbours
        "9007199254740993", "9007199254740992", "9007199254740994", "9007199254740995",
        "9007199254740993.0", "900719925474099.3e1", "18014398509481985", "18014398509481987",
        "1e23", "8.98846567431158e307", "5e-324", "1.5", "2.5", "0.5e-4",
        // long mantissas: 18, 19, 20 and 25 digits, with and without trailing zeros
        "123456789012345678", "1234567890123456789", "12345678901234567890", "9999999999999999999",
        "18446744073709551615", "18446744073709551616", "1234567890123456789012345",
        "1.234567890123456789012345", "1000000000000000000000000", "1.000000000000000000000000000",
        "1234567890123456789000000e-30", "0.1000000000000000055511151231257827",
        "9007199254740993000000000000", "9007199254740993000000000001",
        // the ends of the power table and beyond
        "1e-342", "1e-343", "9e-343", "9999999999999999999e-343", "1e-324", "3e-324", "1e308", "1e309",
        "9999999999999999999e289", "1e-400", "-1e-400", "1e400",
        // leading zeros and long runs of zeros
        "0000000000000000000000000000001", "-000.000", "0.0000000000000000000000000000000000000001",
        "0.00000000000000000000000000000000000000000000000000000000000000000000000000000000000000000000"
            + "00000000000000000000000000000000000000000000000000000000000000000000000000000000000000001",
        "00000000000000000000000.12345678901234567890e0", "0e-400", "-0e400", "0e0", "0.000e-342",
        // Clinger's limits
        "1e22", "1e-22", "9007199254740991e22", "9007199254740991e-22", "9007199254740992e22",
        "1e-23", "123.456e-20",
    })
    void parsesEdgeCasesLikeTheJdk(String s) {
        assertSameAsJdk(s);
        assertSameAsJdk(s.startsWith("-") ? s.substring(1) : "-" + s);
    }

    @Test
    void overflowAndUnderflowKeepTheirSigns() {
        assertEquals(Double.POSITIVE_INFINITY, parse("1e309"));
        assertEquals(Double.NEGATIVE_INFINITY, parse("-1.8e308"));
        assertEquals(Double.POSITIVE_INFINITY, parse("9999999999999999999e300"));
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(parse("-1e-343")));
        assertEquals(Double.doubleToRawLongBits(-0.0), Double.doubleToRawLongBits(parse("-2e-324")));
        assertEquals(Double.doubleToRawLongBits(0.0), Double.doubleToRawLongBits(parse("2e-324")));
        assertEquals(Double.MIN_VALUE, parse("3e-324"));
    }

    @Test
    void allocatesNextToNothingPerNumber() {
        Assumptions.assumeTrue(ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean);
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        Assumptions.assumeTrue(threads.isThreadAllocatedMemorySupported() && threads.isThreadAllocatedMemoryEnabled());
        // Full-precision coordinates as our writer prints them, short ones, and 19-digit ones.
        Random random = new Random(64);
        StringBuilder text = new StringBuilder();
        for (int n = 0; n < 20_000; n++) {
            text.append(random.nextGaussian() * 3).append(' ')
                    .append(Math.round(random.nextGaussian() * 1e4) / 1e4).append(' ')
                    .append(random.nextLong() >>> 1).append("e-").append(random.nextInt(300)).append(' ');
        }
        byte[] b = text.toString().getBytes(StandardCharsets.ISO_8859_1);
        int[] starts = new int[60_000];
        int[] ends = new int[60_000];
        int count = 0;
        for (int i = 0; i < b.length; i++) {
            starts[count] = i;
            while (b[i] != ' ') {
                i++;
            }
            ends[count++] = i;
        }
        double sum = 0;
        sum += DecimalParser.parseDouble(b, starts[0], ends[0]); // loads the parser's classes
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        for (int k = 0; k < count; k++) {
            sum += DecimalParser.parseDouble(b, starts[k], ends[k]);
        }
        long allocated = threads.getThreadAllocatedBytes(thread) - before;
        // A String per number would be megabytes here; fastdoubleparser's rare slow cases
        // (19-digit mantissas it cannot decide at once) allocate a few kilobytes in all.
        assertTrue(allocated < count, allocated + " bytes allocated parsing " + count + " numbers (sum " + sum + ")");
    }
}
