package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

class SecurityRulesTest {

    @Test
    void theCaregiverMayOnlyAcknowledgeAlerts() {
        assertTrue(SecurityFilter.caregiverMay("POST", "/api/alerts/a-1/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("DELETE", "/api/alerts/a-1/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/api/alerts/a-1/acknowledge/x"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/api/rooms"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/api/applications"));
    }

    @Test
    void theCaregiverMayAcknowledgeOnTheCentralBoardAndNothingElseThere() {
        assertTrue(SecurityFilter.caregiverMay("POST", "/board/api/flats/flat-17/alerts/5/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("PUT", "/board/api/flats/flat-17/alerts/5/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("DELETE", "/board/api/flats/flat-17/alerts/5/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/board/api/flats/flat-17/alerts/5/acknowledge/x"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/board/api/flats/flat-17/alerts//acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/board/api/flats/a/b/alerts/5/acknowledge"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/board/api/flats"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/board/"));
        assertFalse(SecurityFilter.caregiverMay("POST", "/x/board/api/flats/17/alerts/5/acknowledge"));
    }

    @Test
    void thePacketLogsNodeComesFromTheOrigin() {
        assertEquals("1.17", LogsApi.node("node 1.17 via udp 127.0.0.1:4000"));
        assertEquals("0014.4F01.0000.1234", LogsApi.node("node 0014.4F01.0000.1234 via serial"));
        assertEquals("1.20", LogsApi.node("node 1.20"));
        assertEquals("", LogsApi.node("BusRadioAmicaUdp"));
    }
}
