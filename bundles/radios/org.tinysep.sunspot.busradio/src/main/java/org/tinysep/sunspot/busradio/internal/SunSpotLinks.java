package org.tinysep.sunspot.busradio.internal;

import java.io.IOException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.log.EventKind;
import org.tinysep.device.support.lifecycle.Closeables;
import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * The three links of the bus radio, built from one configuration and feeding one {@link PacketHandler}: UDP,
 * serial and SDK. Bad settings and links that cannot start are reported (status and PROBLEM event) and leave the
 * other links running.
 */
final class SunSpotLinks implements AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(SunSpotLinks.class);

    private final LinkSettings settings;
    private final RadiogramSource.Opener sdkOpener;
    private final Duration reopenEvery;
    private final String driverName;
    private final List<String> problems = new ArrayList<>(); // activation thread only
    // written while the component activates, read by the shell's thread
    private volatile UdpLink udp;
    private volatile SerialLink serial;
    private volatile SdkLink sdk;
    private volatile String udpState = "off";
    private volatile String serialState = "off";
    private volatile String sdkState = "off";

    SunSpotLinks(LinkSettings settings, RadiogramSource.Opener sdkOpener, Duration reopenEvery, String driverName) {
        this.settings = settings;
        this.sdkOpener = sdkOpener;
        this.reopenEvery = reopenEvery;
        this.driverName = driverName;
    }

    /** Binds the UDP socket, if configured, so that the driver can publish its port; receives nothing yet. */
    void bind() {
        int port = settings.udpPort();
        if (port == LinkSettings.UDP_OFF) {
            return;
        }
        if (port < 0 || port > 0xFFFF) {
            udpState = problem("udp: bad udpPort " + port + ", expected -1 (off), 0 (a free port) or 1..65535");
            return;
        }
        try {
            udp = UdpLink.open(settings.udpBindAddress(), port, driverName);
            udpState = "listening on " + udp.socket().localAddress();
            LOG.info("{} UDP link {} (receive buffer {} bytes)", driverName, udpState,
                    udp.socket().receiveBufferSize());
        } catch (IOException | RuntimeException e) {
            udpState = "cannot listen on " + settings.udpBindAddress() + ":" + port + ": " + e.getMessage();
            // a caregiver notice and a WARNING under the banner (docs/security.md, "Nothing reduces monitoring")
            problem("Monitoring reduced: the Sun SPOT radio cannot listen on " + settings.udpBindAddress() + ":"
                    + port + " (" + e.getMessage() + "): no Sun SPOT sensor is heard over UDP. Another program may "
                    + "hold the port: stop it, or set another udpPort in etc/org.tinysep.sunspot.busradio.cfg, then "
                    + "restart TinySEP");
        }
    }

    /** @return the bound UDP port, if the UDP link is on */
    OptionalInt udpPort() {
        return udp == null ? OptionalInt.empty() : OptionalInt.of(udp.socket().localPort());
    }

    /** Sets who may send on the UDP link (docs/security.md); call before {@link #start}. */
    void gate(org.tinysep.device.support.intake.SourceGate gate, java.util.function.Consumer<String> problems) {
        if (udp != null) {
            udp.gate(gate, problems);
        }
    }

    /** Starts receiving on every configured link; reports the problems met so far as PROBLEM events. */
    void start(PacketHandler handler, SunSpotNodes nodes, DriverContext context) {
        Feed feed = new Feed(handler, nodes, context);
        if (udp != null) {
            udp.start(handler);
        }
        if (settings.serialEnabled()) {
            if (settings.serialBaudRate() <= 0) {
                serialState = problem("serial: bad serialBaudRate " + settings.serialBaudRate());
            } else {
                serial = new SerialLink(settings.serialPort().strip(), settings.serialBaudRate(), reopenEvery, feed);
                serial.start();
            }
        }
        if (settings.sdkEnabled()) {
            int port = settings.sdkRadiogramPort();
            if (port < 1 || port > 255) {
                sdkState = problem("sdk: bad sdkRadiogramPort " + port + ", expected 1..255");
            } else {
                sdk = new SdkLink(sdkOpener, port, reopenEvery, feed);
                sdk.start();
            }
        }
        for (String p : problems) {
            context.event(EventKind.PROBLEM, p);
        }
    }

    private String problem(String text) {
        LOG.error("{} {}", driverName, text);
        problems.add(text);
        return text.substring(text.indexOf(':') + 2);
    }

    /** @return e.g. {@code udp: listening on 127.0.0.1:47012; serial: off; sdk: Sun SPOT SDK not installed (...)} */
    String status() {
        return "udp: " + udpState() + "; serial: " + serialState() + "; sdk: " + sdkState();
    }

    String udpState() {
        return udpState;
    }

    String serialState() {
        SerialLink s = serial;
        return s == null ? serialState : s.state();
    }

    String sdkState() {
        SdkLink s = sdk;
        return s == null ? sdkState : s.state();
    }

    List<Parameter> parameters() {
        List<Parameter> out = new ArrayList<>();
        out.add(Parameter.readOnly("status", status(), "state of the UDP, serial and SDK links"));
        out.add(Parameter.readOnly("udp", udpState(), "UDP link: one frame per datagram"));
        out.add(Parameter.readOnly("serial", serialState(), "serial link to a basestation writing frames"));
        out.add(Parameter.readOnly("sdk", sdkState(), "Sun SPOT SDK link (radiograms)"));
        SerialLink s = serial;
        if (s != null) {
            out.add(Parameter.readOnly("serial.bytesRead", s.bytesRead(), "bytes read from " + s.name()));
        }
        SdkLink k = sdk;
        if (k != null) {
            out.add(Parameter.readOnly("sdk.unreadable", k.unreadable(), "radiograms with an unreadable sender"));
        }
        return out;
    }

    @Override
    public void close() {
        Closeables.closeInOrder(driverName, udp, serial, sdk);
    }
}
