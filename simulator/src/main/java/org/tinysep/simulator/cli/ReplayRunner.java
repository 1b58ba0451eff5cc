package org.tinysep.simulator.cli;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import java.util.concurrent.locks.LockSupport;
import org.tinysep.simulator.node.ReplayNodes;
import org.tinysep.simulator.node.Target;
import org.tinysep.simulator.replay.ReplayPlan;
import org.tinysep.simulator.time.RealTimeDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;
import org.tinysep.simulator.time.Welcome;

/**
 * Replays a recorded home against a platform ({@code --replay}). In lock-step each played second is first TICKed
 * (the platform's clock reads that second), then its frames are sent, stamped with it by the bus radio; after a
 * second with changes the driver pauses {@code --pace-ms} before the next TICK so the radio has taken them.
 */
final class ReplayRunner {

    /** Longest quiet stretch between two lock-step ticks at {@code --rate changes}; divides the keep-alive period. */
    static final int QUIET_STEP = 10;

    private ReplayRunner() {
    }

    static ReplayResult run(Options o) throws Exception {
        ReplayPlan plan = Replay.plan(Path.of(o.replay()), o.mapping());
        InetAddress host = InetAddress.getByName(o.target());
        Target target = new Target(host, o.amicaPort(), o.sunSpotPort());
        SyncClient sync = null;
        Instant notBefore = Instant.now();
        try {
            if (o.lockstep()) {
                sync = new SyncClient(new InetSocketAddress(host, o.syncPort()), 2000, o.syncKeyBytes());
                Welcome w = sync.hello(o.waitSeconds());
                if (!w.external()) {
                    throw new IllegalStateException("the platform clock is " + w.mode()
                            + ": switch it with 'tinysep:time external' in the platform shell, then start again");
                }
                notBefore = w.platformTime();
            }
            LocalDate firstDay = o.date() != null ? o.date() : Replay.firstDayAfter(plan, notBefore);
            Replay replay = Replay.on(plan, firstDay);
            System.out.println("replay " + o.replay() + " (" + plan.nodes().size() + " nodes, " + plan.actions().size()
                    + " events, " + plan.start() + " .. " + plan.end() + ") -> AmICA " + target.amica() + ", rate "
                    + (o.fullRate() ? "full" : "changes") + ", recorded day " + plan.start().toLocalDate()
                    + " = virtual " + firstDay);
            ReplayResult result = play(o, replay, target, sync);
            if (sync != null && o.releaseClock()) {
                sync.bye();
            }
            return result;
        } finally {
            if (sync != null) {
                sync.close();
            }
        }
    }

    private static ReplayResult play(Options o, Replay replay, Target target, SyncClient sync) throws Exception {
        Instant from = Instant.ofEpochSecond(replay.fromSecond());
        Instant until = Instant.ofEpochSecond(o.end() == null ? replay.untilSecond()
                : Math.max(replay.untilSecond(), replay.virtualSecond(o.end())));
        VirtualClock clock = new VirtualClock(from);
        long wall = System.nanoTime();
        long played = 0;
        try (ReplayNodes nodes = ReplayNodes.create(replay.plan().nodes(), target, o.fullRate())) {
            ReplayPlayer player = new ReplayPlayer(replay, nodes, o.fullRate() ? 1 : QUIET_STEP);
            long progressEvery = Math.max(1, o.progressMinutes()) * 60L;
            long nextProgress = from.getEpochSecond() + progressEvery;
            if (sync == null) {
                new RealTimeDriver(clock, o.speed()).run(from, until, t -> player.step(t.getEpochSecond()));
                played = until.getEpochSecond() - from.getEpochSecond();
            } else {
                for (long t = from.getEpochSecond(); t < until.getEpochSecond(); t = player.next(t)) {
                    Instant at = Instant.ofEpochSecond(t);
                    clock.set(at);
                    sync.tick(at);
                    played++;
                    if (player.step(t) > 0 && o.paceMillis() > 0) {
                        LockSupport.parkNanos(o.paceMillis() * 1_000_000L);
                    }
                    if (t >= nextProgress) {
                        System.out.printf("%s (recorded %s)  %d/%d events  %.1f s wall%n", at,
                                replay.recordedTime(at), player.sent(), replay.plan().actions().size(),
                                (System.nanoTime() - wall) / 1e9);
                        nextProgress += progressEvery * ((t - nextProgress) / progressEvery + 1);
                    }
                }
            }
            Duration took = Duration.ofNanos(System.nanoTime() - wall);
            System.out.printf("done: %d events, %d virtual seconds (%d played) in %.1f s wall time%n", player.sent(),
                    until.getEpochSecond() - from.getEpochSecond(), played, took.toNanos() / 1e9);
            return new ReplayResult(replay, player.sent(), played, took);
        }
    }

}
