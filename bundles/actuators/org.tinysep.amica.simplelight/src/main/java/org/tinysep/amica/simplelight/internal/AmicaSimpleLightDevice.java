package org.tinysep.amica.simplelight.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.SimpleLightListener;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.lifecycle.AbstractDevice;
import org.tinysep.device.support.lifecycle.ConfirmedSetting;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.lifecycle.Listeners;
import org.tinysep.device.support.lifecycle.ParameterValues;
import org.tinysep.device.support.lifecycle.Uids;

/**
 * Abstracts one AmICA light node as an on/off light. Light Control status payloads (5 2 0 A) report the light:
 * on when A &gt; 0. {@link #switchLight(boolean)} sends Light Control 100 or 0 and returns at once. Thesis actuator
 * model: the state, its listeners and the event log change only when the node's next status report confirms it;
 * until then the request is shown as the read-only parameter {@code pending}. The command goes on the wire before
 * its "light on requested" line is written to the event log ({@link ConfirmedSetting#request}; issue 29).
 */
final class AmicaSimpleLightDevice extends AbstractDevice implements SimpleLightProvider, BusRadioAmicaListener {

    /** An AmICA actuator node reports its value every 10 s (thesis 3.9.1, docs/protocols/amica.md). */
    static final Duration REPORT_INTERVAL = Duration.ofSeconds(10);
    /**
     * How long after a request a disagreeing status report may still predate the command: two report intervals, so
     * the node has one whole interval to answer before a report of the old value counts as a contradiction.
     */
    static final Duration PATIENCE = REPORT_INTERVAL.multipliedBy(2);

    private final BusRadioAmicaProvider bus;
    private final Listeners<SimpleLightListener> listeners;
    private final ConfirmedSetting<Boolean> on = new ConfirmedSetting<>(v -> v ? "light on" : "light off",
            PATIENCE, this::now, this::event);

    AmicaSimpleLightDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(), "Light " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.SIMPLE_LIGHT});
        publish(this, SimpleLightProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        boolean lit;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof LightControl light)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            lit = light.percent() > 0;
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        status(DeviceStatus.State.ONLINE, "");
        on.report(lit, at).ifPresent(v -> listeners.fire(l -> l.lightSwitched(this, v, at)));
    }

    @Override
    public void switchLight(boolean switchOn) {
        byte[] command = AmicaPayloads.encode(new LightControl(switchOn ? 100 : 0));
        if (!on.request(switchOn, () -> bus.send(command))) {
            status(DeviceStatus.State.ERROR, "last command not sent, see the event log");
        }
    }

    @Override
    public Optional<Boolean> isOn() {
        return on.value();
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(SimpleLightListener listener) {
        return listeners.add(listener);
    }

    @Override
    protected boolean backedUp(String key) {
        return false; // its writable parameter is a command to the node, not a setting (docs/backup.md)
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("on", on.value().orElse(null),
                        "true or false; shows the node's report, a change waits for the node to confirm it"),
                on.pendingParameter());
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"on".equals(key)) {
            throw unknownParameter(key);
        }
        switchLight(ParameterValues.bool("on", value));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
