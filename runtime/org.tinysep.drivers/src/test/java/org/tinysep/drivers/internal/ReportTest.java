package org.tinysep.drivers.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;
import org.junit.jupiter.api.Test;

/** The console line of a drivers-list run: counts, not a dump of every bundle (issue 17 item 8). */
class ReportTest {

    @Test
    void summaryCountsTheChangesByKind() {
        List<String> changes = List.of("installed org.tinysep.amica.door", "installed org.tinysep.amica.window",
                "started org.tinysep.amica.door", "started org.tinysep.amica.window",
                "cannot start org.tinysep.broken: missing requirement", "missing org.tinysep.gone: no file x");
        assertEquals("2 installed, 2 started, 1 failed, 1 missing (tinysep:drivers lists them)",
                Report.summary(changes));
    }

    @Test
    void nothingChangedSaysSo() {
        assertEquals("nothing to do", Report.summary(List.of()));
    }
}
