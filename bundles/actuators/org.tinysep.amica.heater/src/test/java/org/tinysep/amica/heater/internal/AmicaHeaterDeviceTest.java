package org.tinysep.amica.heater.internal;

import org.tinysep.amica.actuator.base.PercentActuatorWiringContract;

/**
 * This bundle's wiring of the shared actuator device (whose model, confirmation and errors are tested in
 * {@code org.tinysep.amica.actuator.base}): HeaterControl reports in, {@code potencyChanged} out; {@code setLevel} and
 * the {@code potency} parameter send HeaterControl ({@code 5 8 0 A}). The checks are the shared
 * {@link PercentActuatorWiringContract}.
 */
class AmicaHeaterDeviceTest extends PercentActuatorWiringContract<AmicaHeaterDevice> {

    AmicaHeaterDeviceTest() {
        super("heater", AmicaHeaterDriver.NAME, AmicaHeaterDevice::new, "Heater", "potency", 8);
        device.connect((source, value, at) -> hear(source, value, at));
    }
}
