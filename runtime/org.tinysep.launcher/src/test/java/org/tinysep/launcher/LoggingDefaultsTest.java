package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.logging.Level;
import java.util.logging.Logger;
import org.junit.jupiter.api.Test;

/** SPI Fly's INFO chatter (a line per JAXB plug-in) stays off the console; its warnings do not (issue 17 item 8). */
class LoggingDefaultsTest {

    @Test
    void spiFlyLogsWarningsOnlyUnlessAskedForMore() {
        LoggingDefaults.apply();
        Logger spifly = Logger.getLogger("org.apache.aries.spifly.BaseActivator");
        assertFalse(spifly.isLoggable(Level.INFO), "'Registered provider …' lines are INFO");
        assertTrue(spifly.isLoggable(Level.WARNING));
        assertEquals(Level.INFO, LoggingDefaults.julLevel("info"));
        assertEquals(Level.FINE, LoggingDefaults.julLevel("DEBUG"));
        assertEquals(Level.WARNING, LoggingDefaults.julLevel("nonsense"));
    }
}
