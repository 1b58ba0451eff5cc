package org.tinysep.evaluation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * CI smoke test of the harness (issue 11): Ordonez Home A cut to its first two days, two collapses, both detectors,
 * through the real distribution. Asserts only that it runs and reports a plausible structure — never a tuned figure:
 * both detector columns, every collapse judged once, counts and shares within their ranges, every alert the platform
 * handed to its Mail Manager arrived at the SMTP sink.
 */
class EvaluationSmokeIT {

    private static final Path REPO = RepoFiles.root();

    @Test
    void shortWindowOfOrdonezAReportsBothDetectors() throws Exception {
        Path ordonez = RepoFiles.require("data", "ordonez");
        assertTrue(Files.isRegularFile(ordonez.resolve("OrdonezA_Sensors.txt")), "the repository's copy of Ordonez A");
        String dist = System.getProperty("tinysep.dist", REPO.resolve("runtime/org.tinysep.launcher/target/tinysep")
                .toString());
        EvalOptions o = EvalOptions.parse(new String[] {"A", "--days", "2", "--collapses", "2", "--batch", "2",
            "--no-readme", "--dist", dist, "--work", "target/smoke-work", "--ordonez", ordonez.toString()}, REPO);

        Evaluate.Outcome out = Evaluate.run(o);

        assertEquals(List.of("LEARNED", "THESIS"), List.copyOf(out.results().keySet()));
        for (Experiment.Result r : out.results().values()) {
            assertTrue(out.markdown().contains("`detector=" + r.detector() + "`"), out.markdown());
            assertEquals(2, r.collapses().size(), "every collapse judged: " + r.collapses());
            r.collapses().forEach(c -> assertTrue(c.outcome() != CollapseResult.Outcome.DETECTED
                    || !c.delay().isNegative() && c.delay().compareTo(CollapseResult.WINDOW) <= 0, c.toString()));
            TestHalfFigures t = r.test();
            assertTrue(t.alertsDay() >= 0 && t.alertsNight() >= 0 && t.days() > 0.5 && t.days() < 1.5, t.toString());
            assertTrue(t.blindShare() >= 0 && t.blindShare() <= 1, t.toString());
            double recall = t.occupancy().recall();
            assertTrue(Double.isNaN(recall) || recall >= 0 && recall <= 1, t.toString());
            assertTrue(r.handedOver() >= t.alertsDay() + t.alertsNight(), "every test-half alert handed over: " + r);
            assertEquals(r.handedOver(), r.mails(), "every alert handed on reached the SMTP sink as its first mail");
            assertTrue(!r.testRun().entries().isEmpty(), "the platform wrote its event log");
        }
    }
}
