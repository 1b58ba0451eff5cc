package org.tinysep.amica.petmovement.internal;

import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.amica.protocol.AmicaPayloads;
import org.tinysep.amica.protocol.AmicaProtocolException;
import org.tinysep.amica.protocol.MotionDetection;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
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

/**
 * Abstracts one AmICA pet collar: its Movement Detection payloads (100 5 0 A, the same bytes as a person's
 * movement sensor; the node type tells them apart) become pet {@link MovementEvent}s. Every report is passed on;
 * only changes (motion / no motion) are written to the event log.
 */
final class AmicaPetMovementDevice extends AbstractDevice implements PetMovementProvider, BusRadioAmicaListener {

    private final BusRadioAmicaProvider bus;
    private final Listeners<PetMovementListener> listeners;
    private volatile MovementEvent last;

    AmicaPetMovementDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, Uids.of(context.driverName(), bus.deviceUid()), context.driverName(),
                "Pet collar " + bus.nodeId());
        this.bus = bus;
        this.listeners = new Listeners<>(uid());
        serviceProperty(DeviceProperties.NODE_ADDRESS, bus.nodeId());
        serviceProperty(DeviceProperties.NODE_TYPE, new String[] {NodeType.PET_COLLAR});
        publish(this, PetMovementProvider.class);
    }

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        MotionDetection motion;
        try {
            if (!(AmicaPayloads.decode(payload) instanceof MotionDetection m)) {
                return; // keep-alives and other types of a multi-type node are not ours
            }
            motion = m;
        } catch (AmicaProtocolException e) {
            return; // the bus radio already rejected and counted it
        }
        MovementEvent event = new MovementEvent(motion.detected(), at);
        MovementEvent previous = last;
        last = event;
        status(DeviceStatus.State.ONLINE, "");
        if (previous == null || previous.detected() != event.detected()) {
            event(event.detected() ? "pet movement detected" : "no pet movement");
        }
        listeners.fire(l -> l.petMovementReported(this, event));
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
        return List.of(Parameter.readOnly("lastMovement",
                e == null ? "" : (e.detected() ? "motion at " : "none at ") + e.at(), "last report"));
    }

    @Override
    protected void onDispose() {
        listeners.closeAll();
    }
}
