package org.tinysep.api.bus;

import java.util.Set;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/**
 * Raw access to one AmICA sensor node (thesis A.1 IBusRadioAmICA), provided by a bus device of a Bus Radio AmICA
 * driver (serial or UDP). Hardware-abstraction devices consume it without knowing the transport.
 */
@ProviderType
public interface BusRadioAmicaProvider extends Provider<BusRadioAmicaListener> {

    /** @return the node's address as {@code netgroup.address}, e.g. {@code 1.17} (thesis getSensorId) */
    String nodeId();

    /** @return the node types announced by the node's keep-alive (values of {@code NodeType}) */
    Set<String> nodeTypes();

    /**
     * Sends a payload (thesis Table 3.1) to the node. Never blocks on I/O: the bus radio queues it.
     *
     * @throws IllegalArgumentException if the payload is empty or longer than 255 bytes
     */
    void send(byte[] payload);
}
