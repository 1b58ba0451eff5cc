package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.tools.process.PlatformProcess;

/**
 * Issue 25, item 7, "ready while deaf": the real distribution as a process, with the AmICA radio's port held by
 * another socket. The banner must not stop at "N/N bundles active": a WARNING line right under it says that the
 * radio cannot listen and that no AmICA sensor is heard.
 */
class DeafRadioIT {

    @TempDir
    Path tmp;

    @Test
    void aRadioThatCannotListenIsAWarningUnderTheBanner() throws Exception {
        Path home = tmp.resolve("home");
        int port = new TestDistribution(home, null).realTimeAmicaRadio();
        try (DatagramSocket squatter = new DatagramSocket(null)) {
            squatter.bind(new InetSocketAddress(InetAddress.getLoopbackAddress(), port));
            try (PlatformProcess p = PlatformProcess.launch(home, home, List.of())) {
                String banner = p.awaitLine("bundles active", Duration.ofSeconds(120));
                System.out.println(banner);
                String warning = p.awaitLine("WARNING: the AmICA radio cannot listen on 127.0.0.1:" + port,
                        Duration.ofSeconds(60));
                System.out.println(warning);
                assertTrue(warning.contains("(Address already in use): no AmICA sensor is heard"), warning);
            }
        }
    }
}
