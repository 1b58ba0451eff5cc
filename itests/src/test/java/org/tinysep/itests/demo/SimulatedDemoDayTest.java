package org.tinysep.itests.demo;

import static org.junit.Assert.assertEquals;
import static org.junit.Assert.assertTrue;

import java.nio.file.Files;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import org.junit.Test;
import org.junit.runner.RunWith;
import org.ops4j.pax.exam.junit.PaxExam;
import org.ops4j.pax.exam.spi.reactors.ExamReactorStrategy;
import org.ops4j.pax.exam.spi.reactors.PerClass;
import org.tinysep.api.log.EventLog;
import org.tinysep.api.service.HouseInformationProvider;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.MailStatus;
import org.tinysep.itests.LockStepTestSupport;
import org.tinysep.itests.Topology;
import org.tinysep.testsupport.mail.SmtpSink;
import org.tinysep.simulator.cli.Run;

/**
 * Issue 5, test item 1: the REAL simulator (flat A, scenario demo-day, seed 1) drives the platform over the wire
 * protocols only (AmICA UDP, Sun SPOT UDP, the time synchroniser in lock-step), 06:00 to 18:05 virtual time (every scripted step up to Ben leaving).
 * Asserted: Flat Occupancy's changes with their virtual times, the sequence of rooms whose light was switched on,
 * Inactivity Recognition's states (exactly one ALERT), exactly one mail naming the Bathroom, and no actuator request
 * given up (every simulated node carries out every command, so a give-up would be false: issue 17).
 * <p>
 * {@code --wander 0}: no random short walks, so the rooms lit are exactly those of the scenario (jitter, seeded,
 * still moves every scripted time). The simulation starts at 06:00 so that the platform has registered every
 * node's devices (placed by the placement configuration) before Anna wakes at 06:45.
 */
@RunWith(PaxExam.class)
@ExamReactorStrategy(PerClass.class)
public class SimulatedDemoDayTest extends LockStepTestSupport {


    /**
     * Flat Occupancy. demo-day: Anna (asleep at home) wakes 06:45 -> OCCUPIED with her first motion; leaves 08:30
     * (± 90 s jitter), the door closes, UNOCCUPIED 600 s (leave timeout) later; arrives 11:40 (± 90 s) -> OCCUPIED
     * when the door opens. Ben's visit (15:30-18:00) happens while Anna is home: no change. Times are those the
     * platform stamped: the second in which the simulator sent the frame (since issue 16's single lock-step driver,
     * which ticks a second before sending its frames; one second later than the earlier frames-then-tick order).
     */
    private static final List<String> OCCUPANCY = List.of(
            "06:45:14 OCCUPIED", // 06:45 wakes (+13 s jitter): her first bedroom motion
            "08:39:29 UNOCCUPIED", // 08:30 leaves (-35 s jitter): door closed 08:29:29, + 600 s leave timeout
            "11:40:13 OCCUPIED"); // 11:40 arrives (+12 s jitter): the outer door opens

    /** Rooms lit, consecutive repeats merged; the scenario's walk along the house graph (Hall links everything). */
    private static final List<String> ROOMS_LIT = List.of(
            "Bedroom", // 06:45 wakes
            "Hall", "Bathroom", // 06:50 bedroom -> bathroom
            "Hall", "Living Room", "Kitchen", // 07:15 kitchen (breakfast)
            "Living Room", // 07:45 living room
            "Hall", // 08:30 leaves; 11:40 arrives (the hall again, merged)
            "Living Room", "Kitchen", // ... in kitchen
            "Living Room", // 12:30 living room
            "Study", // 13:20 study
            "Living Room", "Hall", "Bathroom", // 14:00 bathroom (14:02 collapses there: no more motion)
            "Hall", "Living Room", // 15:30 Ben arrives in living room
            "Hall", "Bathroom", // 15:32 Ben to the bathroom
            "Hall", "Living Room", // 15:40-15:46 Anna gets up, both to the living room
            "Kitchen", // 17:30 Ben kitchen
            "Hall"); // 18:00 Ben leaves (the run ends at 18:05)

    /** Inactivity Recognition: watching while occupied, one ALERT after the bathroom limit (45 min) from 14:02. */
    private static final List<String> INACTIVITY = List.of(
            "06:45:14 WATCHING", "08:39:29 NOT_WATCHING", "11:40:13 WATCHING", // with Flat Occupancy
            // last bathroom motion report about 14:01:15 (she collapses at 14:02 - jitter) + 45 min; to the minute:
            // an unchanged motion report is not paced in lock-step and may be stamped a second or two late
            "14:46 ALERT",
            "15:29:43 WATCHING"); // 15:30 Ben arrives (-18 s jitter): the door opening is activity

    @Override
    protected Map<String, Map<String, String>> initialConfigurations() {
        Map<String, Map<String, String>> configs = new LinkedHashMap<>(super.initialConfigurations());
        DemoFlat.configure(configs, "tinysep-demo-house-");
        return configs;
    }


