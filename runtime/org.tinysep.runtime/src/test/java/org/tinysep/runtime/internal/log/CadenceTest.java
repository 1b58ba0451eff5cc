package org.tinysep.runtime.internal.log;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Clock;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.ScheduledThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.tinysep.api.log.Direction;
import org.tinysep.api.log.PacketEntry;
import org.tinysep.runtime.internal.Threads;

/**
 * Issue 29, item 1: the packet log's writer runs on its own beat while frames come, so a bus radio's receive
 * thread hands it nothing per frame (before: each frame after a pause longer than the 50 ms write delay scheduled
 * a task on the writer and woke its thread, ~100 µs of the receive thread's CPU on this machine).
 */
class CadenceTest {

    static final Instant NOW = Instant.parse("2026-11-22T12:00:00Z");
    static final Clock CLOCK = Clock.fixed(NOW, ZoneOffset.UTC);

    @TempDir
    Path dir;

    private final WriterThread thread = new WriterThread(Thread.currentThread());
    private final RingBuffer<PacketEntry> ring = new RingBuffer<>(1000);
    private PersistentLog<PacketEntry> log;

    /** The writer thread, counting the tasks the recording (test) thread hands it. */
    static final class WriterThread extends ScheduledThreadPoolExecutor {
        final Thread recorder;
        final AtomicInteger fromRecorder = new AtomicInteger();

        WriterThread(Thread recorder) {
            super(1, Threads.named("test-packets-writer"));
            this.recorder = recorder;
        }

        @Override
        public ScheduledFuture<?> schedule(Runnable command, long delay, TimeUnit unit) {
            if (Thread.currentThread() == recorder) {
                fromRecorder.incrementAndGet();
            }
            return super.schedule(command, delay, unit);
        }
    }

    @AfterEach
    void close() {
        if (log != null) {
            log.close();
        }
    }

    private void open(long beatMillis) throws IOException {
        log = PersistentLog.open(ring, new PacketLines(), "packets", LogSettings.in(dir), CLOCK, false, beatMillis,
                thread);
    }

    private void record(int i) {
        byte[] frame = {4, (byte) i};
        log.signal(ring.append(s -> new PacketEntry(s, NOW, Direction.RECEIVED, "node 1.17", frame, "")).sequence());
    }

    /** @return the packet lines in the files once there are {@code n} (or after 5 s) */
    private long linesWhen(long n) throws IOException, InterruptedException {
        long lines = 0;
        for (int wait = 0; wait < 100 && lines < n; wait++) {
            Thread.sleep(50);
            lines = 0;
            for (Path f : new LogFolder(dir, "packets").files()) {
                lines += Files.readAllLines(f).size();
            }
        }
        return lines;
    }

    @Test
    void aTrickleOfFramesHandsTheWriterNothingFromTheReceiveThread() throws Exception {
        open(500);
        for (int i = 0; i < 20; i++) {
            record(i);
            Thread.sleep(60); // slower than the 50 ms write delay: before, every frame woke the writer
        }
        // the first frame starts the beat; a second start only if this thread stalled for more than 4 beats (2 s)
        assertTrue(thread.fromRecorder.get() <= 2, "tasks handed to the writer by the receive thread for 20"
                + " frames: " + thread.fromRecorder.get());
        assertEquals(20, linesWhen(20), "every frame reaches the file on the beat, without a flush");
    }

    @Test
    void afterAPauseTheNextFrameStartsTheBeatAgain() throws Exception {
        open(100);
        record(1);
        assertEquals(1, linesWhen(1));
        for (int wait = 0; wait < 100 && log.beating(); wait++) {
            Thread.sleep(50); // the beat stops after its empty rounds
        }
        assertTrue(!log.beating(), "the beat stopped after " + PersistentLog.IDLE_BEATS + " empty rounds");
        record(2);
        assertEquals(2, thread.fromRecorder.get(), "the frame after the pause started the beat again");
        assertEquals(2, linesWhen(2));
    }

    @Test
    void aBurstWakesTheWriterBeforeItsBeatSoTheRingIsNotOverwritten() throws Exception {
        open(60_000); // a beat far beyond the test: only the burst's wake-up can write in time
        for (int i = 0; i < 900; i++) { // nearly the ring's 1000: the writer must start at a quarter
            record(i);
        }
        assertEquals(900, linesWhen(900), "written before the beat");
        assertEquals(0, log.skipped());
        assertTrue(thread.fromRecorder.get() <= 1 + 900 / 250, "one wake-up per quarter ring at most: "
                + thread.fromRecorder.get());
    }
}
