package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Instant;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.device.Provider;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.rooms.RoomDirectory;
import org.tinysep.device.support.testing.FakeHouse;
import org.tinysep.device.support.time.PlatformClock;

/**
 * Issue 25, item 1: a device that watches the person is not removed when its sensors go (a deliberate deviation
 * from thesis 3.3); it says which sensor in which room it can no longer see, and that it sees it again. A device
 * that does not watch the person keeps the thesis rule.
 */
class WatchingDeviceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    interface Input {
    }

    /** A sensor device placed in a room that provides {@link Input} (as an AmICA movement device does). */
    private static final class Sensor extends AbstractDevice implements Provider<Input> {
        Sensor(DriverContext c, String uid, String name) {
            super(c, uid, "Sensor", name);
        }

        @Override
        public String deviceUid() {
            return uid();
        }

        @Override
        public Connection connect(Input listener) {
            return new ConsumptionsTest.Handle();
        }
    }

    private static final class Watcher extends AbstractDevice {
        private final boolean watches;

        Watcher(DriverContext c, boolean watches) {
            super(c, "watcher-1", "Watcher", "Inactivity recognition");
            this.watches = watches;
        }

        void use(Provider<Input> p, boolean vital) {
            connect(p, Provider.class, new Input() { }, vital);
        }

        @Override
        protected boolean watchesThePerson() {
            return watches;
        }
    }

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final FakeHouse house = new FakeHouse();
    private final DriverContext context = new DriverContext(null, "drv", "Drv", logs.reporter(),
            new PlatformClock(() -> T0), RoomDirectory.of(house));
    private final Sensor bathroom = new Sensor(context, "amica-movement-1-40", "Bathroom movement");
    private final Sensor door = new Sensor(context, "amica-door-1-41", "Front door");

    WatchingDeviceTest() {
        house.add("r-bath", "Bathroom");
        house.add("r-hall", "Hall");
        bathroom.setParameter("room", "Bathroom");
        door.setParameter("room", "Hall");
    }

    private List<String> problems() {
        return logs.events().stream().filter(e -> e.kind() == EventKind.PROBLEM).map(EventEntry::message).toList();
    }

    private static String parameter(AbstractDevice d, String key) {
        return d.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError(d + " has no " + key));
    }

    @Test
    void aWatcherStaysWhenItsLastSensorGoesAndNamesTheRoomItCannotSee() {
        Watcher w = new Watcher(context, true);
        w.use(bathroom, true);
        assertTrue(w.loseProvider(bathroom.uid()), "a watcher stays without any source");
        assertEquals(List.of("Monitoring reduced: Inactivity recognition can no longer see the Bathroom: its sensor "
                + "\"Bathroom movement\" (amica-movement-1-40) went away at 2026-11-22 10:00:00 UTC; activity in the "
                + "Bathroom is not noticed until the sensor is back. It has no sensor left; it keeps running and "
                + "watches again as soon as one is back. Check the sensor and its radio node (tinysep:devices lists "
                + "them); an open alert stays open."), problems());
        assertEquals("Bathroom (its sensor \"Bathroom movement\" went away at 2026-11-22 10:00:00 UTC)",
                parameter(w, "roomsNotSeen"));
        assertEquals(List.of(), w.connections());
    }

    @Test
    void aWatcherWithOtherSourcesLeftNamesTheRoomAndTheSensorComingBackClearsIt() {
        Watcher w = new Watcher(context, true);
        w.use(bathroom, true);
        w.use(door, true);
        assertTrue(w.loseProvider(bathroom.uid()));
        assertEquals(1, problems().size());
        assertTrue(problems().get(0).startsWith("Monitoring reduced: Inactivity recognition can no longer see the "
                + "Bathroom"), problems().get(0));
        assertFalse(problems().get(0).contains("no sensor left"), problems().get(0));
        w.use(bathroom, true);
        assertEquals("", parameter(w, "roomsNotSeen"));
        assertTrue(logs.events().stream().anyMatch(e -> e.message().equals("monitoring restored: the sensor "
                + "\"Bathroom movement\" in the Bathroom is back and watched again")), logs.events().toString());
    }

    @Test
    void losingAnOptionalProviderIsNoReducedMonitoring() {
        Watcher w = new Watcher(context, true);
        w.use(bathroom, true);
        w.use(door, false);
        assertTrue(w.loseProvider(door.uid()));
        assertEquals(List.of(), problems());
        assertEquals("", parameter(w, "roomsNotSeen"));
    }

    @Test
    void aDeviceThatDoesNotWatchThePersonKeepsTheThesisRule() {
        Watcher w = new Watcher(context, false);
        w.use(bathroom, true);
        assertFalse(w.loseProvider(bathroom.uid()), "removed with its last vital connection (thesis 3.3)");
        assertEquals(List.of(), problems());
        assertTrue(w.parameters().stream().noneMatch(p -> p.key().equals("roomsNotSeen")));
    }

    @Test
    void aSensorInNoRoomIsNamedAsSuch() {
        Watcher w = new Watcher(context, true);
        Sensor loose = new Sensor(context, "amica-movement-1-9", "Spare sensor");
        w.use(loose, true);
        w.loseProvider(loose.uid());
        assertTrue(problems().get(0).startsWith("Monitoring reduced: Inactivity recognition lost its sensor \"Spare "
                + "sensor\" (amica-movement-1-9), which is placed in no room"), problems().get(0));
    }
}
