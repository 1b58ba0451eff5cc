package org.tinysep.amica.movement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementLocation;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.sensor.AmicaSensorDevice;
import org.tinysep.device.support.sensor.Movements;

/**
 * Abstracts one AmICA movement node: Movement Detection payloads (100 5 0 A) become {@link MovementEvent}s.
 * Every report is passed on; only changes (motion / no motion) are written to the event log.
 */
final class AmicaMovementDevice extends AmicaSensorDevice<MovementListener, MotionDetection, MovementEvent>
        implements MovementProvider {

    private volatile MovementLocation location = MovementLocation.INSIDE;

    AmicaMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, bus, NodeType.MOVEMENT, "Movement sensor " + bus.nodeId(), AmicaPayloads::decode,
                MotionDetection.class, MovementProvider.class);
    }

    @Override
    protected MovementEvent read(MotionDetection motion, Instant at) {
        return new MovementEvent(motion.detected(), at);
    }

    @Override
    protected boolean isChange(MovementEvent before, MovementEvent now) {
        return Movements.isChange(before, now);
    }

    @Override
    protected String describe(MovementEvent e) {
        return e.detected() ? "movement detected" : "no movement";
    }

    @Override
    protected boolean tellsEveryReport() {
        return true;
    }

    @Override
    protected void tell(MovementListener listener, MovementEvent movement, boolean first, Instant at) {
        listener.movementReported(this, movement);
    }

    @Override
    public Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(latest());
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
        return List.of(Movements.lastMovement(latest()));
    }

    @Override
    protected void applyParameter(String key, String value) {
        if (!"location".equals(key)) {
            throw unknownParameter(key);
        }
        MovementLocation l = Movements.parseLocation(value);
        location = l;
        Instant at = now();
        fire(x -> x.locationChanged(this, l, at));
    }
}