    /** Flat A: 7 movement sensors (6 AmICA, 1 Sun SPOT), 4 simple and 2 dimmable lights, all with their consumers. */
    private static boolean connected(Set<String> graph) {
        return count(graph, "FlatOccupancy <- MovementProvider") == 7
                && count(graph, "InactivityRecognition <- MovementProvider") == 7
                && count(graph, "FollowMeLight <- SimpleLightProvider") == 4
                && count(graph, "FollowMeLight <- DimmableLightProvider") == 2;
    }

    private static long count(Set<String> graph, String prefix) {
        return graph.stream().filter(l -> l.startsWith(prefix)).count();
    }

    private static void simulate(ExecutorService executor, List<String> common, String from, String until)
            throws Exception {
        List<String> args = new ArrayList<>(common);
        args.addAll(List.of("--from", from, "--until", until));
        executor.submit(() -> {
            Run.simulate(args.toArray(new String[0]));
            return null;
        }).get(120, TimeUnit.SECONDS);
    }

    @Test
    public void theDemoDayProducesTheExpectedOccupancyLightsAndOneAlert() throws Exception {
        ExecutorService executor = Executors.newSingleThreadExecutor();
        PlatformRecord record = null;
        try (SmtpSink sink = new SmtpSink().start()) {
            configure("org.tinysep.mailmanager", Map.of("host", "127.0.0.1", "port", Integer.toString(sink.port()),
                    "security", "NONE", "from", "tinysep@home.test", "recipients", "carer@care.test",
                    "connectTimeoutSeconds", "2", "retryInitialSeconds", "1", "retryMaxSeconds", "2",
                    "spoolDir", Files.createTempDirectory("tinysep-demo-spool").toString()));
            MailManagerProvider mail = awaitService(MailManagerProvider.class, null, TIMEOUT);
            await(TIMEOUT, () -> mail.status() == MailStatus.IDLE, "the Mail Manager configured");
            HouseInformationProvider house = awaitService(HouseInformationProvider.class, null, TIMEOUT);
            await(TIMEOUT, () -> house.rooms().size() == 6, "flat A's six rooms");
            record = new PlatformRecord(context, house);
            List<String> common = List.of("--lockstep", "--amica-port", Integer.toString(udpPortOf("BusRadioAmicaUdp")),
                    "--sunspot-port", Integer.toString(udpPortOf("BusRadioSunSpot")), "--sync-port",
                    Integer.toString(syncPort()), syncKeyArgs()[0], syncKeyArgs()[1], "--flat", "flat-a", "--scenario",
                    "demo-day", "--seed", "1", "--wander", "0", "--progress", "120");
            long wall = System.nanoTime();
            // 06:00-06:05: every node's keep-alives; then wait (wall time) until every device is connected to its
            // consumers, however loaded the machine: lock-step plays 45 virtual minutes in about a second
            simulate(executor, common, "06:00", "06:05");
            await(Duration.ofSeconds(30), () -> connected(Topology.of(context)), "flat A's devices connected");
            simulate(executor, common, "06:05", "18:05");
            // the wall time is printed, not asserted: it depends on the machine's load (issue 17: 24 s with a loaded
            // machine, 43-60 s with three more busy loops); each part of the run is bounded by simulate's timeout
            long millis = (System.nanoTime() - wall) / 1_000_000;
            System.out.println("SimulatedDemoDayTest: 06:00-18:05 virtual in " + millis + " ms wall time");
            log.info("recorded: {}", record);
            sink.await(1, Duration.ofSeconds(10));

            // issue 17 item 4: every simulated node carries out every command, so any request given up is false
            List<String> givenUp = awaitService(EventLog.class, null, TIMEOUT).recent(Integer.MAX_VALUE).stream()
                    .filter(e -> e.message().contains("request given up")).map(e -> e.origin() + " " + e.message())
                    .toList();
            System.out.println("SimulatedDemoDayTest: " + givenUp.size() + " request(s) given up");
            assertEquals("requests given up although every node obeys", List.of(), givenUp);
            assertEquals("Flat Occupancy's changes", OCCUPANCY, record.occupancy);
            assertEquals("rooms whose lights Follow Me Light switched on, in order", ROOMS_LIT,
                    record.roomsRequested(awaitService(EventLog.class, null, TIMEOUT), house));
            assertEquals("Inactivity Recognition's states", INACTIVITY,
                    record.inactivity.stream().map(e -> e.endsWith(" ALERT") ? e.substring(0, 5) + " ALERT" : e).toList());
            assertEquals("exactly one ALERT", 1, record.inactivity.stream().filter(s -> s.endsWith(" ALERT")).count());
            assertEquals("exactly one mail", 1, sink.messages().size());
            SmtpSink.Received alert = sink.messages().get(0);
            assertEquals("the alert mail", "TinySEP: no activity in Bathroom since 14:01", alert.subject());
            assertTrue("the mail's text names the Bathroom: " + alert.body(), alert.body().contains("Bathroom"));
        } finally {
            if (record != null) {
                record.close();
            }
            executor.shutdownNow();
        }
    }

}
