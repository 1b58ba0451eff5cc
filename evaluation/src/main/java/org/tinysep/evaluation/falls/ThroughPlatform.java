package org.tinysep.evaluation.falls;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.function.Function;
import org.tinysep.api.sensor.person.Acceleration;
import org.tinysep.evaluation.FallPlatforms;
import org.tinysep.falldetection.internal.FallSettings;

/**
 * Judges recordings through the real distribution: one platform process per subject ({@link FallPlatforms}), with
 * Fall Detection configured with that subject's settings, {@code parallel} platforms at once. The alerts are the
 * ones the platform raised (its event log), not the in-process detector's.
 */
final class ThroughPlatform {

    private ThroughPlatform() {
    }

    static List<Scored> run(Path dist, Path work, Map<String, List<NodeStream>> bySubject,
            Function<String, FallSettings> settings, int parallel, List<Scored> inProcess) throws Exception {
        if (!Files.isRegularFile(dist.resolve("tinysep.jar"))) {
            throw new IllegalArgumentException("falls: no distribution at " + dist + " (build it: mvn -pl "
                    + "runtime/org.tinysep.launcher -am package -DskipTests, or run ./evaluate.sh, which builds it)");
        }
        Path runDir = work.resolve("run-" + System.currentTimeMillis());
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, parallel));
        try {
            List<Future<List<Scored>>> futures = new ArrayList<>();
            for (Map.Entry<String, List<NodeStream>> e : bySubject.entrySet()) {
                futures.add(pool.submit(() -> subject(dist, runDir.resolve(e.getKey()), e.getValue(),
                        settings.apply(e.getKey()))));
            }
            // the upright each recording began with, as the same detector class learned it in process (for --why)
            Map<String, Acceleration> upright = new HashMap<>();
            inProcess.forEach(s -> upright.put(s.stream().recording().name(), s.upright()));
            List<Scored> all = new ArrayList<>();
            for (Future<List<Scored>> f : futures) {
                for (Scored s : f.get()) {
                    all.add(new Scored(s.stream(), s.alerts(), s.refused(),
                            upright.get(s.stream().recording().name())));
                }
            }
            return all;
        } finally {
            pool.shutdownNow();
        }
    }

    private static List<Scored> subject(Path dist, Path dir, List<NodeStream> streams, FallSettings s)
            throws Exception {
        Files.createDirectories(dir);
        List<List<Duration>> alerts = FallPlatforms.run(dist, dir,
                streams.stream().map(NodeStream::samples).toList(), config(s));
        List<Scored> out = new ArrayList<>();
        for (int i = 0; i < streams.size(); i++) {
            List<Instant> at = alerts.get(i).stream().map(NodeStream.T0::plus).toList();
            out.add(new Scored(streams.get(i), at, List.of(), null));
        }
        return out;
    }

    static String config(FallSettings s) {
        return String.format(Locale.ROOT, "impactMg=%d\npostureChangeDegrees=%s\nstillSdMg=%d\nstillSeconds=%d\n"
                + "withinSeconds=%d\nalreadyLyingDegrees=%s", s.impactMg(), s.postureChangeDeg(), s.stillSdMg(),
                s.stillFor().toSeconds(), s.within().toSeconds(), s.alreadyLyingDeg());
    }
}
