package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonReaderTest {

    @Test
    void readsACommand() {
        Map<String, Object> o = JsonReader.object(" {\"parameter\":\"on\", \"value\": true, \"n\": -12, \"d\": 1.5,"
                + " \"s\": \"a\\\"b\\u00e9\", \"l\": [1, null], \"x\": {}} ");
        assertEquals("on", o.get("parameter"));
        assertEquals(Boolean.TRUE, o.get("value"));
        assertEquals(-12L, o.get("n"));
        assertEquals(1.5, o.get("d"));
        assertEquals("a\"bé", o.get("s"));
        assertEquals(java.util.Arrays.asList(1L, null), o.get("l"));
        assertEquals(Map.of(), o.get("x"));
    }

    @Test
    void refusesBadInputInWords() {
        for (String bad : List.of("", "not json", "[1]", "{", "{\"a\":}", "{\"a\":1} x", "{\"a\":\"open",
                "{a:1}", "{\"a\":tru}", "{\"a\":1e}", "[".repeat(5))) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> JsonReader.object(bad),
                    bad);
            assertTrue(e.getMessage().startsWith("the payload is"), e.getMessage());
        }
        String deep = "{\"a\":" + "[".repeat(100) + "]".repeat(100) + "}";
        assertTrue(assertThrows(IllegalArgumentException.class, () -> JsonReader.object(deep)).getMessage()
                .contains("nested too deeply"));
        String huge = "{\"a\":\"" + "x".repeat(JsonReader.MAX_LENGTH) + "\"}";
        assertTrue(assertThrows(IllegalArgumentException.class, () -> JsonReader.object(huge)).getMessage()
                .contains("longer than"));
    }

    @Test
    void writesWhatItReads() {
        Map<String, Object> o = Json.object("t", "line\nbreak \"q\"", "n", 3, "b", false, "z", null);
        assertEquals(o, JsonReader.object(Json.write(o)).entrySet().stream().collect(
                java.util.LinkedHashMap::new, (m, e) -> m.put(e.getKey(), e.getValue() instanceof Long l
                        ? Integer.valueOf(l.intValue()) : e.getValue()), Map::putAll));
    }
}
