package org.tinysep.itests.time;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.temporal.ChronoUnit;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerMethod;
import org.tinysep.api.device.Connection;
import org.tinysep.api.device.Driver;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.ClockMode;
import org.tinysep.api.service.TimeControllerProvider;
import org.tinysep.itests.SyncPeer;

/**
 * The thesis's time synchroniser protocol (5.4.3) over real UDP: each TICK runs every listener before its DONE
 * comes back; a virtual day of 86400 one-second ticks runs in seconds.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerMethod.class)
public class LockStepSyncTest extends TimeTestSupport {

    @Override
    String initialMode() {
        return "EXTERNAL";
    }

    @Test
    public void eachTickHasRunEveryListenerWhenItsDoneArrives() throws Exception {
        TimeControllerProvider clock = clock();
        assertEquals(ClockMode.EXTERNAL, clock.mode());
        List<Instant> heard = new CopyOnWriteArrayList<>();
        try (Connection c = clock.connect((source, now) -> heard.add(now)); SyncPeer sync = new SyncPeer(syncPort())) {
            Instant start = clock.now();
            String welcome = sync.ask("HELLO");
            assertTrue(welcome, welcome.matches("WELCOME " + start + " EXTERNAL [0-9a-f]{16}"));
            Thread.sleep(1100); // a real second passes: the held clock does not move (a check, not a timing)
            assertEquals(start, clock.now());
            assertEquals(List.of(), heard);

            Instant t = start.truncatedTo(ChronoUnit.SECONDS).plusSeconds(3600);
            for (int i = 0; i < 20; i++) {
                Instant at = t.plusSeconds(i);
                sync.tickDone(at);
                assertEquals("listener ran before DONE", at, heard.get(heard.size() - 1));
                assertEquals(at, clock.now());
            }
            assertEquals(20, heard.size());

            sync.tickDone(t.plusSeconds(19)); // equal: re-fires
            assertEquals(21, heard.size());
            Instant jump = t.plus(Duration.ofHours(5));
            sync.tickDone(jump); // a jump: one timeAdvanced with the new instant
            assertEquals(22, heard.size());
            assertTrue(sync.tick(t).startsWith("ERROR " + 23 + " backwards "));
            assertTrue(sync.ask("garbage").startsWith("ERROR - unknown-command "));
            // a local user without the key (issue 10.3): refused, the clock does not move
            assertTrue(sync.ask("TICK 99 " + jump.plusSeconds(60)).startsWith("ERROR 99 unauthorized "));
            assertTrue(sync.ask("TICK 100 " + jump.plusSeconds(60) + " " + "ab".repeat(32))
                    .startsWith("ERROR 100 unauthorized wrong HMAC"));
            assertEquals(jump, clock.now());
            assertEquals(22, heard.size());
            sync.tickDone(jump.plusSeconds(1));
            assertEquals(jump.plusSeconds(1), clock.now());

            Driver driver = awaitService(Driver.class, "(tinysep.driver.name=TimeController)", TIMEOUT);
            assertEquals("1", parameter(driver, "rejected.backwards"));
            assertEquals("1", parameter(driver, "rejected.unknown-command"));
            assertEquals("2", parameter(driver, "rejected.unauthorized"));
            assertEquals("23", parameter(driver, "ticks"));
        }
    }

    @Test
    public void aVirtualDayOf86400TicksRunsInSeconds() throws Exception {
        TimeControllerProvider clock = clock();
        AtomicLong calls = new AtomicLong();
        AtomicReference<Instant> last = new AtomicReference<>();
        try (Connection c = clock.connect((source, now) -> {
                    calls.incrementAndGet();
                    last.set(now);
                });
                SyncPeer sync = new SyncPeer(syncPort())) {
            Instant start = clock.now().truncatedTo(ChronoUnit.SECONDS).plusSeconds(1);
            long began = System.nanoTime();
            for (int i = 0; i < 86_400; i++) {
                Instant at = start.plusSeconds(i);
                String answer = sync.tick(at);
                if (!answer.startsWith("DONE ")) {
                    throw new AssertionError("tick " + i + " answered " + answer);
                }
            }
            long millis = (System.nanoTime() - began) / 1_000_000;
            System.out.printf("VIRTUAL DAY: 86400 lock-step ticks over UDP took %d ms wall time (%.1f us per tick),"
                    + " with every provisioned PlatformTicker user listening%n", millis, millis * 1000.0 / 86_400);
            log.info("Virtual day: 86400 ticks in {} ms", millis);
            assertEquals(86_400, calls.get());
            assertEquals(start.plusSeconds(86_399), last.get());
            assertEquals(start.plusSeconds(86_399), clock.now());
        }
    }

    private static String parameter(Driver driver, String key) {
        return driver.parameters().stream().filter(p -> p.key().equals(key)).map(Parameter::value).findFirst()
                .orElseThrow(() -> new AssertionError("no parameter " + key + " in " + driver.parameters()));
    }
}
