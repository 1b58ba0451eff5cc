package org.tinysep.simulator.agent;

import java.util.ArrayDeque;
import java.util.Deque;

/** A person or pet of the simulation: where it is, what it does and where it is walking. */
final class Agent {

    enum State { AWAY, ACTIVE, ASLEEP, COLLAPSED }

    final String name;
    final boolean pet;
    String room;
    State state = State.AWAY;
    final Deque<String> path = new ArrayDeque<>();
    /** what happens when the path is walked: LEAVES, COLLAPSES, SLEEPS or null */
    Action onArrival;
    long nextMove;
    long lastMove = Long.MIN_VALUE / 2;
    String wanderHome;
    long wanderReturn;

    Agent(String name, boolean pet) {
        this.name = name;
        this.pet = pet;
    }

    boolean home() {
        return state != State.AWAY;
    }

    /** @return the room (with the state unless active), or "away" */
    String whereabouts() {
        if (!home()) {
            return "away";
        }
        return state == State.ACTIVE ? room : room + " (" + state.name().toLowerCase(java.util.Locale.ROOT) + ")";
    }

    void clearPlans() {
        path.clear();
        onArrival = null;
        wanderHome = null;
    }
}
