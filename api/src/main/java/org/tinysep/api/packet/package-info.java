/**
 * Packets in words: {@link org.tinysep.api.packet.PacketDescriber}, a whiteboard service each protocol's bus radio
 * registers and the web console's packet log uses, so that the console needs no protocol library of its own.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.packet;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
