package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.nio.file.attribute.FileTime;
import java.time.Clock;
import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.EventEntry;
import org.tinysep.api.log.EventKind;
import org.tinysep.api.log.LogHistory;
import org.tinysep.api.log.LogQuery;

class PersistentLogTest {

    static final Instant NOW = Instant.parse("2026-11-22T12:00:00Z");
    static final Clock CLOCK = Clock.fixed(NOW, ZoneOffset.UTC);

    @TempDir
    Path dir;

    private PersistentLog<EventEntry> log;
    private RingBuffer<EventEntry> ring;

    @AfterEach
    void close() {
        if (log != null) {
            log.close();
        }
    }

    private LogSettings settings(long maxBytes, int maxFiles, Duration maxAge) {
        return new LogSettings(dir, maxBytes, maxFiles, maxAge, Duration.ofMillis(50));
    }

    private void open(int capacity, LogSettings settings) throws IOException {
        ring = new RingBuffer<>(capacity);
        log = PersistentLog.open(ring, new EventLines(), "events", settings, CLOCK, true);
    }

    /**
     * Appends like EventLogService.record: entry seq at NOW - (10000 - seq) s, origin dev-(seq % 3). Flushes every
     * 10 entries: a burst bigger than the ring, faster than the writer, would lose entries from the files (the
     * ring never blocks its caller), which {@link #aBurstBiggerThanTheRingIsCountedAsSkipped} shows.
     */
    private void append(int n) {
        long first = ring.lastSequence() + 1;
        for (int i = 0; i < n; i++) {
            long seq = first + i;
            ring.append(s -> new EventEntry(s, NOW.minusSeconds(10_000 - seq), seq % 2 == 0 ? EventKind.DEVICE_EVENT
                    : EventKind.STATUS, "dev-" + (seq % 3), "entry " + seq + "\twith tab"));
            log.signal(seq);
            if (i % 10 == 9) {
                log.flush();
            }
        }
        log.flush();
    }

    private List<Path> files() {
        return new LogFolder(dir, "events").files();
    }

    @Test
    void entriesAreWrittenOffTheCallersThreadAndReadBack() throws IOException {
        open(100, LogSettings.in(dir));
        append(50);
        List<String> lines = Files.readAllLines(files().get(0));
        assertEquals(50, lines.size());
        assertEquals(new EventLines().encode(ring.newest(50).get(0)), lines.get(0));
        LogHistory<EventEntry> h = log.query(e -> true, 10);
        assertEquals(41, h.entries().get(0).sequence());
        assertEquals(50, h.matched());
        assertEquals(0, h.damagedLines());
    }

    @Test
    void rotationKeepsEachFileUnderTheBoundAndAtMostMaxFiles() throws IOException {
        // no share per origin (OriginShare, FloodHistoryTest): the files alone
        open(10_000, new LogSettings(dir, 1024, 4, Duration.ZERO, Duration.ofMillis(50), 0, 1));
        append(200); // ~75 bytes a line: ~14 per file, 15 files written, 4 kept
        List<Path> files = files();
        assertEquals(4, files.size(), files.toString());
        for (Path f : files) {
            assertTrue(Files.size(f) <= 1024, f + " " + Files.size(f));
        }
        List<EventEntry> kept = log.query(e -> true, 10_000).entries();
        assertEquals(200, kept.get(kept.size() - 1).sequence(), "the newest entry is kept");
        long first = kept.get(0).sequence();
        assertTrue(first > 1, "the oldest files were deleted");
        assertEquals(201 - first, kept.size(), "no gaps in what is kept");
        assertEquals(String.format("events-%020d.log", first), files.get(0).getFileName().toString());
    }

    @Test
    void retentionDeletesFilesLastWrittenBeforeTheMaximumAge() throws IOException {
        open(10_000, settings(1024, 100, Duration.ofDays(7)));
        append(60);
        List<Path> files = files();
        assertTrue(files.size() >= 3, files.toString());
        Files.setLastModifiedTime(files.get(0), FileTime.from(NOW.minus(Duration.ofDays(8))));
        Files.setLastModifiedTime(files.get(1), FileTime.from(NOW.minus(Duration.ofDays(6))));
        append(40); // a rotation prunes
        List<Path> after = files();
        assertTrue(!after.contains(files.get(0)), "8 days old: deleted " + after);
        assertTrue(after.contains(files.get(1)), "6 days old: kept " + after);
    }

