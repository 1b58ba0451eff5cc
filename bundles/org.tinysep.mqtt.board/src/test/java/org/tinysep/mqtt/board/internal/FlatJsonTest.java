package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.Map;
import org.junit.jupiter.api.Test;

class FlatJsonTest {

    @Test
    void readsTheContractsFlatObjects() {
        assertEquals(Map.of("a", "x\"y\u00e9", "n", "-1.5e3", "b", "true"),
                FlatJson.parse(" {\"a\":\"x\\\"y\\u00e9\",\"n\":-1.5e3,\"b\":true,\"z\":null} "));
        assertEquals(Map.of(), FlatJson.parse("{}"));
    }

    @Test
    void refusesEverythingElseSayingWhere() {
        for (String bad : new String[] {"", "[]", "{\"a\":}", "{\"a\":1", "{\"a\":{}}", "{\"a\":1} x", "{a:1}", "{\"a\":tru}"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> FlatJson.parse(bad), bad);
            assertEquals(true, e.getMessage().startsWith("not a flat JSON object: "), e.getMessage());
        }
    }
}
