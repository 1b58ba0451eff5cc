package org.tinysep.api.sensor.person;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/**
 * A node worn by one person. Its movement is that person's activity, wherever they are; its switches are theirs.
 */
@ProviderType
public interface PersonNodeProvider extends Provider<PersonNodeListener> {

    /** @return the wearer's name as the installer set it (the device parameter {@code person}), or empty */
    Optional<String> person();

    /** @return the latest movement summary, if any arrived since the device started */
    Optional<MovementSummary> lastSummary();
}
