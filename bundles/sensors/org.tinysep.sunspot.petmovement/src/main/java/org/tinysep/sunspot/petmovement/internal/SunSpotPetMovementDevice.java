package org.tinysep.sunspot.petmovement.internal;

import java.time.Instant;
import java.util.function.Function;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.device.support.lifecycle.DriverContext;
import org.tinysep.device.support.sensor.MotionSensorDevice;
import org.tinysep.device.support.sensor.Source;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT pet collar: Pet Movement Detection payloads become pet movement reports. Every report
 * goes to the listeners; only changes (pet moving / still) are written to the event log. Deliberately not a
 * {@code MovementProvider}: a pet moving must not count as a person moving.
 */
final class SunSpotPetMovementDevice extends MotionSensorDevice<PetMovementListener, MovementEvent>
        implements PetMovementProvider {

    private static final Source.Frames FRAMES = new Source.Frames(SunSpotSensorType.PET_COLLAR.code(), "pet collar");

    SunSpotPetMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Source.sunSpot(bus, FRAMES, SunSpotPayloads::decode, PetMovementDetection.class,
                (pet, at) -> new MovementEvent(pet.detected(), at)), NodeType.PET_COLLAR,
                "Pet collar " + bus.nodeAddress(), Function.identity(), "pet movement detected", "no pet movement",
                PetMovementProvider.class);
    }

    @Override
    protected void tell(PetMovementListener listener, MovementEvent movement, boolean first, Instant at) {
        listener.petMovementReported(this, movement);
    }
}
