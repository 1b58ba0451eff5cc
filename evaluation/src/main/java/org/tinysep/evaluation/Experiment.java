package org.tinysep.evaluation;

import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.time.temporal.ChronoUnit;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * The evaluation of one home: the history half replayed once into a fresh platform and its stopped state folder kept
 * as the snapshot; then, per detector, the unmodified test half and one short window per collapse, each from a copy
 * of the snapshot in its own platform process, {@code parallel} at a time.
 */
final class Experiment {

    private final EvalOptions o;
    private final Home home;
    private final PlatformRun.Setup setup;
    /** Recorded → virtual: whole weeks, so weekdays stay weekdays; the virtual days lie ahead of the wall clock. */
    private final long shiftDays;

    Experiment(EvalOptions o, Home home) {
        this.o = o;
        this.home = home;
        this.setup = new PlatformRun.Setup(o.dist(), home);
        long ahead = LocalDate.now(ZoneOffset.UTC).plusDays(2).toEpochDay() - home.events().get(0).time().toLocalDate()
                .toEpochDay();
        this.shiftDays = Math.max(1, (ahead + 6) / 7) * 7;
    }

    /** Results per detector, in the order given. */
    record Result(String detector, TestHalfFigures test, Timeline testTimeline, PlatformRun.Outcome testRun,
            List<CollapseResult> collapses, long mails, long handedOver, long kernelDrops) {
    }

    private final Map<String, java.util.concurrent.atomic.AtomicLong> drops = new java.util.concurrent.ConcurrentHashMap<>();

    Map<String, Result> run() throws Exception {
        LocalDateTime split = home.split();
        List<SensorEvent> history = home.events().stream().filter(e -> e.time().isBefore(split)).toList();
        List<SensorEvent> test = home.events().stream().filter(e -> !e.time().isBefore(split)).toList();
        Path snapshot = o.work().resolve(home.name() + "-history");
        Snapshot.delete(snapshot);
        long wall = System.nanoTime();
        System.out.printf("history: %d events %s .. %s (detector %s while learning; the history is the event log)%n",
                history.size(), history.get(0).time(), history.get(history.size() - 1).time(), o.detectors().get(0));
        PlatformRun.run(setup, null, snapshot, o.detectors().get(0),
                List.of(new PlatformRun.Segment(history, virtualDay(history, 0), null)));
        System.out.printf("history replayed in %.0f s; snapshot %s%n", (System.nanoTime() - wall) / 1e9, snapshot);
        Path state = snapshot.resolve("var");

        List<LocalDateTime> moments = Collapses.draw(Collapses.candidates(home.labels(), test.get(0).time(),
                home.end()), o.collapses(), o.seed());
        ExecutorService pool = Executors.newFixedThreadPool(o.parallel());
        try {
            Map<String, Future<PlatformRun.Outcome>> testRuns = new LinkedHashMap<>();
            Map<String, List<Future<List<CollapseResult>>>> collapseRuns = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                Path dir = o.work().resolve(home.name() + "-" + d + "-test");
                Snapshot.delete(dir);
                testRuns.put(d, pool.submit(() -> PlatformRun.run(setup, state, dir, d,
                        List.of(new PlatformRun.Segment(test, virtualDay(test, 0), null)))));
            }
            List<Window> windows = moments.stream().map(this::window).toList();
            long step = step(windows);
            for (String d : o.detectors()) {
                List<Future<List<CollapseResult>>> list = new ArrayList<>();
                for (int i = 0; i < windows.size(); i += o.batch()) {
                    List<Window> batch = windows.subList(i, Math.min(windows.size(), i + o.batch()));
                    Path dir = o.work().resolve(home.name() + "-" + d + "-collapses-" + i);
                    list.add(pool.submit(collapses(state, dir, d, batch, i, step)));
                }
                collapseRuns.put(d, list);
            }
            Map<String, Result> out = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                PlatformRun.Outcome t = testRuns.get(d).get();
                Timeline tl = Timeline.of(t.entries(), shiftDays, test.get(0).time().minusSeconds(120));
                List<CollapseResult> cs = new ArrayList<>();
                for (Future<List<CollapseResult>> f : collapseRuns.get(d)) {
                    cs.addAll(f.get());
                }
                out.put(d, new Result(d, TestHalfFigures.of(tl, home.labels(), test.get(0).time(), home.end()), tl, t,
                        cs, t.mails().size(), t.handedOver(), t.kernelDrops() < 0 ? -1
                                : t.kernelDrops() + drops.getOrDefault(d, new java.util.concurrent.atomic.AtomicLong())
                                        .get()));
            }
            System.out.printf("all runs done in %.0f s%n", (System.nanoTime() - wall) / 1e9);
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /**
     * A collapse's replay: from {@code warmupHours} before it (earlier if needed, so that at least the last three
     * events before it are replayed) to the collapse; every event of the 12 h after it is deleted, and the replay
     * plays on, quiet, until 12 h and a minute after it.
     */
    record Window(LocalDateTime collapse, LocalDateTime from, List<SensorEvent> events) {
        LocalDateTime quietSince() {
            return events.get(events.size() - 1).time();
        }

