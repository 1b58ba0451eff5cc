/**
 * Event log and packet log contracts (thesis 3.8). Implemented by the device manager; drivers and devices report to them.
 */
@Export
@Version("1.1.0")
package org.tinysep.api.log;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
