package org.tinysep.simulator.agent;

import java.util.List;
import java.util.Random;
import org.tinysep.simulator.flat.House;

/**
 * Seeded extra wandering between scripted points: an idle, active agent at home sometimes walks to a neighbouring
 * room and comes back after 30 to 180 s. Pets wander four times as often as people.
 */
final class Wanderer {

    private final House house;
    private final Random random;
    private final double perSecond;

    /** @param perSecond a person's chance per idle second to start a short walk (0 = no wandering) */
    Wanderer(House house, Random random, double perSecond) {
        this.house = house;
        this.random = random;
        this.perSecond = perSecond;
    }

    void maybeWander(Agent a, long t) {
        if (a.state != Agent.State.ACTIVE || !a.path.isEmpty() || a.onArrival != null) {
            return;
        }
        if (a.wanderHome != null) {
            if (t >= a.wanderReturn) {
                a.path.addAll(house.path(a.room, a.wanderHome));
                a.wanderHome = null;
            }
            return;
        }
        double chance = a.pet ? 4 * perSecond : perSecond;
        if (perSecond <= 0 || random.nextDouble() >= chance) {
            return;
        }
        List<String> n = house.neighbours(a.room);
        if (n.isEmpty()) {
            return;
        }
        a.wanderHome = a.room;
        a.wanderReturn = t + 30 + random.nextInt(151);
        a.path.add(n.get(random.nextInt(n.size())));
        a.nextMove = t + 1;
    }
}
