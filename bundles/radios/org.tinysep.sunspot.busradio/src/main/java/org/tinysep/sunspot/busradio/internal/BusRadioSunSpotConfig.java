package org.tinysep.sunspot.busradio.internal;

import org.osgi.service.metatype.annotations.AttributeDefinition;
import org.osgi.service.metatype.annotations.ObjectClassDefinition;

/** Configuration of the Bus Radio Sun SPOT driver (pid {@value SunSpotBusRadioDriver#PID}): its three links. */
@ObjectClassDefinition(name = "Bus Radio Sun SPOT",
        description = "Receives Sun SPOT node protocol packets over UDP, a serial basestation and the Sun SPOT SDK.")
public @interface BusRadioSunSpotConfig {

    @AttributeDefinition(description = "UDP port for one frame per datagram; 0 picks a free port (published as "
            + "tinysep.udp.port), -1 turns the UDP link off")
    int udpPort() default 47012;

    @AttributeDefinition(description = "Local address of the UDP link; 0.0.0.0 listens on every interface")
    String udpBindAddress() default "127.0.0.1";

    @AttributeDefinition(description = "Serial port of a basestation writing framed packets, e.g. /dev/ttyUSB0; "
            + "empty turns the serial link off")
    String serialPort() default "";

    @AttributeDefinition(description = "Baud rate of the serial link")
    int serialBaudRate() default 115200;

    @AttributeDefinition(description = "Receive radiograms through the Sun SPOT SDK running in-process "
            + "(the SDK must be installed as a bundle, see docs/sunspot-sdk.md)")
    boolean sdkEnabled() default false;

    @AttributeDefinition(description = "Radiogram port the Sun SPOTs send to (radiogram://:port), 1..255")
    int sdkRadiogramPort() default 100;

    @AttributeDefinition(description = "Sources allowed to send on the UDP link when udpBindAddress is not a "
            + "loopback address: IP addresses or blocks (10.0.0.0/24), comma-separated; empty = 127.0.0.1 and ::1 only")
    String allowedSources() default "";

    @AttributeDefinition(description = "Datagrams per second one source IP may send on the UDP link when "
            + "udpBindAddress is not a loopback address; more are rejected and counted; 0 = no limit")
    int sourceRateLimit() default 2000;

    @AttributeDefinition(description = "Report intervals without a valid packet after which a Sun SPOT is OFFLINE")
    int silentAfterIntervals() default 30;

    @AttributeDefinition(description = "Most Sun SPOT addresses this bus radio creates devices for; packets from "
            + "further new addresses are rejected and counted")
    int maxNodes() default 1000;
}
