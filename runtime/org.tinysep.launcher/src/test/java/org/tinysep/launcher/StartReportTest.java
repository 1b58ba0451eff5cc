package org.tinysep.launcher;

import static org.junit.jupiter.api.Assertions.assertEquals;

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
}
