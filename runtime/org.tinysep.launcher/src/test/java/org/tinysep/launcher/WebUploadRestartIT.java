package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.tinysep.launcher.TestDistribution.await;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.jar.Attributes;
import java.util.jar.JarEntry;
import java.util.jar.JarInputStream;
import java.util.jar.JarOutputStream;
import java.util.jar.Manifest;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;
import org.osgi.framework.Version;

/**
 * An update uploaded through the web console's drivers page for an application of {@code bundles/5-apps} lasts
 * across restarts of the real distribution (issue 13): the drivers list then loads the kept upload instead of the
 * older 5-apps copy. When the distribution itself later brings a newer version, that one wins (never run an older
 * copy than the distribution's).
 */
class WebUploadRestartIT extends StateFolderFixture {

    private static final Duration WAIT = Duration.ofSeconds(30);
    private static final String WINDOW = "org.tinysep.amica.window";
    private static final String PASSWORD = "installer-secret-1";

    private final HttpClient http = HttpClient.newBuilder().connectTimeout(Duration.ofSeconds(10)).build();
    private String base;

    @Test
    void anUploadedUpdateOfA5AppsBundleWinsAtTheNextStartUntilTheDistributionBringsANewerOne() throws Exception {
        base = "http://127.0.0.1:" + freePort();
        Files.writeString(tmp.resolve("home/etc/org.apache.felix.http.cfg"), "org.apache.felix.http.host=127.0.0.1\n"
                + "org.osgi.service.http.port=" + base.substring(base.lastIndexOf(':') + 1) + "\n");
        dist.start();
        Path shipped = appJar();
        Version original = Version.parseVersion(manifest(Files.readAllBytes(shipped)).getMainAttributes()
                .getValue("Bundle-Version"));
        assertEquals(original, dist.bundle(WINDOW).getVersion());
        Version uploaded = new Version(original.getMajor(), original.getMinor(), original.getMicro() + 1);

        String[] login = login();
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/applications"))
                .header("Cookie", login[0]).header("X-CSRF-Token", login[1])
                .header("Content-Type", "application/java-archive")
                .POST(HttpRequest.BodyPublishers.ofByteArray(withVersion(Files.readAllBytes(shipped), uploaded)))
                .timeout(WAIT).build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(200, r.statusCode(), r.body());
        assertTrue(r.body().contains("\"action\":\"updated\""), r.body());
        assertEquals(uploaded, dist.bundle(WINDOW).getVersion());

        dist.restart();
        assertEquals(uploaded, dist.bundle(WINDOW).getVersion(), "the upload, not the older 5-apps copy, after a restart");
        assertTrue(r.body().contains("Kept: from the next start on the platform loads this upload"), r.body());
        await(WAIT, () -> dist.hasDriver("AmicaWindow"), "the AmicaWindow driver of the uploaded bundle");
        String list = Files.readString(tmp.resolve("state/drivers.xml"));
        assertTrue(list.contains("web/uploads/" + WINDOW + ".jar</FILE_PATH>"), list);

        // a later distribution brings a newer version than the upload: the distribution's is used
        Version newer = new Version(original.getMajor(), original.getMinor() + 1, 0);
        byte[] next = withVersion(Files.readAllBytes(shipped), newer);
        Files.delete(shipped);
        Files.write(shipped.resolveSibling(WINDOW + "-" + newer + ".jar"), next);
        dist.restart();
        assertEquals(newer, dist.bundle(WINDOW).getVersion(), "the newer distribution's copy wins over an older upload");
        await(WAIT, () -> dist.hasDriver("AmicaWindow"), "the AmicaWindow driver of the distribution's bundle");
        assertTrue(Files.readString(tmp.resolve("state/drivers.xml")).contains("bundles/5-apps/" + WINDOW + "-" + newer
                + ".jar</FILE_PATH>"));
    }

    private Path appJar() throws IOException {
        return dist.apps().stream().filter(p -> p.getFileName().toString().startsWith(WINDOW + "-")).findFirst()
                .orElseThrow();
    }

    /** Sets the installer's password in the shell, logs in over HTTP. @return the cookie and the CSRF token */
    private String[] login() throws Exception {
        await(WAIT, () -> {
            try {
                return dist.shell("tinysep:web-password installer " + PASSWORD).contains("set");
            } catch (Exception e) {
                return false;
            }
        }, "tinysep:web-password");
        await(WAIT, () -> {
            try {
                return http.send(HttpRequest.newBuilder(URI.create(base + "/login.html")).build(),
                        HttpResponse.BodyHandlers.discarding()).statusCode() == 200;
            } catch (IOException e) {
                return false;
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return false;
            }
        }, "the web console at " + base);
        HttpResponse<String> r = http.send(HttpRequest.newBuilder(URI.create(base + "/api/session"))
                .header("Content-Type", "application/json")
                .POST(HttpRequest.BodyPublishers.ofString("{\"user\":\"installer\",\"password\":\"" + PASSWORD + "\"}"))
                .build(), HttpResponse.BodyHandlers.ofString());
        assertEquals(200, r.statusCode(), r.body());
        String cookie = r.headers().firstValue("Set-Cookie").orElseThrow();
        Matcher m = Pattern.compile("\"csrf\":\"([^\"]+)\"").matcher(r.body());
        assertTrue(m.find(), r.body());
        return new String[] {cookie.substring(0, cookie.indexOf(';')), m.group(1)};
    }

    private static Manifest manifest(byte[] jar) throws IOException {
        try (JarInputStream in = new JarInputStream(new java.io.ByteArrayInputStream(jar))) {
            return in.getManifest();
        }
    }

    /** @return the jar with another Bundle-Version */
    private static byte[] withVersion(byte[] jar, Version version) throws IOException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        try (JarInputStream in = new JarInputStream(new java.io.ByteArrayInputStream(jar))) {
            Manifest m = new Manifest(in.getManifest());
            m.getMainAttributes().put(new Attributes.Name("Bundle-Version"), version.toString());
            try (JarOutputStream out = new JarOutputStream(bytes, m)) {
                for (JarEntry e = in.getNextJarEntry(); e != null; e = in.getNextJarEntry()) {
                    out.putNextEntry(new JarEntry(e.getName()));
                    in.transferTo(out);
                    out.closeEntry();
                }
            }
        }
        return bytes.toByteArray();
    }

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            return s.getLocalPort();
        }
    }
}
