package org.tinysep.itests.time;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.HashMap;
import java.util.Map;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.SyncPeer;

/**
 * Issue 17.5: after the synchroniser has gone the platform does not stay frozen. In EXTERNAL mode with a short
 * {@code syncTimeout}, the clock returns to REAL by itself once no TICK has come for that long, says why in the
 * event log, and leaves the configured mode as it was; a TICK then is refused as {@code not-external}.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class SyncTimeoutTest extends TimeTestSupport {

    @Override
    String initialMode() {
        return "EXTERNAL";
    }

    @Test
    public void externalTimeEndsWhenTheSynchroniserFallsSilent() throws Exception {
        TimeControllerProvider clock = clock();
        assertEquals(ClockMode.EXTERNAL, clock.mode());
        try (SyncPeer sync = new SyncPeer(syncPort())) {
            Instant virtual = clock.now().truncatedTo(ChronoUnit.SECONDS).plus(Duration.ofDays(1));
            sync.tickDone(virtual);
            Map<String, Object> config = new HashMap<>(config("EXTERNAL"));
            config.put("syncTimeout", "2");
            configure(TIME_PID, config); // in place: same port and key file
            await(TIMEOUT, () -> clock.mode() == ClockMode.REAL, "REAL after 2 s without a TICK");
            assertTrue("back to the system clock", Duration.between(clock.now(), Instant.now()).abs().toSeconds() < 2);
            EventLog log = awaitService(EventLog.class, null, TIMEOUT);
            assertTrue(log.recent(50).toString(), log.recent(50).stream().anyMatch(e -> e.message().contains(
                    "clock switched to REAL (no TICK from the time synchroniser for 2 s (syncTimeout)")));
            assertEquals("the configured mode stays", "EXTERNAL", admin().getConfiguration(TIME_PID, "?")
                    .getProperties().get("mode"));
            assertTrue(sync.tick(virtual.plusSeconds(1)).startsWith("ERROR 2 not-external "));
        }
    }

    private org.osgi.service.cm.ConfigurationAdmin admin() {
        return awaitService(org.osgi.service.cm.ConfigurationAdmin.class, null, TIMEOUT);
    }
}
