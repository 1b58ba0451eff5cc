package org.tinysep.amica.dimmablelight.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.DimmableLightListener;
import org.tinysep.api.actuator.DimmableLightProvider;
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
 * Abstracts one AmICA light node as a dimmable light. Light Control status payloads (5 2 0 A) report the
 * brightness; {@link #setBrightness(Percent)} sends Light Control A and returns at once. Thesis actuator model:
 * the brightness, its listeners and the event log change only when the node's next status report confirms it;
 * until then the request is shown as the read-only parameter {@code pending}.
 */
final class AmicaDimmableLightDevice extends AbstractDevice implements DimmableLightProvider, BusRadioAmicaListener {

    /** Status reports that may disagree with a request before it is given up (the first may cross it). */
    static final int PATIENCE = 2;

    private final BusRadioAmicaProvider bus;
    private final Listeners<DimmableLightListener> listeners;
    private final ConfirmedSetting<Percent> brightness = new ConfirmedSetting<>(v -> "brightness " + v, PATIENCE,
            this::event);

    AmicaDimmableLightDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Dimmable light " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.DIMMABLE_LIGHT});
        publish(this, DimmableLightProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        Percent reported;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof LightControl light)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            reported = Percent.of(light.percent());
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        status(DeviceStatus.State.ONLINE, "");
        brightness.report(reported).ifPresent(v -> listeners.fire(l -> l.brightnessChanged(this, v, at)));
    }

    @Override
    public void setBrightness(Percent value) {
        if (value == null) {
            throw new IllegalArgumentException("brightness must not be null");
        }
        byte[] command = AmicaPayloads.encode(new LightControl(value.value()));
        if (!brightness.request(value, () -> bus.send(command))) {
            status(DeviceStatus.State.ERROR, "last command not sent, see the event log");
        }
    }

    @Override
    public Optional<Percent> brightness() {
        return brightness.value();
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(DimmableLightListener listener) {
        return listeners.add(listener);
    }

    @Override
    protected boolean backedUp(String key) {
        return false; // its writable parameter is a command to the node, not a setting (docs/backup.md)
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("brightness", brightness.value().orElse(null),
                        "0..100 %; shows the node's report, a change waits for the node to confirm it"),
                brightness.pendingParameter());
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"brightness".equals(key)) {
            throw unknownParameter(key);
        }
        setBrightness(ParameterValues.percent("brightness", value));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
