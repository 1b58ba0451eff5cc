package org.tinysep.testsupport.serial;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * Test utility: a socat pseudo-terminal pair with stable link paths {@code dir/a} and {@code dir/b}, what a USB
 * serial adapter and the node behind it look like to a serial link. Killing it makes both ends vanish; starting it
 * again creates new pseudo-terminals behind the same link paths. Needs the {@code socat} executable on the
 * {@code PATH}.
 */
public final class SocatPair implements AutoCloseable {

    private final Path dir;
    private Process process;
    private int starts;

    /** @param dir an existing folder for the link paths and socat's logs ({@code socat-<n>.log}) */
    public SocatPair(Path dir) {
        this.dir = dir;
    }

    /** @return the link path of one end, {@code dir/a} (usually the port the code under test opens) */
    public Path a() {
        return dir.resolve("a");
    }

    /** @return the link path of the other end, {@code dir/b} (usually the far end, see {@link PtyPeer}) */
    public Path b() {
        return dir.resolve("b");
    }

    /**
     * Starts socat and waits until both link paths exist and it is transferring data.
     *
     * @return this pair
     * @throws IllegalStateException if socat did not come up within 10 s, with its log
     */
    public SocatPair start() throws IOException, InterruptedException {
        Path log = dir.resolve("socat-" + (++starts) + ".log");
        process = new ProcessBuilder(socat(), "-d", "-d", "pty,raw,echo=0,link=" + a(), "pty,raw,echo=0,link=" + b())
                .redirectErrorStream(true).redirectOutput(log.toFile()).start();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!(Files.exists(a()) && Files.exists(b()) && Files.readString(log).contains("starting data transfer"))) {
            if (!process.isAlive() || System.nanoTime() > deadline) {
                throw new IllegalStateException("socat did not come up: " + Files.readString(log));
            }
            Thread.sleep(10);
        }
        return this;
    }

    /** Kills socat and waits (up to 5 s) until it is gone and its link paths are removed; does nothing if stopped. */
    public void kill() throws InterruptedException {
        if (process == null) {
            return;
        }
        process.destroy();
        if (!process.waitFor(5, TimeUnit.SECONDS)) {
            process.destroyForcibly().waitFor(5, TimeUnit.SECONDS);
        }
        process = null;
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(5);
        while ((Files.exists(a()) || Files.exists(b())) && System.nanoTime() < deadline) {
            Thread.sleep(10);
        }
    }

    /** Same as {@link #kill()}. */
    @Override
    public void close() throws InterruptedException {
        kill();
    }

    /**
     * @return the socat executable found on the {@code PATH}
     * @throws AssertionError when socat is not installed, saying how to install it (so the test fails clearly)
     */
    public static String socat() {
        for (String dir : System.getenv().getOrDefault("PATH", "/usr/bin:/bin").split(File.pathSeparator)) {
            File f = new File(dir, "socat");
            if (f.canExecute()) {
                return f.getPath();
            }
        }
        throw new AssertionError("socat is not installed but the serial tests need it for pseudo-terminal pairs: "
                + "run scripts/install-deps.sh (as root it installs socat with apt-get)");
    }
}
