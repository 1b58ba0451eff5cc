package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Map;
import org.junit.jupiter.api.Test;

class FrameworkConfigTest {

    private static final Path HOME = Path.of("/opt/tinysep");

    @Test
    void cacheEtcAndStartLevelLiveUnderHome() {
        Map<String, String> p = FrameworkConfig.properties(HOME, false, 5);
        assertEquals("/opt/tinysep/var/felix-cache", p.get("org.osgi.framework.storage"));
        assertEquals("onFirstInit", p.get("org.osgi.framework.storage.clean"));
        assertEquals("5", p.get("org.osgi.framework.startlevel.beginning"));
        assertEquals("/opt/tinysep/etc", p.get("felix.fileinstall.dir"));
        // issue 25, item 8: FileInstall's working folder lies in the state folder, not a new one in /tmp per start
        assertTrue(p.get("felix.fileinstall.tmpdir").startsWith(p.get("tinysep.var") + "/tmp/"),
                p.get("felix.fileinstall.tmpdir"));
        assertEquals("/opt/tinysep", p.get("tinysep.home"));
        assertEquals("false", p.get("felix.bootdelegation.implicit"));
        assertFalse(p.containsKey("gosh.args"));
        assertEquals("/opt/tinysep/var", p.get("tinysep.var"));
    }

    @Test
    void stateFolderHoldsTheCacheWhenMovedOutOfHome() {
        Map<String, String> p = FrameworkConfig.properties(HOME, Path.of("/data/tinysep"), false, 5);
        assertEquals("/data/tinysep", p.get("tinysep.var"));
        assertEquals("/data/tinysep/felix-cache", p.get("org.osgi.framework.storage"));
        assertEquals("onFirstInit", p.get("org.osgi.framework.storage.clean"));
        assertEquals("/opt/tinysep", p.get("tinysep.home"));
    }

    /** Issue 29: Jetty binds once, where etc/org.apache.felix.http.cfg says, not at 8080 first. */
    @Test
    void theWebConsolesAddressComesFromItsCfgFile(@org.junit.jupiter.api.io.TempDir Path home) throws Exception {
        Map<String, String> none = FrameworkConfig.properties(home, false, 5);
        assertEquals("127.0.0.1", none.get("org.apache.felix.http.host"));
        assertEquals("8080", none.get("org.osgi.service.http.port"));
        java.nio.file.Files.createDirectories(home.resolve("etc"));
        java.nio.file.Files.writeString(home.resolve("etc/org.apache.felix.http.cfg"),
                "# comment\norg.apache.felix.http.host=192.168.1.20\norg.osgi.service.http.port=18080\n");
        Map<String, String> p = FrameworkConfig.properties(home, false, 5);
        assertEquals("192.168.1.20", p.get("org.apache.felix.http.host"));
        assertEquals("18080", p.get("org.osgi.service.http.port"));
        java.nio.file.Files.writeString(home.resolve("etc/org.apache.felix.http.cfg"),
                "org.apache.felix.http.host=${my.host}\norg.osgi.service.http.port=eighty\n");
        Map<String, String> substituted = FrameworkConfig.properties(home, false, 5);
        assertEquals("127.0.0.1", substituted.get("org.apache.felix.http.host"), "left to FileInstall");
        assertEquals("8080", substituted.get("org.osgi.service.http.port"));
    }

    /** Issue 25, item 8: Jetty's own 400 pages carry the console's security headers (WebErrorPagesTest sees them). */
    @Test
    void jettysOwnErrorPagesGetTheSecurityHeaders() {
        String headers = FrameworkConfig.properties(HOME, false, 5).get("org.apache.felix.http.jetty.errorPageCustomHeaders");
        assertEquals("[Content-Security-Policy, X-Content-Type-Options, X-Frame-Options, Referrer-Policy, Cache-Control]",
                java.util.Arrays.stream(headers.split("##")).map(h -> h.substring(0, h.indexOf('='))).toList().toString());
        assertTrue(headers.contains("frame-ancestors 'none'##X-Content-Type-Options=nosniff##X-Frame-Options=DENY"), headers);
    }

    @Test
    void daemonKeepsGogoNonInteractive() {
        assertEquals("--nointeractive", FrameworkConfig.properties(HOME, true, 5).get("gosh.args"));
    }
}
