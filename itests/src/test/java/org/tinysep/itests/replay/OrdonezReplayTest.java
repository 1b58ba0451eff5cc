package org.tinysep.itests.replay;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.time.Instant;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.itests.LockStepTestSupport;
import org.tinysep.simulator.cli.Replay;
import org.tinysep.simulator.cli.ReplayResult;
import org.tinysep.simulator.cli.Run;
import org.tinysep.simulator.measure.KernelDrops;
import org.tinysep.simulator.replay.Agreement;
import org.tinysep.simulator.replay.Evaluation;
import org.tinysep.simulator.replay.Interval;
import org.tinysep.simulator.replay.Label;
import org.tinysep.simulator.replay.NodeSpec;
import org.tinysep.simulator.replay.OrdonezReader;
import org.tinysep.simulator.replay.ReplayPlan;
import org.tinysep.simulator.replay.SensorEvent;
import org.tinysep.testsupport.repo.RepoFiles;

/**
 * Issue 5, test item 2: Ordonez Home A (Ordóñez, de Toledo, Sanchis, Sensors 2013, 13, 5460–5477; UCI data set 271)
 * replayed COMPLETELY by the real simulator through the AmICA wire protocol in lock-step with the Time Controller,
 * mapped by the shipped {@code ordonez-a.mapping}. Checked: every recorded sensor interval arrived at the platform's
 * consumers as one "on" (counts per sensor equal the file's), and Flat Occupancy's UNOCCUPIED periods overlap the
 * data's "Leaving" labels. The agreement (recall, precision) is printed, never tuned: the mapping and Flat
 * Occupancy's defaults are those shipped.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class OrdonezReplayTest extends LockStepTestSupport {

    /** The repository's copy (data/ordonez/PROVENANCE.md); RepoFiles refuses any path outside the clone. */
    private static final Path DATA = RepoFiles.require("data", "ordonez");
    private static final Path SENSORS = DATA.resolve("OrdonezA_Sensors.txt");
    private static final Path LABELS = DATA.resolve("OrdonezA_ADLs.txt");
    private static final Path HOUSE = Path.of("..", "simulator", "src", "main", "resources", "replay", "ordonez-a.house.xml");
    /** {@code changes}: every recorded change at once plus keep-alives; see the README's replay section. */
    private static final String RATE = System.getProperty("tinysep.replay.rate", "changes");

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        try {
            Path house = Files.createTempDirectory("tinysep-ordonez-a-").resolve("house.xml");
            Files.copy(HOUSE, house, StandardCopyOption.REPLACE_EXISTING);
            configs.put("org.tinysep.houseinformation", Map.of("file", house.toString()));
            List<String> placements = new ArrayList<>();
            for (NodeSpec n : Replay.plan(SENSORS, "ordonez-a").nodes()) {
                placements.add(n.address() + "=" + n.room());
            }
            configs.put("org.tinysep.houseinformation.placement", Map.of("placements", String.join(", ", placements)));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (Exception e) {
            throw new IllegalStateException("cannot read " + SENSORS.toAbsolutePath() + " (see data/ordonez/PROVENANCE.md)", e);
        }
        return configs;
    }

    @Test
    public void homeAReplaysCompletelyAndLeavingOverlapsUnoccupied() throws Exception {
        HouseInformationProvider house = awaitService(HouseInformationProvider.class, null, TIMEOUT);
        await(TIMEOUT, () -> house.rooms().size() == 5, "Home A's five rooms");
        ExecutorService executor = Executors.newSingleThreadExecutor();
        try (ReplayRecord record = new ReplayRecord(context)) {
            int radioPort = udpPortOf("BusRadioAmicaUdp");
            long dropsBefore = KernelDrops.at(radioPort);
            String[] args = {"--replay", SENSORS.toString(), "--mapping", "ordonez-a", "--lockstep", "--rate", RATE,
                    "--amica-port", Integer.toString(radioPort),
                    "--sync-port", Integer.toString(syncPort()), syncKeyArgs()[0], syncKeyArgs()[1],
                    "--progress", "1440"};
            ReplayResult result = executor.submit(() -> Run.replay(args)).get(10, TimeUnit.MINUTES);
            long dropped = KernelDrops.at(radioPort) - dropsBefore;
            System.out.printf("OrdonezReplayTest: datagrams the kernel dropped at the AmICA radio's full socket "
                    + "buffer (/proc/net/udp and udp6): %s%n", dropsBefore < 0 ? "n/a" : Long.toString(dropped));
            ReplayPlan plan = result.replay().plan();
            List<SensorEvent> events = OrdonezReader.readSensors(SENSORS);

            NavigableMap<String, Integer> expected = Evaluation.onCountsPerSensor(events);
            Map<String, String> sensorOf = new LinkedHashMap<>();
            plan.nodes().forEach(n -> sensorOf.put(n.address().toString(), n.sensor()));
            try {
                await(TIMEOUT, () -> bySensor(record.onCounts(), sensorOf).equals(expected),
                        "every recorded interval seen by the platform's consumers");
            } catch (AssertionError late) {
                // the comparison below names the sensors that differ
            }
            assertEquals("recorded intervals per sensor = platform 'on' changes per sensor", expected,
                    bySensor(record.onCounts(), sensorOf));
            assertEquals("every recorded event sent", plan.actions().size(), result.sent());

            NavigableMap<LocalDateTime, Occupancy> changes = new TreeMap<>();
            for (Map.Entry<Instant, Occupancy> e : record.occupancy().entrySet()) {
                changes.put(result.replay().recordedTime(e.getKey()), e.getValue());
            }
            List<Label> labels = OrdonezReader.readLabels(LABELS);
            List<Interval> leaving = Evaluation.clip(Evaluation.leaving(labels), plan.start(), plan.end());
            List<Interval> away = Evaluation.clip(Evaluation.whileIn(changes, Occupancy.UNOCCUPIED, plan.end()),
                    plan.start(), plan.end());
            Agreement agreement = Evaluation.agreement(leaving, away);
            long detected = leaving.stream()
                    .filter(l -> !Evaluation.agreement(List.of(l), away).overlap().isZero()).count();
            System.out.printf("OrdonezReplayTest: Home A, %d events, %d virtual seconds (%d ticked) in %.1f s wall "
                    + "time, rate %s; Flat Occupancy changes %d; Leaving %d intervals (%s), UNOCCUPIED %d intervals "
                    + "(%s); overlap %s; recall %.3f, precision %.3f, F1 %.3f; Leaving intervals overlapped %d/%d%n",
                    result.sent(), result.replay().untilSecond() - result.replay().fromSecond(), result.played(),
                    result.wallTime().toMillis() / 1e3, RATE, changes.size(), leaving.size(),
                    agreement.reference(), away.size(), agreement.predicted(), agreement.overlap(), agreement.recall(),
                    agreement.precision(), agreement.f1(), detected, leaving.size());
            log.info("occupancy changes (recorded time): {}", changes);
            assertTrue("Flat Occupancy's away periods overlap the Leaving labels: " + agreement,
                    !agreement.overlap().isZero());
        } finally {
            executor.shutdownNow();
        }
    }

    private static NavigableMap<String, Integer> bySensor(Map<String, Integer> byAddress, Map<String, String> sensorOf) {
        NavigableMap<String, Integer> out = new TreeMap<>();
        byAddress.forEach((address, n) -> out.put(sensorOf.getOrDefault(address, "?" + address), n));
        return out;
    }

}
