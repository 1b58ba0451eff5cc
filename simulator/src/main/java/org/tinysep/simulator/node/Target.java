package org.tinysep.simulator.node;

import java.net.InetAddress;
import java.net.InetSocketAddress;

/** Where the platform listens: the AmICA UDP bus radio and the Sun SPOT UDP bus radio. */
public record Target(InetAddress host, int amicaPort, int sunSpotPort) {

    public static final int DEFAULT_AMICA_PORT = 47011;
    public static final int DEFAULT_SUNSPOT_PORT = 47012;

    public InetSocketAddress amica() {
        return new InetSocketAddress(host, amicaPort);
    }

    public InetSocketAddress sunSpot() {
        return new InetSocketAddress(host, sunSpotPort);
    }

    /** @return the local address to bind node sockets to: loopback for a loopback target, else any */
    public InetSocketAddress bind() {
        return host.isLoopbackAddress() ? new InetSocketAddress(InetAddress.getLoopbackAddress(), 0) : new InetSocketAddress(0);
    }
}
