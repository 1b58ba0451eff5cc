package org.tinysep.amica.actuator.base;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.function.IntFunction;
import java.util.function.ToIntFunction;
import org.tinysep.amica.protocol.AmicaPayload;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.api.actuator.PercentActuator;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.ConfirmedSetting;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.ParameterValues;
import org.tinysep.device.support.lifecycle.Uids;

/**
 * Abstracts one AmICA percent-actuator node. Its status payload of type {@code P} reports the value (a
 * percentage); {@link #setLevel(Percent)} sends the same payload with the new value and returns at once. Thesis
 * actuator model: the value, its listeners and the event log change only when the node's next status report
 * confirms it; until then the request is shown as the read-only parameter {@code pending}. A request is given
 * up only when a report arrives {@link #PATIENCE} or more after it and still disagrees.
 *
 * @param <P> the status / command payload, e.g. {@code HeaterControl}
 * @param <L> the listener type of the provider interface
 */
public abstract class PercentActuatorDevice<P extends AmicaPayload, L> extends AbstractDevice
        implements BusRadioAmicaListener, PercentActuator {

    /** An AmICA actuator node reports its value every 10 s (thesis 3.9.1, docs/protocols/amica.md). */
    public static final Duration REPORT_INTERVAL = Duration.ofSeconds(10);
    /**
     * How long after a request a disagreeing status report may still predate the command: two report intervals, so
     * the node has one whole interval to answer before a report of the old value counts as a contradiction.
     */
    public static final Duration PATIENCE = REPORT_INTERVAL.multipliedBy(2);

    /**
     * The listener call of a provider interface, e.g. {@code HeaterListener::potencyChanged}.
     *
     * @param <L> the listener interface
     * @param <V> the provider interface the listener is told about
     */
    @FunctionalInterface
    public interface ListenerCall<L, V> {
        void tell(L listener, V source, Percent value, Instant at);
    }

    private final BusRadioAmicaProvider bus;
    private final Listeners<L> listeners;
    private final Teller<L> teller;
    private final String quantity;
    private final Class<P> payloadType;
    private final ToIntFunction<P> percentOf;
    private final IntFunction<P> command;
    private final ConfirmedSetting<Percent> setting;

    /**
     * @param label       name prefix, e.g. {@code Heater}; the device is named {@code <label> <node>}
     * @param nodeType    the {@code NodeType} the device abstracts, published as {@code tinysep.node.type}
     * @param quantity    what the percentage means, e.g. {@code potency}: the parameter's key and the event text
     * @param payloadType status payload class; other payloads of a multi-type node are ignored
     * @param percentOf   the percentage a status payload reports
     * @param command     the payload that requests a percentage
     * @param provides    the provider interface the device registers under and is told to listeners as
     * @param call        the listener call, e.g. {@code HeaterListener::potencyChanged}
     */
    protected <V> PercentActuatorDevice(DriverContext context, BusRadioAmicaProvider bus, String label,
            String nodeType, String quantity, Class<P> payloadType, ToIntFunction<P> percentOf, IntFunction<P> command,
            Class<V> provides, ListenerCall<L, ? super V> call) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(), label + " " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        this.quantity = quantity;
        this.payloadType = payloadType;
        this.percentOf = percentOf;
        this.command = command;
        this.setting = new ConfirmedSetting<>(v -> quantity + " " + v, PATIENCE, this::now, this::event);
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {nodeType});
        this.teller = (listener, value, at) -> call.tell(listener, provides.cast(this), value, at);
        publish(this, provides);
    }

    /** A listener call bound to this device as its provider interface. */
    private interface Teller<L> {
        void tell(L listener, Percent value, Instant at);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public final void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        Percent reported;
        try {
            AmicaPayload decoded = AmicaPayloads.decode(payload);
            if (!payloadType.isInstance(decoded)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            reported = Percent.of(percentOf.applyAsInt(payloadType.cast(decoded)));
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        status(DeviceStatus.State.ONLINE, "");
        setting.report(reported, at).ifPresent(v -> listeners.fire(l -> teller.tell(l, v, at)));
    }

    /** Sends the command for {@code value}; the level changes when the node confirms it. */
    @Override
    public final void setLevel(Percent value) {
        if (value == null) {
            throw new IllegalArgumentException(quantity + " must not be null");
        }
        byte[] bytes = AmicaPayloads.encode(command.apply(value.value()));
        if (!setting.request(value, () -> bus.send(bytes))) {
            status(DeviceStatus.State.ERROR, "last command not sent, see the event log");
        }
    }

    /** @return the level the node last reported, empty before its first report */
    @Override
    public final Optional<Percent> level() {
        return setting.value();
    }

    /** The provider interface's {@code connect}. */
    public final Connection connect(L listener) {
        return listeners.add(listener);
    }

    /** The provider interfaces' {@code deviceUid()}. */
    public final String deviceUid() {
        return uid();
    }

    @Override
    protected final boolean backedUp(String key) {
        return false; // the value parameter is a command to the node, not a setting (docs/backup.md)
    }

    @Override
    protected final List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable(quantity, setting.value().orElse(null),
                        "0..100 %; shows the node's report, a change waits for the node to confirm it"),
                setting.pendingParameter());
    }

    @Override
    protected final void applyParameter(String key, String value) {
        if (!quantity.equals(key)) {
            throw unknownParameter(key);
        }
        setLevel(ParameterValues.percent(quantity, value));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
