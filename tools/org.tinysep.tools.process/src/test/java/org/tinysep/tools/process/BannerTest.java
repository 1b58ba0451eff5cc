package org.tinysep.tools.process;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import org.junit.jupiter.api.Test;

class BannerTest {

    @Test
    void readsTheFiguresOfTheLaunchersBanner() {
        Banner b = Banner.parse("TinySEP 0.1.0-SNAPSHOT up in 0.9 s (daemon, start level 6): 41/41 bundles active"
                + " [1-core 12, 2-drivers 2, 5-apps 27]", 950.0, Duration.ofMillis(1700)).orElseThrow();
        assertEquals("0.1.0-SNAPSHOT", b.version());
        assertEquals(0.9, b.upSeconds());
        assertEquals("daemon", b.mode());
        assertEquals(41, b.active());
        assertEquals(0, b.failed());
        assertTrue(b.allActive());
        assertEquals(1700.0, b.cpuMs());
    }

    @Test
    void countsFailedBundles() {
        Banner b = Banner.parse("TinySEP 1.0 up in 2.0 s (interactive, start level 6): 39/41 bundles active [1-core"
                + " 12] — 2 FAILED, see below", 1, null).orElseThrow();
        assertEquals(2, b.failed());
        assertFalse(b.allActive());
        assertTrue(Double.isNaN(b.cpuMs()));
    }

    @Test
    void aPromptBeforeTheBannerIsNotPartOfIt() {
        Banner b = Banner.parse("g! TinySEP 1.0 up in 2.0 s (interactive, start level 6): 41/41 bundles active [1-core"
                + " 12]", 1, null).orElseThrow();
        assertEquals("TinySEP 1.0 up in 2.0 s (interactive, start level 6): 41/41 bundles active [1-core 12]",
                b.line());
    }

    @Test
    void otherLinesAreNoBanner() {
        assertFalse(Banner.is("Web console: http://127.0.0.1:8080/ (up 0.4 s after the banner) - admin"));
        assertFalse(Banner.is("  FAILED org.tinysep.mqtt (5-apps): bundles active"));
    }
}
