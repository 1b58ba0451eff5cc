package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** Request bodies, read with the shared JSON library (its own cases, and the writer's, in org.tinysep.json's tests). */
class JsonTest {

    @Test
    void readsAFlatObject() {
        Map<String, String> body = JsonBody.parse(" {\"value\": \"K\\u00fcche \\\"1\\\"\", \"n\": -1.5, \"b\": true, \"z\": null} ");
        assertEquals(Map.of("value", "Küche \"1\"", "n", "-1.5", "b", "true"), body);
        assertEquals(Map.of(), JsonBody.parse("{}"));
    }

    @Test
    void refusesEverythingElseWithA400ThatSaysWhere() {
        for (String bad : Arrays.asList(null, "", "[]", "{\"a\":[1]}", "{\"a\":{}}", "{\"a\":1,}", "{\"a\" 1}", "{\"a\":\"x\"} x",
                "{\"a\":\"unterminated}", "{a:1}", "{\"a\":tru}")) {
            ApiException e = assertThrows(ApiException.class, () -> JsonBody.parse(bad), bad);
            assertEquals(400, e.status());
            assertTrue(e.getMessage().startsWith("the request body is not a flat JSON object: "), e.getMessage());
        }
        assertEquals("the request body is not a flat JSON object: only text, number, true, false or null values are"
                + " accepted at character 7", assertThrows(ApiException.class, () -> JsonBody.parse("{\"a\": [1]}"))
                .getMessage());
    }
}
