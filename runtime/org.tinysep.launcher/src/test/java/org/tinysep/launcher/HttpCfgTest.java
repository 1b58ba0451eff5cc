package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 29: the launcher holds the web console's port until its first use only where its hand-over is exact — plain
 * HTTP on this machine's loopback address. Anything else (HTTPS, a network address the console's plain-HTTP rule
 * judges by the address a request came to, a value FileInstall substitutes later) starts the console after the banner.
 */
class HttpCfgTest {

    @TempDir
    Path etc;

    @Test
    void theShippedPlainHttpOnLoopbackStartsOnFirstUse() throws IOException {
        assertTrue(HttpCfg.onFirstUse(cfg("org.apache.felix.http.host=127.0.0.1\norg.osgi.service.http.port=8080\n")));
        assertTrue(HttpCfg.onFirstUse(etc.resolve("missing.cfg")), "no file: the defaults, 127.0.0.1:8080");
    }

    @Test
    void httpsOrANetworkAddressStartsAfterTheBanner() throws IOException {
        assertFalse(HttpCfg.onFirstUse(cfg("org.apache.felix.http.host=192.168.1.20\n")),
                "a request forwarded by the launcher would reach Jetty at 127.0.0.1, as if from this machine");
        assertFalse(HttpCfg.onFirstUse(cfg("org.apache.felix.http.host=0.0.0.0\n")));
        assertFalse(HttpCfg.onFirstUse(cfg("org.apache.felix.https.enable=true\norg.osgi.service.http.port.secure=8443\n")));
        assertFalse(HttpCfg.onFirstUse(cfg("org.apache.felix.http.enable=false\n")));
        assertFalse(HttpCfg.onFirstUse(cfg("org.apache.felix.http.host=${env:TINYSEP_HOST}\n")));
    }

    private Path cfg(String text) throws IOException {
        Path f = etc.resolve("org.apache.felix.http.cfg");
        Files.writeString(f, text);
        return f;
    }
}
