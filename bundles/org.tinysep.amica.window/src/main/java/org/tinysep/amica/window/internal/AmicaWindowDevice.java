package org.tinysep.amica.window.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
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
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowListener;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;

/**
 * Abstracts one AmICA reed switch on a window: Reed-Switch Status payloads (100 3 0 A) become window states.
 * Listeners and the event log hear changes only (the node repeats its state every second). The user may give
 * the window's position, which listeners hear as {@code windowPositionChanged}.
 */
final class AmicaWindowDevice extends AbstractDevice implements WindowProvider, BusRadioAmicaListener {

    private final BusRadioAmicaProvider bus;
    private final Listeners<WindowListener> listeners;
    private volatile OpenState state = OpenState.UNKNOWN;
    private volatile Instant since;
    private volatile Optional<Coordinates> position = Optional.empty();

    AmicaWindowDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Window " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.WINDOW});
        publish(this, WindowProvider.class);
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
        event(next == OpenState.OPEN ? "window opened" : "window closed");
        listeners.fire(l -> l.windowChanged(this, next, at));
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(WindowListener listener) {
        return listeners.add(listener);
    }

    @Override
    public OpenState state() {
        return state;
    }

    @Override
    public Optional<Coordinates> position() {
        return position;
    }

    @Override
    protected List<Parameter> moreParameters() {
        return List.of(
                Parameter.writable("position", Positions.format(position),
                        "x,y,z in metres in the house's frame, empty when unknown"),
                Parameter.readOnly("state", state, "last reported state"),
                Parameter.readOnly("since", since, "when the state was entered"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"position".equals(key)) {
            throw unknownParameter(key);
        }
        Optional<Coordinates> next = Positions.parse(value);
        if (next.equals(position)) {
            return;
        }
        position = next;
        if (next.isEmpty()) {
            event("window position cleared"); // WindowListener has no event for "no position"
            return;
        }
        Coordinates c = next.get();
        event("window position set to " + Positions.format(next) + " m");
        Instant at = now();
        listeners.fire(l -> l.windowPositionChanged(this, c, at));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
