package org.tinysep.api.actuator;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;
import org.tinysep.api.sensor.Percent;

/** A heater (thesis A.8 IHeater), with the potency actuator the AmICA heater node offers. */
@ProviderType
public interface HeaterProvider extends Provider<HeaterListener> {

    Optional<Percent> potency();

    /** Asks the node to change potency; confirmed to listeners by the node's next status packet. */
    void setPotency(Percent potency);
}
