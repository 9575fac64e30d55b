package ifold.mesh.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;

class ByteTokenizerTest {
    @TempDir
    Path dir;

    private static double parse(String s) {
        byte[] b = ("xx" + s + "yy").getBytes(StandardCharsets.ISO_8859_1);
        return DecimalParser.parseDouble(b, 2, b.length - 2);
    }

    private static long parseLong(String s) {
        byte[] b = s.getBytes(StandardCharsets.ISO_8859_1);
        return DecimalParser.parseLong(b, 0, b.length);
    }

    private static void assertSameAsJdk(String s) {
        double expected = Double.parseDouble(s);
        double actual = parse(s);
        assertEquals(Double.doubleToRawLongBits(expected), Double.doubleToRawLongBits(actual),
                () -> s + ": expected " + expected + ", got " + actual);
    }

    @ParameterizedTest
    @ValueSource(strings = {"0", "-0", "+0", "0.0", "-0.0", "1", "-1", "1.", ".5", "-.5", "+.5e1", "00012.5000",
        "0.1", "0.2", "0.3", "3.14159", "1e22", "1e23", "9007199254740992", "9007199254740993",
        "9007199254740991e22", "123456789012345678", "1234567890123456789", "12345678901234567890123",
        "0.000000000000000000000000000001", "1e-22", "1e-23", "4.9e-324", "2.4e-324", "2.5e-324",
        "1.7976931348623157e308", "1.7976931348623158e308", "2.2250738585072014E-308",
        "2.2250738585072011e-308", "1E5", "1e+5", "1e-5", "93.87400100000001", "-85.90630299999999",
        "0e999999999", "1e-999999999", "0.1e-1", "100e-2", "7.0E-10", "5.6843418860808015E-14"})
    void parsesLikeTheJdk(String s) {
        assertSameAsJdk(s);
    }

    @Test
    void parsesRandomDecimalsLikeTheJdk() {
        Random random = new Random(42);
        StringBuilder s = new StringBuilder();
        for (int n = 0; n < 200_000; n++) {
            s.setLength(0);
            if (random.nextInt(4) == 0) {
                s.append(random.nextBoolean() ? '-' : '+');
            }
            int digits = 1 + random.nextInt(random.nextBoolean() ? 8 : 24);
            int point = random.nextInt(digits + 1);
            for (int i = 0; i < digits; i++) {
                if (i == point) {
                    s.append('.');
                }
                s.append((char) ('0' + random.nextInt(10)));
            }
            if (random.nextInt(3) == 0) {
                s.append(random.nextBoolean() ? 'e' : 'E').append(random.nextInt(700) - 350);
            }
            assertSameAsJdk(s.toString());
        }
    }

    @Test
    void parsesEveryDoubleAsJavaPrintsIt() {
        Random random = new Random(7);
        for (int n = 0; n < 200_000; n++) {
            double d = Double.longBitsToDouble(random.nextLong());
            if (Double.isFinite(d)) {
                assertSameAsJdk(Double.toString(d));
            }
            assertSameAsJdk(Double.toString(random.nextDouble() * 1000 - 500));
            assertSameAsJdk(String.format("%.6f", random.nextGaussian() * 100));
        }
    }

    @ParameterizedTest
    @ValueSource(strings = {"", "-", "+", ".", "-.", "e5", "1e", "1e+", "1e-", "1.2.3", "0x10", "NaN", "nan",
        "Infinity", "inf", "1d", "1f", " 1", "1 ", "1,5", "--1", "1.#IND", "1.#INF", "1e5.5", "1..2", "abc"})
    void refusesWhatIsNotADecimalNumber(String s) {
        assertTrue(Double.isNaN(parse(s)), s);
    }

    @Test
    void overflowIsInfinite() {
        assertEquals(Double.POSITIVE_INFINITY, parse("1e400"));
        assertEquals(Double.NEGATIVE_INFINITY, parse("-1e400"));
        assertEquals(Double.POSITIVE_INFINITY, parse("1e99999999999"));
    }

