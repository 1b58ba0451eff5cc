package org.tinysep.sunspot.petmovement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.sensor.Movements;
import org.tinysep.device.support.sensor.SunSpotSensorDevice;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT pet collar: Pet Movement Detection payloads become pet movement reports. Every report
 * goes to the listeners; only changes (pet moving / still) are written to the event log. Deliberately not a
 * {@code MovementProvider}: a pet moving must not count as a person moving.
 */
final class SunSpotPetMovementDevice
        extends SunSpotSensorDevice<PetMovementListener, PetMovementDetection, MovementEvent>
        implements PetMovementProvider {

    private static final Frames<PetMovementDetection> FRAMES = new Frames<>(SunSpotSensorType.PET_COLLAR.code(),
            "pet collar", SunSpotPayloads::decode, PetMovementDetection.class);

    SunSpotPetMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, bus, NodeType.PET_COLLAR, "Pet collar " + bus.nodeAddress(), FRAMES,
                PetMovementProvider.class);
    }

    @Override
    protected MovementEvent read(PetMovementDetection pet, Instant at) {
        return new MovementEvent(pet.detected(), at);
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
