package ifold.check;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.SplittableRandom;
import org.junit.jupiter.api.Test;

/** The fast decimal reader gives what Double.parseDouble gives, bit for bit. */
class DecimalsTest {
    private static void assertSame(String text) {
        double expected = Double.parseDouble(text);
        double actual = Decimals.parse(text, 0, text.length());
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual), text + ": " + expected + " read as " + actual);
    }

    @Test
    void everyDoubleReadsBackAsItself() {
        SplittableRandom random = new SplittableRandom(11);
        for (int k = 0; k < 300_000; k++) {
            // Coordinates of models near 1, and doubles of any exponent.
            double x = k % 2 == 0 ? random.nextDouble(-10, 10) * Math.pow(10, random.nextInt(-8, 8))
                    : Double.longBitsToDouble(random.nextLong());
            if (Double.isFinite(x)) {
                assertSame(Double.toString(x));
            }
        }
    }

    @Test
    void decimalsOfEveryLengthReadAsParseDoubleReadsThem() {
        SplittableRandom random = new SplittableRandom(12);
        for (int k = 0; k < 300_000; k++) {
            StringBuilder s = new StringBuilder(random.nextBoolean() ? "-" : "");
            int digits = random.nextInt(1, 21);
            int point = random.nextInt(0, digits + 1);
            for (int d = 0; d < digits; d++) {
                if (d == point) {
                    s.append('.');
                }
                s.append((char) ('0' + random.nextInt(10)));
            }
            if (random.nextInt(3) == 0) {
                s.append(random.nextBoolean() ? 'e' : 'E').append(random.nextInt(-70, 70));
            }
            assertSame(s.toString());
        }
    }

    @Test
    void tiesEdgesAndOddForms() {
        for (String text : new String[] {"0", "-0", "0.0", "1", "1.", ".5", "+2.5", "0.1", "1e23", "9007199254740993",
            "9007199254740992.5", "2.2250738585072014E-308", "4.9e-324", "1.7976931348623157E308", "1e309", "123456789012345678",
            "1234567890123456789012", "0.000000000000000000000000000001", "7.972571507606034E-4", "1e-64", "1e64", "1e65", "1d",
            "Infinity", "-Infinity", "NaN", "0x1p3"}) {
            assertSame(text);
        }
        for (String text : new String[] {"", "-", ".", "e5", "1e", "1e+", "abc", "1.2.3", "--1"}) {
            assertThrows(NumberFormatException.class, () -> Decimals.parse(text, 0, text.length()), text);
        }
        // A number in the middle of a line.
        assertEquals(0.25, Decimals.parse("v 0.25 1", 2, 6));
    }
}
