package org.tinysep.amica.heater.internal;

import org.tinysep.amica.actuator.base.PercentActuatorDevice;
import org.tinysep.amica.protocol.HeaterControl;
import org.tinysep.api.actuator.HeaterListener;
import org.tinysep.api.actuator.HeaterProvider;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Abstracts one AmICA heater node: Heater Control status payloads (5 8 0 A) report the potency,
 * {@code setLevel} sends Heater Control A. The shared actuator model (a request waits for
 * the node's next report to confirm it) is {@link PercentActuatorDevice}.
 */
final class AmicaHeaterDevice extends PercentActuatorDevice<HeaterControl, HeaterListener> implements HeaterProvider {

    AmicaHeaterDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, bus, "Heater", NodeType.HEATER, "potency", HeaterControl.class, HeaterControl::percent, HeaterControl::new,
                HeaterProvider.class, HeaterListener::potencyChanged);
    }
}
