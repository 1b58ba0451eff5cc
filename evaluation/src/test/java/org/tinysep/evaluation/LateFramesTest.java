package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** A node's frames in the platform's packet log against the instants they were played at. */
class LateFramesTest {

    private static final String NODE = "0014.4F01.0000.FA11";
    private static final Instant T = Instant.parse("2026-11-29T14:42:29.020Z");

    @TempDir
    Path var;

    @Test
    void framesStampedAtAnotherInstantThanPlayedAreCounted() throws Exception {
        Files.createDirectories(var.resolve("log"));
        Files.write(var.resolve("log/packets-00000000000000000001.log"), List.of(
                line("2026-11-29T14:42:20Z", "0014.4F01.0000.BEEF"), // before the recordings: not counted
                line("2026-11-29T14:42:29.020Z", NODE), // as played
                line("2026-11-29T14:42:29.280Z", NODE), // as played
                line("2026-11-29T14:42:31.980Z", NODE), // played at 29.92: handled after the next TICK
                line("2026-11-29T14:42:31.980Z", "0014.4F01.0000.BEEF"), // another node
                "2026-11-29T14:42:32Z\t9\tREJECTED\tnode " + NODE + " via udp 127.0.0.1:1\tFF\t"));
        LateFrames late = new LateFrames();
        late.played(List.of(T, T.plusMillis(260), T.plusMillis(900)));
        assertEquals(3, late.played());
        assertEquals(1, late.late(var, NODE, T));
        assertEquals(0, late.late(var.resolve("nothing"), NODE, T), "no packet log: nothing to count");
    }

    private static String line(String at, String node) {
        return at + "\t1\tRECEIVED\tnode " + node + " via udp 127.0.0.1:40989\t0E00\t";
    }
}
