/**
 * Hardware-abstraction interfaces of sensors: movement, door, window, pet movement, temperature, light brightness.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.sensor;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
