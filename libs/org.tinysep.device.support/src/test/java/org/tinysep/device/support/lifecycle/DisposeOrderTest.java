package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.lang.reflect.Proxy;
import java.time.Instant;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Bundle;
import org.osgi.framework.BundleContext;
import org.osgi.framework.FrameworkUtil;
import org.osgi.framework.ServiceRegistration;
import org.tinysep.api.device.Provider;
import org.tinysep.device.support.logs.RecordingLogs;
import org.tinysep.device.support.time.PlatformClock;

/**
 * A removed device closes its inputs before its services go: otherwise an event arriving in between reaches a
 * device nobody hears any more, and a provider that holds events for a replacement consumer (an AmICA bus device
 * during a driver update) starts holding too late. Found when the removal change (a stopping driver's devices
 * are removed by {@code stop()}) met the hot-update test: 2 frames lost during the swap.
 */
class DisposeOrderTest {

    private static final Instant T0 = Instant.parse("2026-11-22T10:00:00Z");

    private final List<String> order = new CopyOnWriteArrayList<>();

    /** A bundle context that registers nothing real but records unregistrations. */
    private BundleContext recordingContext() {
        Bundle bundle = (Bundle) Proxy.newProxyInstance(Bundle.class.getClassLoader(), new Class<?>[] {Bundle.class},
                (p, m, a) -> m.getName().equals("getState") ? Bundle.ACTIVE : null);
        return (BundleContext) Proxy.newProxyInstance(BundleContext.class.getClassLoader(),
                new Class<?>[] {BundleContext.class}, (p, m, a) -> switch (m.getName()) {
                    case "registerService" -> registration(a[0] instanceof Class<?> c ? c.getSimpleName()
                            : a[0] instanceof String[] names ? names[0] : String.valueOf(a[0]));
                    case "getBundle" -> bundle;
                    case "createFilter" -> FrameworkUtil.createFilter((String) a[0]);
                    default -> null;
                });
    }

    private ServiceRegistration<?> registration(String name) {
        return (ServiceRegistration<?>) Proxy.newProxyInstance(ServiceRegistration.class.getClassLoader(),
                new Class<?>[] {ServiceRegistration.class}, (p, m, a) -> {
                    if (m.getName().equals("unregister")) {
                        order.add("unregister " + name.substring(name.lastIndexOf('.') + 1));
                    }
                    return null;
                });
    }

    interface Input {
    }

    private final class Consumer extends AbstractDevice {
        Consumer(DriverContext c) {
            super(c, "dev-1", "Consumer", "Consumer 1");
        }

        void use(Provider<Input> p) {
            connect(p, Provider.class, new Input() { }, true);
        }
    }

    @Test
    void disposingClosesTheInputsBeforeTheServicesGo() {
        RecordingLogs logs = new RecordingLogs(() -> T0);
        DriverContext context = new DriverContext(recordingContext(), "drv", "Consumer", logs.reporter(),
                new PlatformClock(() -> T0));
        Consumer device = new Consumer(context);
        device.register();
        device.use(new Provider<>() {
            @Override
            public String deviceUid() {
                return "bus-1";
            }

            @Override
            public org.tinysep.api.device.Connection connect(Input listener) {
                return new org.tinysep.api.device.Connection() {
                    private volatile boolean open = true;

                    @Override
                    public void close() {
                        if (open) {
                            open = false;
                            order.add("input closed");
                        }
                    }

                    @Override
                    public boolean isOpen() {
                        return open;
                    }
                };
            }
        });
        device.dispose();
        assertEquals("input closed", order.get(0), order.toString());
        assertEquals(List.of("input closed", "unregister Device"), order.subList(0, 2));
    }
}
