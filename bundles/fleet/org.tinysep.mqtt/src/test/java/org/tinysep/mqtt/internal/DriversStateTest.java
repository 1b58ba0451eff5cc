package org.tinysep.mqtt.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.jupiter.api.Test;
import org.tinysep.api.drivers.ApplicationEntry;
import org.tinysep.api.drivers.DriversListService;
import org.tinysep.json.JsonReader;

/** The drivers list on the broker: retained under the flat's prefix, in JSON, with what runs and what does not. */
class DriversStateTest {

    private final Topics topics = new Topics("tinysep", "flat1", "homeassistant");
    private final AtomicReference<List<ApplicationEntry>> apps = new AtomicReference<>(List.of(
            new ApplicationEntry("org.tinysep.amica.door", "org.tinysep.amica.door", "apps/door.jar", true, "ACTIVE"),
            new ApplicationEntry("org.tinysep.sms", "org.tinysep.sms", "apps/sms.jar", false, "DISABLED")));
    private final AtomicBoolean closed = new AtomicBoolean();
    private final DriversState state = new DriversState(topics, () -> service(apps), () -> closed.set(true));

    private static DriversListService service(AtomicReference<List<ApplicationEntry>> apps) {
        return new DriversListService() {
            @Override
            public String file() {
                return "var/drivers.xml";
            }

            @Override
            public List<ApplicationEntry> applications() {
                List<ApplicationEntry> a = apps.get();
                if (a == null) {
                    throw new IllegalStateException("list file unreadable");
                }
                return a;
            }

            @Override
            public List<String> reload() {
                return List.of();
            }

            @Override
            public List<String> setEnabled(String application, boolean enabled) {
                return List.of();
            }

            @Override
            public String use(String symbolicName, String file) {
                return "";
            }
        };
    }

    @Test
    void theListIsARetainedJsonMessageUnderTheFlatsPrefix() {
        Message m = state.message();
        assertEquals("tinysep/flat1/drivers", m.topic());
        assertTrue(m.retained());
        Map<String, Object> json = JsonReader.object(m.text(), 1 << 16);
        List<?> list = (List<?>) json.get("applications");
        assertEquals(2, list.size());
        Map<?, ?> door = (Map<?, ?>) list.get(0);
        assertEquals("org.tinysep.amica.door", door.get("application"));
        assertEquals("apps/door.jar", door.get("location"));
        assertEquals(true, door.get("enabled"));
        assertEquals("ACTIVE", door.get("status"));
        assertEquals(false, ((Map<?, ?>) list.get(1)).get("enabled"));
        assertEquals("2 applications in the drivers list, 1 running; not running: org.tinysep.sms (DISABLED)",
                json.get("explanation"));
    }

    @Test
    void aChangeMakesANewPayloadAndNoChangeTheSame() {
        Message before = state.message();
        assertTrue(before.samePayload(state.message()), "unchanged: the outbox publishes nothing new");
        apps.set(List.of(new ApplicationEntry("org.tinysep.amica.door", "org.tinysep.amica.door", "apps/door.jar",
                true, "ACTIVE")));
        Message after = state.message();
        assertFalse(before.samePayload(after));
        assertEquals("1 application in the drivers list, 1 running",
                JsonReader.object(after.text(), 1 << 16).get("explanation"));
    }

    @Test
    void withoutTheDriversListItSaysWhyInWords() {
        DriversState none = new DriversState(topics, () -> null, () -> { });
        assertEquals("the drivers list is not known: its bundle (org.tinysep.drivers) is not running",
                JsonReader.object(none.message().text(), 1 << 16).get("explanation"));
        apps.set(null);
        Map<String, Object> failing = JsonReader.object(state.message().text(), 1 << 16);
        assertEquals(List.of(), failing.get("applications"));
        assertEquals("the drivers list did not answer; it is read again in a moment", failing.get("explanation"));
    }

    @Test
    void closingStopsFollowingTheService() {
        state.close();
        assertTrue(closed.get());
    }
}
