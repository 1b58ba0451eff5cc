package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/** The bridge's commands read with the shared JSON library (its own cases in org.tinysep.json's tests). */
class CommandPayloadTest {

    @Test
    void readsACommandObject() {
        assertEquals(Map.of("parameter", "on", "value", true), Commands.object("{\"parameter\":\"on\",\"value\":true}"));
    }

    @Test
    void refusesBadPayloadsSayingWhatAndWhere() {
        for (String bad : List.of("", "not json", "[1]", "{\"a\":1} x", "{\"a\":\"\\x\"}", "[".repeat(5))) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> Commands.object(bad), bad);
            assertTrue(e.getMessage().startsWith("the payload is "), e.getMessage());
        }
        assertEquals("the payload is not a JSON object: '{' expected at character 1",
                assertThrows(IllegalArgumentException.class, () -> Commands.object("not json")).getMessage());
        assertEquals("the payload is not valid JSON: ',' or '}' expected at character 8",
                assertThrows(IllegalArgumentException.class, () -> Commands.object("{\"a\":1 2}")).getMessage());
        assertEquals("the payload is longer than 16384 characters", assertThrows(IllegalArgumentException.class,
                () -> Commands.object("{\"a\":\"" + "x".repeat(Commands.MAX_PAYLOAD) + "\"}")).getMessage());
        String deep = "{\"a\":" + "[".repeat(100) + "]".repeat(100) + "}";
        assertTrue(assertThrows(IllegalArgumentException.class, () -> Commands.object(deep)).getMessage()
                .contains("nested too deeply"));
    }
}
