package org.tinysep.evaluation;

import java.nio.file.Path;
import java.time.Duration;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.atomic.AtomicLong;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * The evaluation of one home: the history half replayed once into a fresh platform and its stopped state folder kept
 * as the snapshot; then, per detector, the unmodified test half and one short window per collapse
 * ({@link CollapseWindow}, replayed in batches by {@link CollapseBatch}), each from a copy of the snapshot in its
 * own platform process, {@code parallel} at a time; {@link DetectorResult} sums them.
 */
final class Experiment {

    private final EvalOptions o;
    private final Home home;
    private final PlatformRun.Setup setup;
    /** Recorded → virtual: whole weeks, so weekdays stay weekdays; the virtual days lie ahead of the wall clock. */
    private final long shiftDays;
    private final Split split;
    private final Map<String, AtomicLong> drops = new ConcurrentHashMap<>();

    Experiment(EvalOptions o, Home home) {
        this.o = o;
        this.home = home;
        this.split = Split.of(o.split(), home);
        long ahead = LocalDate.now(ZoneOffset.UTC).plusDays(2).toEpochDay() - home.events().get(0).time().toLocalDate()
                .toEpochDay();
        this.shiftDays = Math.max(1, (ahead + 6) / 7) * 7;
        this.setup = new PlatformRun.Setup(o.dist(), home, "learnHistoryDays=" + historyDays() + "\n"
                + (home.residents() > 0 ? "residents=" + home.residents() + "\n" : "")); // else: from the history
    }

    /** Results per detector, in the order given. */
    record Result(String detector, TestHalfFigures test, Timeline testTimeline, PlatformRun.Outcome testRun,
            List<CollapseResult> collapses, long mails, long handedOver, long kernelDrops) {
    }

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
            List<CollapseWindow> windows = moments.stream()
                    .map(c -> CollapseWindow.of(home, c, o.warmupHours())).toList();
            Map<String, List<Future<List<CollapseResult>>>> collapseRuns = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                collapseRuns.put(d, submitCollapses(pool, states, d, windows, CollapseWindow.step(windows)));
            }
            Map<String, Result> out = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                List<Future<List<CollapseResult>>> runs = collapseRuns.get(d);
                for (Future<List<CollapseResult>> f : runs) {
                    f.get(); // every batch done before its drops are read
                }
                out.put(d, DetectorResult.of(d, home, split, shiftDays, testRuns.get(d), runs,
                        drops.getOrDefault(d, new AtomicLong()).get()));
            }
            System.out.printf("all runs done in %.0f s%n", (System.nanoTime() - wall) / 1e9);
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    /** Submits one detector's collapse batches, per fold, {@code batch} windows per platform. */
    private List<Future<List<CollapseResult>>> submitCollapses(ExecutorService pool, Map<Integer, Future<Path>> states,
            String d, List<CollapseWindow> windows, long step) {
        CollapseBatch runner = new CollapseBatch(setup, shiftDays);
        AtomicLong dropped = drops.computeIfAbsent(d, x -> new AtomicLong());
        List<Future<List<CollapseResult>>> list = new ArrayList<>();
        int n = 0;
        for (Split.Fold f : split.folds()) {
            List<CollapseWindow> mine = windows.stream().filter(w -> split.foldOf(w.collapse()) == f).toList();
            for (int i = 0; i < mine.size(); i += o.batch()) {
                List<CollapseWindow> batch = mine.subList(i, Math.min(mine.size(), i + o.batch()));
                Path dir = o.work().resolve(home.name() + "-" + split.name() + "-" + d + "-collapses-" + n);
                int first = n;
                list.add(pool.submit(() -> runner.run(states.get(f.index()).get(), dir, d, batch, first, step,
                        f.extraDays(), dropped)));
                n += batch.size();
            }
        }
        return list;
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
