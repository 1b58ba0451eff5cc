package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Provider;
import org.tinysep.device.support.rooms.TrackedPlacements;
import org.tinysep.device.support.testing.RealFelix;

/**
 * Issue 29, item 4: creating n devices must cost the same per device at n and 2n. In a real Felix, n bus devices
 * each get a follower device (the hardware-abstraction pattern, {@link ProviderDeviceDriver}), one whole-flat device
 * connects to all of them ({@link SingleDeviceWiring}), and every bus device's name is read once through
 * {@link TrackedPlacements}. Felix keeps each bundle's service uses in one array that every new use searches and
 * copies and every unregistration scans: the work per device is the length of those arrays, counted here (no
 * timing). It must not grow with the number of devices.
 */
class RegistryUsesTest {

    @TempDir
    Path storage;
    private RealFelix fw;
    private BundleContext context;

    @BeforeEach
    void start() throws Exception {
        fw = new RealFelix(storage);
        context = fw.context();
    }

    @AfterEach
    void stop() throws Exception {
        fw.close();
    }

    /** A provider interface of the test: a beacon tells its listeners "seen". */
    public interface Beacon extends Provider<Runnable> {
    }

    static final class BusDevice extends AbstractDevice implements Beacon {
        private final Listeners<Runnable> listeners = new Listeners<>("Beacon");

        BusDevice(DriverContext c, String uid) {
            super(c, uid, "Bus", "Bus " + uid);
            publish(this, Beacon.class);
        }

        @Override
        public String deviceUid() {
            return uid();
        }

        @Override
        public Connection connect(Runnable l) {
            return listeners.add(l);
        }
    }

    static final class BusDriver extends AbstractDriver {
        BusDriver(BundleContext bc) {
            super("TestBus");
            start(bc);
        }

        void add(String uid) {
            addDevice(new BusDevice(context(), uid));
        }

        void drop(String uid) {
            remove(uid);
        }

        void close() {
            stop();
        }
    }

    static final class Follower extends AbstractDevice {
        private final Beacon source;

        Follower(DriverContext c, Beacon source) {
            super(c, "follow-" + source.deviceUid(), "Follower", "Follower of " + source.deviceUid());
            this.source = source;
        }

        @Override
        protected void onRegistered() {
            connect(source, Beacon.class, () -> { }, true);
        }
    }

    static final class FollowerDriver extends ProviderDeviceDriver<Beacon> {
        FollowerDriver(BundleContext bc) {
            super("TestFollower", Beacon.class, null);
            open(bc);
        }

        @Override
        protected AbstractDevice createDevice(Beacon provider) {
            return new Follower(context(), provider);
        }

        void shut() {
            close();
        }
    }

    static final class Watcher extends WholeFlatDevice {
        Watcher(DriverContext c) {
            super(c, "watcher", "Watcher", "Watcher");
        }

        void watch(Beacon b) {
            connect(b, Beacon.class, () -> { }, true);
        }

        @Override
        protected boolean watchesThePerson() {
            return true;
        }
    }

    static final class WatcherDriver extends AbstractDriver {
        private final SingleDeviceWiring<Watcher> wiring;

        WatcherDriver(BundleContext bc) {
            super("TestWatcher");
            start(bc);
            wiring = new SingleDeviceWiring<>(this, Watcher.class, () -> new Watcher(context()), (d, uid) -> { });
            wiring.source(bc, Beacon.class, Watcher::watch);
        }

        void shut() {
            wiring.close();
            stop();
        }
    }

    private static long cpuNanos() {
        return java.lang.management.ManagementFactory.getThreadMXBean().getCurrentThreadCpuTime();
    }


    /** Creates {@code n} bus devices (and so n followers and n connections of the watcher); @return uses after */
    private int usesAfterCreating(BusDriver bus, TrackedPlacements names, int from, int n)
            throws ReflectiveOperationException {
        for (int i = from; i < from + n; i++) {
            bus.add("bus-" + i);
            assertEquals("Bus bus-" + i, names.nameOf("bus-" + i));
        }
        return fw.usesInRegistry();
    }

