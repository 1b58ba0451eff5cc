package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class AlertRouteTest {

    @Test
    void mailedAlertsAreStatedAndAnythingElseIsAWarning() {
        assertEquals("Alerts: alerts are mailed through smtp.example:25 to a@b",
                AlertRoute.describe("smtp", "alerts are mailed through smtp.example:25 to a@b"));
        assertEquals("WARNING: alerts: no SMTP host configured: alerts are only written to the log",
                AlertRoute.describe("none", "no SMTP host configured: alerts are only written to the log"));
        assertEquals("WARNING: alerts: mail \"x\" NOT delivered; alerts are mailed through h:25 to a@b",
                AlertRoute.describe("smtp", "mail \"x\" NOT delivered; alerts are mailed through h:25 to a@b"));
    }
}
