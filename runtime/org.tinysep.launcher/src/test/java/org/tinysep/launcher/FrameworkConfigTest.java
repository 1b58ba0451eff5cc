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
