package org.tinysep.simulator.cli;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDate;
import org.tinysep.simulator.node.ReplayNodes;
import org.tinysep.simulator.node.Target;
import org.tinysep.simulator.replay.ReplayPlan;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.RealTimeDriver;
import org.tinysep.simulator.time.Stepper;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;
import org.tinysep.simulator.time.Welcome;

/**
 * Replays a recorded home against a platform ({@code --replay}), in real time or in lock-step through the
 * simulator's one {@link LockStepDriver} (each played second TICKed, then its frames sent and stamped with it),
 * skipping to the next second with something to send ({@link ReplayPlayer#next}).
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
            ReplayProgress progress = new ReplayProgress(replay, o.progressMinutes(), from);
            if (sync == null) {
                new RealTimeDriver(clock, o.speed()).run(from, until, t -> player.step(t.getEpochSecond()));
                played = until.getEpochSecond() - from.getEpochSecond();
            } else {
                Stepper stepper = at -> {
                    int changed = player.step(at.getEpochSecond());
                    progress.report(at, player.sent(), wall);
                    return changed;
                };
                played = new LockStepDriver(sync, clock, o.paceMillis() * 1_000_000L).run(from, until, stepper,
                        player::next);
            }
            Duration took = Duration.ofNanos(System.nanoTime() - wall);
            System.out.printf("done: %d events, %d virtual seconds (%d played) in %.1f s wall time%n", player.sent(),
                    until.getEpochSecond() - from.getEpochSecond(), played, took.toNanos() / 1e9);
            return new ReplayResult(replay, player.sent(), played, took);
        }
    }

}
