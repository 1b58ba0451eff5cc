package org.tinysep.device.support.lifecycle;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.BiConsumer;
import java.util.function.Consumer;
import java.util.function.Supplier;
import org.osgi.framework.BundleContext;

/**
 * The wiring of a service with one device for the whole flat (Inactivity Recognition, Follow Me Light): the device
 * is created when the first provider of a {@link #source source} type appears and is given every later one (the
 * device connects to it, vital: it removes itself with its last source and is created anew with the next, unless
 * it watches the person, {@link AbstractDevice#watchesThePerson()}: then it stays);
 * providers of an {@link #optional optional} type are given to the device whenever present, then and later. A
 * provider that goes is forgotten by the device before the driver drops the connections to it.
 *
 * @param <D> the device
 */
public final class SingleDeviceWiring<D extends AbstractDevice> implements AutoCloseable {

    private final AbstractDriver driver;
    private final Class<D> deviceType;
    private final Supplier<D> create;
    private final BiConsumer<D, String> forget;
    /** How to give each optional provider present now to a device. */
    private final Map<String, Consumer<D>> optional = new ConcurrentHashMap<>();
    private final List<ProviderTracker<?>> trackers = new ArrayList<>();

    /**
     * @param create makes the (not yet registered) device
     * @param forget tells the device that the provider of that UID went
     */
    public SingleDeviceWiring(AbstractDriver driver, Class<D> deviceType, Supplier<D> create,
            BiConsumer<D, String> forget) {
        this.driver = driver;
        this.deviceType = deviceType;
        this.create = create;
        this.forget = forget;
    }

    /** Every provider of {@code type} is a source: the first creates the device, each is given to it. */
    public <P> void source(BundleContext bc, Class<P> type, BiConsumer<D, P> watch) {
        trackers.add(new ProviderTracker<>(bc, type, null, ProviderTracker.Callback.of(
                (p, uid) -> watch.accept(device(), p), (p, uid) -> gone(uid))).open());
    }

    /** Every provider of {@code type} is given to the device ({@code use}) whenever both are there. */
    public <P> void optional(BundleContext bc, Class<P> type, BiConsumer<D, P> use) {
        trackers.add(new ProviderTracker<>(bc, type, null, ProviderTracker.Callback.of((p, uid) -> {
            Consumer<D> give = d -> use.accept(d, p);
            optional.put(type.getName() + '/' + uid, give);
            current().forEach(give);
        }, (p, uid) -> {
            optional.remove(type.getName() + '/' + uid);
            gone(uid);
        })).open());
    }

    private void gone(String uid) {
        current().forEach(d -> forget.accept(d, uid));
        driver.providerGone(uid);
    }

    /** @return the device, or none */
    public List<D> current() {
        return driver.devices(deviceType);
    }

    /** @return the single device, created (and given the optional providers) on first need */
    private synchronized D device() {
        List<D> all = current();
        if (!all.isEmpty()) {
            return all.get(0);
        }
        D d = driver.addDevice(create.get());
        optional.values().forEach(give -> give.accept(d));
        return d;
    }

    /** Closes the trackers, the last opened first; the driver stops (and removes the device) afterwards. */
    @Override
    public void close() {
        for (int i = trackers.size() - 1; i >= 0; i--) {
            trackers.get(i).close();
        }
        trackers.clear();
    }
}
