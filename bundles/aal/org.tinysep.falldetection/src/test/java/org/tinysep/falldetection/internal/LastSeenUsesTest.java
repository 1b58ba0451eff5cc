package org.tinysep.falldetection.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.reflect.Proxy;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Hashtable;
import java.util.List;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.osgi.framework.ServiceRegistration;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.testing.RealFelix;

/**
 * Issue 29, item 4: Fall Detection connects to every movement sensor. Felix keeps each bundle's service uses in
 * one array that every new use searches and copies and every unregistration scans; a use held per sensor made
 * creating and stopping n sensors cost n². Counted in a real Felix (no timing): the uses held do not grow with the
 * number of sensors, and every sensor is still connected.
 */
class LastSeenUsesTest {

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


    private final AtomicInteger connected = new AtomicInteger();

    /** A movement sensor's provider service as a device registers it: a plain object with its UID. */
    private ServiceRegistration<?> sensor(int i) {
        Connection c = new Connection() {
            private boolean open = true;

            @Override
            public void close() {
                if (open) {
                    open = false;
                    connected.decrementAndGet();
                }
            }

            @Override
            public boolean isOpen() {
                return open;
            }
        };
        MovementProvider p = (MovementProvider) Proxy.newProxyInstance(getClass().getClassLoader(),
                new Class<?>[] {MovementProvider.class}, (proxy, m, args) -> switch (m.getName()) {
                    case "connect" -> {
                        connected.incrementAndGet();
                        yield c;
                    }
                    case "deviceUid" -> "move-" + i;
                    case "hashCode" -> System.identityHashCode(proxy);
                    case "equals" -> proxy == args[0];
                    default -> null;
                });
        Hashtable<String, Object> props = new Hashtable<>();
        props.put(DeviceProperties.DEVICE_UID, "move-" + i);
        return context.registerService(MovementProvider.class, p, props);
    }

    @Test
    void theUsesHeldDoNotGrowWithTheNumberOfSensors() throws Exception {
        int n = 500;
        List<ServiceRegistration<?>> regs = new ArrayList<>();
        try (LastSeenWatch watch = new LastSeenWatch(context)) {
            int base = fw.usesInRegistry();
            for (int i = 0; i < n; i++) {
                regs.add(sensor(i));
            }
            int atN = fw.usesInRegistry();
            for (int i = n; i < 2 * n; i++) {
                regs.add(sensor(i));
            }
            int at2N = fw.usesInRegistry();
            assertEquals(2 * n, connected.get(), "every sensor is connected");
            assertTrue(atN - base <= 2, "uses held after " + n + " sensors: " + (atN - base) + " (base " + base + ")");
            assertEquals(atN, at2N, "uses held after " + 2 * n + " sensors vs after " + n);
            for (int i = 0; i < n; i++) {
                regs.get(i).unregister();
            }
            assertEquals(n, connected.get(), "a sensor that went is disconnected");
        }
        assertEquals(0, connected.get(), "closing the watch closes every connection");
        for (int i = n; i < 2 * n; i++) {
            regs.get(i).unregister();
        }
    }
}
