package org.tinysep.testsupport.mqtt;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

/**
 * A real Mosquitto broker (Debian's {@code mosquitto} binary, installed by {@code scripts/install-deps.sh}) for tests.
 *
 * <p>It listens on a free port of 127.0.0.1 only, with a configuration generated into its own temporary folder:
 * persistence off unless {@link Builder#persistence(boolean) asked}, anonymous access unless a
 * {@link Builder#user(String, String) user} is given (then a password file made with {@code mosquitto_passwd}),
 * optionally TLS with a freshly generated self-signed certificate for 127.0.0.1 ({@link #trustStore()} holds it for
 * Java clients). {@link #start()} waits until the broker accepts TCP connections; {@link #stop()} and
 * {@link #start()} again keep the same port (the "broker down, then back" tests). {@link #close()} stops only this
 * broker's own process and deletes its folder.
 *
 * <pre>{@code
 * try (Mosquitto broker = Mosquitto.builder().start()) {
 *     String url = broker.url();   // tcp://127.0.0.1:NNNNN
 * }
 * }</pre>
 */
public final class Mosquitto implements AutoCloseable {

    /** The password of the generated PKCS12 trust store ({@link #trustStore()}). */
    public static final String TRUST_STORE_PASSWORD = "changeit";

    private final Builder options;
    private final Path dir;
    private final int port;
    private final BrokerProcess process;

    private Mosquitto(Builder options) throws IOException {
        this.options = options;
        this.dir = Files.createTempDirectory("tinysep-mosquitto-");
        this.port = options.port > 0 ? options.port : BrokerProcess.freePort();
        if (options.user != null) {
            Passwords.write(dir.resolve("passwd"), options.user, options.password);
        }
        if (options.tls) {
            Certificates.generate(dir);
        }
        if (options.clientCertificates) {
            Certificates.generateClientCa(dir);
        }
        Files.writeString(dir.resolve("mosquitto.conf"), BrokerConfig.text(options, dir, port), StandardCharsets.UTF_8);
        Files.createDirectories(dir.resolve("data"));
        this.process = new BrokerProcess(dir.resolve("mosquitto.conf"), dir.resolve("mosquitto.log"), port, this::log);
    }

    /** @return a builder for a broker with the defaults: anonymous, plain TCP, no persistence */
    public static Builder builder() {
        return new Builder();
    }

    /** Starts a default broker (anonymous, plain TCP, no persistence) and waits until it accepts connections. */
    public static Mosquitto startDefault() {
        return builder().start();
    }

    /** @return the path of the broker binary: {@code /usr/sbin/mosquitto} or the one on the PATH */
    public static String binary() {
        return BrokerProcess.binary();
    }

    /** @return true when the mosquitto binary is installed (tests may use this for an assumption message) */
    public static boolean isInstalled() {
        return Files.isExecutable(Path.of(binary())) || BrokerProcess.onPath("mosquitto");
    }

    /**
     * Starts (or restarts after {@link #stop()}) the broker on this port and waits until it accepts connections.
     *
     * @return this
     * @throws IllegalStateException when it does not start (the message carries its log)
     */
    public Mosquitto start() {
        process.start();
        return this;
    }

    /** Stops the broker (SIGTERM, then SIGKILL after 10 s) and waits until its process has ended. Idempotent. */
    public void stop() {
        process.stop();
    }

    /** Kills the broker abruptly (SIGKILL): no orderly shutdown, persistence not saved. */
    public void kill() {
        process.kill();
    }

    /** @return true while this broker's process runs */
    public boolean isRunning() {
        return process.isRunning();
    }

    /** @return the port on 127.0.0.1, the same across {@link #stop()}/{@link #start()} */
    public int port() {
        return port;
    }

    /** @return {@code tcp://127.0.0.1:port}, or {@code ssl://127.0.0.1:port} with TLS */
    public String url() {
        return (options.tls ? "ssl" : "tcp") + "://127.0.0.1:" + port;
    }

