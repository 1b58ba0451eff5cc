package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.LocalDate;
import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.atomic.AtomicInteger;
import org.tinysep.simulator.cli.ReplayResult;
import org.tinysep.simulator.cli.Run;
import org.tinysep.simulator.replay.EventsCsv;
import org.tinysep.simulator.replay.SensorEvent;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.testsupport.mail.SmtpSink;

/**
 * One replay through one platform process: copy the snapshot (if any) to a fresh state folder, start the
 * distribution, replay the events in lock-step, wait until every alert the platform handed to its Mail Manager has
 * arrived at the SMTP sink, stop the platform and read back what it wrote to its event log.
 */
final class PlatformRun {

    /** How long to wait for alert mails after the replay (they are sent on the Mail Manager's own thread). */
    private static final long MAIL_WAIT_NANOS = 60_000_000_000L;
    private static final int MAX_ATTEMPTS = 3;
    private static final AtomicInteger RETRIES = new AtomicInteger();

    private PlatformRun() {
    }

    /**
     * @param snapshot  a stopped platform's state folder to start from, or null for an empty one
     * @param dir       the run's folder (home/ and var/ are created in it)
     * @param segments  what to replay, one after another, each later in virtual time than the one before
     * @return the outcome: the entries this run wrote, the mails received
     */
    static Outcome run(Setup setup, Path snapshot, Path dir, String detector, List<Segment> segments)
            throws Exception {
        for (int attempt = 1;; attempt++) {
            try {
                return runOnce(setup, snapshot, dir, detector, segments);
            } catch (SyncClient.NoAnswer e) {
                // the free port the harness chose for the synchroniser was taken by another process before the
                // platform bound it (its log: "TimeController cannot listen on …: Address already in use"): the
                // platform never answers; start it again from a fresh copy, on new ports
                if (attempt == MAX_ATTEMPTS) {
                    throw e;
                }
                RETRIES.incrementAndGet();
                System.out.printf("platform run %s: %s; started again (attempt %d of %d)%n", dir.getFileName(),
                        e.getMessage(), attempt + 1, MAX_ATTEMPTS);
                Snapshot.delete(dir);
            }
        }
    }

    /** @return how many platform runs had to be started again (see {@link #run}) */
    static int retries() {
        return RETRIES.get();
    }

    private static Outcome runOnce(Setup setup, Path snapshot, Path dir, String detector, List<Segment> segments)
            throws Exception {
        Files.createDirectories(dir);
        Path var = dir.resolve("var");
        if (snapshot != null) {
            Snapshot.copy(snapshot, var);
        }
        long before = LogEntry.lastSequence(var);
        try (SmtpSink smtp = new SmtpSink().start();
                HarnessPlatform platform = HarnessPlatform.start(setup.dist(), dir.resolve("home"), var, smtp.port(), detector,
                        Map.of("org.tinysep.houseinformation", "file=" + setup.home().house().toAbsolutePath() + "\n",
                                "org.tinysep.houseinformation.placement", "placements=" + setup.home().placements()
                                        + "\n", "org.tinysep.inactivity", setup.inactivity()))) {
            List<ReplayResult> results = new ArrayList<>();
            for (int k = 0; k < segments.size(); k++) {
                Segment s = segments.get(k);
                Path recording = dir.resolve("events-" + k + ".csv");
                EventsCsv.write(StateReports.prepend(setup.home().events(), s.events()), recording);
                List<String> args = new ArrayList<>(List.of("--replay", recording.toString(), "--mapping",
                        setup.home().mapping().toString(), "--lockstep", "--rate", "changes", "--amica-port",
                        Integer.toString(platform.amicaPort()), "--sync-port", Integer.toString(platform.syncPort()),
                        "--sync-key", platform.syncKey().toString(), "--wait-platform", "120", "--date",
                        s.firstDay().toString(), "--progress", "1000000"));
                if (s.end() != null) {
                    args.addAll(List.of("--end", s.end().toString()));
                }
                results.add(Run.replay(args.toArray(String[]::new)));
            }
            long deadline = System.nanoTime() + MAIL_WAIT_NANOS;
            while (handedOver(var, before) > alertMails(subjects(smtp)).size() && System.nanoTime() < deadline) {
                Thread.sleep(100);
            }
            long drops = org.tinysep.simulator.measure.KernelDrops.at(platform.amicaPort());
            platform.close();
            List<LogEntry> entries = LogEntry.read(var).stream().filter(e -> e.sequence() > before).toList();
            return new Outcome(entries, alertMails(subjects(smtp)), results, handedOver(var, before), drops);
        }
    }

    /**
     * One replay within a run.
     *
     * @param events   what to replay; the replay starts with every contact's and mat's state before them (recorded
     *                 changes only would make a sensor's first change in the segment its first report to the platform,
     *                 {@link StateReports})
     * @param firstDay the virtual day of the events' first recorded day
     * @param end      recorded time to play on to (quiet) after the last event, or null
     */
    record Segment(List<SensorEvent> events, LocalDate firstDay, LocalDateTime end) {
    }

    /**
     * @return each alert's first mail (the alert service's repeats, escalations and all clears, and Sensor Health's
     *         notices, are not alerts)
     */
    /** @return the subjects of the messages the sink received so far, in order */
    private static List<String> subjects(SmtpSink smtp) {
        return smtp.messages().stream().map(SmtpSink.Received::subject).toList();
    }

    static List<String> alertMails(List<String> subjects) {
        return subjects.stream().filter(s -> s.startsWith("TinySEP: no activity")).toList();
    }

    /** @return the alerts Inactivity Recognition handed on: to the alert service, or without it the Mail Manager */
    private static long handedOver(Path var, long after) throws IOException {
        return LogEntry.read(var).stream()
                .filter(e -> e.sequence() > after && (e.message().startsWith("alert handed to the Mail Manager")
                        || e.message().startsWith("alert handed to the alert service")))
                .count();
    }

    /**
     * What one run produced.
     *
     * @param entries    the event-log entries this run wrote
     * @param mails      subjects of the alert mails the SMTP sink received (each alert's first)
     * @param replays    the replays' results (their virtual-time placement)
     * @param handedOver alerts the platform handed to its Mail Manager (event log)
     * @param kernelDrops datagrams the kernel dropped at the platform's AmICA radio socket (-1: not measurable)
     */
    record Outcome(List<LogEntry> entries, List<String> mails, List<ReplayResult> replays, long handedOver,
            long kernelDrops) {
    }

    /**
     * What every run of one home shares.
     *
     * @param inactivity further lines of Inactivity Recognition's configuration (e.g. {@code learnHistoryDays})
     */
    record Setup(java.nio.file.Path dist, Home home, String inactivity) {
        Setup {
            if (!Files.isRegularFile(dist.resolve("tinysep.jar"))) {
                throw new IllegalArgumentException("no distribution at " + dist.toAbsolutePath()
                        + " (build it: mvn -B -o -pl evaluation -am package -DskipTests)");
            }
        }
    }
}
