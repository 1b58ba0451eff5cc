package org.tinysep.amica.dimmablelight.internal;

import org.tinysep.amica.actuator.base.PercentActuatorDevice;
import org.tinysep.amica.protocol.LightControl;
import org.tinysep.api.actuator.DimmableLightListener;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Abstracts one AmICA light node as a dimmable light: Light Control status payloads (5 2 0 A) report the
 * brightness, {@code setLevel} sends Light Control A. The shared actuator model (a request waits for
 * the node's next report to confirm it) is {@link PercentActuatorDevice}.
 */
final class AmicaDimmableLightDevice extends PercentActuatorDevice<LightControl, DimmableLightListener> implements DimmableLightProvider {

    AmicaDimmableLightDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, bus, "Dimmable light", NodeType.DIMMABLE_LIGHT, "brightness", LightControl.class, LightControl::percent, LightControl::new,
                DimmableLightProvider.class, DimmableLightListener::brightnessChanged);
    }
}
