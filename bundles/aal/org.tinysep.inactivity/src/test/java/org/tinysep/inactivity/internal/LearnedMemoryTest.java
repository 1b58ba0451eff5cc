package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.EventLog;
import org.tinysep.inactivity.internal.learn.HistoryLearner;
import org.tinysep.inactivity.internal.learn.LearnedLimits;
import org.tinysep.inactivity.internal.learn.LearningSettings;
import org.tinysep.inactivity.internal.learn.Limit;
import org.tinysep.inactivity.internal.learn.Sighting;
import org.tinysep.inactivity.internal.learn.SleepRule;

/**
 * Issue 25, item 6: the learned detector's memory does not live only in the rotating event log. A home's ten days
 * of activity are in an event log that keeps its newest 2,000 entries (rotation, as on disk); the detector learns a
 * bathroom limit of 20 min and saves its memory; then 10,000 STATUS entries of a flapping node rotate the activity
 * away. After a restart the detector's limit is unchanged; a detector with only the event log is back at the fixed
 * 45 min (what happened on main).
 */
class LearnedMemoryTest {

    private static final LocalDate MONDAY = LocalDate.of(2026, 11, 2);
    private static final Map<String, String> ROOM_OF = Map.of("bath-motion", "Bathroom", "kitchen-motion", "Kitchen");

    @TempDir
    Path dir;

    /** An event log that keeps its newest {@code cap} entries, like the rotating files. */
    private static final class RotatingLog implements EventLog {
        private final Deque<EventEntry> entries = new ArrayDeque<>();
        private final int cap;
        private long seq;
        Instant time;

        RotatingLog(int cap) {
            this.cap = cap;
        }

        @Override
        public void record(EventKind kind, String origin, String message) {
            entries.addLast(new EventEntry(++seq, time, kind, origin, message));
            if (entries.size() > cap) {
                entries.removeFirst();
            }
        }

        @Override
        public List<EventEntry> recent(int max) {
            List<EventEntry> all = new ArrayList<>(entries);
            return all.subList(Math.max(0, all.size() - max), all.size());
        }
    }

    private static Instant at(int day, int hour, int minute) {
        return MONDAY.plusDays(day).atTime(hour, minute).toInstant(ZoneOffset.UTC);
    }

