package org.tinysep.itests.serial;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;

/**
 * A socat pseudo-terminal pair with stable link paths {@code dir/a} and {@code dir/b}: what a USB serial adapter
 * and the node behind it look like to the link. Killing it makes both ends vanish; starting it again creates new
 * pseudo-terminals behind the same link paths.
 * <p>
 * A deliberate copy of {@code org.tinysep.serial.support.testing.SocatPair}, the one the unit tests share: these
 * tests run inside Pax Exam's probe bundle, which loads only its own classes and packages exported in the
 * framework, and no bundle exports that package (ClassNotFoundException when tried).
 */
final class SocatPair implements AutoCloseable {

    private final Path dir;
    private Process process;
    private int starts;

    SocatPair(Path dir) {
        this.dir = dir;
    }

    Path a() {
        return dir.resolve("a");
    }

    Path b() {
        return dir.resolve("b");
    }

    /** Starts socat and waits until both link paths exist and it is transferring data. */
    SocatPair start() throws IOException, InterruptedException {
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

    /** Kills socat and waits until it is gone and its link paths are removed. */
    void kill() throws InterruptedException {
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

    @Override
    public void close() throws InterruptedException {
        kill();
    }

    /** @return the socat executable; fails with a clear message when it is not installed */
    static String socat() {
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
