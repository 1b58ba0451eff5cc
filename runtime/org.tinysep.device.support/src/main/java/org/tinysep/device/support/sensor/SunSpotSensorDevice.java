package org.tinysep.device.support.sensor;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.DeviceStatus;
import org.tinysep.api.device.Parameter;
import org.tinysep.device.support.DriverContext;

/**
 * A sensor of a Sun SPOT node: connects to its bus device (vital), keeps the frames of its sensor type (the other
 * sensors of a multi-sensor node are not its own) and decodes them. A frame of its type that cannot be read, or
 * carries another payload, is rejected: counted ({@code rejectedPayloads}) and the device is in ERROR until the
 * next good one.
 *
 * @param <L> the listener interface
 * @param <P> the payload type, e.g. the protocol's {@code LightStatus}
 * @param <V> the reading
 */
public abstract class SunSpotSensorDevice<L, P, V> extends SensorDevice<L, V> implements BusRadioSunSpotListener {

    /** What a sensor reads: its sensor type code, its name in messages ("light"), its decoder and payload type. */
    public record Frames<P>(int sensorType, String word, Decoder decoder, Class<P> payloadType) {
    }

    private final BusRadioSunSpotProvider bus;
    private final Frames<P> frames;
    private final AtomicLong rejected = new AtomicLong();

    protected SunSpotSensorDevice(DriverContext context, BusRadioSunSpotProvider bus, String nodeType, String name,
            Frames<P> frames, Class<?>... provides) {
        super(context, bus.deviceUid(), bus.nodeAddress(), nodeType, name, provides);
        this.bus = bus;
        this.frames = frames;
    }

    /** @return the reading a payload carries; may throw for a value out of range (a reject) */
    protected abstract V read(P payload, Instant at);

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioSunSpotProvider.class, this, true);
    }

    @Override
    public final void payloadReceived(BusRadioSunSpotProvider source, int sensorType, byte[] payload, Instant at) {
        if (sensorType != frames.sensorType()) {
            return; // other sensors of a multi-sensor node are not ours
        }
        V reading;
        try {
            Object decoded = frames.decoder().decode(payload);
            if (!frames.payloadType().isInstance(decoded)) {
                reject("a " + frames.word() + " frame carried " + decoded.getClass().getSimpleName());
                return;
            }
            reading = read(frames.payloadType().cast(decoded), at);
        } catch (Exception e) {
            reject(e.getMessage());
            return;
        }
        report(reading, at);
    }

    private void reject(String reason) {
        rejected.incrementAndGet();
        status(DeviceStatus.State.ERROR, "rejected payload: " + reason);
    }

    @Override
    protected List<Parameter> moreParameters() {
        List<Parameter> all = new ArrayList<>(super.moreParameters());
        all.add(Parameter.readOnly("rejectedPayloads", rejected.get(),
                frames.word() + " payloads that could not be read"));
        return all;
    }
}