    /** @return the broker's folder (configuration, log, certificates, password file) */
    public Path dir() {
        return dir;
    }

    /** @return the PEM of the self-signed server certificate (TLS only) */
    public Path certificatePem() {
        requireTls();
        return dir.resolve(Certificates.CERT);
    }

    /** @return a PKCS12 trust store holding the server certificate, password {@link #TRUST_STORE_PASSWORD} */
    public Path trustStore() {
        requireTls();
        return dir.resolve(Certificates.TRUST_STORE);
    }

    /** @return the PEM of the CA whose client certificates the broker accepts (see {@link ClientCertificates}) */
    public Path clientCa() {
        if (!options.clientCertificates) {
            throw new IllegalStateException("this broker does not ask for client certificates"
                    + " (Mosquitto.builder().requireClientCertificate(true))");
        }
        return dir.resolve(Certificates.CLIENT_CA);
    }

    private void requireTls() {
        if (!options.tls) {
            throw new IllegalStateException("this broker runs without TLS (Mosquitto.builder().tls(true))");
        }
    }

    /** @return the broker's log so far (connections, refusals, errors) */
    public String log() {
        try {
            Path log = dir.resolve("mosquitto.log");
            return Files.exists(log) ? Files.readString(log, StandardCharsets.UTF_8) : "";
        } catch (IOException e) {
            return "(log unreadable: " + e.getMessage() + ")";
        }
    }

    /** Stops the broker (only this instance's own process) and deletes its folder. */
    @Override
    public void close() {
        stop();
        try (Stream<Path> files = Files.walk(dir)) {
            for (Path p : files.sorted(Comparator.reverseOrder()).toList()) {
                Files.deleteIfExists(p);
            }
        } catch (IOException e) {
            // a temp folder left behind is harmless
        }
    }

    @Override
    public String toString() {
        return "Mosquitto[" + url() + (isRunning() ? ", running" : ", stopped") + ", " + dir + "]";
    }

    /** Options of a broker; {@link #start()} creates and starts it. */
    public static final class Builder {
        boolean persistence;
        boolean tls;
        boolean clientCertificates;
        String user;
        String password;
        int port;
        final List<String> extraLines = new ArrayList<>();

        private Builder() {
        }

        /** Keeps retained messages and sessions across {@link Mosquitto#stop()}/{@link Mosquitto#start()}. */
        public Builder persistence(boolean on) {
            this.persistence = on;
            return this;
        }

        /** Serves TLS with a generated self-signed certificate for 127.0.0.1 (url {@code ssl://...}). */
        public Builder tls(boolean on) {
            this.tls = on;
            return this;
        }

        /**
         * Serves TLS (as {@link #tls(boolean)}) and refuses every client without a certificate signed by the broker's
         * own client CA ({@code require_certificate true}); {@link ClientCertificates#issue} makes such certificates.
         */
        public Builder requireClientCertificate(boolean on) {
            this.clientCertificates = on;
            this.tls = tls || on;
            return this;
        }

        /** Refuses anonymous clients; this user (password file made by {@code mosquitto_passwd}) may connect. */
        public Builder user(String name, String password) {
            this.user = name;
            this.password = password;
            return this;
        }

        /** Uses this port instead of a free one. */
        public Builder port(int port) {
            this.port = port;
            return this;
        }

        /** Appends a line to the generated mosquitto.conf (e.g. {@code max_queued_messages 10}). */
        public Builder configLine(String line) {
            extraLines.add(line);
            return this;
        }

        /** Creates the broker's folder and configuration, starts it and waits until it accepts connections. */
        public Mosquitto start() {
            try {
                return new Mosquitto(this).start();
            } catch (IOException e) {
                throw new UncheckedIOException("cannot prepare the mosquitto broker: " + e.getMessage(), e);
            }
        }
    }
}
