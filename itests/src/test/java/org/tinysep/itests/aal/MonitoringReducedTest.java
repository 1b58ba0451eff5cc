package org.tinysep.itests.aal;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.net.URI;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.osgi.framework.Bundle;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * Nothing switches monitoring off in silence (issue 25, item 3), on a real framework: disabling Inactivity
 * Recognition through the drivers list, or replacing its code, is a {@code PROBLEM} entry "Monitoring reduced: …"
 * and a notice mail to the caregiver (the Mail Manager on a real SMTP sink), through the alert service's notices.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class MonitoringReducedTest extends AalTestSupport {

    private static final String CARER = "carer@care.test";
    private static final String INACTIVITY = "org.tinysep.inactivity";

    @Override
    protected List<String> applications() {
        return plus(super.applications(), "org.tinysep.alerts");
    }

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = super.initialConfigurations();
        configs.put("org.tinysep.alerts", Map.of("summaryTime", "", "timeZone", "UTC"));
        return configs;
    }

    @Test
    public void disablingInactivityRecognitionThroughTheDriversListIsAProblemAndANoticeMail() throws Exception {
        try (SmtpSink sink = new SmtpSink().start()) {
            mailTo(sink, CARER);
            Bundle b = activeBundle(INACTIVITY);
            shell("tinysep:drivers use " + INACTIVITY + " \"" + Path.of(URI.create(b.getLocation())) + "\"");
            shell("tinysep:drivers disable " + INACTIVITY);
            awaitProblem("Monitoring reduced: Inactivity Recognition (" + INACTIVITY);
            assertTrue("a notice mailed to the caregiver", sink.await(1, TIMEOUT));
            SmtpSink.Received m = sink.messages().get(0);
            assertEquals(List.of(CARER), m.to());
            String subject = AlertEscalationTest.unfolded(m.data());
            assertTrue(subject, subject.startsWith("TinySEP watches less than it should: Inactivity Recognition"));
            assertTrue(m.data(), m.data().contains("What to do"));
            Thread.sleep(5_000); // a second poll: the notice is not repeated
            assertEquals("one notice, not repeated", 1, sink.messages().size());
        }
    }

    @Test
    public void replacingInactivityRecognitionsCodeIsAProblem() throws Exception {
        activeBundle(INACTIVITY).update();
        EventEntry e = awaitProblem("Monitoring reduced: Inactivity Recognition (" + INACTIVITY + ") was replaced");
        assertTrue(e.message(), e.message().contains("is no longer the one installed with TinySEP"));
    }

    private Bundle activeBundle(String bsn) {
        Bundle b = Stream.of(context.getBundles()).filter(x -> bsn.equals(x.getSymbolicName())).findFirst()
                .orElseThrow();
        await(TIMEOUT, () -> b.getState() == Bundle.ACTIVE, bsn + " active");
        return b;
    }

    private EventEntry awaitProblem(String start) {
        EventLog events = awaitService(EventLog.class, null, TIMEOUT);
        await(TIMEOUT, () -> events.recent(2_000).stream().anyMatch(e -> e.kind() == EventKind.PROBLEM
                && e.message().startsWith(start)), "a PROBLEM entry starting '" + start + "'");
        return events.recent(2_000).stream().filter(e -> e.message().startsWith(start)).findFirst().orElseThrow();
    }
}
