package org.tinysep.simulator.agent;

import java.time.Instant;
import java.time.ZoneOffset;
import java.time.format.DateTimeFormatter;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Map;
import java.util.NavigableSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentSkipListSet;
import org.tinysep.simulator.node.Environment;
import org.tinysep.simulator.node.Wearer;

/**
 * What the agents did, as the sensors see it: the last second a person moved in each room, the last second each
 * pet moved, and when the outer door was opened (it stands open for {@link #DOOR_OPEN_SECONDS}). Pets do not
 * count as person motion (pet-immune movement sensors); collapsed and sleeping people make no motion.
 */
public final class World implements Environment {

    public static final int DOOR_OPEN_SECONDS = 3;
    private static final DateTimeFormatter HMS = DateTimeFormatter.ofPattern("HH:mm:ss").withZone(ZoneOffset.UTC);

    private final Map<String, Long> personMotion = new ConcurrentHashMap<>();
    private final Map<String, Long> petMotion = new ConcurrentHashMap<>();
    private final Map<String, NavigableSet<Long>> doorOpened = new ConcurrentHashMap<>();
    private final Map<String, Wearer> wearers = new ConcurrentHashMap<>();
    private final List<String> trace = Collections.synchronizedList(new ArrayList<>());

    void personMoved(String room, long second) {
        personMotion.put(room, second);
    }

    void petMoved(String pet, long second) {
        petMotion.put(pet, second);
    }

    void doorPassed(String room, long second) {
        doorOpened.computeIfAbsent(room, r -> new ConcurrentSkipListSet<>()).add(second);
    }

    /** A person's state at second {@code t} (recorded every second); since when it holds is kept. */
    void personState(String person, Wearer.State state, long t) {
        wearers.compute(person, (k, w) -> w != null && w.state() == state ? w : new Wearer(state, t));
    }

    @Override
    public Wearer wearer(String person) {
        return wearers.getOrDefault(person, Wearer.AWAY);
    }

    void trace(long t, String who, String what) {
        trace.add(HMS.format(Instant.ofEpochSecond(t)) + " " + who + " " + what);
    }

    /** @return what happened so far, one entry per room change or state change, {@code HH:MM:SS agent what} */
    public List<String> trace() {
        synchronized (trace) {
            return List.copyOf(trace);
        }
    }

    @Override
    public boolean personMotion(String room, long after, long upTo) {
        return personMotion.getOrDefault(room, Long.MIN_VALUE) > after;
    }

    @Override
    public boolean petMotion(String agent, long after, long upTo) {
        return petMotion.getOrDefault(agent, Long.MIN_VALUE) > after;
    }

    @Override
    public boolean doorOpen(String room, long second) {
        NavigableSet<Long> openings = doorOpened.get(room);
        Long opened = openings == null ? null : openings.floor(second);
        return opened != null && second >= opened && second < opened + DOOR_OPEN_SECONDS;
    }
}
