package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

class StartReportTest {

    @Test
    void bannerIsOneLinePlusOneLinePerFailure() {
        Map<String, Integer> active = new LinkedHashMap<>();
        active.put("1-boot", 6);
        active.put("5-apps", 4);
        StartReport report = new StartReport("0.1.0", Duration.ofMillis(1234), 5, true, active, 11,
                List.of(new StartReport.Failure("org.tinysep.door 0.1.0", "5-apps", "missing requirement x")));

        assertEquals(List.of(
                "TinySEP 0.1.0 up in 1.2 s (daemon, start level 5): 10/11 bundles active [1-boot 6, 5-apps 4] — 1 FAILED, see below",
                "  FAILED org.tinysep.door 0.1.0 (5-apps): missing requirement x"), report.lines());
    }

    @Test
    void noFailureNoSuffix() {
        StartReport report = new StartReport("0.1.0", Duration.ZERO, 1, false, Map.of("1-boot", 1), 1, List.of());
        assertEquals(List.of("TinySEP 0.1.0 up in 0.0 s (interactive, start level 1): 1/1 bundles active [1-boot 1]"),
                report.lines());
    }

    @Test
    void signalsOfTheStartAreWarningLinesUnderTheBanner() {
        StartReport report = new StartReport("0.1.0", Duration.ZERO, 5, true, Map.of("5-apps", 3), 3, List.of())
                .withWarnings(List.of("WARNING: the AmICA radio cannot listen on 127.0.0.1:47011 (Address already "
                        + "in use): no AmICA sensor is heard"));
        assertEquals(2, report.lines().size(), report.lines().toString());
        assertTrue(report.lines().get(0).contains("3/3 bundles active"));
        assertEquals("WARNING: the AmICA radio cannot listen on 127.0.0.1:47011 (Address already in use): no AmICA "
                + "sensor is heard", report.lines().get(1));
    }
}
