package org.tinysep.api.device;

import org.osgi.annotation.versioning.ProviderType;

/** Handle of one provider-listener connection. Closing is idempotent. */
@ProviderType
public interface Connection extends AutoCloseable {

    /** Stops delivery to the listener. Safe to call more than once and from any thread. */
    @Override
    void close();

    /** @return whether events are still delivered through this connection */
    boolean isOpen();
}
