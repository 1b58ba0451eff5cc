/**
 * Hardware-connection interfaces: raw payload access to one sensor node (thesis A.1, A.2).
 */
@Export
@Version("1.0.0")
package org.tinysep.api.bus;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