    @Test
    void parsesIntegers() {
        assertEquals(0, parseLong("0"));
        assertEquals(0, parseLong("-0"));
        assertEquals(42, parseLong("+42"));
        assertEquals(-17, parseLong("-17"));
        assertEquals(353535235358L, parseLong("353535235358"));
        assertEquals(999_999_999_999_999_999L, parseLong("999999999999999999"));
        assertEquals(5, parseLong("0000000000000000000000005"));
        assertEquals(DecimalParser.TOO_LARGE, parseLong("1000000000000000000"));
        assertEquals(DecimalParser.TOO_LARGE, parseLong("-99999999999999999999999"));
        for (String s : new String[] {"", "-", "1.0", "1e3", "12a", "a12", "1-", "1234567890123456789x"}) {
            assertEquals(DecimalParser.NOT_AN_INTEGER, parseLong(s), s);
        }
    }

    /** Runs the tokenizer over {@code text}: tokens as "line:text", ends of line as "/", then "$". */
    private String tokens(String text, boolean continuation) throws IOException, MeshFormatException {
        Path file = Fixtures.file(dir, "t.txt", text);
        List<String> out = new ArrayList<>();
        try (ByteTokenizer t = ByteTokenizer.open(file, continuation)) {
            for (;;) {
                int kind = t.advance();
                if (kind == ByteTokenizer.EOF) {
                    out.add("$");
                    return String.join(" ", out);
                }
                out.add(kind == ByteTokenizer.EOL ? "/" : t.tokenLine() + ":"
                        + new String(t.buffer(), t.tokenStart(), t.tokenEnd() - t.tokenStart(), StandardCharsets.ISO_8859_1));
            }
        }
    }

    @Test
    void splitsTokensAndLines() throws Exception {
        assertEquals("1:a 1:b / 2:c / 3:d / / 5:e $", tokens("a\tb\r\nc #x y\rd\n\ne", false));
        assertEquals("1:a / 2:b / $", tokens("a # comment # more\r\n  \f b\u000B\n", false));
    }

    @Test
    void hashEndsATokenButNotAnMsvcNonFinite() throws Exception {
        assertEquals("1:0 / 2:1.#IND 2:-1.#INF 2:x. / 3:2 $", tokens("0#red 4 5\n1.#IND -1.#INF x.#c\n2", false));
    }

    @Test
    void backslashContinuesALineOnlyWhenAsked() throws Exception {
        assertEquals("1:f 1:1 1:2 2:3 / 3:v $", tokens("f 1 2 \\\n 3\nv", true));
        assertEquals("1:f 1:1 1:2 2:3 / $", tokens("f 1 2\\\r\n3\r\n", true));
        assertEquals("1:f 1:\\ / 2:3 $", tokens("f \\\n3", false));
    }

    @Test
    void keepsTokensWholeAcrossBufferRefills() throws Exception {
        StringBuilder text = new StringBuilder();
        List<String> expected = new ArrayList<>();
        Random random = new Random(3);
        while (text.length() < 5 * ByteTokenizer.BUFFER_SIZE) {
            String token = Double.toString(random.nextDouble() * 1e6);
            text.append(token).append(random.nextBoolean() ? " " : "   ");
            expected.add("1:" + token);
        }
        expected.add("$");
        assertEquals(String.join(" ", expected), tokens(text.toString(), false));
    }

    @Test
    void skipsAUtf8ByteOrderMark() throws Exception {
        assertEquals("1:OFF $", tokens("\u00EF\u00BB\u00BFOFF", false));
    }

    @Test
    void refusesBinaryAndUtf16() throws Exception {
        for (String text : new String[] {"\u00FF\u00FEO\u0000F\u0000", "\u00FE\u00FF\u0000O", "OFF\n1 2\u0000 3",
            "OFF\n1 2 # \u0000\n", "v 1 2\u0001 3"}) {
            MeshFormatException e = assertThrows(MeshFormatException.class, () -> tokens(text, false));
            assertTrue(e.problem().contains("binary or UTF-16 content, expected a text OFF/OBJ file"), e.getMessage());
            assertEquals(text.startsWith("\u00FF") || text.startsWith("\u00FE") || text.startsWith("v") ? 1 : 2,
                    e.line(), e.getMessage());
        }
    }

    @Test
    void refusesATokenLongerThanTheBuffer() throws Exception {
        String text = "OFF\n" + "7".repeat(ByteTokenizer.BUFFER_SIZE + 10) + " 1\n";
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> tokens(text, false));
        assertTrue(e.problem().contains("a token longer than 65536 bytes"), e.getMessage());
        assertEquals(2, e.line());
    }

    @Test
    void refusesAnEmptyFile() throws Exception {
        MeshFormatException e = assertThrows(MeshFormatException.class, () -> tokens("", false));
        assertEquals("empty file", e.problem());
        assertEquals(0, e.line());
    }
}
