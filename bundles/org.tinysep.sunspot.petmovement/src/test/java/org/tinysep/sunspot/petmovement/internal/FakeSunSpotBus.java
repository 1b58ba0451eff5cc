package org.tinysep.sunspot.petmovement.internal;

import java.util.Set;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;

/** A Sun SPOT bus device as the abstraction sees it through the API contract; payloads are fed in by the test. */
final class FakeSunSpotBus implements BusRadioSunSpotProvider {

    @Override
    public String deviceUid() {
        return "bus-1";
    }

    @Override
    public Connection connect(BusRadioSunSpotListener listener) {
        throw new UnsupportedOperationException("the test calls payloadReceived itself");
    }

    @Override
    public String nodeAddress() {
        return "0014.4F01.0000.1234";
    }

    @Override
    public Set<String> nodeTypes() {
        return Set.of("pet-collar", "movement");
    }
}
