package org.tinysep.device.support.lifecycle;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.api.device.Device;
import org.tinysep.api.device.Parameter;
import org.tinysep.api.service.Room;
import org.tinysep.device.support.health.HealthWords;
import org.tinysep.device.support.rooms.RoomDirectory;

/**
 * The sources a device that watches the person (Inactivity Recognition, Flat Occupancy) lost:
 * such a device is not removed when its sensors go (a deliberate deviation from thesis 3.3), it says instead which
 * sensor in which room it can no longer see, as a {@code Monitoring reduced: } PROBLEM entry and its
 * {@value #PARAMETER} parameter, until the sensor is back.
 */
final class LostSources {

    /** The read-only parameter of a watching device that names the rooms it can no longer see. */
    static final String PARAMETER = "roomsNotSeen";
    /** The shared prefix of caregiver-visible "monitoring reduced" signals (docs/security.md). */
    static final String REDUCED = "Monitoring reduced: ";

    /** A sensor gone: its UID and name, its room's name (null when it was placed in no room), since when. */
    record Lost(String providerUid, String sensorName, String roomName, Instant since) {
    }

    private static final Pattern LABEL = Pattern.compile("(.*) \\(([^()]*)\\)$");

    private final Map<String, Lost> lost = new LinkedHashMap<>();

    synchronized void add(Lost l) {
        lost.put(l.providerUid(), l);
    }

    /** @return the sensor of that UID if it was lost (it is back now), else null */
    synchronized Lost back(String providerUid) {
        return lost.remove(providerUid);
    }

    /** @return e.g. {@code Bathroom (its sensor "Bathroom movement" went away at 2026-11-22 10:00:00 UTC)}, or "" */
    synchronized String describe() {
        List<String> out = new ArrayList<>();
        for (Lost l : lost.values()) {
            out.add((l.roomName() == null ? "a sensor placed in no room" : l.roomName()) + " (its sensor \""
                    + l.sensorName() + "\" went away at " + HealthWords.time(l.since()) + ")");
        }
        return String.join(", ", out);
    }

    /**
     * @param provider the provider object that went (a {@link Device} in practice: its name and room are read)
     * @return the lost sensor in words the caregiver knows: its name and its room's name
     */
    static Lost of(String providerUid, Object provider, RoomDirectory rooms, Instant now) {
        String name = providerUid;
        String room = null;
        if (provider instanceof Device d) {
            try {
                name = d.name();
                room = d.parameters().stream().filter(p -> p.key().equals(RoomPlacement.KEY)).map(Parameter::value)
                        .filter(v -> v != null && !v.isBlank()).findFirst().map(v -> roomName(v, rooms)).orElse(null);
            } catch (RuntimeException e) { // a device half gone: its UID is all there is
                name = providerUid;
            }
        }
        return new Lost(providerUid, name, room, now);
    }

    /** @return the room's name from a room parameter's value: {@code Name (uid)}, or a bare UID */
    static String roomName(String shown, RoomDirectory rooms) {
        Matcher m = LABEL.matcher(shown.strip());
        String uid = m.matches() ? m.group(2) : shown.strip();
        String fallback = m.matches() ? m.group(1) : shown.strip();
        try {
            return rooms.room(uid).map(Room::name).orElse(fallback);
        } catch (RuntimeException e) {
            return fallback;
        }
    }

    /** @return the PROBLEM entry: what went, where, since when, what it means and what to do */
    static String problem(String watcher, Lost l, boolean sourcesLeft) {
        String sensor = "\"" + l.sensorName() + "\"" + (l.sensorName().equals(l.providerUid()) ? ""
                : " (" + l.providerUid() + ")");
        String what = l.roomName() == null
                ? watcher + " lost its sensor " + sensor + ", which is placed in no room, at " + HealthWords.time(l.since())
                        + ": what that sensor saw is not noticed until it is back"
                : watcher + " can no longer see the " + l.roomName() + ": its sensor " + sensor + " went away at "
                        + HealthWords.time(l.since()) + "; activity in the " + l.roomName()
                        + " is not noticed until the sensor is back";
        return REDUCED + what + (sourcesLeft ? "" : ". It has no sensor left; it keeps running and watches again as "
                + "soon as one is back") + ". Check the sensor and its radio node (tinysep:devices lists them)"
                + "; an open alert stays open.";
    }

    /** @return the event when the sensor is back */
    static String backWords(Lost l) {
        return "monitoring restored: the sensor \"" + l.sensorName() + "\""
                + (l.roomName() == null ? "" : " in the " + l.roomName()) + " is back and watched again";
    }
}
