package org.tinysep.sunspot.petmovement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.DeviceProperties;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.NodeType;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.sensor.MovementEvent;
import org.tinysep.api.sensor.PetMovementListener;
import org.tinysep.api.sensor.PetMovementProvider;
import org.tinysep.device.support.AbstractDevice;
import org.tinysep.device.support.DriverContext;
import org.tinysep.device.support.Listeners;
import org.tinysep.device.support.Uids;
import org.tinysep.sunspot.protocol.PetMovementDetection;
import org.tinysep.sunspot.protocol.SunSpotPayload;
import org.tinysep.sunspot.protocol.SunSpotPayloads;
import org.tinysep.sunspot.protocol.SunSpotProtocolException;
import org.tinysep.sunspot.protocol.SunSpotSensorType;

/**
 * Abstracts one Sun SPOT pet collar: Pet Movement Detection payloads become pet movement reports. Every report
 * goes to the listeners; only changes (pet moving / still) are written to the event log. Deliberately not a
 * {@code MovementProvider}: a pet moving must not count as a person moving.
 */
final class SunSpotPetMovementDevice extends AbstractDevice implements PetMovementProvider, BusRadioSunSpotListener {

    private final BusRadioSunSpotProvider bus;
    private final Listeners<PetMovementListener> listeners;
    private final AtomicLong rejected = new AtomicLong();
    private volatile MovementEvent last;

    SunSpotPetMovementDevice(DriverContext context, BusRadioSunSpotProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Pet collar " + bus.nodeAddress());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeAddress());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.PET_COLLAR});
        publish(this, PetMovementProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioSunSpotProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at) {
        if (sensorType != SunSpotSensorType.PET_COLLAR.code()) {
            return; // other sensors of a multi-sensor node are not ours
        }
        PetMovementDetection pet;
        try {
            SunSpotPayload decoded = SunSpotPayloads.decode(payload);
            if (!(decoded instanceof PetMovementDetection p)) {
                reject("a pet collar frame carried " + decoded.getClass().getSimpleName());
                return;
            }
            pet = p;
        } catch (SunSpotProtocolException | RuntimeException e) {
            reject(e.getMessage());
            return;
        }
        MovementEvent event = new MovementEvent(pet.detected(), at);
        MovementEvent previous = last;
        last = event;
        status(DeviceStatus.State.ONLINE, "");
        if (previous == null || previous.detected() != event.detected()) {
            event(event.detected() ? "pet movement detected" : "no pet movement");
        }
        listeners.fire(l -> l.petMovementReported(this, event));
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
    public Connection connect(PetMovementListener listener) {
        return listeners.add(listener);
    }

    @Override
    public Optional<MovementEvent> lastMovement() {
        return Optional.ofNullable(last);
    }

    @Override
    protected List<Parameter> moreParameters() {
        MovementEvent e = last;
        return List.of(
                Parameter.readOnly("lastMovement", e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(),
                        "last report"),
                Parameter.readOnly("rejectedPayloads", rejected.get(), "pet collar payloads that could not be read"));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
