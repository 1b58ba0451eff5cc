package org.tinysep.amica.movement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;

/**
 * Abstracts one AmICA movement node: Movement Detection payloads (100 5 0 A) become {@link MovementEvent}s.
 * Every report is passed on; only changes (motion / no motion) are written to the event log.
 */
final class AmicaMovementDevice extends AbstractDevice implements MovementProvider, BusRadioAmicaListener {

    private final BusRadioAmicaProvider bus;
    private final Listeners<MovementListener> listeners;
    private volatile MovementEvent last;
    private volatile MovementLocation location = MovementLocation.INSIDE;

    AmicaMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Movement sensor " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.MOVEMENT});
        publish(this, MovementProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        MotionDetection motion;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof MotionDetection m)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            motion = m;
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        MovementEvent event = new MovementEvent(motion.detected(), at);
        MovementEvent previous = last;
        last = event;
        status(DeviceStatus.State.ONLINE, "");
        if (previous == null || previous.detected() != event.detected()) {
            event(event.detected() ? "movement detected" : "no movement");
        }
        listeners.fire(l -> l.movementReported(this, event));
    }

    @Override
    public String deviceUid() {
        return uid();
    }

    @Override
    public Connection connect(MovementListener listener) {
        return listeners.add(listener);
    }

    @Override
    public Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(last);
    }

    @Override
    public MovementLocation location() {
        return location;
    }

    @Override
    protected List<Parameter> moreParameters() {
        MovementEvent e = last;
        return List.of(
                Parameter.writable("location", location, "INSIDE or OUTSIDE the flat"),
                Parameter.readOnly("lastMovement", e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(),
                        "last report"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"location".equals(key)) {
            throw unknownParameter(key);
        }
        MovementLocation l;
        try {
            l = MovementLocation.valueOf(value.strip().toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException | NullPointerException e) {
            throw new IllegalArgumentException("location must be INSIDE or OUTSIDE, was '" + value + "'");
        }
        location = l;
        Instant at = now();
        listeners.fire(x -> x.locationChanged(this, l, at));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
