package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class OutboxTest {

    @TempDir
    Path dir;

    private static List<String> topics(List<Message> ms) {
        return ms.stream().map(Message::topic).toList();
    }

    private Message alert(Outbox o, String id) throws Exception {
        long seq = o.spool().nextSeq();
        Message m = new Message("a/" + id, ("{\"seq\":" + seq + "}").getBytes(StandardCharsets.UTF_8), true, seq, id);
        o.alert(m);
        return m;
    }

    @Test
    void statusFirstThenAlertsBySeqThenResultsThenState() throws Exception {
        Outbox o = new Outbox(new AlertSpool(dir), "status");
        o.state(Message.state("occupancy", "x"));
        o.state(Message.state("status", "online"));
        o.transientMessage(Message.transientMessage("result", "r"));
        alert(o, "1");
        alert(o, "2");
        o.connected();
        assertEquals(List.of("status", "a/1", "a/2", "result", "occupancy"), topics(o.next()));
        assertTrue(o.next().isEmpty(), "nothing twice while in flight");
    }

    @Test
    void stateIsCoalescedPerTopicAndUnchangedValuesAreNotSentAgain() throws Exception {
        Outbox o = new Outbox(new AlertSpool(dir), "status");
        o.connected();
        o.state(Message.state("t", "1"));
        o.state(Message.state("t", "2"));
        o.state(Message.state("t", "3"));
        List<Message> sent = o.next();
        assertEquals(1, sent.size());
        assertEquals("3", sent.get(0).text());
        assertEquals(2, o.coalesced());
        o.done(sent.get(0), true);
        o.state(Message.state("t", "3"));
        assertTrue(o.next().isEmpty(), "the same value is not sent again");
        o.connected();
        assertEquals(List.of("t"), topics(o.next()), "every state topic again after a reconnection");
    }

    @Test
    void anAlertStaysOnDiskUntilAcknowledgedAndIsResentAfterAFailure() throws Exception {
        Outbox o = new Outbox(new AlertSpool(dir), "status");
        Message a = alert(o, "7");
        o.connected();
        assertEquals(List.of(a), o.next());
        o.done(a, false);
        assertEquals(1, o.waitingAlerts());
        assertEquals(List.of(a), o.next(), "sent again after the failure");
        o.done(a, true);
        assertEquals(0, o.waitingAlerts());
        assertEquals(0, new AlertSpool(dir).pending().size(), "gone from the disk too");
        o.connected();
        assertEquals(List.of(a), o.next(), "the last delivered message is re-published after a reconnection");
    }

    @Test
    void theWindowBoundsWhatIsInFlightAndResultsAreBounded() throws Exception {
        Outbox o = new Outbox(new AlertSpool(dir), "status");
        o.connected();
        for (int i = 0; i < Outbox.MAX_TRANSIENT + 5; i++) {
            o.transientMessage(Message.transientMessage("result", Integer.toString(i)));
        }
        assertEquals(5, o.droppedTransient());
        List<Message> first = o.next();
        assertEquals(Outbox.WINDOW, first.size());
        assertEquals("5", first.get(0).text(), "the oldest were dropped");
        assertTrue(o.next().isEmpty());
        o.done(first.get(0), true);
        assertEquals(1, o.next().size());
    }
}
