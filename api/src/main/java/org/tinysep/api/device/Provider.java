package org.tinysep.api.device;

import org.osgi.annotation.versioning.ConsumerType;

/**
 * The provider side of a TinySEP interface (the thesis's signal-slot pair). A device registers one service per
 * interface it provides; every such service carries the {@link DeviceProperties} of its device.
 * <p>
 * Events flow by direct method calls from the provider to the connected listeners, on the provider's thread
 * (for sensors: the bus radio's receive thread). Listeners must return quickly and hand slow work to an
 * executor of their own. A listener that throws is logged and skipped; delivery to the others goes on.
 *
 * @param <L> the listener side of the interface
 */
@ConsumerType
public interface Provider<L> {

    /** @return the UID of the device that provides this interface */
    String deviceUid();

    /**
     * Subscribes a listener. Connecting the same listener twice yields two independent connections.
     *
     * @param listener receives this interface's events until the returned connection is closed
     * @return the handle that closes the connection; it is also closed when the provider goes away
     */
    Connection connect(L listener);
}
