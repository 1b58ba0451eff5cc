package org.tinysep.followmelight.internal;

import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.function.Predicate;
import org.tinysep.api.actuator.DimmableLightProvider;
import org.tinysep.api.actuator.SimpleLightProvider;
import org.tinysep.api.device.Provider;
import org.tinysep.api.sensor.Percent;
import org.tinysep.device.support.rooms.Placements;

/**
 * The connected lights, found by room in a {@link RoomIndex}: a light's room is read from the placements when the
 * light is connected and again when it is said to have moved ({@link #moved}), not per switching, so lighting a
 * room costs the same with 4 lights in the flat or 400. Remembers which lights this service switched on: only
 * those are ever switched off, so a light a person switched on by hand is left alone; a light a person switched
 * off is forgotten.
 */
final class Lights {

    private final Placements directory;
    private final Percent brightness;
    private final RoomIndex index = new RoomIndex();
    private final Map<String, Provider<?>> all = new LinkedHashMap<>();
    private final Set<String> ours = new HashSet<>();

    /** @param directory the rooms of the lights (read when a light is connected or moved) and their names */
    Lights(Placements directory, Percent brightness) {
        this.directory = directory;
        this.brightness = brightness;
    }

    synchronized void add(Provider<?> light) {
        String uid = light.deviceUid();
        all.put(uid, light);
        index.place(uid, directory.roomOf(uid).orElse(null));
    }

    synchronized void forget(String uid) {
        all.remove(uid);
        ours.remove(uid);
        index.remove(uid);
    }

    /** Light {@code uid} may be in another room now (its placement changed): its room is read again. */
    synchronized void moved(String uid) {
        if (all.containsKey(uid)) {
            index.place(uid, directory.roomOf(uid).orElse(null));
        }
    }

    /** Every light may be in another room now (the house plan changed): their rooms are read again. */
    synchronized void movedAll() {
        for (String uid : all.keySet()) {
            index.place(uid, directory.roomOf(uid).orElse(null));
        }
    }

    /** A light reported it is off (by us or by hand): it is no longer ours to switch off. */
    synchronized void reportedOff(String uid) {
        ours.remove(uid);
    }

    /**
     * Switches on the lights of the room that are not on yet: every command is sent before any name is looked up
     * (a name is read through the service registry). @return the names of those switched
     */
    synchronized List<String> on(String roomUid) {
        List<String> uids = new ArrayList<>();
        for (String uid : index.in(roomUid)) {
            Provider<?> p = all.get(uid);
            if (isOn(p)) {
                continue;
            }
            if (p instanceof DimmableLightProvider d) {
                d.setLevel(brightness);
            } else if (p instanceof SimpleLightProvider s) {
                s.switchLight(true);
            }
            ours.add(uid);
            uids.add(uid);
        }
        return names(uids);
    }

    private List<String> names(List<String> uids) {
        List<String> names = new ArrayList<>(uids.size());
        uids.forEach(uid -> names.add(directory.nameOf(uid)));
        return names;
    }

    /** Switches off the room's lights that this service switched on. @return their names */
    synchronized List<String> off(String roomUid) {
        return offWhere(uid -> roomUid.equals(index.roomOf(uid)));
    }

    /** Switches off every light this service switched on, wherever it is now. @return their names */
    synchronized List<String> offAll() {
        return offWhere(uid -> true);
    }

    private List<String> offWhere(Predicate<String> which) {
        List<String> switched = new ArrayList<>();
        for (String uid : List.copyOf(ours)) {
            Provider<?> p = all.get(uid);
            if (p == null || !which.test(uid)) {
                continue;
            }
            if (p instanceof DimmableLightProvider d) {
                d.setLevel(Percent.ZERO);
            } else if (p instanceof SimpleLightProvider s) {
                s.switchLight(false);
            }
            ours.remove(uid);
            switched.add(uid);
        }
        return names(switched);
    }

    private static boolean isOn(Provider<?> p) {
        if (p instanceof DimmableLightProvider d) {
            return d.level().map(b -> b.value() > 0).orElse(false);
        }
        return p instanceof SimpleLightProvider s && s.isOn().orElse(false);
    }

    synchronized Set<String> ours() {
        return Set.copyOf(ours);
    }

    synchronized int count() {
        return all.size();
    }
}
