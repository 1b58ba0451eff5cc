package org.tinysep.amica.petmovement.internal;

import java.time.Instant;
import java.util.function.Function;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.MotionSensorDevice;
import org.tinysep.device.support.sensor.Source;

/**
 * Abstracts one AmICA pet collar: its Movement Detection payloads (100 5 0 A, the same bytes as a person's
 * movement sensor; the node type tells them apart) become pet {@link MovementEvent}s. Every report is passed on;
 * only changes (motion / no motion) are written to the event log.
 */
final class AmicaPetMovementDevice extends MotionSensorDevice<PetMovementListener, MovementEvent>
        implements PetMovementProvider {

    AmicaPetMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Source.amica(bus, AmicaPayloads::decode, MotionDetection.class,
                (m, at) -> new MovementEvent(m.detected(), at)), NodeType.PET_COLLAR, "Pet collar " + bus.nodeId(),
                Function.identity(), "pet movement detected", "no pet movement", PetMovementProvider.class);
    }

    @Override
    protected void tell(PetMovementListener listener, MovementEvent movement, boolean first, Instant at) {
        listener.petMovementReported(this, movement);
    }
}
