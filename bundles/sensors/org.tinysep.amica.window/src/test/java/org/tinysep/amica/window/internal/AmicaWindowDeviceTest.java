package org.tinysep.amica.window.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.KeepAlive;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/** Reed-switch payloads in, window changes out; the position parameter is validated and announced. */
class AmicaWindowDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final FakeBus bus = new FakeBus("1.21", "window", "movement");
    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final AmicaWindowDevice window = new AmicaWindowDevice(
            new DriverContext(null, "d", AmicaWindowDriver.NAME, logs.reporter(), new PlatformClock(() -> T0)), bus);
    private final List<String> heard = new ArrayList<>();

    AmicaWindowDeviceTest() {
        window.connect(new WindowListener() {
            @Override
            public void windowChanged(WindowProvider source, OpenState state, Instant at) {
                heard.add(state + "@" + (at.getEpochSecond() - T0.getEpochSecond()));
            }

            @Override
            public void windowPositionChanged(WindowProvider source, Coordinates position, Instant at) {
                heard.add("position " + position);
            }
        });
    }

    private void receive(Object payload, int second) {
        byte[] bytes = payload instanceof byte[] b ? b
                : AmicaPayloads.encode((org.tinysep.amica.protocol.AmicaPayload) payload);
        window.payloadReceived(bus, bytes, T0.plusSeconds(second));
    }

    @Test
    void announcesChangesOnlyAndIgnoresTheNodesOtherPayloads() {
        assertEquals(OpenState.UNKNOWN, window.state());
        receive(new ReedSwitchStatus(false), 0);
        receive(new ReedSwitchStatus(false), 1);
        receive(new MotionDetection(true), 1);
        receive(new KeepAlive(1, 2900, 1, 0x05, 7), 1);
        receive(new LightControl(40), 1);
        receive(new ReedSwitchStatus(true), 2);
        receive(new ReedSwitchStatus(true), 3);
        receive(new byte[] {100, 3, 0, 2}, 4); // bad value: the bus radio rejects these; never a state
        receive(new ReedSwitchStatus(false), 5);

        assertEquals(List.of("CLOSED@0", "OPEN@2", "CLOSED@5"), heard);
        assertEquals(OpenState.CLOSED, window.state());
        List<String> logged = logs.events().stream().filter(e -> e.kind() == EventKind.DEVICE_EVENT)
                .map(e -> e.message()).toList();
        assertEquals(List.of("window closed", "window opened", "window closed"), logged);
        assertEquals(0, bus.sent.size(), "a window sends nothing");
        assertEquals(T0.plusSeconds(5).toString(), parameter("since"));
    }

    @Test
    void positionIsOptionalValidatedAndAnnounced() {
        assertEquals(Optional.empty(), window.position());
        assertEquals("", parameter("position"));

        window.setParameter("position", " 1.5, 2 ,0.9 ");
        assertEquals(Optional.of(new Coordinates(1.5, 2, 0.9)), window.position());
        assertEquals("1.5,2.0,0.9", parameter("position"), "round-trips through setParameter");
        window.setParameter("position", parameter("position"));
        assertEquals(List.of("position " + new Coordinates(1.5, 2, 0.9)), heard, "an equal value is no change");

        for (String bad : new String[] {"1,2", "1,2,3,4", "a,b,c", "NaN,0,0", "1,,3", "1;2;3"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> window.setParameter("position", bad));
            assertEquals("position must be x,y,z in metres (e.g. 2.5,0,1.2) or empty for none, was '" + bad + "'",
                    e.getMessage());
        }
        assertEquals(Optional.of(new Coordinates(1.5, 2, 0.9)), window.position(), "unchanged after bad values");

        window.setParameter("position", "");
        assertEquals(Optional.empty(), window.position());
        assertEquals(1, heard.size(), "clearing has no listener event");
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("window position cleared")));
    }

    @Test
    void stateIsReadOnly() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> window.setParameter("state", "OPEN"));
        assertEquals("unknown or read-only parameter 'state' of AmicaWindow; writable: name, room, position", e.getMessage());
    }

    private String parameter(String key) {
        return window.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow();
    }
}
