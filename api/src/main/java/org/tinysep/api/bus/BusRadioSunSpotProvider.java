package org.tinysep.api.bus;

import java.util.Set;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** Raw access to one Sun SPOT node (thesis A.2 IBusRadioSunSPOT). */
@ProviderType
public interface BusRadioSunSpotProvider extends Provider<BusRadioSunSpotListener> {

    /** @return the node's 64-bit IEEE address in Sun SPOT notation, e.g. {@code 0014.4F01.0000.1234} */
    String nodeAddress();

    /** @return the node types seen from this node so far (values of {@code NodeType}) */
    Set<String> nodeTypes();
}
