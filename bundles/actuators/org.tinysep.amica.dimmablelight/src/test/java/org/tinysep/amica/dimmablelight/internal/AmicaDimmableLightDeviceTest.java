package org.tinysep.amica.dimmablelight.internal;

import org.tinysep.amica.actuator.base.PercentActuatorWiringContract;

/**
 * This bundle's wiring of the shared actuator device (whose model, confirmation and errors are tested in
 * {@code org.tinysep.amica.actuator.base}): LightControl reports in, {@code brightnessChanged} out; {@code setLevel} and
 * the {@code brightness} parameter send LightControl ({@code 5 2 0 A}). The checks are the shared
 * {@link PercentActuatorWiringContract}.
 */
class AmicaDimmableLightDeviceTest extends PercentActuatorWiringContract<AmicaDimmableLightDevice> {

    AmicaDimmableLightDeviceTest() {
        super("dimmable-light", AmicaDimmableLightDriver.NAME, AmicaDimmableLightDevice::new, "Dimmable light", "brightness", 2);
        device.connect((source, value, at) -> hear(source, value, at));
    }
}
