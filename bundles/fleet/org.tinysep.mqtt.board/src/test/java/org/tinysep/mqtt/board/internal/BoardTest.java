package org.tinysep.mqtt.board.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.mqtt.board.internal.Flat.Entry;
import org.tinysep.mqtt.board.internal.Liveness.Rules;
import org.tinysep.mqtt.board.internal.Liveness.Status;
import org.tinysep.mqtt.board.internal.Liveness.Verdict;

/** The board's state machine on the contract's messages, without a broker. */
class BoardTest {

    static final Rules RULES = new Rules(3, 26, 20, ZoneOffset.UTC);
    final Board board = new Board("tinysep", 100);
    Instant now = Instant.parse("2026-11-25T14:00:00Z");

    boolean send(String topic, String payload) {
        return board.accept(topic, payload.getBytes(StandardCharsets.UTF_8), now);
    }

    Verdict verdict(String flat) {
        return Liveness.judge(board.find(flat).orElseThrow().snapshot(), RULES, now);
    }

    static String platform(Instant heartbeat) {
        return platform(Instant.parse("2026-11-25T08:00:00Z"), heartbeat);
    }

    /** A flat's platform message; started is also the board's reference for the daily summary until one comes. */
    static String platform(Instant started, Instant heartbeat) {
        return "{\"flat\":\"17\",\"version\":\"0.1.0\",\"startedAt\":\"" + started + "\",\"heartbeatAt\":\""
                + heartbeat + "\",\"heartbeatSeconds\":60}";
    }

    static String alert(long id, String state, long seq) {
        return "{\"id\":\"" + id + "\",\"flat\":\"17\",\"kind\":\"INACTIVITY\",\"state\":\"" + state
                + "\",\"raisedAt\":\"2026-11-25T14:00:00Z\",\"room\":\"Bedroom\",\"title\":\"No movement\","
                + "\"text\":\"Anna has not moved for 2 h\",\"acknowledgedBy\":" + (state.equals("OPEN") ? "null" : "\"Eva\"")
                + ",\"acknowledgedAt\":" + (state.equals("OPEN") ? "null" : "\"2026-11-25T14:05:00Z\"") + ",\"seq\":" + seq + "}";
    }

    @Test
    void onlineThenSilentThenOfflineEachExplained() {
        send("tinysep/17/status", "online");
        send("tinysep/17/platform", platform(now));
        send("tinysep/17/occupancy", "{\"state\":\"OCCUPIED\",\"since\":\"2026-11-25T13:00:00Z\",\"explanation\":\"movement in the kitchen\"}");
        assertEquals(Status.ONLINE, verdict("17").status());
        assertTrue(verdict("17").explanation().startsWith("Flat 17: online since 14:00"), verdict("17").explanation());

        now = now.plusSeconds(180); // exactly 3 heartbeats: not yet
        assertEquals(Status.ONLINE, verdict("17").status());
        now = now.plusSeconds(1);
        Verdict silent = verdict("17");
        assertEquals(Status.SILENT, silent.status());
        assertEquals("Flat 17: platform silent since 14:00 — no heartbeat for 3 min (it sends one every 60 s);"
                + " its last words: occupancy OCCUPIED (movement in the kitchen) at 14:00", silent.explanation());

        now = now.plusSeconds(60);
        send("tinysep/17/platform", platform(now)); // heartbeat again: online
        assertEquals(Status.ONLINE, verdict("17").status());

        send("tinysep/17/status", "offline"); // the Last Will
        Verdict offline = verdict("17");
        assertEquals(Status.OFFLINE, offline.status());
        assertTrue(offline.explanation().contains("platform offline since 14:04") && offline.explanation().contains("Last Will")
                && offline.explanation().contains("its last words: occupancy OCCUPIED"), offline.explanation());
    }

    @Test
    void anOldRetainedHeartbeatCountsFromItsOwnTime() {
        send("tinysep/17/status", "online");
        send("tinysep/17/platform", platform(now.minusSeconds(600))); // retained, read when the board starts
        assertEquals(Status.SILENT, verdict("17").status());
        assertTrue(verdict("17").explanation().contains("no heartbeat for 10 min"), verdict("17").explanation());
    }

