package org.tinysep.amica.busradio.serial.internal;

import org.osgi.service.component.annotations.Component;
import org.tinysep.amica.busradio.base.AmicaPacketWords;
import org.tinysep.api.packet.PacketDescriber;

/** This bus radio's AmICA frames in words for the packet log's readers (the web console), as a whiteboard service. */
@Component(service = PacketDescriber.class)
public final class AmicaPacketDescriber extends AmicaPacketWords {
}
