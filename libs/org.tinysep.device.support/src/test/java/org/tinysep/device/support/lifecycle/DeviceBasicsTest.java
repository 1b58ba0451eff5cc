package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Provider;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * What every device does without a line of its own, as the event log shows it: status changes, renaming and its
 * connections (the parts AbstractDevice delegates to DeviceStatusHolder, DeviceParameters and DeviceRegistration).
 */
class DeviceBasicsTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    interface Input {
    }

    private static final class Sensor extends AbstractDevice {
        Sensor(DriverContext c) {
            super(c, "dev-1", "Sensor", "Sensor 1");
        }

        void online(String detail) {
            status(DeviceStatus.State.ONLINE, detail);
        }

        void use(Provider<Input> p, boolean vital) {
            connect(p, Provider.class, new Input() { }, vital);
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final Sensor sensor = new Sensor(new DriverContext(null, "drv", "Sensor", logs.reporter(),
            new PlatformClock(() -> T0)));

    private List<String> events(EventKind kind) {
        return logs.events().stream().filter(e -> e.kind() == kind).map(EventEntry::message).toList();
    }

    private static Provider<Input> provider(String uid) {
        return new Provider<>() {
            @Override
            public String deviceUid() {
                return uid;
            }

            @Override
            public Connection connect(Input listener) {
                return new ConsumptionsTest.Handle();
            }
        };
    }

    @Test
    void aStatusChangeIsLoggedOnceAndTheSameStatusAgainIsNot() {
        assertEquals(DeviceStatus.State.UNKNOWN, sensor.status().state());
        sensor.online("");
        sensor.online(null);
        sensor.online("battery low");
        assertEquals(DeviceStatus.State.ONLINE, sensor.status().state());
        assertEquals("battery low", sensor.status().detail());
        assertEquals(2, events(EventKind.STATUS).size(), () -> events(EventKind.STATUS).toString());
    }

    @Test
    void aNameIsStrippedAndLoggedAndABlankOneIsRefused() {
        sensor.setParameter("name", "  Hall sensor ");
        assertEquals("Hall sensor", sensor.name());
        assertEquals(List.of("renamed to \"Hall sensor\""), events(EventKind.DEVICE_EVENT));
        assertEquals("name must not be blank",
                assertThrows(IllegalArgumentException.class, () -> sensor.setParameter("name", " ")).getMessage());
        assertEquals("Hall sensor", sensor.name());
    }

    @Test
    void aNameWithHalfACharacterIsRefusedInPlainWordsAndAWholeOneIsKept() { // issue 25, item 8
        for (String bad : List.of("\ud800", "bad\ud800name", "x\udc00")) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> sensor.setParameter("name", bad));
            assertTrue(e.getMessage().startsWith("name has a broken character at position "), e.getMessage());
        }
        assertTrue(assertThrows(IllegalArgumentException.class, () -> sensor.setParameter("name", "bad\ud800name"))
                .getMessage().contains("position 4 (half of a UTF-16 surrogate pair, U+D800)"));
        sensor.setParameter("name", "Hall \ud83d\ude00");
        assertEquals("Hall \ud83d\ude00", sensor.name());
    }

    @Test
    void connectionsAreLoggedAndAGoneProviderTakesItsVitalConnectionAlong() {
        sensor.use(provider("bus-1"), true);
        sensor.use(provider("clock-1"), false);
        assertEquals(List.of(new ConnectionInfo("Provider", "bus-1", true),
                new ConnectionInfo("Provider", "clock-1", false)), sensor.connections());
        assertEquals(List.of("connected to Provider of bus-1 (vital)", "connected to Provider of clock-1 (optional)"),
                events(EventKind.CONNECTED));
        assertTrue(sensor.providerGone("clock-1"), "the vital one is still held");
        assertFalse(sensor.providerGone("bus-1"));
        assertEquals(List.of("disconnected from Provider of clock-1 (provider removed)",
                "disconnected from Provider of bus-1 (provider removed)"), events(EventKind.DISCONNECTED));
        assertEquals(List.of(), sensor.connections());
    }
}
