package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import org.tinysep.tools.process.DistributionCopy;
import org.tinysep.tools.process.PlatformLaunch;
import org.tinysep.tools.process.PlatformProcess;
import org.tinysep.tools.process.Ports;

/**
 * The real distribution ({@code <dist>/tinysep.jar}) as its own process ({@link PlatformProcess}), like {@code
 * scripts/demo-flat.sh} runs the demo: a private home ({@code bundles} linked to the distribution's, its own {@code
 * etc/}) and its own state folder. The configuration puts the bus radio and the synchroniser on free loopback ports,
 * the clock in EXTERNAL mode, the Mail Manager on the harness's SMTP sink and Inactivity Recognition on the chosen
 * detector.
 */
final class HarnessPlatform implements AutoCloseable {

    /** JVM options: small heap and quick start (the harness runs two platforms at once on 2 CPUs). */
    static final List<String> JVM = List.of("-Xmx256m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1");
    private static final Duration START = Duration.ofSeconds(180);
    private static final String HEADER = "# written by the evaluation harness\n";

    private final PlatformProcess process;
    private final int amicaPort;
    private final int syncPort;
    private final Path var;

    private HarnessPlatform(PlatformProcess process, int amicaPort, int syncPort, Path var) {
        this.process = process;
        this.amicaPort = amicaPort;
        this.syncPort = syncPort;
        this.var = var;
    }

    /**
     * Writes {@code home/etc}, starts {@code java -jar <dist>/tinysep.jar --daemon --home home --var var} and returns
     * once the banner is printed and the bus radio's socket is bound.
     *
     * @param extra further {@code <pid>.cfg} files (pid → {@code key=value} lines)
     */
    static HarnessPlatform start(Path dist, Path home, Path var, int smtpPort, String detector, Map<String, String> extra)
            throws IOException {
        DistributionCopy.linked(dist, home);
        Files.createDirectories(var);
        int amica = Ports.freeUdp();
        int sync = Ports.freeUdp();
        PlatformLaunch launch = PlatformProcess.in(home).jar(dist.resolve(DistributionCopy.JAR)).jvm(JVM).daemon()
                .args("--home", home.toAbsolutePath().toString(), "--var", var.toAbsolutePath().toString())
                .stdoutCopy(home.resolve("platform.out")).stopTimeout(Duration.ofSeconds(60))
                // a recording carries changes only; the replayed nodes add a keep-alive a minute, not the thesis's
                // status report every 1-2 s that sensor health expects: 600 missed reports (10-20 min without even
                // a keep-alive) before a node counts as OFFLINE, else every node would flap OFFLINE/ONLINE each minute
                .cfg("org.tinysep.amica.busradio.udp", HEADER + "port=" + amica + "\nbindAddress=127.0.0.1\n"
                        + "silentAfterIntervals=600\n")
                .cfg("org.tinysep.sunspot.busradio", HEADER + "udpPort=0\nudpBindAddress=127.0.0.1\n")
                .cfg("org.apache.felix.http", HEADER
                        + "org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=0\n")
                .cfg("org.tinysep.timecontroller", HEADER + "mode=EXTERNAL\nsyncPort=" + sync
                        + "\nsyncBindAddress=127.0.0.1\nsyncTimeout=0\n")
                .cfg("org.tinysep.mailmanager", HEADER + "host=127.0.0.1\nport=" + smtpPort + "\nsecurity=NONE\n"
                        + "from=tinysep@localhost\nrecipients=carer@localhost\nretryInitialSeconds=1\n"
                        + "retryMaxSeconds=5\n")
                .cfg("org.tinysep.inactivity", HEADER + "detector=" + detector + "\ntimeZone=UTC\n"
                        + extra.getOrDefault("org.tinysep.inactivity", ""));
        for (Map.Entry<String, String> e : extra.entrySet()) {
            if (!e.getKey().equals("org.tinysep.inactivity")) {
                launch.cfg(e.getKey(), HEADER + e.getValue());
            }
        }
        long deadline = System.nanoTime() + START.toNanos();
        PlatformProcess p = launch.start(START);
        p.awaitUntil(() -> Ports.udpBound(amica), "its AmICA bus radio bound 127.0.0.1:" + amica,
                Duration.ofNanos(Math.max(0, deadline - System.nanoTime())));
        return new HarnessPlatform(p, amica, sync, var);
    }

    int amicaPort() {
        return amicaPort;
    }

    int syncPort() {
        return syncPort;
    }

    Path syncKey() {
        return var.resolve("sync.key");
    }

    /** SIGTERM: the launcher's shutdown hook stops the framework cleanly (logs flushed, backups written). */
    @Override
    public void close() throws InterruptedException {
        process.close();
    }
}
