package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.IntStream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.tools.process.PlatformProcess;

/**
 * Issue 12 item 5, "ready means ready": the banner ("N/N bundles active") comes only once the bus radios listen
 * with their configuration from {@code etc/}. The real distribution as a process: keep-alives of ten nodes are
 * sent the moment the banner line is read, and each of the ten nodes must become a device (a lost frame never
 * would: keep-alives are not repeated here).
 */
class ReadyIT {

    private static final int NODES = 10;

    @TempDir
    Path tmp;

    @Test
    void framesSentRightAfterTheBannerAreNotLost() throws Exception {
        Path home = tmp.resolve("home");
        int port = new TestDistribution(home, null).realTimeAmicaRadio();
        try (PlatformProcess p = PlatformProcess.launch(home, home, List.of()); AmicaSender sender = new AmicaSender(port)) {
            String banner = p.awaitLine("bundles active", Duration.ofSeconds(120));
            for (int node = 1; node <= NODES; node++) {
                sender.keepAlive(3, node);
            }
            System.out.println(banner);
            List<String> missing = new ArrayList<>();
            long end = System.nanoTime() + Duration.ofSeconds(60).toNanos();
            while (System.nanoTime() < end) {
                String devices = p.text("tinysep:devices");
                missing.clear();
                IntStream.rangeClosed(1, NODES).mapToObj(n -> "3." + n)
                        .filter(n -> !devices.contains("\"AmICA node " + n + "\"")).forEach(missing::add);
                if (missing.isEmpty()) {
                    break;
                }
                Thread.sleep(500);
            }
            assertTrue(missing.isEmpty(), "keep-alives sent right after the banner were lost, no device for nodes "
                    + missing + "; " + p.text("tinysep:drivers"));
        }
    }
}
