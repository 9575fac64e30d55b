package ifold.foldfile;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.exc.StreamConstraintsException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * A FOLD file's JSON, read into plain maps, lists, doubles, strings and booleans: one object,
 * nothing after it. A UTF-8 byte order mark before it is skipped, as editors on Windows write one.
 */
public final class FoldJson {
    private static final int BOM_1 = 0xEF;
    private static final int BOM_2 = 0xBB;
    private static final int BOM_3 = 0xBF;

    private FoldJson() {
    }

    /**
     * Whether the file is FOLD (JSON) rather than a fold script: its first character that is
     * not white space, after a byte order mark if there is one, begins JSON ('{', or '[' of a
     * list, which is then refused as no FOLD object rather than read as a script).
     */
    public static boolean isFoldFile(Path file) throws IOException {
        try (InputStream in = Files.newInputStream(file)) {
            byte[] head = in.readNBytes(4096);
            int start = head.length >= 3 && (head[0] & 0xFF) == BOM_1 && (head[1] & 0xFF) == BOM_2 && (head[2] & 0xFF) == BOM_3 ? 3 : 0;
            for (int i = start; i < head.length; i++) {
                if (!Character.isWhitespace(head[i])) {
                    return head[i] == '{' || head[i] == '[';
                }
            }
            return false;
        }
    }

    /**
     * Reads the file's one JSON object (jackson skips a byte order mark itself).
     *
     * @throws CreasePattern.Refused if it is not one JSON object, naming the line where it goes wrong
     */
    @SuppressWarnings("unchecked")
    public static Map<String, Object> read(Path file) throws IOException, CreasePattern.Refused {
        // A key given twice is refused rather than the last one taken: the file says two things.
        try (JsonParser parser = new JsonFactory().enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION).createParser(file.toFile())) {
            if (parser.nextToken() != JsonToken.START_OBJECT) {
                throw new CreasePattern.Refused("not a FOLD file: it does not begin with a JSON object");
            }
            Map<String, Object> fold = (Map<String, Object>) value(parser);
            // jackson reads a stream of values; a FOLD file is one, and text after it is a file
            // cut and pasted together or a mistake that would otherwise pass unseen.
            JsonToken after;
            try {
                after = parser.nextToken();
            } catch (JsonParseException e) {
                throw trailing(e.getLocation().getLineNr());
            }
            if (after != null) {
                throw trailing(parser.currentLocation().getLineNr());
            }
            return fold;
        } catch (JsonParseException e) {
            throw new CreasePattern.Refused(String.format(Locale.ROOT, "line %d: not valid JSON: %s", e.getLocation().getLineNr(),
                    inWords(e.getOriginalMessage())));
        } catch (StreamConstraintsException e) {
            // jackson gives no place for a limit it met.
            throw new CreasePattern.Refused("not a FOLD file: " + (e.getOriginalMessage().contains("nesting depth")
                    ? "lists or objects nested more than 1,000 deep" : inWords(e.getOriginalMessage())));
        }
    }

    /**
     * jackson's message without what it says to its own programmers ("enable
     * `JsonReadFeature.ALLOW_NON_NUMERIC_NUMBERS` to allow", "from
     * `StreamReadConstraints...`"): a user cannot enable anything.
     */
    static String inWords(String message) {
        String words = message.replaceAll(", from `[^`]*`", "").replaceAll(": enable `[^`]*` to allow", "").strip();
        words = words.replaceFirst("^Non-standard token '([^']*)'", "'$1' is not a number JSON allows");
        return words.replaceFirst("^Duplicate field '([^']*)'", "the key '$1' is given twice");
    }

    private static CreasePattern.Refused trailing(int line) {
        return new CreasePattern.Refused(String.format(Locale.ROOT,
                "line %d: text after the FOLD object's closing brace: a FOLD file holds one JSON object", line));
    }

    private static Object value(JsonParser parser) throws IOException {
        JsonToken token = parser.currentToken();
        switch (token) {
            case START_OBJECT -> {
                Map<String, Object> map = new LinkedHashMap<>();
                while (parser.nextToken() != JsonToken.END_OBJECT) {
                    String name = parser.currentName();
                    parser.nextToken();
                    map.put(name, value(parser));
                }
                return map;
            }
            case START_ARRAY -> {
                List<Object> list = new ArrayList<>();
                while (parser.nextToken() != JsonToken.END_ARRAY) {
                    list.add(value(parser));
                }
                return list;
            }
            case VALUE_NUMBER_INT, VALUE_NUMBER_FLOAT -> {
                return parser.getDoubleValue();
            }
            case VALUE_STRING -> {
                return parser.getText();
            }
            case VALUE_TRUE, VALUE_FALSE -> {
                return parser.getBooleanValue();
            }
            default -> {
                return null;
            }
        }
    }
}
