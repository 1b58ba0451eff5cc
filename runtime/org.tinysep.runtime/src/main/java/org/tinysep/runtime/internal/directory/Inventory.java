package org.tinysep.runtime.internal.directory;

import java.util.List;

/** What the device manager currently knows: a consistent-enough snapshot, safe to call from any thread. */
public interface Inventory {

    /** @return the tracked drivers, sorted by name then UID */
    List<DriverRecord> drivers();

    /** @return the tracked devices, sorted by UID */
    List<DeviceRecord> devices();

    /** @return the simple names of the interfaces provided by that device, sorted, without duplicates */
    List<String> interfacesOf(String deviceUid);
}
