package org.tinysep.amica.petmovement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.sensor.AmicaSensorDevice;
import org.tinysep.device.support.sensor.Movements;

/**
 * Abstracts one AmICA pet collar: its Movement Detection payloads (100 5 0 A, the same bytes as a person's
 * movement sensor; the node type tells them apart) become pet {@link MovementEvent}s. Every report is passed on;
 * only changes (motion / no motion) are written to the event log.
 */
final class AmicaPetMovementDevice extends AmicaSensorDevice<PetMovementListener, MotionDetection, MovementEvent>
        implements PetMovementProvider {

    AmicaPetMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, bus, NodeType.PET_COLLAR, "Pet collar " + bus.nodeId(), AmicaPayloads::decode,
                MotionDetection.class, PetMovementProvider.class);
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
        return e.detected() ? "pet movement detected" : "no pet movement";
    }

    @Override
    protected boolean tellsEveryReport() {
        return true;
    }

    @Override
    protected void tell(PetMovementListener listener, MovementEvent movement, boolean first, Instant at) {
        listener.petMovementReported(this, movement);
    }

    @Override
    public Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(latest());
    }

    @Override
    protected List<Parameter> readings() {
        return List.of(Movements.lastMovement(latest()));
    }
}
