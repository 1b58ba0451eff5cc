package org.tinysep.api.sensor;

import java.util.Optional;
import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A window contact (thesis A.4 IWindow). */
@ProviderType
public interface WindowProvider extends Provider<WindowListener> {

    OpenState state();

    /** @return where the window is, if the user gave it */
    Optional<Coordinates> position();
}
