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
import java.util.function.Supplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.link.frame.FrameStream;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * The runner of the doc-vector tests of both protocol families: reads the fenced {@code vector} blocks of a protocol
 * document ({@code docs/protocols/<name>.md}) and checks each vector against the family's codec, so the document
 * stays honest. A vector is a block of {@code key: value} lines; blank lines separate vectors.
 */
public final class DocVectors {

    /** What only a family checks of its valid vectors; the runner checks the rest. */
    public interface Family<F, P> {

        /**
         * @param payload the vector's payload bytes
         * @return the frame the vector's {@code frame} line states (see {@link #frameLine})
         */
        F frame(String name, Map<String, String> vector, byte[] payload);

        /** The family's own checks of a valid vector whose payload decodes (e.g. a keep-alive's node types). */
        void payload(String name, Map<String, String> vector, F frame, P payload);
    }

    private DocVectors() {
    }

    /** @param doc the document's file name under {@code docs/protocols/}, e.g. {@code "amica.md"} */
    public static List<Map<String, String>> read(String doc) throws IOException {
        Path path = RepoFiles.require("docs", "protocols", doc);
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

    /**
     * The document has at least 20 vectors, and for each of {@code required} a vector whose {@code key} value
     * contains it (e.g. a vector's name, or the payload text of a valid vector).
     */
    public static void assertRequired(List<Map<String, String>> vectors, String key, List<String> required) {
        assertTrue(vectors.size() >= 20, "vectors found: " + vectors.size());
        for (String r : required) {
            assertTrue(vectors.stream().anyMatch(v -> v.getOrDefault(key, "").contains(r)),
                    "no vector whose " + key + " contains " + r);
        }
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
     * Each vector has a name, hex and dec bytes that agree, and is either rejected by the codec with its
     * {@code reject} reason, or decodes to the frame its {@code frame} line states and encodes back to its bytes;
     * then its payload is rejected with its {@code payload-reject} reason, or decodes to the {@code payload} text,
     * encodes back and passes the family's own checks.
     */
    public static <F, P> void check(List<Map<String, String>> vectors, Codecs<F, P, ?> codecs, Family<F, P> family)
            throws Exception {
        for (Map<String, String> v : vectors) {
            String name = v.get("name");
            assertTrue(name != null && v.containsKey("hex") && v.containsKey("dec"), "incomplete vector " + v);
            byte[] bytes = TestBytes.hex(v.get("hex"));
            assertArrayEquals(bytes, TestBytes.dec(v.get("dec")), name + ": hex and dec differ");
            if (v.containsKey("reject")) {
                assertEquals(v.get("reject"), codecs.frameRejection(name, bytes).name(), name);
                continue;
            }
            byte[] payload = codecs.payloadOf(bytes);
            F expected = family.frame(name, v, payload);
            assertEquals(expected, codecs.frame(bytes), name + ": decode");
            assertArrayEquals(bytes, codecs.encode().apply(expected), name + ": encode");
            if (v.containsKey("payload-reject")) {
                assertEquals(v.get("payload-reject"), codecs.payloadRejection(name, payload).name(), name);
                continue;
            }
            P decoded = codecs.decodePayload().decode(payload);
            assertEquals(v.get("payload"), decoded.toString(), name + ": payload");
            assertArrayEquals(payload, codecs.encodePayload().apply(decoded), name + ": payload encode");
            family.payload(name, v, expected, decoded);
        }
    }

    /**
     * @param format how the line must look, for the failure message
     * @return the vector's {@code frame} line matched by {@code pattern}; fails the vector if it does not match
     */
    public static Matcher frameLine(Pattern pattern, String name, Map<String, String> vector, String format) {
        Matcher m = pattern.matcher(vector.getOrDefault("frame", ""));
        if (!m.matches()) {
            fail(name + ": needs 'frame: " + format + "' or 'reject:'");
        }
        return m;
    }

    /**
     * The bytes of every valid vector that {@code keep} accepts (at least {@code atLeast} of them), written as one
     * stream, must be found by the family's stream decoder, frame by frame, without a skipped byte.
     *
     * @param sinks    makes the family's recording sink
     * @param decoders makes the family's stream decoder with a sink
     */
    public static <F, R, S extends Recording<F, R>> void assertStreamFindsEvery(List<Map<String, String>> vectors,
            Predicate<byte[]> keep, int atLeast, Supplier<S> sinks, Function<S, FrameStream<F, R>> decoders) {
        List<byte[]> valid = new ArrayList<>();
        for (Map<String, String> v : vectors) {
            byte[] bytes = TestBytes.hex(v.get("hex"));
            if (!v.containsKey("reject") && keep.test(bytes)) {
                valid.add(bytes);
            }
        }
        assertTrue(valid.size() >= atLeast, "valid frames: " + valid.size());
        byte[] stream = TestBytes.concat(valid.toArray(new byte[0][]));
        S sink = sinks.get();
        decoders.apply(sink).accept(stream, 0, stream.length);
        assertEquals(valid.size(), sink.frames, "frames found");
        assertEquals(0, sink.skipped, "bytes skipped");
    }
}