    @Test
    void noDailySummaryForMoreThan26HoursIsSilent() {
        send("tinysep/17/status", "online");
        send("tinysep/17/summary", "{\"at\":\"" + now + "\",\"text\":\"TinySEP is running\"}");
        for (int i = 0; i < 26 * 60; i++) { // heartbeats every minute for 26 h
            now = now.plusSeconds(60);
            send("tinysep/17/platform", platform(now));
        }
        assertEquals(Status.ONLINE, verdict("17").status());
        now = now.plusSeconds(60);
        send("tinysep/17/platform", platform(now));
        Verdict v = verdict("17");
        assertEquals(Status.SILENT, v.status());
        assertTrue(v.explanation().contains("no daily summary for 26 h (the last one at 2026-11-25 14:00), more than 26 h"),
                v.explanation());
    }

    @Test
    void noStatusYetIsUnknown() {
        send("tinysep/17/occupancy", "{\"state\":\"UNOCCUPIED\"}");
        assertEquals(Status.UNKNOWN, verdict("17").status());
        assertTrue(verdict("17").explanation().startsWith("Flat 17: no status yet"));
    }

    @Test
    void fallAndHelpAlertsAreNamedInWordsEvenWithoutATitle() {
        assertTrue(send("tinysep/17/alert/4", alert(4, "OPEN", 1).replace("\"INACTIVITY\"", "\"FALL\"")
                .replace("\"No movement\"", "\"\"").replace("Anna has not moved for 2 h", "a fall of Anna was detected "
                + "at 14:00; last seen in the Bathroom at 13:59 by its motion sensor")));
        assertEquals("Flat 17: fall (the person may have fallen) in Bedroom, raised at 14:00: a fall of Anna was "
                + "detected at 14:00; last seen in the Bathroom at 13:59 by its motion sensor — not acknowledged yet",
                BoardView.alertWords("17", only("17"), RULES, now));
        assertEquals("help button (the person asked for help)", BoardTime.kind("HELP"));
        assertEquals("something new", BoardTime.kind("SOMETHING_NEW"));
    }

    @Test
    void alertOpenThenAcknowledgedThenClearedThenGone() {
        assertTrue(send("tinysep/17/alert/3", alert(3, "OPEN", 1)));
        Entry open = only("17");
        assertEquals("OPEN", open.alert().state());
        assertTrue(BoardView.alertWords("17", open, RULES, now).endsWith("not acknowledged yet"));

        assertTrue(board.find("17").orElseThrow().ackSent("3", "Eva", now));
        assertTrue(BoardView.alertWords("17", only("17"), RULES, now)
                .endsWith("acknowledgement sent by Eva at 14:00, waiting for the flat to confirm it"));

        now = now.plusSeconds(2);
        assertTrue(send("tinysep/17/alert/3", alert(3, "ACKNOWLEDGED", 2)));
        Entry acked = only("17");
        assertEquals("ACKNOWLEDGED", acked.alert().state());
        assertNotNull(acked.confirmedAt());
        assertEquals("Flat 17: No movement in Bedroom, raised at 14:00: Anna has not moved for 2 h — acknowledged by Eva"
                + " at 14:05; the flat confirmed it at 14:00", BoardView.alertWords("17", acked, RULES, now));

        assertTrue(send("tinysep/17/alert/3", alert(3, "CLEARED", 3)));
        assertEquals("CLEARED", only("17").alert().state());
        assertTrue(send("tinysep/17/alert/3", "")); // the retained topic emptied
        assertTrue(board.find("17").orElseThrow().snapshot().alerts().isEmpty());
        assertFalse(send("tinysep/17/alert/3", alert(3, "OPEN", 1)), "a late duplicate must not bring it back");
        assertTrue(board.find("17").orElseThrow().snapshot().alerts().isEmpty());
    }

    @Test
    void duplicatesAndStaleMessagesAreDroppedBySeq() {
        assertTrue(send("tinysep/17/alert/3", alert(3, "OPEN", 5)));
        assertFalse(send("tinysep/17/alert/3", alert(3, "OPEN", 5)));
        assertTrue(send("tinysep/17/alert/3", alert(3, "ACKNOWLEDGED", 7)));
        assertFalse(send("tinysep/17/alert/3", alert(3, "OPEN", 6)), "older than what the board has");
        assertEquals("ACKNOWLEDGED", only("17").alert().state());
        assertEquals(2, board.totals().duplicates());
        assertEquals(2, board.find("17").orElseThrow().snapshot().duplicates());
    }

