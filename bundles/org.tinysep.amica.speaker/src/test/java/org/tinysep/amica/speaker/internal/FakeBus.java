package org.tinysep.amica.speaker.internal;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import org.tinysep.api.bus.BusRadioAmicaListener;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.Connection;

/** A hand-written AmICA bus device: one node, records every payload sent to it, or fails on demand. */
final class FakeBus implements BusRadioAmicaProvider {

    final List<byte[]> sent = new ArrayList<>();
    RuntimeException failure;
    private final String nodeId;
    private final Set<String> types;

    FakeBus(String nodeId, String... types) {
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
