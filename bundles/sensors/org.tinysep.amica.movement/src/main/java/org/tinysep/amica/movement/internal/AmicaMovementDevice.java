package org.tinysep.amica.movement.internal;

import java.time.Instant;
import java.util.function.Function;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.MovementListener;
import org.tinysep.api.sensor.MovementProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.MovementSensorDevice;
import org.tinysep.device.support.sensor.Source;

/**
 * Abstracts one AmICA movement node: Movement Detection payloads (100 5 0 A) become {@link MovementEvent}s.
 * Every report is passed on; only changes (motion / no motion) are written to the event log.
 */
final class AmicaMovementDevice extends MovementSensorDevice<MovementEvent> {

    AmicaMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Source.amica(bus, AmicaPayloads::decode, MotionDetection.class,
                (m, at) -> new MovementEvent(m.detected(), at)), NodeType.MOVEMENT, "Movement sensor " + bus.nodeId(),
                Function.identity(), MovementProvider.class);
    }

    @Override
    protected void tell(MovementListener listener, MovementEvent movement, boolean first, Instant at) {
        listener.movementReported(this, movement);
    }
}
