package org.tinysep.sunspot.busradio.internal;

/**
 * The link settings of the bus radio, taken from its configuration ({@link BusRadioSunSpotConfig}); a plain
 * record so that links can be built in tests without Declarative Services.
 */
record LinkSettings(int udpPort, String udpBindAddress, String serialPort, int serialBaudRate, boolean sdkEnabled,
        int sdkRadiogramPort) {

    /** Turns the UDP link off. */
    static final int UDP_OFF = -1;

    static LinkSettings of(BusRadioSunSpotConfig c) {
        return new LinkSettings(c.udpPort(), c.udpBindAddress(), c.serialPort(), c.serialBaudRate(),
                c.sdkEnabled(), c.sdkRadiogramPort());
    }

    /** @return the UDP-only settings of a test or simulator: a free port on the loopback address */
    static LinkSettings udpOnly() {
        return new LinkSettings(0, "127.0.0.1", "", 115200, false, 100);
    }

    boolean serialEnabled() {
        return serialPort != null && !serialPort.isBlank();
    }
}
