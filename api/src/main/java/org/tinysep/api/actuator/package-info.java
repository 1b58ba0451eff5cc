/**
 * Hardware-abstraction interfaces of actuators: simple and dimmable light, heater, speaker.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.actuator;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
