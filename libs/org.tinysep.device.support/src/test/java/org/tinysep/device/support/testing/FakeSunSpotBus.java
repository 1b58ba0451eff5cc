package org.tinysep.device.support.testing;

import java.util.Set;
import org.tinysep.api.bus.BusRadioSunSpotListener;
import org.tinysep.api.bus.BusRadioSunSpotProvider;
import org.tinysep.api.device.Connection;

/**
 * For unit tests of Sun SPOT sensor devices: a bus device as the abstraction sees it through the API contract, a
 * node with movement, temperature and light sensors unless told other types; the test feeds payloads to the device
 * itself.
 */
public class FakeSunSpotBus implements BusRadioSunSpotProvider {

    private final Set<String> types;

    public FakeSunSpotBus() {
        this("movement", "temperature", "light-sensor");
    }

    public FakeSunSpotBus(String... types) {
        this.types = Set.of(types);
    }

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
        return types;
    }
}
