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
import org.tinysep.simulator.replay.Interval;
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

    private final Split split;

    Experiment(EvalOptions o, Home home) {
        this.o = o;
        this.home = home;
        this.split = Split.of(o.split(), home);
        long ahead = LocalDate.now(ZoneOffset.UTC).plusDays(2).toEpochDay() - home.events().get(0).time().toLocalDate()
                .toEpochDay();
        this.shiftDays = Math.max(1, (ahead + 6) / 7) * 7;
        this.setup = new PlatformRun.Setup(o.dist(), home, "learnHistoryDays=" + historyDays() + "\n");
    }

    /** Results per detector, in the order given. */
    record Result(String detector, TestHalfFigures test, Timeline testTimeline, PlatformRun.Outcome testRun,
            List<CollapseResult> collapses, long mails, long handedOver, long kernelDrops) {
    }

    private final Map<String, java.util.concurrent.atomic.AtomicLong> drops = new java.util.concurrent.ConcurrentHashMap<>();
    private final Map<String, java.util.concurrent.atomic.AtomicLong> mails = new java.util.concurrent.ConcurrentHashMap<>();

    /**
     * The learning window written into every platform's configuration: 28 days (the detector's default) plus how
     * far the harness places replays beyond their recorded time (cv's test days after the recording, a batch's
     * later windows), so every replay sees the same recorded history the default would in a home, not less.
     */
    long historyDays() {
        long windows = (long) Math.max(1, o.batch()) * (home.end().toLocalDate().toEpochDay()
                - home.events().get(0).time().toLocalDate().toEpochDay() + 9);
        return 28 + split.folds().get(0).extraDays() + windows;
    }

    Split split() {
        return split;
    }

    Map<String, Result> run() throws Exception {
        long wall = System.nanoTime();
        ExecutorService pool = Executors.newFixedThreadPool(o.parallel());
        try {
            Map<Integer, Future<Path>> states = new LinkedHashMap<>();
            for (Split.Fold f : split.folds()) {
                states.put(f.index(), pool.submit(() -> history(f)));
            }
            List<Interval> candidates = new ArrayList<>();
            for (Split.Fold f : split.folds()) {
                for (Split.TestSegment t : Split.testSegments(home, f)) {
                    candidates.addAll(Collapses.candidates(home.labels(), t.judged().start(), t.judged().end()));
                }
            }
            List<LocalDateTime> moments = Collapses.draw(candidates, o.collapses(), o.seed());
            Map<String, List<Future<PlatformRun.Outcome>>> testRuns = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                List<Future<PlatformRun.Outcome>> list = new ArrayList<>();
                for (Split.Fold f : split.folds()) {
                    list.add(pool.submit(() -> test(d, f, states.get(f.index()).get())));
                }
                testRuns.put(d, list);
            }
            List<Window> windows = moments.stream().map(this::window).toList();
            long step = step(windows);
            Map<String, List<Future<List<CollapseResult>>>> collapseRuns = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                List<Future<List<CollapseResult>>> list = new ArrayList<>();
                int n = 0;
                for (Split.Fold f : split.folds()) {
                    List<Window> mine = windows.stream().filter(w -> split.foldOf(w.collapse()) == f).toList();
                    for (int i = 0; i < mine.size(); i += o.batch()) {
                        List<Window> batch = mine.subList(i, Math.min(mine.size(), i + o.batch()));
                        Path dir = o.work().resolve(home.name() + "-" + split.name() + "-" + d + "-collapses-" + n);
                        int first = n;
                        list.add(pool.submit(() -> collapses(states.get(f.index()).get(), dir, d, batch, first, step,
                                f.extraDays()).call()));
                        n += batch.size();
                    }
                }
                collapseRuns.put(d, list);
            }
            Map<String, Result> out = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                List<TestHalfFigures> parts = new ArrayList<>();
                Timeline first = null;
                PlatformRun.Outcome firstRun = null;
                long mailCount = 0;
                long handed = 0;
                long kernel = 0;
                for (int i = 0; i < split.folds().size(); i++) {
                    Split.Fold f = split.folds().get(i);
                    PlatformRun.Outcome t = testRuns.get(d).get(i).get();
                    List<Split.TestSegment> segs = Split.testSegments(home, f);
                    Timeline tl = Timeline.of(t.entries(), shiftDays + f.extraDays(),
                            segs.get(0).events().get(0).time().minusSeconds(120));
                    parts.add(TestHalfFigures.of(tl, home.labels(), segs.stream().map(Split.TestSegment::judged)
                            .toList()));
                    if (first == null) {
                        first = tl;
                        firstRun = t;
                    }
                    mailCount += t.mails().size();
                    handed += t.handedOver();
                    kernel = kernel < 0 || t.kernelDrops() < 0 ? -1 : kernel + t.kernelDrops();
                }
                List<CollapseResult> cs = new ArrayList<>();
                for (Future<List<CollapseResult>> f : collapseRuns.get(d)) {
                    cs.addAll(f.get());
                }
                cs.sort(java.util.Comparator.comparing(CollapseResult::at));
                out.put(d, new Result(d, TestHalfFigures.sum(parts), first, firstRun, cs, mailCount, handed,
                        kernel < 0 ? -1 : kernel + drops.getOrDefault(d, new java.util.concurrent.atomic.AtomicLong())
                                .get()));
            }
            System.out.printf("all runs done in %.0f s%n", (System.nanoTime() - wall) / 1e9);
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /** Replays a fold's history into a fresh platform; @return its stopped state folder (the snapshot) */
    private Path history(Split.Fold f) throws Exception {
        List<SensorEvent> history = f.history();
        Path snapshot = o.work().resolve(home.name() + "-" + split.name() + "-history-" + f.index());
        Snapshot.delete(snapshot);
        long wall = System.nanoTime();
        System.out.printf("fold %d history: %d events %s .. %s (detector %s while learning; the history is the event "
                + "log)%n", f.index(), history.size(), history.get(0).time(), history.get(history.size() - 1).time(),
                o.detectors().get(0));
        PlatformRun.run(setup, null, snapshot, o.detectors().get(0),
                List.of(new PlatformRun.Segment(history, virtualDay(history, 0), null)));
        System.out.printf("fold %d history replayed in %.0f s; snapshot %s%n", f.index(),
                (System.nanoTime() - wall) / 1e9, snapshot);
        return snapshot.resolve("var");
    }

    /** Replays a fold's test segments (unmodified) from its snapshot, {@code extraDays} later than recorded. */
    private PlatformRun.Outcome test(String d, Split.Fold f, Path state) throws Exception {
        Path dir = o.work().resolve(home.name() + "-" + split.name() + "-" + d + "-test-" + f.index());
        Snapshot.delete(dir);
        List<PlatformRun.Segment> segments = Split.testSegments(home, f).stream()
                .map(t -> new PlatformRun.Segment(t.events(), virtualDay(t.events(), f.extraDays()), null)).toList();
        return PlatformRun.run(setup, state, dir, d, segments);
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
            int first, long step, long extraDays) {
        return () -> {
            Snapshot.delete(dir);
            List<PlatformRun.Segment> segments = new ArrayList<>();
            for (int k = 0; k < batch.size(); k++) {
                Window w = batch.get(k);
                segments.add(new PlatformRun.Segment(w.events(), virtualDay(w.events(), extraDays + k * step),
                        w.end()));
            }
            long wall = System.nanoTime();
            PlatformRun.Outcome r = PlatformRun.run(setup, state, dir, detector, segments);
            drops.computeIfAbsent(detector, x -> new java.util.concurrent.atomic.AtomicLong())
                    .addAndGet(Math.max(0, r.kernelDrops()));
            List<CollapseResult> out = new ArrayList<>();
            java.time.Instant previousEnd = java.time.Instant.MIN;
            for (int k = 0; k < batch.size(); k++) {
                Window w = batch.get(k);
                long shift = shiftDays + extraDays + k * step;
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
