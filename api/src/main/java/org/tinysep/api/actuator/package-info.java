/**
 * Hardware-abstraction interfaces of actuators: simple and dimmable light, heater, speaker. 2.0: the three percent
 * actuators share {@link org.tinysep.api.actuator.PercentActuator} ({@code level()}, {@code setLevel(Percent)}) in
 * place of 1.0's {@code brightness()/setBrightness}, {@code potency()/setPotency}, {@code volume()/setVolume}.
 */
@Export
@Version("2.0.0")
package org.tinysep.api.actuator;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
