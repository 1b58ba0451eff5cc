package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.osgi.framework.Bundle;
import org.osgi.framework.Constants;

/**
 * The headless gateway profile (issue 29, {@code --headless}): the distribution started headless has no HTTP port
 * open and no web console bundle, and every other bundle of {@code bundles/} is active, radios included.
 */
class HeadlessIT {

    @TempDir
    Path home;

    @Test
    void headlessHasNoHttpPortAndEveryOtherBundleActive() throws Exception {
        TestDistribution dist = new TestDistribution(home, null).headless();
        try {
            StartReport report = dist.start();
            assertTrue(report.failures().isEmpty(), () -> String.join("\n", report.lines()));
            assertEquals(report.installed(), report.activeCount(), () -> String.join("\n", report.lines()));
            List<String> expected = expectedBundles(home.resolve("bundles"));
            assertFalse(expected.isEmpty());
            for (String bsn : expected) {
                Bundle b = dist.bundle(bsn);
                assertTrue(b != null && (b.getState() == Bundle.ACTIVE
                        || b.getHeaders().get(Constants.FRAGMENT_HOST) != null), bsn + " active: " + b);
            }
            for (String web : webBundles(home.resolve("bundles"))) {
                assertNull(dist.bundle(web), web + " (web console) is not installed headless");
            }
            assertNull(dist.context().getAllServiceReferences(
                    "org.osgi.service.servlet.runtime.HttpServiceRuntime", null), "no HTTP service");
            TestDistribution.await(Duration.ofSeconds(15), () -> dist.hasDriver("BusRadioAmicaUdp"), "the AmICA radio");
            Thread.sleep(2_000); // Jetty, were it there, would have bound by now
            assertFalse(WebConsoleProbe.listening(dist.httpPort()),
                    "nothing listens on the web console's port " + dist.httpPort());
        } finally {
            dist.stop();
        }
    }

    /** @return the symbolic names of every bundle of every group but the web console's and the interactive shell */
    private static List<String> expectedBundles(Path bundles) throws IOException {
        List<String> out = new ArrayList<>();
        for (Path jar : jars(bundles)) {
            String bsn = Launcher.symbolicName(jar);
            if (!jar.getParent().getFileName().toString().endsWith("-" + Launcher.WEB_GROUP)
                    && !Launcher.SHELL_BSN.equals(bsn)) {
                out.add(bsn);
            }
        }
        return out;
    }

    private static List<String> webBundles(Path bundles) throws IOException {
        List<String> out = new ArrayList<>();
        for (Path jar : jars(bundles)) {
            if (jar.getParent().getFileName().toString().endsWith("-" + Launcher.WEB_GROUP)) {
                out.add(Launcher.symbolicName(jar));
            }
        }
        assertTrue(out.contains("org.apache.felix.http.jetty12"), "the web group holds Jetty: " + out);
        return out;
    }

    private static List<Path> jars(Path bundles) throws IOException {
        try (Stream<Path> files = Files.walk(bundles, 2)) {
            return files.filter(f -> f.toString().endsWith(".jar")).sorted().toList();
        }
    }
}
