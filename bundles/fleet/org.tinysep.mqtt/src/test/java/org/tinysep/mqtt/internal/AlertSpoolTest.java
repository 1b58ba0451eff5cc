package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class AlertSpoolTest {

    @TempDir
    Path dir;

    private static Message alert(AlertSpool spool, String id, String payload) throws Exception {
        long seq = spool.nextSeq();
        Message m = new Message("tinysep/f/alert/" + id, payload.getBytes(StandardCharsets.UTF_8), true, seq, id);
        spool.add(m);
        return m;
    }

    @Test
    void waitingAlertsSurviveARestartInSeqOrderAndSeqGoesOn() throws Exception {
        AlertSpool spool = new AlertSpool(dir);
        Message a = alert(spool, "1", "{\"state\":\"OPEN\",\"seq\":1}");
        Message b = alert(spool, "2", "{\"state\":\"OPEN\",\"seq\":2}");
        Message c = alert(spool, "1", "{\"state\":\"ACKNOWLEDGED\",\"seq\":3}");
        spool.delivered(a);

        AlertSpool again = new AlertSpool(dir);
        assertEquals(List.of(b, c), again.pending(), "the undelivered ones, oldest first");
        assertEquals(List.of(a), again.delivered());
        assertEquals(c, again.latest("1"));
        assertEquals(4, again.nextSeq(), "seq never goes back after a restart");
    }

    @Test
    void anEmptiedAlertIsForgotten() throws Exception {
        AlertSpool spool = new AlertSpool(dir);
        Message cleared = alert(spool, "5", "{\"state\":\"CLEARED\"}");
        Message empty = alert(spool, "5", "");
        spool.delivered(cleared);
        spool.delivered(empty);
        AlertSpool again = new AlertSpool(dir);
        assertTrue(again.pending().isEmpty());
        assertTrue(again.delivered().isEmpty());
        assertNull(again.latest("5"));
        assertEquals(3, again.nextSeq());
    }

    @Test
    void aDamagedFileIsMovedAsideAndTheOthersAreKept() throws Exception {
        AlertSpool spool = new AlertSpool(dir);
        Message ok = alert(spool, "1", "{\"state\":\"OPEN\"}");
        Files.writeString(dir.resolve("outbox").resolve("00000000000000000099.msg"), "garbage");
        AlertSpool again = new AlertSpool(dir);
        assertEquals(List.of(ok), again.pending());
        try (var files = Files.list(dir.resolve("outbox"))) {
            assertTrue(files.anyMatch(f -> f.getFileName().toString().contains(".broken-")));
        }
    }
}
