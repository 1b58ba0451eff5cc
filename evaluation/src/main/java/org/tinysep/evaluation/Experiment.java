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
            List<CollapseResult> collapses, long mails, long handedOver) {
    }

    Map<String, Result> run() throws Exception {
        LocalDateTime split = home.split();
        List<SensorEvent> history = home.events().stream().filter(e -> e.time().isBefore(split)).toList();
        List<SensorEvent> test = home.events().stream().filter(e -> !e.time().isBefore(split)).toList();
        Path snapshot = o.work().resolve(home.name() + "-history");
        Snapshot.delete(snapshot);
        long wall = System.nanoTime();
        System.out.printf("history: %d events %s .. %s (detector %s while learning; the history is the event log)%n",
                history.size(), history.get(0).time(), history.get(history.size() - 1).time(), o.detectors().get(0));
        PlatformRun.run(setup, null, snapshot, o.detectors().get(0), history, virtualDay(history), null);
        System.out.printf("history replayed in %.0f s; snapshot %s%n", (System.nanoTime() - wall) / 1e9, snapshot);
        Path state = snapshot.resolve("var");

        List<LocalDateTime> moments = Collapses.draw(Collapses.candidates(home.labels(), test.get(0).time(),
                home.end()), o.collapses(), o.seed());
        ExecutorService pool = Executors.newFixedThreadPool(o.parallel());
        try {
            Map<String, Future<PlatformRun.Outcome>> testRuns = new LinkedHashMap<>();
            Map<String, List<Future<CollapseResult>>> collapseRuns = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                Path dir = o.work().resolve(home.name() + "-" + d + "-test");
                Snapshot.delete(dir);
                testRuns.put(d, pool.submit(() -> PlatformRun.run(setup, state, dir, d, test, virtualDay(test), null)));
            }
            for (String d : o.detectors()) {
                List<Future<CollapseResult>> list = new ArrayList<>();
                for (int i = 0; i < moments.size(); i++) {
                    LocalDateTime c = moments.get(i);
                    Path dir = o.work().resolve(home.name() + "-" + d + "-collapse-" + i);
                    list.add(pool.submit(collapse(state, dir, d, c, i)));
                }
                collapseRuns.put(d, list);
            }
            Map<String, Result> out = new LinkedHashMap<>();
            for (String d : o.detectors()) {
                PlatformRun.Outcome t = testRuns.get(d).get();
                Timeline tl = Timeline.of(t.entries(), shiftDays, test.get(0).time().minusSeconds(120));
                List<CollapseResult> cs = new ArrayList<>();
                for (Future<CollapseResult> f : collapseRuns.get(d)) {
                    cs.add(f.get());
                }
                out.put(d, new Result(d, TestHalfFigures.of(tl, home.labels(), test.get(0).time(), home.end()), tl, t,
                        cs, t.mails().size(), t.handedOver()));
            }
            System.out.printf("all runs done in %.0f s%n", (System.nanoTime() - wall) / 1e9);
            return out;
        } finally {
            pool.shutdownNow();
        }
    }

    private Callable<CollapseResult> collapse(Path state, Path dir, String detector, LocalDateTime c, int i) {
        return () -> {
            List<SensorEvent> before = home.events().stream().filter(e -> e.time().isBefore(c)).toList();
            LocalDateTime third = before.get(Math.max(0, before.size() - 3)).time();
            LocalDateTime from = earlier(c.minusHours(o.warmupHours()), third.minusMinutes(10));
            List<SensorEvent> window = before.stream().filter(e -> !e.time().isBefore(from)).toList();
            LocalDateTime quietSince = window.get(window.size() - 1).time();
            Snapshot.delete(dir);
            PlatformRun.Outcome r = PlatformRun.run(setup, state, dir, detector, window, virtualDay(window),
                    c.plus(CollapseResult.WINDOW).plusMinutes(1));
            Timeline t = Timeline.of(r.entries(), shiftDays, window.get(0).time().minusSeconds(120));
            CollapseResult result = CollapseResult.judge(c, quietSince, t.alerts());
            Snapshot.delete(dir);
            System.out.printf("%s collapse %d at %s (quiet since %s, %d events replayed from %s): %s%s%n", detector, i,
                    c, quietSince, window.size(), from, result.outcome(),
                    result.delay() == null ? "" : " after " + result.delay().truncatedTo(ChronoUnit.SECONDS));
            return result;
        };
    }

    private static LocalDateTime earlier(LocalDateTime a, LocalDateTime b) {
        return a.isBefore(b) ? a : b;
    }

    private LocalDate virtualDay(List<SensorEvent> events) {
        return events.get(0).time().toLocalDate().plusDays(shiftDays);
    }

    long shiftDays() {
        return shiftDays;
    }

    Duration testSpan() {
        return Duration.between(home.split(), home.end());
    }
}
