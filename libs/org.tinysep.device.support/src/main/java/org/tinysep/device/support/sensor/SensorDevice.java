package org.tinysep.device.support.sensor;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Consumer;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.device.Provider;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.Uids;

/**
 * What every sensor abstraction device does, written once: a stable UID from its driver and bus device, the node
 * address and its own node type as service properties, decoding its {@link Source}'s payloads and ignoring other
 * types, ONLINE with every report it accepts, change detection, the first-report rule, the {@code state}/{@code
 * since} parameters and firing its listeners. A sensor declares only what differs: its source, the listener call
 * ({@link #tell}), and if needed what counts as a change ({@link #isChange}), its event-log words
 * ({@link #describe}) and whether listeners hear every report ({@link #tellsEveryReport}).
 * <p>
 * <b>The first-report rule.</b> A device's first report after it started (the node powered up, the platform or
 * the driver restarted) establishes the state; it is not a change. Listeners hear it with {@code first = true}.
 * <p>
 * The device is its bus device's listener; it takes payloads of its source's node family only.
 *
 * @param <L> the listener interface of the provided interface
 * @param <V> the reading, e.g. {@code OpenState}; never null
 */
public abstract class SensorDevice<L, V> extends AbstractDevice
        implements BusRadioAmicaListener, BusRadioSunSpotListener {

    /**
     * The listener call of a provider interface, passed to the constructor instead of overriding {@link #tell}, e.g.
     * {@code DoorListener::doorChanged}.
     *
     * @param <L> the listener interface
     * @param <P> the provider interface the listener is told about
     * @param <V> the reading
     */
    @FunctionalInterface
    public interface ListenerCall<L, P, V> {
        void tell(L listener, P source, V reading, boolean first, Instant at);
    }

    /** A listener call bound to the provider interface the device is told as. */
    private record BoundCall<L, P, V>(Class<P> provider, ListenerCall<L, ? super P, V> call) {
        void tell(L listener, Object device, V reading, boolean first, Instant at) {
            call.tell(listener, provider.cast(device), reading, first, at);
        }
    }

    private final Source<V> source;
    private final Listeners<L> listeners;
    private final BoundCall<L, ?, V> call; // null: the subclass overrides tell
    private V latest; // guarded by this; null until the first report
    private V announced; // guarded by this; the reading of the last change
    private volatile Instant since;
    private volatile Instant lastUpdate;

    /**
     * @param nodeType this device's own node type only, even if the node announces several
     * @param provides the provider interfaces this device registers under
     */
    protected SensorDevice(DriverContext context, Source<V> source, String nodeType, String name,
            Class<?>... provides) {
        this(context, source, nodeType, name, null, provides);
    }

    /**
     * A sensor that declares its listener call instead of overriding {@link #tell}.
     *
     * @param provides the provider interface this device registers under and is told to listeners as
     * @param call     the listener call, e.g. {@code DoorListener::doorChanged}
     */
    protected <P> SensorDevice(DriverContext context, Source<V> source, String nodeType, String name,
            Class<P> provides, ListenerCall<L, ? super P, V> call) {
        this(context, source, nodeType, name, new BoundCall<>(provides, call), provides);
    }

    private SensorDevice(DriverContext context, Source<V> source, String nodeType, String name,
            BoundCall<L, ?, V> call, Class<?>... provides) {
        super(context, Uids.of(context.driverName(), source.busDeviceUid()), context.driverName(), name);
        this.source = source;
        this.listeners = new Listeners<>(uid());
        this.call = call;
        serviceProperty(DeviceProperties.NODE_ADDRESS, source.nodeAddress());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {nodeType});
        publish(this, provides);
    }

    /**
     * Calls one listener: the reading is a change, or the first report ({@code first}), or any report. By default
     * the listener call given to the constructor; a sensor built without one overrides this.
     */
    protected void tell(L listener, V reading, boolean first, Instant at) {
        if (call == null) {
            throw new IllegalStateException(getClass().getName() + " gives no listener call and does not override tell");
        }
        call.tell(listener, this, reading, first, at);
    }

    /** @return whether {@code now} differs from the reading of the last change; default: not equal */
    protected boolean isChange(V before, V now) {
        return !before.equals(now);
    }

    /** @return the event-log entry for a change to {@code reading}, or null for none (default) */
    protected String describe(V reading) {
        return null;
    }

    /** @return true if listeners hear every report (movement), false if changes only (default) */
    protected boolean tellsEveryReport() {
        return false;
    }

    /** Called with every accepted reading before anything is announced; default nothing. */
    protected void accepted(V reading) {
    }

    @Override
    protected void onRegistered() {
        source.attach(this);
    }

    @SuppressWarnings("unchecked")
    final <X> void connectBus(Provider<X> bus, Class<?> busInterface) {
        connect(bus, busInterface, (X) this, true); // the bus provider's listener: this device (both interfaces)
    }

    @Override
    public final void payloadReceived(BusRadioAmicaProvider bus, byte[] payload, Instant at) {
        if (source instanceof Source.Amica<V> amica) {
            amica.received(this, payload, at);
        }
    }

    @Override
    public final void payloadReceived(BusRadioSunSpotProvider bus, int sensorType, byte[] payload, Instant at) {
        if (source instanceof Source.SunSpot<V> sunSpot) {
            sunSpot.received(this, sensorType, payload, at);
        }
    }

    final void rejected(String reason) {
        status(DeviceStatus.State.ERROR, "rejected payload: " + reason);
    }

    /** A decoded report from the node: the device is ONLINE, and a change (or the first report) is announced. */
    final void report(V reading, Instant at) {
        status(DeviceStatus.State.ONLINE, "");
        boolean first;
        boolean change;
        synchronized (this) {
            first = announced == null;
            change = first || isChange(announced, reading);
            latest = reading;
            lastUpdate = at;
            if (change) {
                announced = reading;
                since = at;
            }
        }
        accepted(reading);
        String words = change ? describe(reading) : null;
        if (words != null) {
            event(words);
        }
        if (change || tellsEveryReport()) {
            listeners.fire(l -> tell(l, reading, first, at));
        }
    }

    /** @return the latest reading, null before the first report */
    protected final synchronized V latest() {
        return latest;
    }

    /** @return the latest reading, {@code unknown} before the first report */
    protected final V latestOr(V unknown) {
        V v = latest();
        return v == null ? unknown : v;
    }

    /** @return when the reading of the last change arrived, null before the first report */
    protected final Instant since() {
        return since;
    }

    /** @return when the latest report arrived, null before the first */
    protected final Instant lastUpdate() {
        return lastUpdate;
    }

    /** Tells every listener something other than a reading, e.g. a setting the user changed. */
    protected final void fire(Consumer<? super L> call) {
        listeners.fire(call);
    }

    public final String deviceUid() {
        return uid();
    }

    public final Connection connect(L listener) {
        return listeners.add(listener);
    }

    /** @return the writable parameters, shown first; default none */
    protected List<Parameter> settings() {
        return List.of();
    }

    /** @return the state as the {@code state} parameter shows it; default the latest reading, empty before one */
    protected Object shownState() {
        return latest();
    }

    /** @return the read-only parameters; default {@code state} ({@link #shownState}) and {@code since} */
    protected List<Parameter> readings() {
        return List.of(Parameter.readOnly("state", shownState(), "last reported state"),
                Parameter.readOnly("since", since, "when the state was entered"));
    }

    @Override
    protected final List<Parameter> moreParameters() {
        List<Parameter> all = new ArrayList<>(settings());
        all.addAll(readings());
        all.addAll(source.parameters());
        return all;
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
