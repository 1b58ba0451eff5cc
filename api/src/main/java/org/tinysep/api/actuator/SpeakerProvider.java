package org.tinysep.api.actuator;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;
import org.tinysep.api.sensor.Percent;

/** A speaker (thesis A.9 ISpeaker), with its volume actuator. */
@ProviderType
public interface SpeakerProvider extends Provider<SpeakerListener> {

    Optional<Percent> volume();

    /** Asks the node to change volume; confirmed to listeners by the node's next status packet. */
    void setVolume(Percent volume);
}