    @Test
    void badPayloadsAreCountedWithTheirReasonNeverThrown() {
        List<String[]> bad = List.of(
                new String[] {"tinysep/17/status", "maybe"},
                new String[] {"tinysep/17/platform", "{not json"},
                new String[] {"tinysep/17/platform", "{\"heartbeatAt\":\"yesterday\",\"heartbeatSeconds\":60}"},
                new String[] {"tinysep/17/occupancy", "{\"state\":\"FULL\"}"},
                new String[] {"tinysep/17/alert/3", "{\"id\":\"3\",\"state\":\"OPEN\"}"},
                new String[] {"tinysep/17/alert/3", "{\"id\":\"4\",\"state\":\"OPEN\",\"seq\":1}"},
                new String[] {"tinysep/17/alert/3", "{\"id\":\"3\",\"flat\":\"18\",\"state\":\"OPEN\",\"seq\":1}"},
                new String[] {"tinysep/17/device/x/health", "{\"status\":\"ONLINE\",\"battery\":\"full\"}"},
                new String[] {"tinysep/17/summary", "[1,2]"},
                new String[] {"tinysep/17/summary", "x".repeat(Payloads.MAX_PAYLOAD + 1)});
        for (String[] m : bad) {
            assertFalse(send(m[0], m[1]), m[0] + " " + m[1]);
        }
        assertFalse(board.accept("tinysep/17/alert/3", new byte[] {(byte) 0xff, '{'}, now));
        assertFalse(send("elsewhere/17/status", "online"));
        Flat.Snapshot s = board.find("17").orElseThrow().snapshot();
        assertEquals(bad.size() + 1, s.bad());
        assertEquals(bad.size() + 2, board.totals().bad());
        assertTrue(s.lastBad().startsWith("tinysep/17/alert/3: not a flat JSON object"), s.lastBad());
        assertTrue(send("tinysep/17/status", "online"), "the flat still works after bad messages");
    }

    @Test
    void memoryPerFlatIsBounded() {
        for (int i = 1; i <= 100; i++) {
            send("tinysep/17/alert/" + i, alert(i, i % 2 == 0 ? "CLEARED" : "OPEN", i).replace("\"id\":\"" + i + "\"", "\"id\":\"" + i + "\""));
        }
        Flat.Snapshot s = board.find("17").orElseThrow().snapshot();
        assertEquals(Flat.MAX_ALERTS, s.alerts().size());
        assertEquals(50, s.alerts().stream().filter(e -> e.alert().state().equals("OPEN")).count(), "cleared ones go first");
        for (int i = 0; i < Flat.MAX_DEVICES + 10; i++) {
            send("tinysep/17/device/d" + i + "/health", "{\"status\":\"OFFLINE\",\"battery\":10}");
        }
        s = board.find("17").orElseThrow().snapshot();
        assertEquals(Flat.MAX_DEVICES, s.devices().size());
        assertEquals(10, s.dropped());
        Board small = new Board("tinysep", 2);
        for (int i = 0; i < 5; i++) {
            small.accept("tinysep/f" + i + "/status", "online".getBytes(StandardCharsets.UTF_8), now);
        }
        assertEquals(2, small.totals().flats());
        assertEquals(3, small.totals().refusedFlats());
    }

    @Test
    void theBoardJsonListsFlatsThatNeedSomeoneFirst() {
        send("tinysep/a/status", "online");
        send("tinysep/b/status", "offline");
        send("tinysep/c/status", "online");
        send("tinysep/c/alert/1", alert(1, "OPEN", 1).replace("\"flat\":\"17\"", "\"flat\":\"c\""));
        send("tinysep/a/device/s1/health", "{\"status\":\"OFFLINE\",\"battery\":15,\"explanation\":\"movement sensor silent since 13:00\"}");
        send("tinysep/a/device/s2/health", "{\"status\":\"ONLINE\",\"battery\":null,\"batteryMillivolts\":2150,"
                + "\"batteryLow\":true,\"lastReport\":null,\"linkQuality\":null,\"explanation\":\"fine\"}"); // as the bridge sends it
        String json = BoardView.json(board, RULES, now.plus(Duration.ofSeconds(5)), "connected", true);
        int c = json.indexOf("\"flat\":\"c\"");
        int b = json.indexOf("\"flat\":\"b\"");
        int a = json.indexOf("\"flat\":\"a\"");
        assertTrue(c > 0 && c < b && b < a, json);
        assertTrue(json.contains("\"explanation\":\"movement sensor silent since 13:00\""), json);
        assertTrue(json.contains("battery of s1 at 15 % (low at 20 % or less)"), json);
        assertTrue(json.contains("battery of s2 low, its node says (2.15 V)"), json);
    }

    Entry only(String flat) {
        List<Entry> alerts = board.find(flat).orElseThrow().snapshot().alerts();
        assertEquals(1, alerts.size());
        return alerts.get(0);
    }
}
