package org.tinysep.amica.presence.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.time.PlatformClock;

/** Reed-Switch Status in, presence ON/OFF out, with the kind of the node type; repeats are not re-announced. */
class AmicaPresenceDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-26T10:00:00Z");

    private final RecordingLogs logs = new RecordingLogs(() -> T0);

    private AmicaPresenceDevice device(FakeAmicaBus bus) {
        return new AmicaPresenceDevice(
                new DriverContext(null, "d", "AmicaPresence", logs.reporter(), new PlatformClock(() -> T0)), bus);
    }

    private static void send(AmicaPresenceDevice d, FakeAmicaBus bus, Object payload, int second) {
        byte[] bytes = payload instanceof ReedSwitchStatus r ? AmicaPayloads.encode(r)
                : payload instanceof MotionDetection m ? AmicaPayloads.encode(m)
                : AmicaPayloads.encode((KeepAlive) payload);
        d.payloadReceived(bus, bytes, T0.plusSeconds(second));
    }

    @Test
    void aSeatMatAnnouncesTheFirstReportThenChangesOnlyAndLogsThemInTheHistoryWords() {
        FakeAmicaBus bus = new FakeAmicaBus("1.41", NodeType.PRESENCE_SEAT);
        AmicaPresenceDevice seat = device(bus);
        List<String> seen = new ArrayList<>();
        seat.connect((src, present, first, at) -> seen.add((first ? "first " : "change ") + present + "@"
                + (at.getEpochSecond() - T0.getEpochSecond()) + " " + src.kind()));

        assertFalse(seat.present(), "nothing reported yet");
        assertEquals("UNKNOWN", parameter(seat, "state"));
        send(seat, bus, new ReedSwitchStatus(false), 0);
        send(seat, bus, new ReedSwitchStatus(false), 1);
        send(seat, bus, new KeepAlive(1, 3000, 1, 0x0200, 9), 2);
        send(seat, bus, new MotionDetection(true), 2); // another type's payload is not ours
        send(seat, bus, new ReedSwitchStatus(true), 3);
        send(seat, bus, new ReedSwitchStatus(true), 4);
        send(seat, bus, new ReedSwitchStatus(false), 9);

        assertEquals(List.of("first false@0 SEAT", "change true@3 SEAT", "change false@9 SEAT"), seen);
        assertFalse(seat.present());
        assertEquals(List.of("seat off", "seat on", "seat off"), deviceEvents(),
                "Inactivity Recognition's history reads exactly these words (HistoryFromLog)");
        assertEquals("OFF", parameter(seat, "state"));
        assertEquals(T0.plusSeconds(9).toString(), parameter(seat, "since"));
        assertEquals("SEAT", parameter(seat, "kind"));
        assertEquals("Seat mat 1.41", seat.name());
        assertEquals(0, bus.sent.size(), "a presence node is never sent anything");
    }

    @Test
    void theKindAndTheOwnNodeTypeComeFromTheAnnouncedPresenceType() {
        for (PresenceKind k : List.of(PresenceKind.BED, PresenceKind.SEAT, PresenceKind.FLUSH,
                PresenceKind.APPLIANCE)) {
            String type = NodeType.PRESENCE_PREFIX + k.name().toLowerCase(java.util.Locale.ROOT);
            AmicaPresenceDevice d = device(new FakeAmicaBus("1.50", type, NodeType.MOVEMENT));
            assertEquals(k, d.kind(), type);
            assertEquals(type, PresenceNodeKind.typeName(k), "its own node type (service property)");
        }
        AmicaPresenceDevice both = device(new FakeAmicaBus("1.51", NodeType.PRESENCE_APPLIANCE,
                NodeType.PRESENCE_BED));
        assertEquals(PresenceKind.BED, both.kind(), "two presence types: the first of bed, seat, flush, appliance");
        assertEquals("Bed mat 1.51", both.name());
        assertEquals(PresenceKind.OTHER, PresenceNodeKind.of(Set.of(NodeType.WINDOW)));
    }

    @Test
    void aBedMatOnLogsBedOnAndIsPresentUntilOff() {
        FakeAmicaBus bus = new FakeAmicaBus("1.50", NodeType.PRESENCE_BED);
        AmicaPresenceDevice bed = device(bus);
        send(bed, bus, new ReedSwitchStatus(true), 0);
        assertTrue(bed.present(), "a first report ON: someone lies in bed");
        assertEquals("ON", parameter(bed, "state"));
        send(bed, bus, new ReedSwitchStatus(false), 5);
        assertFalse(bed.present());
        assertEquals(List.of("bed on", "bed off"), deviceEvents());
    }

    @Test
    void nothingCanBeSet() {
        AmicaPresenceDevice d = device(new FakeAmicaBus("1.22", NodeType.PRESENCE_FLUSH));
        assertThrows(IllegalArgumentException.class, () -> d.setParameter("kind", "BED"));
        assertThrows(IllegalArgumentException.class, () -> d.setParameter("state", "ON"));
        assertEquals(PresenceKind.FLUSH, d.kind());
    }

    private List<String> deviceEvents() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message())
                .toList();
    }

    private static String parameter(AmicaPresenceDevice d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError("no parameter " + key));
    }
}
