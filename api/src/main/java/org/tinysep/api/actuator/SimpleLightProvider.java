package org.tinysep.api.actuator;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** An on/off light (the thesis's ISimpleLight, named in the text but missing from Appendix A). */
@ProviderType
public interface SimpleLightProvider extends Provider<SimpleLightListener> {

    /** @return whether the node last reported the light on; empty before its first report */
    Optional<Boolean> isOn();

    /**
     * Asks the node to switch. Returns at once; the new state is reported to listeners when the node's next
     * status packet confirms it.
     */
    void switchLight(boolean on);
}
