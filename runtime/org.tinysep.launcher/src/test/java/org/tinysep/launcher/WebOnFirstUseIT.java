package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.net.BindException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.URI;
import java.net.http.HttpClient;
import java.net.http.HttpRequest;
import java.net.http.HttpResponse;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;

/**
 * Issue 29, item 3: the default distribution's web console starts on its first use. After the banner (every radio
 * listening, as before) Jetty is not installed and no HTTP service exists, while the console's port is
 * held; the first HTTP request starts it and gets the console's own answer; before that, the shell's
 * {@code tinysep:web-password} starts it too and sets the password.
 */
class WebOnFirstUseIT {

    private static final String JETTY = "org.apache.felix.http.jetty12";
    private static final String HTTP_RUNTIME = "org.osgi.service.servlet.runtime.HttpServiceRuntime";

    @TempDir
    Path home;

    @Test
    void theFirstRequestStartsTheConsoleAndIsAnsweredByIt() throws Exception {
        TestDistribution dist = new TestDistribution(home, null);
        try {
            StartReport report = dist.start();
            assertEquals(report.installed(), report.activeCount(), () -> String.join("\n", report.lines()));
            TestDistribution.await(Duration.ofSeconds(15), () -> dist.hasDriver("BusRadioAmicaUdp"), "the AmICA radio");
            Thread.sleep(1_000); // were it started after the banner, Jetty would be starting by now
            assertNull(dist.bundle(JETTY), "Jetty is not even installed before the console's first use");
            assertNull(dist.context().getAllServiceReferences(HTTP_RUNTIME, null), "no HTTP service while idle");
            try (ServerSocket other = new ServerSocket()) { // not a connection: that would be the first use
                assertThrows(BindException.class, () -> other.bind(new InetSocketAddress("127.0.0.1", dist.httpPort())),
                        "the console's port is held for its first use");
            }

            HttpResponse<String> first = HttpClient.newHttpClient().send(HttpRequest.newBuilder(
                    URI.create("http://127.0.0.1:" + dist.httpPort() + "/login.html")).timeout(Duration.ofSeconds(30))
                    .build(), HttpResponse.BodyHandlers.ofString());
            assertEquals(200, first.statusCode(), first.body());
            assertTrue(first.body().contains("<form"), "the console's login page: " + first.body());
            assertEquals(Bundle.ACTIVE, dist.bundle(JETTY).getState(), "Jetty started by the first request");
        } finally {
            dist.stop();
        }
    }

    @Test
    void theShellsPasswordCommandStartsTheConsoleAndSetsThePassword() throws Exception {
        TestDistribution dist = new TestDistribution(home, null);
        try {
            dist.start();
            assertNull(dist.bundle(JETTY));
            String out = dist.shell("tinysep:web-password installer correct-horse");
            assertTrue(out.contains("web console password of the installer set"), out);
            assertTrue(Files.readString(home.resolve("var/web/passwords.properties")).contains("installer="));
            assertEquals(Bundle.ACTIVE, dist.bundle(JETTY).getState(), "the command started the console");
            assertTrue(dist.shell("tinysep:web-password caregiver correct-horse2").contains("caregiver set"),
                    "the console's own command answers from now on");
        } finally {
            dist.stop();
        }
    }
}