    @Test
    void theRegistrysUsesPerBundleDoNotGrowWithTheNumberOfDevices() throws Exception {
        int n = 500;
        BusDriver bus = new BusDriver(context);
        FollowerDriver followers = new FollowerDriver(context);
        WatcherDriver watcher = new WatcherDriver(context);
        try (TrackedPlacements names = new TrackedPlacements(context)) {
            int base = fw.usesInRegistry();
            long c0 = cpuNanos();
            int atN = usesAfterCreating(bus, names, 0, n);
            long c1 = cpuNanos();
            int at2N = usesAfterCreating(bus, names, n, n);
            long c2 = cpuNanos();
            // for the report only (CPU time of this thread, so the machine's load does not count): never asserted
            System.out.printf("RegistryUsesTest: creation CPU per device: first %d %.0f µs, next %d %.0f µs%n", n,
                    (c1 - c0) / 1e3 / n, n, (c2 - c1) / 1e3 / n);

            assertEquals(2 * n, followers.devices().size(), "one follower per bus device");
            assertEquals(2 * n, watcher.devices().get(0).connections().size(), "the watcher hears every bus device");
            // before issue 29 each tracker held one use per device, and each name read left one behind: ~3 per device
            assertTrue(atN - base <= 2, "uses held after " + n + " devices: " + (atN - base) + " (base " + base + ")");
            assertEquals(atN, at2N, "uses held after " + 2 * n + " devices vs after " + n);

            // the objects kept are the live devices: every bus device has its follower and the watcher listening
            for (var d : bus.devices()) {
                assertEquals(2, ((BusDevice) d).listeners.size(), d.uid());
            }

            // the bus devices go (as when the bus radio stops first): each one costs its own consumers, one follower
            // and the watcher, not a look at every device's connections
            long examined0 = followers.examined + watcher.examined;
            for (int i = 0; i < n; i++) {
                bus.drop("bus-" + i);
            }
            long firstHalf = followers.examined + watcher.examined - examined0;
            for (int i = n; i < 2 * n; i++) {
                bus.drop("bus-" + i);
            }
            long secondHalf = followers.examined + watcher.examined - examined0 - firstHalf;
            assertEquals(2L * n, firstHalf, "devices examined while " + n + " of " + 2 * n + " bus devices went");
            assertEquals(2L * n, secondHalf, "devices examined while the last " + n + " went");
            assertEquals(0, followers.devices().size(), "each follower went with its bus device");
            assertEquals(0, watcher.devices().get(0).connections().size(), "the watcher stays, with no source");
        } finally {
            watcher.shut();
            followers.shut();
            bus.close();
        }
        assertEquals(0, fw.usesInRegistry(), "every use is given back after the stop");
    }

    @Test
    void aFactoryServiceStaysHeldWhileTrackedAndIsGivenBackOnRelease() throws Exception {
        org.osgi.framework.ServiceRegistration<?> reg = context.registerService(Runnable.class.getName(),
                new org.osgi.framework.ServiceFactory<Runnable>() {
                    @Override
                    public Runnable getService(org.osgi.framework.Bundle b,
                            org.osgi.framework.ServiceRegistration<Runnable> r) {
                        return () -> { };
                    }

                    @Override
                    public void ungetService(org.osgi.framework.Bundle b,
                            org.osgi.framework.ServiceRegistration<Runnable> r, Runnable s) {
                    }
                }, null);
        @SuppressWarnings("unchecked")
        org.osgi.framework.ServiceReference<Runnable> ref = (org.osgi.framework.ServiceReference<Runnable>) reg
                .getReference();
        Runnable taken = ServiceUse.take(context, ref);
        assertTrue(taken != null);
        assertEquals(1, context.getBundle().getServicesInUse().length, "a factory's object is held while kept");
        ServiceUse.release(context, ref);
        assertEquals(null, context.getBundle().getServicesInUse(), "and given back on release");
        reg.unregister();
    }
}
