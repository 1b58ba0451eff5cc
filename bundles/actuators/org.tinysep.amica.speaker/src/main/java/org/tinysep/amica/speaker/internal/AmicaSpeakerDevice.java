package org.tinysep.amica.speaker.internal;

import org.tinysep.amica.actuator.base.PercentActuatorDevice;
import org.tinysep.amica.protocol.SpeakerControl;
import org.tinysep.api.actuator.SpeakerListener;
import org.tinysep.api.actuator.SpeakerProvider;
import org.tinysep.api.bus.BusRadioAmicaProvider;
import org.tinysep.api.device.NodeType;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * Abstracts one AmICA speaker node: Speaker Control status payloads report the volume,
 * {@code setLevel} sends Speaker Control A. The shared actuator model (a request waits for
 * the node's next report to confirm it) is {@link PercentActuatorDevice}.
 */
final class AmicaSpeakerDevice extends PercentActuatorDevice<SpeakerControl, SpeakerListener> implements SpeakerProvider {

    AmicaSpeakerDevice(DriverContext context, BusRadioAmicaProvider bus) {
        super(context, bus, "Speaker", NodeType.SPEAKER, "volume", SpeakerControl.class, SpeakerControl::percent, SpeakerControl::new,
                SpeakerProvider.class, SpeakerListener::volumeChanged);
    }
}
