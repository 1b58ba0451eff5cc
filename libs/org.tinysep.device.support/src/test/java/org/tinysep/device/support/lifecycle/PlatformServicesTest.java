package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceRegistration;
import org.osgi.framework.hooks.service.ListenerHook;
import org.tinysep.api.backup.BackupStore;
import org.tinysep.api.device.Connection;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.HouseInformationListener;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Room;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.device.support.testing.RealFelix;

/**
 * Issue 29, item 4: Felix matches every service event (each device registered or removed) against every service
 * listener of the framework, so what each driver context listens with is paid once per device event per driver. A
 * driver context in a real Felix follows its five platform services with one listener, and still follows them.
 */
class PlatformServicesTest {

    @TempDir
    Path storage;
    private RealFelix fw;
    private BundleContext context;
    private final AtomicInteger listeners = new AtomicInteger();

    @BeforeEach
    void start() throws Exception {
        fw = new RealFelix(storage);
        context = fw.context();
        context.registerService(ListenerHook.class, new ListenerHook() {
            @Override
            public void added(Collection<ListenerInfo> added) {
                added.forEach(l -> listeners.incrementAndGet());
            }

            @Override
            public void removed(Collection<ListenerInfo> removed) {
                removed.forEach(l -> listeners.decrementAndGet());
            }
        }, null);
    }

    @AfterEach
    void stop() throws Exception {
        fw.close();
    }

    @Test
    void aDriverContextListensOnceForItsPlatformServices() {
        int before = listeners.get();
        DriverContext c = new DriverContext(context, "driver-1", "Test");
        assertEquals(1, listeners.get() - before, "service listeners added by one driver context");
        c.close();
        assertEquals(before, listeners.get(), "and removed when it closes");
    }

    @Test
    void theContextFollowsEachPlatformServiceAsItComesRanksAndGoes() {
        DriverContext c = new DriverContext(context, "driver-1", "Test");
        assertFalse(c.backups().available());
        assertFalse(c.rooms().house().isPresent());

        List<String> low = new ArrayList<>();
        List<String> high = new ArrayList<>();
        register(EventLog.class, (m, a) -> m.equals("record") ? low.add((String) a[2]) : null, 0);
        c.event(EventKind.DEVICE_EVENT, "one");
        ServiceRegistration<?> better = register(EventLog.class,
                (m, a) -> m.equals("record") ? high.add((String) a[2]) : null, 5);
        c.event(EventKind.DEVICE_EVENT, "two");
        better.unregister();
        c.event(EventKind.DEVICE_EVENT, "three");
        assertEquals(List.of("one", "three"), low);
        assertEquals(List.of("two"), high, "the best ranked event log while it is there");

        Instant then = Instant.parse("2012-05-01T08:00:00Z");
        ServiceRegistration<?> clock = register(TimeControllerProvider.class,
                (m, a) -> m.equals("now") ? then : null, 0);
        assertEquals(then, c.now());
        clock.unregister();
        assertTrue(c.now().isAfter(then), "the system clock without a Time Controller");

        register(BackupStore.class, (m, a) -> null, 0);
        assertTrue(c.backups().available());

        List<HouseInformationListener> relays = new ArrayList<>();
        ServiceRegistration<?> house = register(HouseInformationProvider.class, (m, a) -> switch (m) {
            case "connect" -> {
                relays.add((HouseInformationListener) a[0]);
                yield connection(relays, (HouseInformationListener) a[0]);
            }
            case "rooms" -> List.of();
            default -> null;
        }, 0);
        List<List<Room>> told = new ArrayList<>();
        c.rooms().watch(told::add);
        assertTrue(c.rooms().house().isPresent());
        assertEquals(1, relays.size(), "the house's changes are relayed to the rooms");
        relays.get(0).houseChanged(null, List.of(), then);
        assertEquals(1, told.size());
        house.unregister();
        assertEquals(0, relays.size(), "the relay is closed when the house goes");
        assertFalse(c.rooms().house().isPresent());
        c.close();
    }

    private interface Answer {
        Object answer(String method, Object[] args);
    }

    private <T> ServiceRegistration<?> register(Class<T> type, Answer answer, int ranking) {
        Object service = Proxy.newProxyInstance(type.getClassLoader(), new Class<?>[] {type},
                (proxy, method, args) -> switch (method.getName()) {
                    case "hashCode" -> System.identityHashCode(proxy);
                    case "equals" -> proxy == args[0];
                    case "toString" -> type.getSimpleName();
                    default -> answer.answer(method.getName(), args);
                });
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(Constants.SERVICE_RANKING, ranking);
        return context.registerService(type.getName(), service, props);
    }

    private static Connection connection(List<HouseInformationListener> relays, HouseInformationListener l) {
        return new Connection() {
            @Override
            public void close() {
                relays.remove(l);
            }

            @Override
            public boolean isOpen() {
                return relays.contains(l);
            }
        };
    }
}
