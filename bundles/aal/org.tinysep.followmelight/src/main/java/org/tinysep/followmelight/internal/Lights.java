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
 * The connected lights, found by room through the {@link Placements} at the moment of switching. Remembers
 * which lights this service switched on: only those are ever switched off, so a light a person switched on by
 * hand is left alone; a light a person switched off is forgotten.
 */
final class Lights {

    private final Placements directory;
    private final Percent brightness;
    private final Map<String, Provider<?>> all = new LinkedHashMap<>();
    private final Set<String> ours = new HashSet<>();

    Lights(Placements directory, Percent brightness) {
        this.directory = directory;
        this.brightness = brightness;
    }

    synchronized void add(Provider<?> light) {
        all.put(light.deviceUid(), light);
    }

    synchronized void forget(String uid) {
        all.remove(uid);
        ours.remove(uid);
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
        for (Provider<?> p : all.values()) {
            if (!roomUid.equals(directory.roomOf(p.deviceUid()).orElse(null)) || isOn(p)) {
                continue;
            }
            if (p instanceof DimmableLightProvider d) {
                d.setLevel(brightness);
            } else if (p instanceof SimpleLightProvider s) {
                s.switchLight(true);
            }
            ours.add(p.deviceUid());
            uids.add(p.deviceUid());
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
        return offWhere(uid -> roomUid.equals(directory.roomOf(uid).orElse(null)));
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
