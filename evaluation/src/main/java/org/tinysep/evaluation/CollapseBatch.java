package org.tinysep.evaluation;

import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

/**
 * One platform process for a batch of collapses: window k is replayed {@code k * step} days later in virtual time
 * than its recorded day + the shift, so that the windows follow each other in the platform's time; each window's
 * alerts are then judged against its collapse.
 *
 * @param setup     the platforms' distribution and configuration
 * @param shiftDays recorded → virtual days (whole weeks)
 */
record CollapseBatch(PlatformRun.Setup setup, long shiftDays) {

    /**
     * @param state     the snapshot's state folder every platform starts from a copy of
     * @param dir       this platform's folder
     * @param first     the number of the batch's first collapse (for the output)
     * @param extraDays how much later than recorded the fold's test days are replayed
     * @param drops     adds the datagrams the kernel dropped
     */
    List<CollapseResult> run(Path state, Path dir, String detector, List<CollapseWindow> batch, int first, long step,
            long extraDays, AtomicLong drops) throws Exception {
        Snapshot.delete(dir);
        List<PlatformRun.Segment> segments = new ArrayList<>();
        for (int k = 0; k < batch.size(); k++) {
            CollapseWindow w = batch.get(k);
            segments.add(new PlatformRun.Segment(w.events(), virtualDay(w, extraDays + k * step), w.end()));
        }
        long wall = System.nanoTime();
        PlatformRun.Outcome r = PlatformRun.run(setup, state, dir, detector, segments);
        drops.addAndGet(Math.max(0, r.kernelDrops()));
        List<CollapseResult> out = new ArrayList<>();
        Instant previousEnd = Instant.MIN;
        for (int k = 0; k < batch.size(); k++) {
            CollapseWindow w = batch.get(k);
            long shift = shiftDays + extraDays + k * step;
            Instant end = w.end().plusDays(shift).toInstant(ZoneOffset.UTC);
            Instant after = previousEnd;
            List<LogEntry> mine = r.entries().stream()
                    .filter(e -> e.time().isAfter(after) && !e.time().isAfter(end)).toList();
            previousEnd = end;
            Timeline t = Timeline.of(mine, shift, w.events().get(0).time().minusSeconds(120));
            CollapseResult result = CollapseResult.judge(w.collapse(), w.quietSince(), t.alerts());
            out.add(result);
            System.out.printf("%s collapse %d at %s (quiet since %s, %d events replayed from %s): %s%s%n",
                    detector, first + k, w.collapse(), w.quietSince(), w.events().size(), w.from(),
                    result.outcome(), result.delay() == null ? ""
                            : " after " + result.delay().truncatedTo(ChronoUnit.SECONDS));
        }
        System.out.printf("%s collapses %d..%d: one platform, %.0f s wall%n", detector, first,
                first + batch.size() - 1, (System.nanoTime() - wall) / 1e9);
        Snapshot.delete(dir);
        return out;
    }

    private LocalDate virtualDay(CollapseWindow w, long extraDays) {
        return w.events().get(0).time().toLocalDate().plusDays(shiftDays + extraDays);
    }
}
