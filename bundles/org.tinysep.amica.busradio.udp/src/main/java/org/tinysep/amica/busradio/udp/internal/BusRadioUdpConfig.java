package org.tinysep.amica.busradio.udp.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the Bus Radio AmICA UDP/IP driver (pid {@value AmicaUdpDriver#PID}). */
@ObjectClassDefinition(name = "Bus Radio AmICA UDP/IP",
        description = "Receives AmICA node protocol frames, one per UDP datagram.")
public @interface BusRadioUdpConfig {

    @AttributeDefinition(description = "UDP port to listen on; 0 picks a free port (published as tinysep.udp.port)")
    int port() default 47011;

    @AttributeDefinition(description = "Local address to bind; 0.0.0.0 listens on every interface")
    String bindAddress() default "127.0.0.1";

    @AttributeDefinition(description = "Socket receive buffer in bytes (large, so millisecond stalls drop nothing)")
    int receiveBufferBytes() default 4 * 1024 * 1024;
}