        LocalDateTime end() {
            return collapse.plus(CollapseResult.WINDOW).plusMinutes(1);
        }
    }

    private Window window(LocalDateTime c) {
        List<SensorEvent> before = home.events().stream().filter(e -> e.time().isBefore(c)).toList();
        LocalDateTime third = before.get(Math.max(0, before.size() - 3)).time();
        LocalDateTime from = earlier(c.minusHours(o.warmupHours()), third.minusMinutes(10));
        return new Window(c, from, before.stream().filter(e -> !e.time().isBefore(from)).toList());
    }

    /** @return days between two windows of one run: whole weeks, more than any window's span plus a day */
    private static long step(List<Window> windows) {
        LocalDateTime first = windows.stream().map(Window::from).min(LocalDateTime::compareTo).orElseThrow();
        LocalDateTime last = windows.stream().map(Window::end).max(LocalDateTime::compareTo).orElseThrow();
        long days = Duration.between(first, last).toDays() + 2;
        return (days + 6) / 7 * 7;
    }

    /**
     * One platform process for a batch of collapses: window k is replayed {@code k * step} days later in virtual
     * time than its recorded day + the shift, so that the windows follow each other in the platform's time.
     */
    private Callable<List<CollapseResult>> collapses(Path state, Path dir, String detector, List<Window> batch,
            int first, long step) {
        return () -> {
            Snapshot.delete(dir);
            List<PlatformRun.Segment> segments = new ArrayList<>();
            for (int k = 0; k < batch.size(); k++) {
                Window w = batch.get(k);
                segments.add(new PlatformRun.Segment(w.events(), virtualDay(w.events(), k * step), w.end()));
            }
            long wall = System.nanoTime();
            PlatformRun.Outcome r = PlatformRun.run(setup, state, dir, detector, segments);
            drops.computeIfAbsent(detector, x -> new java.util.concurrent.atomic.AtomicLong())
                    .addAndGet(Math.max(0, r.kernelDrops()));
            List<CollapseResult> out = new ArrayList<>();
            java.time.Instant previousEnd = java.time.Instant.MIN;
            for (int k = 0; k < batch.size(); k++) {
                Window w = batch.get(k);
                long shift = shiftDays + k * step;
                java.time.Instant end = w.end().plusDays(shift).toInstant(ZoneOffset.UTC);
                java.time.Instant after = previousEnd;
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
        };
    }

    private static LocalDateTime earlier(LocalDateTime a, LocalDateTime b) {
        return a.isBefore(b) ? a : b;
    }

    private LocalDate virtualDay(List<SensorEvent> events, long extraDays) {
        return events.get(0).time().toLocalDate().plusDays(shiftDays + extraDays);
    }

    long shiftDays() {
        return shiftDays;
    }

    Duration testSpan() {
        return Duration.between(home.split(), home.end());
    }
}
