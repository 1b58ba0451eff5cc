package org.tinysep.json;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;

class JsonWriterTest {

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
                + "\"ok\":true,\"none\":null,\"at\":\"2026-11-25T14:00:00Z\",\"list\":[1,\"a\"]}", JsonWriter.write(m));
    }

    /** The MQTT payloads: JSON's own escapes only, byte for byte what the bridge wrote before. */
    @Test
    void plainLeavesMarkupAlone() {
        assertEquals("{\"t\":\"a < b & c > d \\\"q\\\" \\\\ \\n\\r\\t\\u0001\u2028\",\"n\":3,\"b\":false,\"z\":null}",
                JsonWriter.writePlain(JsonWriter.object("t", "a < b & c > d \"q\" \\ \n\r\t\u0001\u2028", "n", 3, "b",
                        false, "z", null)));
    }

    @Test
    void writesNumbersEnumsAndOddValues() {
        assertEquals("[1,2,1.5,0.25,null,null,\"SECONDS\",\"2026-11-25T14:00:00Z\",{},[]]", JsonWriter.write(List.of(1,
                2L, 1.5, 0.25f, Double.NaN, Double.POSITIVE_INFINITY, TimeUnit.SECONDS,
                Instant.parse("2026-11-25T14:00:00Z"), Map.of(), List.of())));
        assertEquals("\"\\u2028\\u2029\\u0008\\u000c\"", JsonWriter.write("\u2028\u2029\b\f"));
    }

    /** The board's views are written piece by piece. */
    @Test
    void buildsPieceByPiece() {
        JsonWriter j = new JsonWriter().open('{').field("ok", true).field("explanation", "a & b");
        j.key("flats").open('[');
        for (int i = 0; i < 2; i++) {
            j.open('{').field("flat", "f" + i).field("battery", i == 0 ? null : 7).key("alerts").open('[').close(']')
                    .close('}');
        }
        j.close(']').field("nan", Double.NaN).key("m").value(Map.of("k", List.of(1))).close('}');
        assertEquals("{\"ok\":true,\"explanation\":\"a \\u0026 b\",\"flats\":[{\"flat\":\"f0\",\"battery\":null,"
                + "\"alerts\":[]},{\"flat\":\"f1\",\"battery\":7,\"alerts\":[]}],\"nan\":null,\"m\":{\"k\":[1]}}",
                j.toString());
    }
}
