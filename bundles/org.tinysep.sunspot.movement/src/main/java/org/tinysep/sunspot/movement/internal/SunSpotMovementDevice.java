package org.tinysep.sunspot.movement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.sensor.Movements;
import org.tinysep.device.support.sensor.SunSpotSensorDevice;
import org.tinysep.sunspot.protocol.MovementDetection;
import org.tinysep.sunspot.protocol.Position;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT movement node: Movement Detection payloads become {@link MovementEvent}s, and a version-2
 * payload's position becomes {@link Coordinates} (thesis 3.5 interface extension: registered as both
 * {@link MovementWithCoordinatesProvider} and {@link MovementProvider}). Every report goes to the listeners; only
 * changes (motion / no motion) are written to the event log.
 */
final class SunSpotMovementDevice
        extends SunSpotSensorDevice<MovementListener, MovementDetection, SunSpotMovementDevice.Located>
        implements MovementWithCoordinatesProvider {

    /** A report and where the motion was (null if the payload had no position). */
    record Located(MovementEvent event, Coordinates where) {
    }

    private static final Frames<MovementDetection> FRAMES = new Frames<>(SunSpotSensorType.MOVEMENT.code(),
            "movement", SunSpotPayloads::decode, MovementDetection.class);

    private volatile Coordinates lastCoordinates;
    private volatile MovementLocation location = MovementLocation.INSIDE;

    SunSpotMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, bus, NodeType.MOVEMENT, "Movement sensor " + bus.nodeAddress(), FRAMES,
                MovementWithCoordinatesProvider.class, MovementProvider.class);
    }

    @Override
    protected Located read(MovementDetection motion, Instant at) {
        Located l = new Located(new MovementEvent(motion.detected(), at), toMetres(motion.position()));
        if (motion.detected()) {
            lastCoordinates = l.where();
        }
        return l;
    }

    @Override
    protected boolean isChange(Located before, Located now) {
        return Movements.isChange(before.event(), now.event());
    }

    @Override
    protected String describe(Located l) {
        return l.event().detected() ? "movement detected" + (l.where() == null ? "" : " at " + l.where())
                : "no movement";
    }

    @Override
    protected boolean tellsEveryReport() {
        return true;
    }

    @Override
    protected void tell(MovementListener listener, Located l, boolean first, Instant at) {
        listener.movementReported(this, l.event());
        if (l.where() != null && listener instanceof MovementWithCoordinatesListener located) {
            located.movementLocated(this, l.event(), l.where());
        }
    }

    /** @return the position in metres, or null when the payload had none */
    static Coordinates toMetres(Position p) {
        return p == null ? null
                : new Coordinates(p.xCentimetres() / 100.0, p.yCentimetres() / 100.0, p.zCentimetres() / 100.0);
    }

    @Override
    public Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(latest()).map(Located::event);
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
    protected List<Parameter> settings() {
        return List.of(Movements.location(location));
    }

    @Override
    protected List<Parameter> readings() {
        Coordinates c = lastCoordinates;
        return List.of(Movements.lastMovement(lastMovement().orElse(null)),
                Parameter.readOnly("lastCoordinates", c == null ? "" : c, "where the last motion was, in metres"));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"location".equals(key)) {
            throw unknownParameter(key);
        }
        MovementLocation l = Movements.parseLocation(value);
        location = l;
        event("location set to " + l);
        Instant at = now();
        fire(x -> x.locationChanged(this, l, at));
    }
}
