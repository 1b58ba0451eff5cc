package org.tinysep.api.sensor;

import org.osgi.annotation.versioning.ProviderType;
import org.tinysep.api.device.Provider;

/** A door contact (the thesis's IDoor, named in the text but missing from Appendix A). */
@ProviderType
public interface DoorProvider extends Provider<DoorListener> {

    /** @return open, closed, or unknown before the first report */
    OpenState state();

    /** @return outer (to the outside) or inner door; configured by the user */
    DoorKind kind();
}
