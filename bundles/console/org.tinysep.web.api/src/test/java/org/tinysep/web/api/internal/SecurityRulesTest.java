package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
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
        String ack = "/board/api/flats/flat-17/alerts/5/acknowledge";
        assertTrue(SecurityFilter.caregiverMay("POST", ack));
        for (String method : List.of("PUT", "DELETE", "PATCH")) {
            assertFalse(SecurityFilter.caregiverMay(method, ack), method);
        }
        for (String path : List.of(ack + "/x", "/board/api/flats/flat-17/alerts//acknowledge",
                "/board/api/flats/a/b/alerts/5/acknowledge", "/board/api/flats", "/board/", "/x" + ack)) {
            assertFalse(SecurityFilter.caregiverMay("POST", path), path);
        }
    }

    @Test
    void thePacketLogsNodeComesFromTheOrigin() {
        assertEquals("1.17", LogsApi.node("node 1.17 via udp 127.0.0.1:4000"));
        assertEquals("0014.4F01.0000.1234", LogsApi.node("node 0014.4F01.0000.1234 via serial"));
        assertEquals("1.20", LogsApi.node("node 1.20"));
        assertEquals("", LogsApi.node("BusRadioAmicaUdp"));
    }
}
