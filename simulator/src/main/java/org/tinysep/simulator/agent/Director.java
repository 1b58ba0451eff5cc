package org.tinysep.simulator.agent;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.function.BiConsumer;
import org.tinysep.simulator.flat.House;
import org.tinysep.simulator.node.Wearer;

/**
 * Moves the agents through the house, one virtual second at a time: applies the scenario's steps at their
 * (jittered) times, walks paths one room per {@link #WALK_SECONDS}, lets idle agents wander, and records what the
 * sensors see in the {@link World}. Deterministic for a given seed.
 */
public final class Director {

    public static final int WALK_SECONDS = 4;

    private final House house;
    private final String entrance;
    private final World world;
    private final Wanderer wanderer;
    private final Map<String, Agent> agents = new LinkedHashMap<>();
    private final List<long[]> due = new ArrayList<>();
    private final List<Step> steps;
    private final BiConsumer<String, Boolean> battery;

    /**
     * @param midnight  epoch second of the simulated day's 00:00
     * @param jitter    steps move by a random -jitter..+jitter seconds (order per agent kept)
     * @param entrance  room of the outer door, or null when the flat has none
     * @param battery   switches a node off (false) or on (true) by id
     */
    public Director(House house, String entrance, Scenario scenario, long midnight, long seed, int jitter,
            double wander, World world, BiConsumer<String, Boolean> battery) {
        this.house = house;
        this.entrance = entrance;
        this.world = world;
        this.battery = battery;
        this.steps = scenario.steps();
        Random random = new Random(seed);
        this.wanderer = new Wanderer(house, random, wander);
        Map<String, Long> last = new LinkedHashMap<>();
        for (Step s : steps) {
            long at = midnight + s.secondOfDay();
            if (s.agent() != null) {
                at = Math.max(at + (jitter == 0 ? 0 : random.nextInt(2 * jitter + 1) - jitter), last.getOrDefault(s.agent(), midnight - 1) + 1);
                last.put(s.agent(), at);
                agents.computeIfAbsent(s.agent(), n -> place(new Agent(n, scenario.pets().contains(n)), s));
            }
            due.add(new long[] {at});
        }
        if (entrance == null && steps.stream().anyMatch(s -> s.action() == Action.LEAVES || s.action() == Action.ARRIVES)) {
            throw new IllegalArgumentException("the scenario has people leaving or arriving but the flat has no outer door (door=outer)");
        }
    }

    /** An agent whose first step is not an arrival is at home from the start, in the first room it names. */
    private static Agent place(Agent a, Step first) {
        if (first.action() != Action.ARRIVES && first.action() != Action.LEAVES && first.room() != null) {
            a.room = first.room();
            a.state = Agent.State.ACTIVE;
        }
        return a;
    }

    /** Plays one virtual second {@code t} (epoch seconds). */
    public void advance(long t) {
        List<Step> now = new ArrayList<>();
        for (int i = 0; i < steps.size(); i++) {
            if (due.get(i)[0] <= t) {
                now.add(steps.get(i));
                due.get(i)[0] = Long.MAX_VALUE;
            }
        }
        now.forEach(s -> apply(s, t));
        for (Agent a : agents.values()) {
            walk(a, t);
            if (a.home()) {
                wanderer.maybeWander(a, t);
            }
            if (!a.pet) {
                world.personState(a.name, Wearer.State.valueOf(a.state.name()), t); // what a worn node feels
            }
            if (a.state == Agent.State.ACTIVE) {
                if (a.pet && t - a.lastMove < 20) {
                    world.petMoved(a.name, t);
                } else if (!a.pet) {
                    world.personMoved(a.room, t);
                }
            }
        }
    }

    private void apply(Step s, long t) {
        if (s.action() == Action.BATTERY) {
            trace(t, s.target(), "battery " + (s.on() ? "on" : "off"));
            battery.accept(s.target(), s.on());
            return;
        }
        Agent a = agents.get(s.agent());
        a.clearPlans();
        switch (s.action()) {
        case GO -> goTo(a, s.room(), t);
        case FROM_TO -> {
            goTo(a, s.room(), t);
            String from = a.path.isEmpty() ? a.room : a.path.peekLast();
            a.path.addAll(house.path(from, s.room2()));
        }
        case ARRIVES -> {
            if (!a.home()) {
                arrive(a, t);
            }
            if (s.room() != null) {
                a.path.addAll(house.path(a.room, s.room()));
            }
        }
        case LEAVES -> {
            if (a.home()) {
                a.state = Agent.State.ACTIVE;
                a.path.addAll(house.path(a.room, entrance));
                a.onArrival = Action.LEAVES;
            }
        }
        case COLLAPSES, SLEEPS -> {
            if (s.room() != null) {
                goTo(a, s.room(), t);
            }
            a.onArrival = s.action();
        }
        case WAKES -> {
            if (a.home()) {
                state(a, Agent.State.ACTIVE, t, "gets up in " + a.room);
            }
        }
        default -> throw new IllegalStateException(s.action().name());
        }
        a.nextMove = Math.max(a.nextMove, t);
        walk(a, t);
    }

    private void goTo(Agent a, String room, long t) {
        if (!a.home()) {
            arrive(a, t);
        }
        a.state = Agent.State.ACTIVE;
        a.path.addAll(house.path(a.room, room));
    }

    private void arrive(Agent a, long t) {
        a.room = entrance;
        world.doorPassed(entrance, t);
        a.lastMove = t;
        a.nextMove = t + WALK_SECONDS; // through the door first, then on
        if (!a.pet) {
            world.personMoved(entrance, t);
        }
        state(a, Agent.State.ACTIVE, t, "arrives in " + entrance);
    }

    private void walk(Agent a, long t) {
        if (!a.path.isEmpty() && t >= a.nextMove) {
            a.room = a.path.poll();
            a.lastMove = t;
            a.nextMove = t + WALK_SECONDS;
            if (!a.pet) {
                world.personMoved(a.room, t); // walking in is motion, even if the person lies down at once
            }
            trace(t, a.name, a.room);
        }
        if (a.path.isEmpty() && a.onArrival != null && t >= a.nextMove - WALK_SECONDS) {
            Action done = a.onArrival;
            a.onArrival = null;
            switch (done) {
            case LEAVES -> {
                world.doorPassed(a.room, t);
                state(a, Agent.State.AWAY, t, "leaves");
                a.room = null;
            }
            case COLLAPSES -> state(a, Agent.State.COLLAPSED, t, "collapses in " + a.room);
            case SLEEPS -> state(a, Agent.State.ASLEEP, t, "sleeps in " + a.room);
            default -> throw new IllegalStateException(done.name());
            }
        }
    }

    private void state(Agent a, Agent.State s, long t, String what) {
        a.state = s;
        trace(t, a.name, what);
    }

    private void trace(long t, String who, String what) {
        world.trace(t, who, what);
    }

    /** @return the room each agent is in (null when away), for progress reports */
    public Map<String, String> whereabouts() {
        Map<String, String> m = new LinkedHashMap<>();
        agents.values().forEach(a -> m.put(a.name, a.whereabouts()));
        return m;
    }
}
