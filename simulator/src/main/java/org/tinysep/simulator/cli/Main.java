package org.tinysep.simulator.cli;

import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.time.Instant;
import java.time.LocalDate;
import java.time.ZoneOffset;
import org.tinysep.simulator.agent.Scenario;
import org.tinysep.simulator.flat.Flat;
import org.tinysep.simulator.flat.FlatLoader;
import org.tinysep.simulator.node.Target;
import org.tinysep.simulator.time.LockStepDriver;
import org.tinysep.simulator.time.RealTimeDriver;
import org.tinysep.simulator.time.SyncClient;
import org.tinysep.simulator.time.VirtualClock;
import org.tinysep.simulator.time.Welcome;
import org.tinysep.tools.cli.Cli;

/** The simulator's command line: loads a flat and a scenario and plays them against a platform. */
public final class Main {

    private Main() {
    }

    /** Exit code 2 for a refused command line (one line naming it, then the usage), 1 for a failed run. */
    public static void main(String[] args) {
        Flags flags = new Flags();
        int code = Cli.main(flags, args, System.out, System.err, () -> {
            run(flags.options());
            return Cli.OK;
        });
        if (code != Cli.OK) {
            System.exit(code);
        }
    }

    static void run(Options o) throws Exception {
        if (o.replay() != null) {
            ReplayRunner.run(o);
            return;
        }
        Flat flat = o.noPendant() ? FlatLoader.load(o.flat()).withoutPersonNodes() : FlatLoader.load(o.flat());
        Scenario scenario = Simulation.scenario(o.scenario(), flat);
        InetAddress host = InetAddress.getByName(o.target());
        Target target = new Target(host, o.amicaPort(), o.sunSpotPort());
        LocalDate day = o.date() != null ? o.date() : LocalDate.now(ZoneOffset.UTC);
        SyncClient sync = null;
        if (o.lockstep()) {
            sync = new SyncClient(new InetSocketAddress(host, o.syncPort()), 2000, o.syncKeyBytes());
            Welcome w = sync.hello(o.waitSeconds());
            System.out.println("platform time " + w.platformTime() + ", clock " + w.mode());
            if (!w.external()) {
                sync.close();
                throw new IllegalStateException("the platform clock is " + w.mode()
                        + ": switch it with 'tinysep:time external' in the platform shell, then start again");
            }
            if (o.date() == null) {
                day = w.platformTime().atZone(ZoneOffset.UTC).toLocalDate();
                if (day.atStartOfDay(ZoneOffset.UTC).plusSeconds(o.fromSecond()).toInstant().isBefore(w.platformTime())) {
                    day = day.plusDays(1);
                }
            }
        }
        long midnight = day.atStartOfDay(ZoneOffset.UTC).toEpochSecond();
        Instant from = Instant.ofEpochSecond(midnight + o.fromSecond());
        Instant until = Instant.ofEpochSecond(midnight + o.untilSecond());
        VirtualClock clock = new VirtualClock(from);
        System.out.println("flat " + flat.name() + ": " + flat.house().rooms().size() + " rooms, " + flat.nodes().size()
                + " nodes -> AmICA " + target.amica() + ", Sun SPOT " + target.sunSpot() + "; scenario " + o.scenario()
                + " (" + scenario.agents() + "), seed " + o.seed() + ", " + from + " .. " + until);
        try (Simulation sim = new Simulation(flat, scenario, target, midnight, o.seed(), o.jitter(), o.wander(),
                e -> System.out.println(clock.now() + " " + e), sync != null)) {
            for (long t = midnight; t < from.getEpochSecond(); t++) {
                sim.rehearse(t);
            }
            Progress progress = new Progress(sim, o.progressMinutes(), from);
            long wall = System.nanoTime();
            if (sync != null) {
                new LockStepDriver(sync, clock, o.paceMillis() * 1_000_000L).run(from, until, progress.wrap(sim::step));
                if (o.releaseClock()) {
                    sync.bye();
                    System.out.println("BYE: the platform clock follows real time again");
                }
                sync.close();
            } else {
                new RealTimeDriver(clock, o.speed()).run(from, until, progress.wrap(sim::step));
            }
            System.out.printf("done: %d virtual seconds in %.1f s wall time%n", until.getEpochSecond() - from.getEpochSecond(),
                    (System.nanoTime() - wall) / 1e9);
        }
    }
}
