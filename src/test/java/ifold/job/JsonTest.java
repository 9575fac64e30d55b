package ifold.job;

import static org.junit.jupiter.api.Assertions.assertEquals;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;

/** Every number of a report reads back as the double computed; lists stay lists. */
class JsonTest {
    @Test
    void numbersReadBackExactly() throws Exception {
        List<Double> tricky = new ArrayList<>(List.of(5.97844e-10, 0.1 + 0.2, Math.pow(2, -44), 1e23, Double.MIN_VALUE,
                Double.MAX_VALUE, -0.000123456789012345, 123456789012345678.0, 4.35, 1.0, -7.0));
        Random random = new Random(9);
        for (int i = 0; i < 2000; i++) {
            tricky.add(Double.longBitsToDouble(random.nextLong()));
        }
        tricky.removeIf(d -> !Double.isFinite(d));
        Map<String, Object> report = new LinkedHashMap<>();
        report.put("values", tricky);
        report.put("one", 5.97844e-10);
        report.put("count", 42);
        report.put("name", "a \"quoted\"\nname");
        String text = Json.write(report);
        try (JsonParser parser = new JsonFactory().createParser(text)) {
            assertEquals(JsonToken.START_OBJECT, parser.nextToken());
            assertEquals("values", parser.nextFieldName());
            assertEquals(JsonToken.START_ARRAY, parser.nextToken());
            for (double expected : tricky) {
                parser.nextToken();
                assertEquals(expected, parser.getDoubleValue(), 0, "written as " + parser.getText());
                assertEquals(expected, Double.parseDouble(parser.getText()), 0);
            }
            assertEquals(JsonToken.END_ARRAY, parser.nextToken());
            assertEquals("one", parser.nextFieldName());
            parser.nextToken();
            assertEquals(5.97844e-10, Double.parseDouble(parser.getText()), 0, "the number the old writer cut to 5.97844e-1");
            assertEquals("count", parser.nextFieldName());
            parser.nextToken();
            assertEquals("42", parser.getText());
            assertEquals("name", parser.nextFieldName());
            parser.nextToken();
            assertEquals("a \"quoted\"\nname", parser.getText());
        }
    }
}
