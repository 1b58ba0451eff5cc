package org.tinysep.device.support.testing;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;

/**
 * For unit tests of AmICA sensor and actuator devices: a hand-written bus device of one node that records every
 * payload sent to it, or fails on demand. The test feeds payloads to the device itself. Never referenced by main
 * code, so bnd never copies it into a bundle.
 */
public class FakeAmicaBus implements BusRadioAmicaProvider {

    /** Payloads sent, in order. */
    public final List<byte[]> sent = new ArrayList<>();
    /** Thrown by {@link #send} when set. */
    public RuntimeException failure;
    private final String nodeId;
    private final Set<String> types;

    public FakeAmicaBus(String nodeId, String... types) {
        this.nodeId = nodeId;
        this.types = Set.of(types);
    }

    @Override
    public String deviceUid() {
        return "bus-" + nodeId;
    }

    @Override
    public Connection connect(BusRadioAmicaListener listener) {
        throw new UnsupportedOperationException("devices under test are fed directly");
    }

    @Override
    public String nodeId() {
        return nodeId;
    }

    @Override
    public Set<String> nodeTypes() {
        return types;
    }

    @Override
    public void send(byte[] payload) {
        if (failure != null) {
            throw failure;
        }
        sent.add(payload.clone());
    }
}
