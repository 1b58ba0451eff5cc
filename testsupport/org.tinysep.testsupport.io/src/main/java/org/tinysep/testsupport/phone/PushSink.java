package org.tinysep.testsupport.phone;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;

/**
 * A push server for tests: HTTPS on 127.0.0.1 with a certificate for 127.0.0.1/localhost made by the JDK's
 * {@code keytool} in the test's folder ({@link #certificatePem()} is what the client must trust). Every POST is
 * kept ({@link #published()}) and answered 200 with an ntfy-like JSON id, or with the status set by
 * {@link #answer(int)}; a request without the expected bearer token is answered 401.
 */
public final class PushSink implements AutoCloseable {

    /** One request: its path, headers (lower-case names) and body. */
    public record Published(String path, Map<String, String> headers, String body) {
    }

    private static final String PASSWORD = "changeit";
    private final Path dir;
    private final String token;
    private final List<Published> published = new CopyOnWriteArrayList<>();
    private final ExecutorService thread = Executors.newSingleThreadExecutor(r -> new Thread(r, "push-sink"));
    private ServerSocket server;
    private volatile int status = 200;

    /** @param token the bearer token the server expects; empty = none needed */
    public PushSink(Path dir, String token) {
        this.dir = dir.toAbsolutePath();
        this.token = token;
    }

    public PushSink start() throws Exception {
        Path store = dir.resolve("push-server.p12");
        keytool("-genkeypair", "-alias", "push", "-keyalg", "EC", "-groupname", "secp256r1", "-dname",
                "CN=127.0.0.1", "-ext", "san=ip:127.0.0.1,dns:localhost", "-validity", "2", "-storetype", "PKCS12",
                "-keystore", store.toString(), "-storepass", PASSWORD, "-keypass", PASSWORD);
        keytool("-exportcert", "-rfc", "-alias", "push", "-keystore", store.toString(), "-storetype", "PKCS12",
                "-storepass", PASSWORD, "-file", certificatePem().toString());
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(store)) {
            ks.load(in, PASSWORD.toCharArray());
        }
        KeyManagerFactory kmf = KeyManagerFactory.getInstance(KeyManagerFactory.getDefaultAlgorithm());
        kmf.init(ks, PASSWORD.toCharArray());
        SSLContext tls = SSLContext.getInstance("TLS");
        tls.init(kmf.getKeyManagers(), null, null);
        server = tls.getServerSocketFactory().createServerSocket(0, 10, InetAddress.getLoopbackAddress());
        thread.execute(this::serve);
        return this;
    }

    public Path certificatePem() {
        return dir.resolve("push-server.pem");
    }

    /** @return e.g. {@code https://127.0.0.1:40123} */
    public String url() {
        return "https://127.0.0.1:" + server.getLocalPort();
    }

    /** Every later request is answered with this HTTP status (200 = accepted). */
    public void answer(int httpStatus) {
        status = httpStatus;
    }

    public List<Published> published() {
        return List.copyOf(published);
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                s.setSoTimeout(5000);
                exchange(s);
            } catch (IOException e) {
                // a client that failed the handshake, or the server closing
            }
        }
    }

    private void exchange(Socket s) throws IOException {
        InputStream in = s.getInputStream();
        BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
        String request = r.readLine();
        if (request == null) {
            return;
        }
        Map<String, String> headers = new TreeMap<>();
        for (String line = r.readLine(); line != null && !line.isEmpty(); line = r.readLine()) {
            int colon = line.indexOf(':');
            if (colon > 0) {
                headers.put(line.substring(0, colon).strip().toLowerCase(Locale.ROOT), line.substring(colon + 1)
                        .strip());
            }
        }
        int length = Integer.parseInt(headers.getOrDefault("content-length", "0"));
        char[] body = new char[length];
        int read = 0;
        while (read < length) { // ASCII JSON from the tests' clients: characters = bytes only for ASCII
            int n = r.read(body, read, length - read);
            if (n < 0) {
                break;
            }
            read += n;
        }
        String path = request.split(" ").length > 1 ? request.split(" ")[1] : "";
        boolean authorised = token.isEmpty() || ("Bearer " + token).equals(headers.get("authorization"));
        int code = authorised ? status : 401;
        if (authorised) {
            published.add(new Published(path, headers, new String(body, 0, read)));
        }
        String answer = code == 200 ? "{\"id\":\"p" + published.size() + "\",\"event\":\"message\"}"
                : "{\"code\":" + code + ",\"error\":\"" + (code == 401 ? "unauthorized" : "refused by test") + "\"}";
        byte[] bytes = answer.getBytes(StandardCharsets.UTF_8);
        OutputStream out = s.getOutputStream();
        out.write(("HTTP/1.1 " + code + " " + (code == 200 ? "OK" : "Error") + "\r\nContent-Type: application/json"
                + "\r\nContent-Length: " + bytes.length + "\r\nConnection: close\r\n\r\n").getBytes(
                        StandardCharsets.US_ASCII));
        out.write(bytes);
        out.flush();
    }

    private static void keytool(String... args) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "keytool")
                .toString()));
        cmd.addAll(List.of(args));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (p.waitFor() != 0) {
            throw new IOException("keytool failed: " + out);
        }
    }

    @Override
    public void close() throws IOException {
        if (server != null) {
            server.close();
        }
        thread.shutdownNow();
        try {
            thread.awaitTermination(2, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}
