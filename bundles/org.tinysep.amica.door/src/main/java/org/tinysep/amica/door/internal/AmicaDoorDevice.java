package org.tinysep.amica.door.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.ReedSwitchStatus;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorListener;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;

/**
 * Abstracts one AmICA reed switch on a door: Reed-Switch Status payloads (100 3 0 A) become door states.
 * Listeners and the event log hear changes only (the node repeats its state every second).
 */
final class AmicaDoorDevice extends AbstractDevice implements DoorProvider, BusRadioAmicaListener {

    private final BusRadioAmicaProvider bus;
    private final Listeners<DoorListener> listeners;
    private volatile OpenState state = OpenState.UNKNOWN;
    private volatile Instant since;
    private volatile DoorKind kind = DoorKind.OUTER;

    AmicaDoorDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Door " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.DOOR});
        publish(this, DoorProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        OpenState next;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof ReedSwitchStatus reed)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            next = reed.open() ? OpenState.OPEN : OpenState.CLOSED;
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        status(DeviceStatus.State.ONLINE, "");
        if (next == state) {
            return;
        }
        state = next;
        since = at;
        event(next == OpenState.OPEN ? "door opened" : "door closed");
        listeners.fire(l -> l.doorChanged(this, next, at));
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(DoorListener listener) {
        return listeners.add(listener);
    }

    @Override
    public OpenState state() {
        return state;
    }

    @Override
    public DoorKind kind() {
        return kind;
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("kind", kind, "OUTER (to the outside; watched by Flat Occupancy) or INNER"),
                Parameter.readOnly("state", state, "last reported state"),
                Parameter.readOnly("since", since, "when the state was entered"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"kind".equals(key)) {
            throw unknownParameter(key);
        }
        try {
            kind = DoorKind.valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException | NullPointerException e) {
            throw new IllegalArgumentException("kind must be OUTER or INNER, was '" + value + "'");
        }
        event("door kind set to " + kind);
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
