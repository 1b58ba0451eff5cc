package org.tinysep.itests.web;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;
import static org.ops4j.pax.exam.CoreOptions.frameworkProperty;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.KeyStore;
import java.time.Duration;
import java.util.List;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.Option;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;

/**
 * HTTPS as docs/web-api.md documents it: the HTTP service configured with a keystore (a self-signed certificate
 * for 127.0.0.1 made by the JDK's keytool before the framework starts), the console logged into over TLS with a
 * client that trusts exactly that certificate; the session cookie then carries the Secure flag.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class WebTlsTest extends WebTestSupport {

    private static final String PASSWORD = "keystore-secret";
    private static final String HTTPS_PORT = "org.osgi.service.http.port.secure";

    private static Path keystore() {
        return Path.of("target", "itest-tls", "keystore.p12").toAbsolutePath();
    }

    @Override
    protected List<Option> options() {
        makeKeystore();
        List<Option> o = super.options();
        o.add(frameworkProperty("org.apache.felix.https.enable").value("true"));
        o.add(frameworkProperty(HTTPS_PORT).value(Integer.toString(freePort())));
        o.add(frameworkProperty("org.apache.felix.https.keystore").value(keystore().toString()));
        o.add(frameworkProperty("org.apache.felix.https.keystore.password").value(PASSWORD));
        o.add(frameworkProperty("org.apache.felix.https.keystore.key.password").value(PASSWORD));
        return o;
    }

    /** The command docs/web-api.md gives, plus the address the test connects to as subject alternative name. */
    private static void makeKeystore() {
        try {
            Files.createDirectories(keystore().getParent());
            Files.deleteIfExists(keystore());
            Path keytool = Path.of(System.getProperty("java.home"), "bin", "keytool");
            Process p = new ProcessBuilder(keytool.toString(), "-genkeypair", "-alias", "tinysep", "-keyalg", "EC",
                    "-keystore", keystore().toString(), "-storetype", "PKCS12", "-storepass", PASSWORD, "-keypass", PASSWORD,
                    "-dname", "CN=tinysep", "-ext", "SAN=ip:127.0.0.1", "-validity", "30")
                    .redirectErrorStream(true).start();
            String out = new String(p.getInputStream().readAllBytes());
            if (!p.waitFor(60, TimeUnit.SECONDS) || p.exitValue() != 0) {
                throw new IllegalStateException("keytool failed: " + out);
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    private static HttpClient tlsClient() throws Exception {
        KeyStore ks = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(keystore())) {
            ks.load(in, PASSWORD.toCharArray());
        }
        TrustManagerFactory tmf = TrustManagerFactory.getInstance(TrustManagerFactory.getDefaultAlgorithm());
        tmf.init(ks);
        SSLContext ssl = SSLContext.getInstance("TLS");
        ssl.init(null, tmf.getTrustManagers(), null);
        return HttpClient.newBuilder().sslContext(ssl).connectTimeout(Duration.ofSeconds(10))
                .followRedirects(HttpClient.Redirect.NEVER).build();
    }

    @Test
    public void theConsoleIsServedOverTlsWithASecureCookie() throws Exception {
        setPasswords();
        base(); // the HTTP service is up
        String https = "https://127.0.0.1:" + context.getProperty(HTTPS_PORT);
        HttpClient client = tlsClient();
        await(Duration.ofSeconds(30), () -> {
            try {
                return client.send(HttpRequest.newBuilder(URI.create(https + "/login.html")).GET().build(),
                        HttpResponse.BodyHandlers.ofString()).statusCode() == 200;
            } catch (IOException e) {
                return false;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }, "the console over HTTPS at " + https);
        HttpResponse<String> login = client.send(HttpRequest.newBuilder(URI.create(https + "/api/session"))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{\"user\":\"installer\",\"password\":\"" + INSTALLER_PASSWORD + "\"}"))
                .build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(login.body(), 200, login.statusCode());
        String cookie = login.headers().firstValue("Set-Cookie").orElseThrow();
        log.info("Set-Cookie over TLS: {}", cookie.replaceAll("=[^;]+;", "=…;"));
        assertTrue(cookie, cookie.contains("; Secure"));
        assertTrue(cookie, cookie.contains("HttpOnly") && cookie.contains("SameSite=Strict"));
        HttpResponse<String> devices = client.send(HttpRequest.newBuilder(URI.create(https + "/api/devices"))
                .header("Cookie", cookie.substring(0, cookie.indexOf(';'))).GET().build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(devices.body(), 200, devices.statusCode());
        Login plain = login("installer", INSTALLER_PASSWORD);
        assertTrue("no Secure flag over plain HTTP: " + plain.setCookie(), !plain.setCookie().contains("Secure"));
    }
}
