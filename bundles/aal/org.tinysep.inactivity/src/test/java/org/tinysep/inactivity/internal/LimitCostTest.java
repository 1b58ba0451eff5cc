package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import java.time.ZoneOffset;
import java.time.ZonedDateTime;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.AllocationMeter;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 29, item 1: the limit of a movement report's quiet period, found per report on the radio's delivery thread.
 * The THESIS detector built its explanation's words per report (only a reader needs them: made once per room now);
 * the LEARNED detector's cache asked a region's zone rules for the offset per report (a local date and a boxed year
 * each time: kept until the zone's next transition now).
 */
class LimitCostTest {

    private static final ZoneId HOME = ZoneId.of("Europe/Zurich");
    private static final Instant T0 = Instant.parse("2026-11-23T09:00:00Z");
    private static final Duration FORTY_FIVE = Duration.ofMinutes(45);

    @Test
    void theThesisWordsAreMadeOncePerRoomNotPerReport() {
        LimitPolicy thesis = LimitPolicy.thesis();
        Limit first = thesis.limitAfter(bath(T0), FORTY_FIVE, T0);
        Limit next = thesis.limitAfter(bath(T0.plusSeconds(1)), FORTY_FIVE, T0.plusSeconds(1));
        assertEquals(new Limit(FORTY_FIVE, false, "fixed limit of 45 min for Bathroom (detector THESIS)"), first);
        assertSame(first.explanation(), next.explanation(), "the explanation is made once per room, not per report");
        Sighting s = bath(T0.plusSeconds(2));
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> thesis.limitAfter(s, FORTY_FIVE, T0));
        assertTrue(bytes < 8, "bytes allocated per THESIS limit of a report: " + bytes);
        assertEquals("fixed limit of 30 min for Bathroom (detector THESIS)",
                thesis.limitAfter(s, Duration.ofMinutes(30), T0).explanation(), "a changed fixed limit: new words");
        assertEquals("fixed limit of 30 min for Kitchen (detector THESIS)", thesis.limitAfter(new Sighting(T0,
                "r-k", "Kitchen", "Kitchen", false), Duration.ofMinutes(30), T0).explanation());
    }

    @Test
    void aLearnedLimitInARegionsZoneAllocatesNothingPerReport() {
        CachedLimits cached = new CachedLimits(new LearnedLimits(new HistoryLearner(HOME, new SleepRule(21, 7, HOME),
                LearningSettings.defaults())));
        Sighting[] reports = new Sighting[40_001]; // made before: the reports are no cost of their limit
        for (int k = 0; k < reports.length; k++) {
            reports[k] = bath(T0.plusMillis(100L * k));
        }
        Limit first = cached.limitAfter(reports[0], FORTY_FIVE, T0);
        int[] i = {1};
        double bytes = AllocationMeter.bytesPerCall(20_000, () -> {
            Sighting s = reports[i[0]++];
            cached.limitAfter(s, FORTY_FIVE, s.at());
        });
        assertTrue(bytes < 8, "bytes allocated per learned limit of a report (Europe/Zurich): " + bytes);
        assertEquals(first, cached.limitAfter(reports[40_000], FORTY_FIVE, reports[40_000].at()), "an hour later");
    }

    @Test
    void theKeptOffsetTurnsWithTheClocksAlsoForLateReports() {
        CachedLimits cached = new CachedLimits(new LearnedLimits(new HistoryLearner(HOME, new SleepRule(21, 7, HOME),
                LearningSettings.defaults())));
        List<Instant> times = new ArrayList<>();
        for (Instant change : List.of(ZonedDateTime.of(2026, 3, 29, 1, 0, 0, 0, ZoneOffset.UTC).toInstant(),
                ZonedDateTime.of(2026, 10, 25, 1, 0, 0, 0, ZoneOffset.UTC).toInstant())) {
            for (long s = -7_200; s <= 7_200; s += 37) {
                times.add(change.plusSeconds(s).plusMillis(s % 1000 == 0 ? 0 : 999));
            }
            times.add(change);
            times.add(change.minusNanos(1));
        }
        List<Instant> late = new ArrayList<>(times);
        Collections.shuffle(late, new Random(29));
        times.addAll(late);
        for (ZoneId zone : List.of(HOME, ZoneOffset.UTC, ZoneId.of("America/St_Johns"))) {
            for (Instant t : times) {
                assertEquals(t.atZone(zone).toLocalDateTime().toEpochSecond(ZoneOffset.UTC),
                        cached.localSeconds(t, zone), zone + " at " + t);
            }
        }
    }

    private static Sighting bath(Instant at) {
        return new Sighting(at, "r-bath", "Bathroom", "Bathroom", false);
    }
}
