package org.tinysep.amica.speaker.internal;

import org.tinysep.amica.actuator.base.PercentActuatorWiringContract;

/**
 * This bundle's wiring of the shared actuator device (whose model, confirmation and errors are tested in
 * {@code org.tinysep.amica.actuator.base}): SpeakerControl reports in, {@code volumeChanged} out; {@code setLevel} and
 * the {@code volume} parameter send SpeakerControl ({@code 5 4 0 A}). The checks are the shared
 * {@link PercentActuatorWiringContract}.
 */
class AmicaSpeakerDeviceTest extends PercentActuatorWiringContract<AmicaSpeakerDevice> {

    AmicaSpeakerDeviceTest() {
        super("speaker", AmicaSpeakerDriver.NAME, AmicaSpeakerDevice::new, "Speaker", "volume", 4);
        device.connect((source, value, at) -> hear(source, value, at));
    }
}
