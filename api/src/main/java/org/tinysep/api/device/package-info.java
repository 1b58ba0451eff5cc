/**
 * The TinySEP driver model and signal-slot contract (thesis 3.1-3.3, Tables 4.1 and 4.2).
 * <p>
 * A {@link org.tinysep.api.device.Driver} creates {@link org.tinysep.api.device.Device}s. A device provides
 * interfaces ({@link org.tinysep.api.device.Provider} services) and consumes others by calling
 * {@link org.tinysep.api.device.Provider#connect(Object)} with its listener; the returned
 * {@link org.tinysep.api.device.Connection} closes that link. The OSGi service registry plays the thesis's
 * device manager role of announcing interfaces; events never pass through the device manager.
 */
@Export
@Version("1.2.0")
package org.tinysep.api.device;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
