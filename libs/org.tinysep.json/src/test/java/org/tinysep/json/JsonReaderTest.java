package org.tinysep.json;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonReaderTest {

    private static final int MAX = 16 * 1024;

    @Test
    void readsACommand() {
        Map<String, Object> o = JsonReader.object(" {\"parameter\":\"on\", \"value\": true, \"n\": -12, \"d\": 1.5,"
                + " \"s\": \"a\\\"b\\u00e9\", \"l\": [1, null], \"x\": {}} ", MAX);
        assertEquals("on", o.get("parameter"));
        assertEquals(Boolean.TRUE, o.get("value"));
        assertEquals(-12L, o.get("n"));
        assertEquals(1.5, o.get("d"));
        assertEquals("a\"bé", o.get("s"));
        assertEquals(Arrays.asList(1L, null), o.get("l"));
        assertEquals(Map.of(), o.get("x"));
        assertEquals(List.of("a", 2.5e-3, false), JsonReader.value("[\"a\",2.5E-3,false]", MAX));
    }

    @Test
    void readsTheContractsFlatObjects() {
        assertEquals(Map.of("a", "x\"y\u00e9", "n", "-1.5e3", "b", "true"),
                JsonReader.flatObject(" {\"a\":\"x\\\"y\\u00e9\",\"n\":-1.5e3,\"b\":true,\"z\":null} ", MAX));
        assertEquals(Map.of("value", "Küche \"1\"", "n", "-1.5", "b", "true"), JsonReader.flatObject(
                " {\"value\": \"K\\u00fcche \\\"1\\\"\", \"n\": -1.5, \"b\": true, \"z\": null} ", MAX));
        assertEquals(Map.of(), JsonReader.flatObject("{}", MAX));
        assertEquals(List.of("b", "a"), List.copyOf(JsonReader.flatObject("{\"b\":1,\"a\":2}", MAX).keySet()));
    }

    @Test
    void refusesBadObjectsInWords() {
        for (String bad : List.of("", "not json", "[1]", "{", "{\"a\":}", "{\"a\":1} x", "{\"a\":\"open",
                "{a:1}", "{\"a\":tru}", "{\"a\":1e}", "[".repeat(5))) {
            JsonException e = assertThrows(JsonException.class, () -> JsonReader.object(bad, MAX), bad);
            assertTrue(e.getMessage().startsWith("not "), e.getMessage());
            assertTrue(e.position() > 0, e.getMessage());
        }
        assertEquals("not a JSON object: '{' expected at character 1",
                assertThrows(JsonException.class, () -> JsonReader.object("not json", MAX)).getMessage());
        String deep = "{\"a\":" + "[".repeat(100) + "]".repeat(100) + "}";
        assertTrue(assertThrows(JsonException.class, () -> JsonReader.object(deep, MAX)).getMessage()
                .contains("nested too deeply"));
        String huge = "{\"a\":\"" + "x".repeat(MAX) + "\"}";
        JsonException tooLong = assertThrows(JsonException.class, () -> JsonReader.object(huge, MAX));
        assertEquals("longer than 16384 characters", tooLong.getMessage());
        assertEquals(0, tooLong.position());
    }

    @Test
    void refusesEverythingButAFlatObjectSayingWhere() {
        for (String bad : Arrays.asList(null, "", "[]", "{\"a\":}", "{\"a\":1", "{\"a\":[1]}", "{\"a\":{}}", "{\"a\":1,}",
                "{\"a\" 1}", "{\"a\":\"x\"} x", "{\"a\":1} x", "{\"a\":\"unterminated}", "{a:1}", "{\"a\":tru}")) {
            JsonException e = assertThrows(JsonException.class, () -> JsonReader.flatObject(bad, MAX), bad);
            assertTrue(e.getMessage().startsWith("not a flat JSON object: "), e.getMessage());
        }
    }

    @Test
    void namesTheCharacterWhereTheTextGoesWrong() {
        String flat = "not a flat JSON object: ";
        String[][] cases = {
            {"{\"a\":[1]}", flat + "only text, number, true, false or null values are accepted at character 6"},
            {"{\"a\":1 \"b\":2}", flat + "',' or '}' expected at character 8"},
            {"{\"a\":1,}", flat + "a quoted key expected at character 8"},
            {"{\"a\":1", flat + "the text ends too early at character 7"},
            {"{\"a\":\"x\"} x", flat + "nothing may follow the object at character 11"},
            {"{\"a\":\"open", "not valid JSON: a string is not closed at character 11"},
            {"{\"a\":tru}", "not valid JSON: a value expected at character 6"},
            {"{\"a\":99999999999999999999}", "not valid JSON: the number 99999999999999999999 is out of range at character 6"},
            {"[1 2]", "not valid JSON: ',' or ']' expected at character 4"}};
        for (String[] c : cases) {
            assertEquals(c[1], message(() -> {
                if (c[1].startsWith(flat)) {
                    JsonReader.flatObject(c[0], MAX);
                } else {
                    JsonReader.value(c[0], MAX);
                }
            }), c[0]);
        }
    }

    /** What the bridge's old reader let through (lenient escapes, raw control characters, sloppy numbers). */
    @Test
    void isStrict() {
        for (String bad : List.of("{\"a\":\"\\x\"}", "{\"a\":\"tab\there\"}", "{\"a\":01}", "{\"a\":1.}", "{\"a\":.5}",
                "{\"a\":+1}", "{\"a\":\"\\u+123\"}", "{\"a\":\"\\u12\"}", "{\"a\":true1}",
                "\u000b{}", "{\"a\":NaN}")) {
            assertThrows(JsonException.class, () -> JsonReader.object(bad, MAX), bad);
            assertThrows(JsonException.class, () -> JsonReader.flatObject(bad, MAX), bad);
        }
        assertThrows(JsonException.class, () -> JsonReader.object("{\"a\":1e999}", MAX));
        assertEquals(Map.of("a", "1e999"), JsonReader.flatObject("{\"a\":1e999}", MAX)); // valid JSON, kept as written
        assertEquals(Map.of("a", "/\b\f\n\r\t\u0000"), JsonReader.flatObject("{\"a\":\"\\/\\b\\f\\n\\r\\t\\u0000\"}", MAX));
    }

    @Test
    void readsWhatItWrites() {
        Map<String, Object> o = JsonWriter.object("t", "line\nbreak \"q\" <b> & \u2028", "n", 3L, "d", -0.25, "b", false,
                "z", null, "l", List.of(1L, "x"));
        assertEquals(o, JsonReader.object(JsonWriter.writePlain(o), MAX));
        assertEquals(o, JsonReader.object(JsonWriter.write(o), MAX));
    }

    private static String message(Runnable r) {
        return assertThrows(JsonException.class, r::run).getMessage();
    }
}
