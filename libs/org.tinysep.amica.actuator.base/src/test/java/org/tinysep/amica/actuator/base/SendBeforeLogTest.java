package org.tinysep.amica.actuator.base;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.testing.FakeAmicaBus;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 29, packet → light command: a command is on the wire before its "requested" line is written to the event
 * log (writing an entry wakes the log's threads, which on a 2-core gateway took the CPU from the send). The lines
 * and their order are unchanged, a failed send included.
 */
class SendBeforeLogTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    /** A bus that records how many event-log entries existed when each command was sent. */
    private static final class Wire extends FakeAmicaBus {
        final List<Integer> entriesAtSend = new ArrayList<>();
        private final RecordingLogs logs;

        Wire(RecordingLogs logs) {
            super("1.22", "heater");
            this.logs = logs;
        }

        @Override
        public void send(byte[] payload) {
            entriesAtSend.add(logs.events().size());
            super.send(payload);
        }
    }

    private static final class Heater extends PercentActuatorDevice<HeaterControl, Object> {
        Heater(DriverContext context, FakeAmicaBus bus) {
            super(context, bus, "Heater", NodeType.HEATER, "potency", HeaterControl.class, HeaterControl::percent,
                    HeaterControl::new, Heater.class, (listener, self, value, at) -> { });
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final Wire wire = new Wire(logs);
    private final Heater device = new Heater(new DriverContext(null, "d", "TestHeater", logs.reporter(),
            new PlatformClock(() -> T0)), wire);

    private List<String> deviceEvents() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT).map(e -> e.message()).toList();
    }

    @Test
    void theCommandIsSentBeforeItsRequestIsLogged() {
        int before = logs.events().size();
        device.setLevel(Percent.of(40));
        device.setLevel(Percent.of(60));
        assertEquals(List.of(before, before + 1), wire.entriesAtSend,
                "event-log entries when each command was sent (the first found " + before + " before it)");
        assertEquals(List.of("potency 40% requested", "potency 60% requested"), deviceEvents());
    }

    @Test
    void aFailedSendStillSaysBothLinesInOrder() {
        wire.failure = new IllegalStateException("bus radio is closed");
        device.setLevel(Percent.of(40));
        assertEquals(List.of("potency 40% requested", "potency 40% not sent: bus radio is closed"), deviceEvents());
    }
}
