package org.tinysep.evaluation;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.net.BindException;
import java.net.DatagramSocket;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.SocketException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

/**
 * The real distribution ({@code <dist>/tinysep.jar}) as its own process, like {@code scripts/demo-flat.sh} runs the
 * demo: a private home ({@code bundles} linked to the distribution's, its own {@code etc/}) and its own state folder.
 * The configuration puts the bus radio and the synchroniser on free loopback ports, the clock in EXTERNAL mode, the
 * Mail Manager on the harness's SMTP sink and Inactivity Recognition on the chosen detector.
 */
final class Platform implements AutoCloseable {

    /** JVM options: small heap and quick start (the harness runs two platforms at once on 2 CPUs). */
    static final List<String> JVM = List.of("-Xmx256m", "-XX:+UseSerialGC", "-XX:TieredStopAtLevel=1");
    private static final Duration START = Duration.ofSeconds(180);

    /** Platforms still running: a harness that ends early (error, Ctrl-C) must not leave them behind. */
    private static final java.util.Set<Process> RUNNING = java.util.concurrent.ConcurrentHashMap.newKeySet();

    static {
        Runtime.getRuntime().addShutdownHook(new Thread(() -> RUNNING.forEach(Process::destroyForcibly),
                "platforms-stop"));
    }

    private final Process process;
    private final int amicaPort;
    private final int syncPort;
    private final Path var;
    private final CountDownLatch up = new CountDownLatch(1);

    private Platform(Process process, int amicaPort, int syncPort, Path var) {
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
    static Platform start(Path dist, Path home, Path var, int smtpPort, String detector, Map<String, String> extra)
            throws IOException, InterruptedException {
        Path etc = home.resolve("etc");
        Files.createDirectories(etc);
        Files.createDirectories(home.resolve("deploy"));
        Files.createDirectories(var);
        if (!Files.exists(home.resolve("bundles"))) {
            Files.createSymbolicLink(home.resolve("bundles"), dist.resolve("bundles").toAbsolutePath());
        }
        for (Path f : Files.newDirectoryStream(dist.resolve("etc"), "*.cfg")) {
            Files.copy(f, etc.resolve(f.getFileName()), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        }
        int amica = freeUdpPort();
        int sync = freeUdpPort();
        // a recording carries changes only; the replayed nodes add a keep-alive a minute, not the thesis's status
        // report every 1-2 s that sensor health expects: 600 missed reports (10-20 min without even a keep-alive)
        // before a node counts as OFFLINE, else every node would flap OFFLINE/ONLINE each minute
        write(etc, "org.tinysep.amica.busradio.udp", "port=" + amica + "\nbindAddress=127.0.0.1\n"
                + "silentAfterIntervals=600\n");
        write(etc, "org.tinysep.sunspot.busradio", "udpPort=0\nudpBindAddress=127.0.0.1\n");
        write(etc, "org.apache.felix.http", "org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=0\n");
        write(etc, "org.tinysep.timecontroller", "mode=EXTERNAL\nsyncPort=" + sync
                + "\nsyncBindAddress=127.0.0.1\nsyncTimeout=0\n");
        write(etc, "org.tinysep.mailmanager", "host=127.0.0.1\nport=" + smtpPort + "\nsecurity=NONE\n"
                + "from=tinysep@localhost\nrecipients=carer@localhost\nretryInitialSeconds=1\nretryMaxSeconds=5\n");
        write(etc, "org.tinysep.inactivity", "detector=" + detector + "\ntimeZone=UTC\n"
                + extra.getOrDefault("org.tinysep.inactivity", ""));
        for (Map.Entry<String, String> e : extra.entrySet()) {
            if (!e.getKey().equals("org.tinysep.inactivity")) {
                write(etc, e.getKey(), e.getValue());
            }
        }
        List<String> cmd = new java.util.ArrayList<>();
        cmd.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        cmd.addAll(JVM);
        cmd.addAll(List.of("-jar", dist.resolve("tinysep.jar").toAbsolutePath().toString(), "--daemon",
                "--home", home.toAbsolutePath().toString(), "--var", var.toAbsolutePath().toString()));
        Process p = new ProcessBuilder(cmd).directory(home.toFile()).redirectErrorStream(false)
                .redirectError(ProcessBuilder.Redirect.appendTo(home.resolve("platform.log").toFile())).start();
        RUNNING.add(p);
        Platform platform = new Platform(p, amica, sync, var);
        platform.readStdout(home.resolve("platform.out"));
        platform.awaitUp();
        return platform;
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

    private void readStdout(Path copy) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(),
                    StandardCharsets.UTF_8)); var w = Files.newBufferedWriter(copy)) {
                for (String line; (line = r.readLine()) != null; ) {
                    w.write(line);
                    w.newLine();
                    w.flush();
                    if (line.startsWith("TinySEP ") && line.contains(" up in ")) {
                        up.countDown();
                    }
                }
            } catch (IOException ignored) {
                // the process ended
            }
        }, "platform-stdout");
        t.setDaemon(true);
        t.start();
    }

    private void awaitUp() throws IOException, InterruptedException {
        long deadline = System.nanoTime() + START.toNanos();
        if (!up.await(START.toSeconds(), TimeUnit.SECONDS)) {
            close();
            throw new IOException("the platform did not print its banner within " + START.toSeconds() + " s");
        }
        while (!bound(amicaPort)) {
            if (System.nanoTime() > deadline || !process.isAlive()) {
                close();
                throw new IOException("the platform's AmICA bus radio did not bind 127.0.0.1:" + amicaPort);
            }
            Thread.sleep(50);
        }
    }

    /** @return true if someone holds the UDP port on 127.0.0.1 (our own bind fails) */
    private static boolean bound(int port) {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), port))) {
            return false;
        } catch (BindException e) {
            return true;
        } catch (SocketException e) {
            return false;
        }
    }

    private static int freeUdpPort() throws SocketException {
        try (DatagramSocket s = new DatagramSocket(new InetSocketAddress(InetAddress.getLoopbackAddress(), 0))) {
            return s.getLocalPort();
        }
    }

    private static void write(Path etc, String pid, String text) throws IOException {
        Files.writeString(etc.resolve(pid + ".cfg"), "# written by the evaluation harness\n" + text);
    }

    /** SIGTERM: the launcher's shutdown hook stops the framework cleanly (logs flushed, backups written). */
    @Override
    public void close() throws InterruptedException {
        try {
            if (process.isAlive()) {
                process.destroy();
                if (!process.waitFor(60, TimeUnit.SECONDS)) {
                    process.destroyForcibly();
                    process.waitFor();
                }
            }
        } catch (InterruptedException e) {
            process.destroyForcibly(); // the harness is giving up: never leave a platform behind
            throw e;
        } finally {
            if (!process.isAlive()) {
                RUNNING.remove(process);
            }
        }
    }
}
