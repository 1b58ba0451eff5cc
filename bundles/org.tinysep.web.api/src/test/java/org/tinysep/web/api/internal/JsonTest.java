package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class JsonTest {

    @Test
    void writesValuesAndEscapesMarkup() {
        Map<String, Object> m = new LinkedHashMap<>();
        m.put("name", "<script>alert(\"x\")</script> & \n");
        m.put("n", 3L);
        m.put("ok", true);
        m.put("none", null);
        m.put("at", Instant.parse("2026-11-25T14:00:00Z"));
        m.put("list", List.of(1, "a"));
        assertEquals("{\"name\":\"\\u003cscript\\u003ealert(\\\"x\\\")\\u003c/script\\u003e \\u0026 \\n\",\"n\":3,"
                + "\"ok\":true,\"none\":null,\"at\":\"2026-11-25T14:00:00Z\",\"list\":[1,\"a\"]}", Json.write(m));
    }

    @Test
    void readsAFlatObject() {
        Map<String, String> body = JsonBody.parse(" {\"value\": \"K\\u00fcche \\\"1\\\"\", \"n\": -1.5, \"b\": true, \"z\": null} ");
        assertEquals(Map.of("value", "Küche \"1\"", "n", "-1.5", "b", "true"), body);
        assertEquals(Map.of(), JsonBody.parse("{}"));
    }

    @Test
    void refusesEverythingElseWithA400ThatSaysWhere() {
        for (String bad : Arrays.asList("", "[]", "{\"a\":[1]}", "{\"a\":{}}", "{\"a\":1,}", "{\"a\" 1}", "{\"a\":\"x\"} x",
                "{\"a\":\"unterminated}", "{a:1}", "{\"a\":tru}")) {
            ApiException e = assertThrows(ApiException.class, () -> JsonBody.parse(bad), bad);
            assertEquals(400, e.status());
            assertTrue(e.getMessage().startsWith("the request body is not a flat JSON object: "), e.getMessage());
        }
    }
}
