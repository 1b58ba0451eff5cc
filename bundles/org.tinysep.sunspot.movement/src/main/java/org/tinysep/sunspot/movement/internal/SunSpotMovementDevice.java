package org.tinysep.sunspot.movement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT movement node: Movement Detection payloads become {@link MovementEvent}s, and a version-2
 * payload's position becomes {@link Coordinates} (thesis 3.5 interface extension: registered as both
 * {@link MovementWithCoordinatesProvider} and {@link MovementProvider}). Every report goes to the listeners; only
 * changes (motion / no motion) are written to the event log.
 */
final class SunSpotMovementDevice extends AbstractDevice
        implements MovementWithCoordinatesProvider, BusRadioSunSpotListener {

    private final BusRadioSunSpotProvider bus;
    private final Listeners<MovementListener> listeners;
    private final AtomicLong rejected = new AtomicLong();
    private volatile MovementEvent last;
    private volatile Coordinates lastCoordinates;
    private volatile MovementLocation location = MovementLocation.INSIDE;

    SunSpotMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Movement sensor " + bus.nodeAddress());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeAddress());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.MOVEMENT});
        publish(this, MovementWithCoordinatesProvider.class, MovementProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioSunSpotProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at) {
        if (sensorType != SunSpotSensorType.MOVEMENT.code()) {
            return; // other sensors of a multi-sensor node are not ours
        }
        MovementDetection motion;
        try {
            SunSpotPayload decoded = SunSpotPayloads.decode(payload);
            if (!(decoded instanceof MovementDetection m)) {
                reject("a movement frame carried " + decoded.getClass().getSimpleName());
                return;
            }
            motion = m;
        } catch (SunSpotProtocolException | RuntimeException e) {
            reject(e.getMessage());
            return;
        }
        report(new MovementEvent(motion.detected(), at), toMetres(motion.position()));
    }

    private void report(MovementEvent event, Coordinates where) {
        MovementEvent previous = last;
        last = event;
        if (event.detected()) {
            lastCoordinates = where;
        }
        status(DeviceStatus.State.ONLINE, "");
        if (previous == null || previous.detected() != event.detected()) {
            event(event.detected() ? "movement detected" + (where == null ? "" : " at " + where) : "no movement");
        }
        listeners.fire(l -> {
            l.movementReported(this, event);
            if (where != null && l instanceof MovementWithCoordinatesListener located) {
                located.movementLocated(this, event, where);
            }
        });
    }

    /** @return the position in metres, or null when the payload had none */
    static Coordinates toMetres(Position p) {
        return p == null ? null
                : new Coordinates(p.xCentimetres() / 100.0, p.yCentimetres() / 100.0, p.zCentimetres() / 100.0);
    }

    private void reject(String reason) {
        rejected.incrementAndGet();
        status(DeviceStatus.State.ERROR, "rejected payload: " + reason);
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
    public Optional<Coordinates> lastCoordinates() {
        return Optional.ofNullable(lastCoordinates);
    }

    @Override
    public MovementLocation location() {
        return location;
    }

    @Override
    protected List<Parameter> moreParameters() {
        MovementEvent e = last;
        Coordinates c = lastCoordinates;
        return List.of(
                Parameter.writable("location", location, "INSIDE or OUTSIDE the flat"),
                Parameter.readOnly("lastMovement", e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(),
                        "last report"),
                Parameter.readOnly("lastCoordinates", c == null ? "" : c, "where the last motion was, in metres"),
                Parameter.readOnly("rejectedPayloads", rejected.get(), "movement payloads that could not be read"));
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
        event("location set to " + l);
        Instant at = now();
        listeners.fire(x -> x.locationChanged(this, l, at));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
