package org.tinysep.link.frame.testing;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Function;
import java.util.function.Predicate;

/**
 * The runner of the doc-vector tests of both protocol families: reads the fenced {@code vector} blocks of a protocol
 * document ({@code docs/protocols/<name>.md}) and checks each vector against the family's codec, so the document
 * stays honest. A vector is a block of {@code key: value} lines; blank lines separate vectors.
 */
public final class DocVectors {

    /** What a family checks. */
    public interface Family {

        /** @return the name of the reason the codec rejects {@code bytes} with; fails if it decodes them */
        String rejection(String name, byte[] bytes);

        /** Checks a vector that must decode: its frame, encoding and payload. */
        void valid(String name, Map<String, String> vector, byte[] bytes) throws Exception;
    }

    private DocVectors() {
    }

    /** @param doc the document's file name under {@code docs/protocols/}, e.g. {@code "amica.md"} */
    public static List<Map<String, String>> read(String doc) throws IOException {
        Path path = Path.of(System.getProperty("basedir", "."), "../../docs/protocols", doc);
        List<Map<String, String>> out = new ArrayList<>();
        boolean inBlock = false;
        Map<String, String> current = new LinkedHashMap<>();
        for (String line : Files.readAllLines(path, StandardCharsets.UTF_8)) {
            if (!inBlock) {
                inBlock = line.trim().equals("```vector");
                continue;
            }
            if (line.trim().startsWith("```") || line.isBlank()) {
                if (!current.isEmpty()) {
                    out.add(current);
                    current = new LinkedHashMap<>();
                }
                inBlock = !line.trim().startsWith("```");
                continue;
            }
            int colon = line.indexOf(':');
            assertTrue(colon > 0, "vector line without key: " + line);
            String key = line.substring(0, colon).trim();
            assertTrue(current.put(key, line.substring(colon + 1).trim()) == null, "duplicate key " + key);
        }
        assertTrue(!inBlock, "unterminated vector block");
        return out;
    }

    /** Every reason but the exceptions must be the {@code reject} or {@code payload-reject} of some vector. */
    public static void assertEveryReasonUsed(List<Map<String, String>> vectors, Enum<?>[] reasons,
            List<? extends Enum<?>> except) {
        for (Enum<?> r : reasons) {
            if (!except.contains(r)) {
                assertTrue(vectors.stream().anyMatch(v -> r.name().equals(v.get("reject"))
                        || r.name().equals(v.get("payload-reject"))), "no vector rejected with " + r);
            }
        }
    }

    /**
     * Each vector has a name, hex and dec bytes that agree, and is either rejected with its {@code reject} reason
     * or valid as the family checks it.
     */
    public static void check(List<Map<String, String>> vectors, Family family) throws Exception {
        for (Map<String, String> v : vectors) {
            String name = v.get("name");
            assertTrue(name != null && v.containsKey("hex") && v.containsKey("dec"), "incomplete vector " + v);
            byte[] bytes = TestBytes.hex(v.get("hex"));
            assertArrayEquals(bytes, TestBytes.dec(v.get("dec")), name + ": hex and dec differ");
            if (v.containsKey("reject")) {
                assertEquals(v.get("reject"), family.rejection(name, bytes), name);
            } else {
                family.valid(name, v, bytes);
            }
        }
    }

    /** Fails the vector {@code name} unless {@code frame} matched: it needs a frame line like {@code format}. */
    public static void requireFrame(boolean matched, String name, String format) {
        if (!matched) {
            fail(name + ": needs 'frame: " + format + "' or 'reject:'");
        }
    }

    /**
     * The bytes of every valid vector that {@code keep} accepts (at least {@code atLeast} of them), written as one
     * stream, must be found by the family's stream decoder, frame by frame, without a skipped byte.
     *
     * @param decode decodes a stream; returns the frames found and the bytes skipped
     */
    public static void assertStreamFindsEvery(List<Map<String, String>> vectors, Predicate<byte[]> keep, int atLeast,
            Function<byte[], long[]> decode) {
        List<byte[]> valid = new ArrayList<>();
        for (Map<String, String> v : vectors) {
            byte[] bytes = TestBytes.hex(v.get("hex"));
            if (!v.containsKey("reject") && keep.test(bytes)) {
                valid.add(bytes);
            }
        }
        assertTrue(valid.size() >= atLeast, "valid frames: " + valid.size());
        long[] found = decode.apply(TestBytes.concat(valid.toArray(new byte[0][])));
        assertEquals(valid.size(), found[0], "frames found");
        assertEquals(0, found[1], "bytes skipped");
    }
}
