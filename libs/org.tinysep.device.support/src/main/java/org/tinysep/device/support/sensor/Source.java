package org.tinysep.device.support.sensor;

import java.time.Instant;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.BiFunction;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.device.Provider;

/**
 * Where a sensor's readings come from: its bus device, the node family's decoder, the payload type it reads and
 * how a payload becomes a reading. Made with {@link #amica} or {@link #sunSpot}; the device connects to the bus
 * device (vital, thesis Fig 3.4) and hands each payload to its source.
 *
 * @param <V> the reading
 */
public abstract sealed class Source<V> permits Source.Amica, Source.SunSpot {

    /** How a Sun SPOT sensor's frames are told apart: its sensor type code and its name in messages ("light"). */
    public record Frames(int sensorType, String word) {
    }

    /**
     * An AmICA node: payloads of other types (keep-alives, the other types of a multi-type node) are not this
     * sensor's; a malformed payload was already rejected and counted by the bus radio.
     *
     * @param decoder the protocol's decoder, {@code AmicaPayloads::decode}
     * @param type    the payloads this sensor reads, e.g. {@code ReedSwitchStatus.class}
     * @param read    a payload of that type and its arrival to the reading
     */
    public static <P, V> Source<V> amica(BusRadioAmicaProvider bus, Decoder decoder, Class<P> type,
            BiFunction<? super P, Instant, ? extends V> read) {
        return new Amica<>(bus, decoder, type, read);
    }

    /**
     * A Sun SPOT node: frames of other sensor types are not this sensor's; a frame of its type that cannot be
     * read, or carries another payload, is rejected: counted ({@code rejectedPayloads}) and the device is in ERROR
     * until the next good one.
     */
    public static <P, V> Source<V> sunSpot(BusRadioSunSpotProvider bus, Frames frames, Decoder decoder,
            Class<P> type, BiFunction<? super P, Instant, ? extends V> read) {
        return new SunSpot<>(bus, frames, decoder, type, read);
    }

    private final Provider<?> bus;
    private final Class<?> busInterface;
    private final String nodeAddress;
    private final Decoder decoder;
    private final Class<?> type;
    private final BiFunction<Object, Instant, ? extends V> read;

    @SuppressWarnings("unchecked")
    private <P> Source(Provider<?> bus, Class<?> busInterface, String nodeAddress, Decoder decoder, Class<P> type,
            BiFunction<? super P, Instant, ? extends V> read) {
        this.bus = bus;
        this.busInterface = busInterface;
        this.nodeAddress = nodeAddress;
        this.decoder = decoder;
        this.type = type;
        this.read = (BiFunction<Object, Instant, ? extends V>) read;
    }

    final String busDeviceUid() {
        return bus.deviceUid();
    }

    final String nodeAddress() {
        return nodeAddress;
    }

    /** Connects the device to its bus device (vital). */
    final void attach(SensorDevice<?, V> device) {
        device.connectBus(bus, busInterface);
    }

    /** @return the source's own read-only parameters, shown last */
    List<Parameter> parameters() {
        return List.of();
    }

    /** @return the decoded payload; throws if it cannot be decoded */
    final Object decode(byte[] payload) throws Exception {
        return decoder.decode(payload);
    }

    /** @return whether a decoded payload is of the type this sensor reads */
    final boolean ours(Object decoded) {
        return type.isInstance(decoded);
    }

    final V read(Object payload, Instant at) {
        return read.apply(payload, at);
    }

    static final class Amica<V> extends Source<V> {

        <P> Amica(BusRadioAmicaProvider bus, Decoder decoder, Class<P> type,
                BiFunction<? super P, Instant, ? extends V> read) {
            super(bus, BusRadioAmicaProvider.class, bus.nodeId(), decoder, type, read);
        }

        void received(SensorDevice<?, V> device, byte[] payload, Instant at) {
            Object decoded;
            try {
                decoded = decode(payload);
            } catch (Exception e) {
                return; // the bus radio already rejected and counted it
            }
            if (ours(decoded)) { // keep-alives and other types of a multi-type node are not ours
                device.report(read(decoded, at), at);
            }
        }
    }

    static final class SunSpot<V> extends Source<V> {
        private final Frames frames;
        private final AtomicLong rejected = new AtomicLong();

        <P> SunSpot(BusRadioSunSpotProvider bus, Frames frames, Decoder decoder, Class<P> type,
                BiFunction<? super P, Instant, ? extends V> read) {
            super(bus, BusRadioSunSpotProvider.class, bus.nodeAddress(), decoder, type, read);
            this.frames = frames;
        }

        void received(SensorDevice<?, V> device, int sensorType, byte[] payload, Instant at) {
            if (sensorType != frames.sensorType()) {
                return; // other sensors of a multi-sensor node are not ours
            }
            V reading;
            try {
                Object decoded = decode(payload);
                if (!ours(decoded)) {
                    reject(device, "a " + frames.word() + " frame carried " + decoded.getClass().getSimpleName());
                    return;
                }
                reading = read(decoded, at);
            } catch (Exception e) {
                reject(device, e.getMessage());
                return;
            }
            device.report(reading, at);
        }

        private void reject(SensorDevice<?, V> device, String reason) {
            rejected.incrementAndGet();
            device.rejected(reason);
        }

        @Override
        List<Parameter> parameters() {
            return List.of(Parameter.readOnly("rejectedPayloads", rejected.get(),
                    frames.word() + " payloads that could not be read"));
        }
    }
}
