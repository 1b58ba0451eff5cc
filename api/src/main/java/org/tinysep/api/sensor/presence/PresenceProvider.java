package org.tinysep.api.sensor.presence;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A presence or use sensor: a bed or seat mat, a flush, an appliance. */
@ProviderType
public interface PresenceProvider extends Provider<PresenceListener> {

    /** @return what it observes */
    PresenceKind kind();

    /** @return whether it is ON now (someone on the mat, the appliance running); false before its first report */
    boolean present();
}