    @Test
    void damagedLinesAreSkippedAndCountedNeverStopTheQuery() throws IOException {
        open(100, LogSettings.in(dir));
        append(10);
        log.close();
        Path f = files().get(0);
        List<String> lines = Files.readAllLines(f);
        lines.set(2, "this is not a log line");
        lines.set(5, lines.get(5).replace("\t6\t", "\tsix\t"));
        lines.add(7, "\u0000\u0000\u0000");
        Files.write(f, lines);
        Files.writeString(f, "2026-11-22T11:", StandardOpenOption.APPEND); // torn by a crash, no line feed
        open(100, LogSettings.in(dir));
        assertEquals(3, log.loadedDamaged(), "the torn last line is not counted: it may be in progress");
        assertEquals(8, ring.size(), "the other 8 entries are back");
        assertEquals(10, ring.lastSequence());
        append(1); // the writer ends the torn line first: the new entry starts on its own line
        LogHistory<EventEntry> h = log.query(e -> true, 100);
        assertEquals(9, h.entries().size());
        assertEquals(4, h.damagedLines(), "the torn line now ends with a line feed: damaged");
        assertEquals(11, h.entries().get(8).sequence());
    }

    @Test
    void afterARestartTheRingHoldsTheHistoryAndNumberingGoesOn() throws IOException {
        open(30, settings(1024, 100, Duration.ZERO));
        append(100);
        log.close();
        open(30, settings(1024, 100, Duration.ZERO));
        assertEquals(30, ring.size());
        assertEquals(71, ring.newest(30).get(0).sequence());
        assertEquals(100, ring.lastSequence());
        append(1);
        assertEquals(101, ring.newest(1).get(0).sequence());
        assertEquals(101, log.query(e -> true, 1000).matched(), "nothing written twice");
    }

    @Test
    void queriesFilterByTimeOriginAndKindNewestLast() throws IOException {
        open(10_000, settings(1024, 100, Duration.ZERO));
        append(300);
        Instant from = NOW.minusSeconds(10_000 - 101);
        Instant to = NOW.minusSeconds(10_000 - 200);
        LogQuery q = new LogQuery(from, to, Set.of("dev-1"), Set.of("DEVICE_EVENT"), 5);
        LogHistory<EventEntry> h = log.query(q::matches, q.limit());
        // seq 101..200, seq % 3 == 1 and even: 4, 10, 16 ... i.e. seq % 6 == 4
        List<Long> expected = java.util.stream.LongStream.rangeClosed(101, 200).filter(s -> s % 6 == 4).boxed()
                .toList();
        assertEquals(expected.size(), h.matched());
        assertEquals(expected.subList(expected.size() - 5, expected.size()),
                h.entries().stream().map(EventEntry::sequence).toList());
    }

    @Test
    void aBurstBiggerThanTheRingIsCountedAsSkipped() throws IOException {
        open(5, LogSettings.in(dir));
        for (int i = 0; i < 1000; i++) { // the writer cannot keep up with 1000 appends into a ring of 5
            log.signal(ring.append(s -> new EventEntry(s, NOW, EventKind.STATUS, "o", "m")).sequence());
        }
        log.flush();
        long written = log.query(e -> true, 10_000).matched();
        assertEquals(1000, written + log.skipped(), "every entry is either written or counted as skipped");
    }

    /** Issue 29, idle: the writer thread is not woken for a sync while nothing was written. */
    @Test
    void anIdleLogWakesItsWriterOnlyToSyncWhatWasWritten() throws IOException, InterruptedException {
        open(100, settings(1 << 20, 5, Duration.ofDays(1)));
        assertEquals(1, log.waitingTasks(), "idle: only the hourly prune waits, no sync every 50 ms");
        append(3);
        long deadline = System.nanoTime() + 10_000_000_000L;
        while (log.waitingTasks() > 1 && System.nanoTime() < deadline) {
            Thread.sleep(10); // the sync is due 50 ms after the write
        }
        assertEquals(1, log.waitingTasks(), "after its sync the writer waits for the prune only");
    }
}
