package org.tinysep.device.support.sensor;

import java.time.Instant;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.device.support.DriverContext;

/**
 * A sensor on an AmICA node: connects to its bus device (vital: the device goes with it, thesis Fig 3.4), decodes
 * each payload and keeps those of its payload type; keep-alives and the other types of a multi-type node are not
 * its own, and a malformed payload was already rejected and counted by the bus radio. A sensor declares its
 * payload type and {@link #read} (payload to reading), and what {@link SensorDevice} asks.
 *
 * @param <L> the listener interface
 * @param <P> the payload type, e.g. the protocol's {@code ReedSwitchStatus}
 * @param <V> the reading
 */
public abstract class AmicaSensorDevice<L, P, V> extends SensorDevice<L, V> implements BusRadioAmicaListener {

    private final BusRadioAmicaProvider bus;
    private final Decoder decoder;
    private final Class<P> payloadType;

    /**
     * @param decoder     the protocol's decoder, {@code AmicaPayloads::decode}
     * @param payloadType the payloads this sensor reads
     */
    protected AmicaSensorDevice(DriverContext context, BusRadioAmicaProvider bus, String nodeType, String name,
            Decoder decoder, Class<P> payloadType, Class<?>... provides) {
        super(context, bus.deviceUid(), bus.nodeId(), nodeType, name, provides);
        this.bus = bus;
        this.decoder = decoder;
        this.payloadType = payloadType;
    }

    /** @return the reading a payload of this sensor's type carries */
    protected abstract V read(P payload, Instant at);

    @Override
    protected void onRegistered() {
        connect(bus, BusRadioAmicaProvider.class, this, true);
    }

    @Override
    public final void payloadReceived(BusRadioAmicaProvider source, byte[] payload, Instant at) {
        Object decoded;
        try {
            decoded = decoder.decode(payload);
        } catch (Exception e) {
            return; // the bus radio already rejected and counted it
        }
        if (payloadType.isInstance(decoded)) { // keep-alives and other types of a multi-type node are not ours
            report(read(payloadType.cast(decoded), at), at);
        }
    }
}
