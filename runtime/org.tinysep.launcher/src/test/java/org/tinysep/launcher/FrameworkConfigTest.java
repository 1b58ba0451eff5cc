package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

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
        assertEquals("/opt/tinysep", p.get("tinysep.home"));
        assertEquals("false", p.get("felix.bootdelegation.implicit"));
        assertFalse(p.containsKey("gosh.args"));
    }

    @Test
    void daemonKeepsGogoNonInteractive() {
        assertEquals("--nointeractive", FrameworkConfig.properties(HOME, true, 5).get("gosh.args"));
    }
}
