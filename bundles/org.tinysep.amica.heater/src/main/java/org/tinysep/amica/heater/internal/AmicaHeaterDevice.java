package org.tinysep.amica.heater.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.actuator.HeaterListener;
import org.tinysep.api.actuator.HeaterProvider;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.ConfirmedSetting;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.ParameterValues;
import org.tinysep.device.support.Uids;

/**
 * Abstracts one AmICA heater node. Heater Control status payloads (5 8 0 A) report the potency;
 * {@link #setPotency(Percent)} sends Heater Control A and returns at once. Thesis actuator model:
 * the potency, its listeners and the event log change only when the node's next status report confirms it;
 * until then the request is shown as the read-only parameter {@code pending}.
 */
final class AmicaHeaterDevice extends AbstractDevice implements HeaterProvider, BusRadioAmicaListener {

    /** Status reports that may disagree with a request before it is given up (the first may cross it). */
    static final int PATIENCE = 2;

    private final BusRadioAmicaProvider bus;
    private final Listeners<HeaterListener> listeners;
    private final ConfirmedSetting<Percent> potency = new ConfirmedSetting<>(v -> "potency " + v, PATIENCE,
            this::event);

    AmicaHeaterDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Heater " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.HEATER});
        publish(this, HeaterProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        Percent reported;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof HeaterControl control)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            reported = Percent.of(control.percent());
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        status(DeviceStatus.State.ONLINE, "");
        potency.report(reported).ifPresent(v -> listeners.fire(l -> l.potencyChanged(this, v, at)));
    }

    @Override
    public void setPotency(Percent value) {
        if (value == null) {
            throw new IllegalArgumentException("potency must not be null");
        }
        byte[] command = AmicaPayloads.encode(new HeaterControl(value.value()));
        if (!potency.request(value, () -> bus.send(command))) {
            status(DeviceStatus.State.ERROR, "last command not sent, see the event log");
        }
    }

    @Override
    public Optional<Percent> potency() {
        return potency.value();
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(HeaterListener listener) {
        return listeners.add(listener);
    }

    @Override
    protected boolean backedUp(String key) {
        return false; // its writable parameter is a command to the node, not a setting (docs/backup.md)
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("potency", potency.value().orElse(null),
                        "0..100 %; shows the node's report, a change waits for the node to confirm it"),
                potency.pendingParameter());
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"potency".equals(key)) {
            throw unknownParameter(key);
        }
        setPotency(ParameterValues.percent("potency", value));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