    /** A detector starting now: its learner, loaded from the log (and its memory), every logged device placed. */
    private static Limit start(EventLog log, LearnedMemory memory, Instant now, List<HistoryFromLog> keep) {
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, new SleepRule(21, 7, ZoneOffset.UTC),
                LearningSettings.defaults().withMinPeriodsToShorten(0));
        HistoryFromLog fromLog = new HistoryFromLog(learner);
        fromLog.load(log, now, 28, memory);
        fromLog.resolve(r -> Optional.of(new Sighting(r.at(), ROOM_OF.get(r.device()), ROOM_OF.get(r.device()),
                ROOM_OF.get(r.device()), false)));
        keep.add(fromLog);
        return new LearnedLimits(learner).limitAfter(new Sighting(now, "Bathroom", "Bathroom", "Bathroom", false),
                Duration.ofMinutes(45), now);
    }

    /** A log of {@code capacity} entries with ten days of movement: bathroom, then kitchen 5 min later, every 2 h. */
    private static RotatingLog tenDays(int capacity) {
        RotatingLog log = new RotatingLog(capacity);
        for (int day = 0; day < 10; day++) {
            for (int hour = 8; hour <= 18; hour += 2) {
                log.time = at(day, hour, 0);
                log.record(EventKind.DEVICE_EVENT, "bath-motion", "movement detected");
                log.time = at(day, hour, 5);
                log.record(EventKind.DEVICE_EVENT, "kitchen-motion", "movement detected");
            }
        }
        return log;
    }

    @Test
    void aFloodOfEventLogEntriesDoesNotMakeTheDetectorForget() throws IOException {
        RotatingLog log = tenDays(2000);
        Instant now = at(10, 14, 0);
        LearnedMemory memory = new LearnedMemory(dir.resolve("inactivity").resolve("learned-history.txt"));
        List<HistoryFromLog> detectors = new ArrayList<>();
        Limit learned = start(log, memory, now, detectors);
        assertEquals(Duration.ofMinutes(20), learned.limit(), learned.explanation());
        assertTrue(detectors.get(0).save(memory, now));
        assertTrue(Files.readString(memory.file()).startsWith(LearnedMemory.HEADER + "\ncovered\t" + now + "\n"));

        for (int i = 0; i < 10_000; i++) { // a flapping node: far more than the log keeps
            log.time = now.plusSeconds(i);
            log.record(EventKind.STATUS, "amica-node-1.17", i % 2 == 0 ? "status OFFLINE" : "status ONLINE");
        }
        assertTrue(log.recent(Integer.MAX_VALUE).stream().allMatch(e -> e.kind() == EventKind.STATUS),
                "the activity was rotated out of the event log");

        Instant later = now.plus(Duration.ofHours(4));
        Limit afterFlood = start(log, memory, later, detectors);
        assertEquals(learned.limit(), afterFlood.limit(), afterFlood.explanation());
        Limit logOnly = start(log, null, later, detectors);
        assertEquals(Duration.ofMinutes(45), logOnly.limit(), "with the event log alone it forgot: "
                + logOnly.explanation());
    }

    @Test
    void theMemoryKeepsWaitingEntriesAndReadsOnlyNewerLogEntries() throws IOException {
        RotatingLog log = new RotatingLog(100);
        log.time = at(0, 9, 0);
        log.record(EventKind.DEVICE_EVENT, "sofa\tseat", "seat on");
        HistoryLearner learner = new HistoryLearner(ZoneOffset.UTC, new SleepRule(21, 7, ZoneOffset.UTC),
                LearningSettings.defaults());
        HistoryFromLog first = new HistoryFromLog(learner);
        LearnedMemory memory = new LearnedMemory(dir.resolve("learned-history.txt"));
        assertTrue(!first.save(memory, at(0, 9, 0)), "nothing saved before the history was loaded");
        first.load(log, at(0, 10, 0), 28, memory);
        assertTrue(first.save(memory, at(0, 10, 0)));
        log.time = at(0, 11, 0);
        log.record(EventKind.DEVICE_EVENT, "bath-motion", "movement detected");

        HistoryFromLog second = new HistoryFromLog(new HistoryLearner(ZoneOffset.UTC,
                new SleepRule(21, 7, ZoneOffset.UTC), LearningSettings.defaults()));
        String said = second.load(log, at(0, 12, 0), 28, memory);
        assertTrue(said.contains("learning from its own memory (0 activities, saved at 2026-11-02T10:00:00Z) and the "
                + "event log's history since 2026-11-02T10:00:00.000000001Z: 1 activity entries"), said);
        List<HistoryFromLog.Raw> waiting = new ArrayList<>();
        second.resolve(r -> {
            waiting.add(r);
            return Optional.empty();
        });
        assertEquals(List.of(new HistoryFromLog.Raw(at(0, 9, 0), "sofa\tseat", false, true),
                new HistoryFromLog.Raw(at(0, 11, 0), "bath-motion", false, false)), waiting);

        Files.writeString(memory.file(), "something else\n");
        assertNull(memory.load(), "not such a file: ignored");
    }

    /** Issue 28 item 2: getting out of bed ("bed off") survives the memory, for sightings and waiting entries. */
    @Test
    void gettingUpFromBedSurvivesTheMemory() throws IOException {
        LearnedMemory memory = new LearnedMemory(dir.resolve("learned-history.txt"));
        Sighting up = new Sighting(at(0, 3, 0), "bedroom", "Bedroom", "Bedroom", false, false, true);
        HistoryFromLog.Raw waiting = new HistoryFromLog.Raw(at(0, 3, 0), "bed-mat", false, false, true);
        memory.save(new HistoryLearner.Memory(List.of(up), List.of(), null), List.of(waiting), at(0, 4, 0));
        LearnedMemory.Content c = memory.load();
        assertEquals(List.of(up), c.memory().sightings());
        assertEquals(List.of(waiting), c.pending());
        assertEquals(0, c.damaged());
    }

    /** Issue 28, session 33: a waiting flush OFF keeps the device of the activity before it across the memory. */
    @Test
    void aWaitingFlushOffKeepsTheDeviceBeforeIt() throws IOException {
        LearnedMemory memory = new LearnedMemory(dir.resolve("learned-history.txt"));
        HistoryFromLog.Raw flushOff = new HistoryFromLog.Raw(at(0, 1, 41), "flush", false, false, false,
                PresenceKind.FLUSH, "bed\tmat");
        HistoryFromLog.Raw plain = new HistoryFromLog.Raw(at(0, 1, 40), "bed\tmat", true, false);
        memory.save(new HistoryLearner.Memory(List.of(), List.of(), null), List.of(plain, flushOff), at(0, 4, 0));
        LearnedMemory.Content c = memory.load();
        assertEquals(List.of(plain, flushOff), c.pending());
        assertEquals(0, c.damaged());
    }

    /**
     * Issue 28, session 33: the platform stops after its Time Controller, so the clock when the memory is saved is
     * the wall clock, weeks behind the (virtual) times of the history it holds. Reading the log "after the save"
     * then handed the whole history to the learner a second time: on Ordonez B the platform's learned limits counted
     * 106–178 quiet periods where the core counts 84–94 (duplicates 0 s apart are quiet periods too), and shortened
     * limits the core does not. The memory covers the newest time it holds.
     */
    @Test
    void aMemorySavedWithTheClockBehindItsHistoryIsNotLearnedTwice() throws IOException {
        RotatingLog log = tenDays(10_000);
        Instant now = at(10, 14, 0);
        Instant wallBehind = at(-30, 12, 0);
        LearnedMemory memory = new LearnedMemory(dir.resolve("learned-history.txt"));
        List<HistoryFromLog> detectors = new ArrayList<>();
        Limit first = start(log, memory, now, detectors);
        assertTrue(detectors.get(0).save(memory, wallBehind));
        int remembered = memory.load().memory().sightings().size();
        assertTrue(memory.load().covered().equals(now), "covers the newest it holds: " + memory.load().covered());

        Limit restarted = start(log, memory, now, detectors);
        assertEquals(first.explanation(), restarted.explanation(), "the same history, learned once");
        assertTrue(detectors.get(1).save(memory, wallBehind));
        assertEquals(remembered, memory.load().memory().sightings().size(), "120 logged and the live one, once");
    }
}
