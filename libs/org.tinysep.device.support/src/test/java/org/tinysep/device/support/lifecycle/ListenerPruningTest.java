package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collection;
import java.util.Hashtable;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.BundleContext;
import org.osgi.framework.Constants;
import org.osgi.framework.ServiceEvent;
import org.osgi.framework.ServiceRegistration;
import org.osgi.framework.UnfilteredServiceListener;
import org.osgi.framework.hooks.service.EventListenerHook;
import org.osgi.framework.hooks.service.ListenerHook.ListenerInfo;
import org.osgi.util.tracker.ServiceTracker;
import org.tinysep.device.support.testing.RealFelix;

/**
 * Issue 29, item 4: registering a device's service must not cost a filter match per service listener of the
 * framework. In a real Felix with many trackers of other services, a second hook (ranked last) counts the
 * listeners the framework would still match against each registration: with {@link ListenerPruning}, only those
 * that may want the service, however many others there are; and every listener that wants it is still told.
 */
class ListenerPruningTest {

    /** The service of the test's devices. */
    public interface TestDevice {
    }

    private static final String DEVICE = TestDevice.class.getName();

    @TempDir
    Path storage;
    private RealFelix fw;
    private BundleContext context;
    private final List<ServiceTracker<?, ?>> trackers = new ArrayList<>();
    private final AtomicInteger offered = new AtomicInteger();

    @BeforeEach
    void start() throws Exception {
        fw = new RealFelix(storage);
        context = fw.context();
        Hashtable<String, Object> last = new Hashtable<>();
        last.put(Constants.SERVICE_RANKING, Integer.MIN_VALUE);
        context.registerService(EventListenerHook.class, new EventListenerHook() {
            @Override
            public void event(ServiceEvent event, Map<BundleContext, Collection<ListenerInfo>> listeners) {
                String[] classes = (String[]) event.getServiceReference().getProperty(Constants.OBJECTCLASS);
                if (event.getType() == ServiceEvent.REGISTERED && classes[0].equals(DEVICE)) {
                    listeners.values().forEach(l -> offered.addAndGet(l.size()));
                }
            }
        }, last);
    }

    @AfterEach
    void stop() throws Exception {
        trackers.forEach(ServiceTracker::close);
        fw.close();
    }

    private ServiceTracker<Object, Object> track(String filter) throws Exception {
        ServiceTracker<Object, Object> t = new ServiceTracker<>(context, context.createFilter(filter), null);
        t.open();
        trackers.add(t);
        return t;
    }

    private void others(int n) throws Exception {
        for (int i = 0; i < n; i++) {
            track("(objectClass=test.Other" + i + ")");
        }
    }

    /** @return the listeners offered to the framework per registration of a device service */
    private double offeredPerDevice(int devices) {
        offered.set(0);
        for (int i = 0; i < devices; i++) {
            Hashtable<String, Object> props = new Hashtable<>();
            props.put("device.uid", "d" + i);
            context.registerService(new String[] {DEVICE}, new TestDevice() { }, props);
        }
        return offered.get() / (double) devices;
    }

    @Test
    void aRegistrationReachesOnlyTheListenersOfItsClassHoweverManyOthersThereAre() throws Exception {
        ServiceTracker<Object, Object> plain = track("(objectClass=" + DEVICE + ")");
        ServiceTracker<Object, Object> narrowed = track("(&(objectClass=" + DEVICE + ")(device.uid=d1))");
        new ListenerPruning().register(context);
        others(100);
        double at100 = offeredPerDevice(20);
        others(200);
        double at300 = offeredPerDevice(20);

        assertEquals(2.0, at100, 0.01, "listeners matched per device registration with 100 others");
        assertEquals(at100, at300, 0.01, "work per registration must not grow with the listeners of other services");
        assertEquals(40, plain.size(), "every device service reached its tracker");
        assertEquals(2, narrowed.size(), "the narrowed tracker got its device d1 of each round");
    }

    @Test
    void aModifiedServiceStillLeavesATrackerWhoseFilterNoLongerMatches() throws Exception {
        new ListenerPruning().register(context);
        ServiceTracker<Object, Object> kitchen = track("(&(objectClass=" + DEVICE + ")(room=kitchen))");
        Hashtable<String, Object> props = new Hashtable<>(Map.of("room", "kitchen"));
        ServiceRegistration<?> r = context.registerService(new String[] {DEVICE}, new TestDevice() { }, props);
        assertEquals(1, kitchen.size());
        props.put("room", "hall");
        r.setProperties(props);
        assertEquals(0, kitchen.size(), "MODIFIED_ENDMATCH still reaches the tracker");
    }

    @Test
    void anUnfilteredListenerAndFiltersItCannotReadAreKept() throws Exception {
        ListenerPruning pruning = new ListenerPruning();
        pruning.register(context);
        AtomicInteger unfiltered = new AtomicInteger();
        context.addServiceListener((UnfilteredServiceListener) e -> unfiltered.incrementAndGet(),
                "(objectClass=test.Other)");
        ServiceTracker<Object, Object> wildcard = track("(objectClass=" + DEVICE.substring(0, 20) + "*)");
        ServiceTracker<Object, Object> either = track("(|(objectClass=test.Other)(objectClass=" + DEVICE + "))");
        offeredPerDevice(3);
        assertEquals(3, unfiltered.get(), "an UnfilteredServiceListener hears every event");
        assertEquals(3, wildcard.size());
        assertEquals(3, either.size());
    }

    @Test
    void readsTheClassesAFilterRequires() {
        assertArrayEquals(new String[] {"a.B"}, ListenerPruning.requiredClasses("(objectClass=a.B)"));
        assertArrayEquals(new String[] {"a.B"}, ListenerPruning.requiredClasses("(OBJECTCLASS=a.B)"));
        assertArrayEquals(new String[] {"a.B"},
                ListenerPruning.requiredClasses("(&(objectClass=a.B)(|(x=1)(y=2)))"));
        assertArrayEquals(new String[] {"a.B", "c.D"},
                ListenerPruning.requiredClasses("(&(x=1)(objectClass=a.B)(objectClass=c.D))"));
        for (String unknown : new String[] {null, "(objectClass=a.*)", "(objectClass= a.B)", "(!(objectClass=a.B))",
                "(|(objectClass=a.B)(objectClass=c.D))", "(objectClass=a\\(B)", "(&(x=1)(y=2))",
                "(objectClass>=a.B)", "(&(objectClass=a.B)"}) {
            assertEquals(0, ListenerPruning.requiredClasses(unknown).length, "cannot be read for certain: " + unknown);
        }
    }
}
