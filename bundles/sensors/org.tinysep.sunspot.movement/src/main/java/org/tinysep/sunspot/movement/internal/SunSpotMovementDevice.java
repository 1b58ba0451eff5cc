package org.tinysep.sunspot.movement.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.Coordinates;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.api.sensor.MovementWithCoordinatesListener;
import org.tinysep.api.sensor.MovementWithCoordinatesProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.MovementSensorDevice;
import org.tinysep.device.support.sensor.Source;
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
final class SunSpotMovementDevice extends MovementSensorDevice<SunSpotMovementDevice.Located>
        implements MovementWithCoordinatesProvider {

    /** A report and where the motion was (null if the payload had no position). */
    record Located(MovementEvent event, Coordinates where) {
    }

    private static final Source.Frames FRAMES = new Source.Frames(SunSpotSensorType.MOVEMENT.code(), "movement");

    private volatile Coordinates lastCoordinates;

    SunSpotMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Source.sunSpot(bus, FRAMES, SunSpotPayloads::decode, MovementDetection.class,
                (m, at) -> new Located(new MovementEvent(m.detected(), at), toMetres(m.position()))),
                NodeType.MOVEMENT, "Movement sensor " + bus.nodeAddress(), Located::event,
                MovementWithCoordinatesProvider.class, MovementProvider.class);
    }

    /** @return the position in metres, or null when the payload had none */
    static Coordinates toMetres(Position p) {
        return p == null ? null
                : new Coordinates(p.xCentimetres() / 100.0, p.yCentimetres() / 100.0, p.zCentimetres() / 100.0);
    }

    @Override
    protected void accepted(Located l) {
        if (l.event().detected()) {
            lastCoordinates = l.where();
        }
    }

    @Override
    protected String describe(Located l) {
        return super.describe(l) + (l.event().detected() && l.where() != null ? " at " + l.where() : "");
    }

    @Override
    protected void tell(MovementListener listener, Located l, boolean first, Instant at) {
        listener.movementReported(this, l.event());
        if (l.where() != null && listener instanceof MovementWithCoordinatesListener located) {
            located.movementLocated(this, l.event(), l.where());
        }
    }

    @Override
    public Optional<Coordinates> lastCoordinates() {
        return Optional.ofNullable(lastCoordinates);
    }

    @Override
    protected List<Parameter> readings() {
        Coordinates c = lastCoordinates;
        List<Parameter> all = new ArrayList<>(super.readings());
        all.add(Parameter.readOnly("lastCoordinates", c == null ? "" : c, "where the last motion was, in metres"));
        return all;
    }
}
