package diffract.scene;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonLocation;
import com.fasterxml.jackson.core.JsonParseException;
import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonToken;
import com.fasterxml.jackson.core.StreamReadConstraints;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * A JSON document read with Jackson's streaming parser into a small tree whose every value remembers the line it
 * started on: Jackson's own tree ({@code JsonNode}) drops token locations, and scene errors must name the line.
 * Duplicate keys are refused here (Jackson's tree would silently keep the last one).
 */
final class JsonTree {
    /** Nesting deeper than this is no scene: refusing it keeps a hostile file from exhausting the stack. */
    private static final int MAX_DEPTH = 64;

    private JsonTree() {
    }

    /** A value and the line it starts on; {@code value} is a Map, List, String, Double/Long, Boolean or null. */
    record Located(Object value, int line) {
        /** The JSON type, as a message names it. */
        String typeName() {
            if (value == null) {
                return "null";
            } else if (value instanceof Map) {
                return "an object";
            } else if (value instanceof List) {
                return "an array";
            } else if (value instanceof String) {
                return "a string";
            } else if (value instanceof Boolean) {
                return "a boolean";
            }
            return "a number";
        }
    }

    /** A problem with the text itself (not its meaning), at a line. */
    static final class SyntaxError extends Exception {
        private static final long serialVersionUID = 1L;
        final int line;

        SyntaxError(String message, int line) {
            super(message);
            this.line = line;
        }
    }

    static Located parse(String text) throws SyntaxError {
        // Jackson's own limit one level above ours: our check names the line and the limit in the scene's words
        JsonFactory factory = JsonFactory.builder()
                .streamReadConstraints(StreamReadConstraints.builder().maxNestingDepth(MAX_DEPTH + 1).build()).build();
        JsonParser parser = null;
        try {
            parser = factory.createParser(text);
            JsonToken first = parser.nextToken();
            if (first == null) {
                throw new SyntaxError("the file is empty; a scene is a JSON object { ... }", 1);
            }
            Located root = value(parser, first, 1);
            JsonToken after = parser.nextToken();
            if (after != null) {
                throw new SyntaxError("more text after the end of the scene object", line(parser.currentLocation()));
            }
            return root;
        } catch (JsonParseException e) {
            JsonLocation where = e.getLocation();
            throw new SyntaxError("malformed JSON: " + e.getOriginalMessage().split("\n")[0],
                    where == null ? 1 : line(where));
        } catch (IOException e) {
            int line = parser == null ? 1 : line(parser.currentLocation());
            throw new SyntaxError("malformed JSON: " + e.getMessage().split("\n")[0], line);
        } finally {
            if (parser != null) {
                try {
                    parser.close();
                } catch (IOException ignored) {
                    // a string parser holds nothing to release
                }
            }
        }
    }

    private static Located value(JsonParser parser, JsonToken token, int depth) throws IOException, SyntaxError {
        int line = line(parser.currentTokenLocation());
        if (depth > MAX_DEPTH && (token == JsonToken.START_OBJECT || token == JsonToken.START_ARRAY)) {
            throw new SyntaxError("objects and arrays nest more than " + MAX_DEPTH + " levels deep here (a scene"
                    + " needs four at most); the file is not a scene", line);
        }
        switch (token) {
            case START_OBJECT: {
                Map<String, Located> members = new LinkedHashMap<>();
                Map<String, Integer> keyLines = new LinkedHashMap<>();
                JsonToken next;
                while ((next = parser.nextToken()) == JsonToken.FIELD_NAME) {
                    String key = parser.currentName();
                    int keyLine = line(parser.currentTokenLocation());
                    if (members.containsKey(key)) {
                        throw new SyntaxError("key '" + key + "' appears twice in one object (first on line "
                                + keyLines.get(key) + "); keep one", keyLine);
                    }
                    Located member = value(parser, parser.nextToken(), depth + 1);
                    // the key's line, not the value's: that is where a reader looks for the key
                    members.put(key, new Located(member.value(), keyLine));
                    keyLines.put(key, keyLine);
                }
                if (next != JsonToken.END_OBJECT) {
                    throw new SyntaxError("malformed JSON: unexpected end of the object", line);
                }
                return new Located(members, line);
            }
            case START_ARRAY: {
                List<Located> items = new ArrayList<>();
                JsonToken next;
                while ((next = parser.nextToken()) != JsonToken.END_ARRAY) {
                    if (next == null) {
                        throw new SyntaxError("malformed JSON: unexpected end of the array", line);
                    }
                    items.add(value(parser, next, depth + 1));
                }
                return new Located(items, line);
            }
            case VALUE_STRING:
                return new Located(parser.getText(), line);
            case VALUE_NUMBER_INT:
            case VALUE_NUMBER_FLOAT:
                return new Located(parser.getDoubleValue(), line);
            case VALUE_TRUE:
                return new Located(Boolean.TRUE, line);
            case VALUE_FALSE:
                return new Located(Boolean.FALSE, line);
            case VALUE_NULL:
                return new Located(null, line);
            default:
                throw new SyntaxError("malformed JSON: unexpected " + token, line);
        }
    }

    private static int line(JsonLocation location) {
        return Math.max(1, location.getLineNr());
    }
}
