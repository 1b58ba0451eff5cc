package org.tinysep.device.support.time;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class TickGateTest {

    private static final Instant T0 = Instant.parse("2026-11-30T04:00:00Z");

    private final List<Instant> called = new ArrayList<>();

    private TickGate gate(Instant asks) {
        return new TickGate(now -> {
            called.add(now);
            return asks;
        });
    }

    private static void ticks(TickGate g, int from, int to) {
        for (int s = from; s <= to; s++) {
            g.tick(T0.plusSeconds(s));
        }
    }

    @Test
    void aComponentWithNothingDueIsCalledOnceOverAnHourOfTicks() {
        TickGate g = gate(null);
        ticks(g, 0, 3600);
        assertEquals(List.of(T0), called, "only the first tick (it learns there is nothing due)");
    }

    @Test
    void aComponentIsCalledAtTheFirstTickAtOrAfterItsDueTime() {
        TickGate g = new TickGate(now -> {
            called.add(now);
            return now.plusSeconds(30).plusMillis(500);
        });
        ticks(g, 0, 40);
        assertEquals(List.of(T0, T0.plusSeconds(31)), called);
    }

    @Test
    void aWakeUpBringsTheNextCallForward() {
        TickGate g = gate(null);
        ticks(g, 0, 9);
        g.wake(T0.plusSeconds(12));
        ticks(g, 10, 20);
        assertEquals(List.of(T0, T0.plusSeconds(12)), called);
    }

    @Test
    void aWakeUpDuringTheCallIsKeptBesideWhatTheCallAsked() {
        TickGate[] g = new TickGate[1];
        g[0] = new TickGate(now -> {
            called.add(now);
            if (called.size() == 1) {
                g[0].wake(now.plusSeconds(5)); // an event on another thread, while this tick runs
            }
            return now.plusSeconds(3600);
        });
        ticks(g[0], 0, 10);
        assertEquals(List.of(T0, T0.plusSeconds(5)), called);
    }

    @Test
    void theClockGoingBackOrChangingModeAlwaysReachesTheComponent() {
        TickGate g = gate(T0.plusSeconds(3600));
        ticks(g, 0, 5);
        g.tick(T0.minusSeconds(100)); // virtual time, then real time again
        g.next();
        g.tick(T0.minusSeconds(99));
        g.tick(T0.minusSeconds(98));
        assertEquals(List.of(T0, T0.minusSeconds(100), T0.minusSeconds(99)), called);
    }

    @Test
    void aTimeNotAfterNowMeansEveryTickAsThePlainTicker() {
        TickGate g = new TickGate(now -> {
            called.add(now);
            return now;
        });
        ticks(g, 0, 9);
        assertEquals(10, called.size());
        assertEquals(10, g.calls());
    }

    @Test
    void aCallThatThrowsIsTriedAgainAtTheNextTick() {
        TickGate g = new TickGate(now -> {
            called.add(now);
            throw new IllegalStateException("broken");
        });
        for (int s = 0; s < 3; s++) {
            try {
                g.tick(T0.plusSeconds(s));
            } catch (IllegalStateException expected) {
                // the ticker logs it
            }
        }
        assertEquals(3, called.size());
    }
}
