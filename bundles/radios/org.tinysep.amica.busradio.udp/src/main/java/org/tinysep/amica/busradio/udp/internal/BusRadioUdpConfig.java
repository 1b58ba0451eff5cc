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

    @AttributeDefinition(description = "Sources allowed to send when bindAddress is not a loopback address: IP "
            + "addresses or blocks (10.0.0.0/24), comma-separated; empty = 127.0.0.1 and ::1 only (docs/security.md)")
    String allowedSources() default "";

    @AttributeDefinition(description = "Datagrams per second one source IP may send when bindAddress is not a "
            + "loopback address; more are rejected and counted; 0 = no limit")
    int sourceRateLimit() default 2000;

    @AttributeDefinition(description = "Report intervals without a valid frame after which a node is OFFLINE")
    int silentAfterIntervals() default 30;

    @AttributeDefinition(description = "Keep-alive battery voltage (mV) below which a node's battery is reported "
            + "low; 0 = never")
    int lowBatteryMillivolts() default 2200;

    @AttributeDefinition(description = "Most nodes this bus radio creates; keep-alives of further new nodes are "
            + "rejected and counted")
    int maxNodes() default 1000;

    @AttributeDefinition(description = "Milliseconds a device may spend on one payload before it is taken out of "
            + "the ordered delivery and gets its payloads through its own queue until it keeps up; "
            + "100 to 60000")
    int slowListenerMillis() default 1000;
}
