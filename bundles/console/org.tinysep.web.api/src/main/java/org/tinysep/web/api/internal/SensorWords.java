package org.tinysep.web.api.internal;

import java.time.Instant;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.util.Set;
import org.tinysep.api.device.NodeType;

/**
 * Plain words for the caregiver about a sensor's health: what kind of sensor a node is ("motion sensor") and what
 * its silence means ("falls there cannot be noticed").
 */
final class SensorWords {

    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("yyyy-MM-dd HH:mm");

    private SensorWords() {
    }

    /** @return what the node is, in words: "motion sensor", "door sensor", … ("sensor" for an unknown type) */
    static String kind(Set<String> nodeTypes) {
        if (nodeTypes.contains(NodeType.MOVEMENT)) {
            return "motion sensor";
        }
        if (nodeTypes.contains(NodeType.DOOR)) {
            return "door sensor";
        }
        if (nodeTypes.contains(NodeType.WINDOW)) {
            return "window sensor";
        }
        if (nodeTypes.contains(NodeType.PET_COLLAR)) {
            return "pet collar";
        }
        if (nodeTypes.contains(NodeType.SIMPLE_LIGHT) || nodeTypes.contains(NodeType.DIMMABLE_LIGHT)) {
            return "light";
        }
        if (nodeTypes.contains(NodeType.HEATER)) {
            return "heater";
        }
        if (nodeTypes.contains(NodeType.SPEAKER)) {
            return "speaker";
        }
        if (nodeTypes.contains(NodeType.TEMPERATURE)) {
            return "temperature sensor";
        }
        if (nodeTypes.contains(NodeType.LIGHT_SENSOR)) {
            return "light sensor";
        }
        return "sensor";
    }

    /** @return whether the node watches a person (movement, door, window): its silence hides inactivity */
    static boolean watches(Set<String> nodeTypes) {
        return nodeTypes.contains(NodeType.MOVEMENT) || nodeTypes.contains(NodeType.DOOR)
                || nodeTypes.contains(NodeType.WINDOW);
    }

    /** @return what a silent node means for the person, for a room that still has (or has no) working sensor */
    static String meaning(Set<String> nodeTypes, String room, boolean roomUnmonitored) {
        if (room == null) {
            return "it is not placed in a room, so it watches no room";
        }
        if (watches(nodeTypes)) {
            return roomUnmonitored
                    ? "the " + room + " has no working sensor now: a fall or a long stillness there cannot be noticed"
                    : "the " + room + "'s other sensors still report, so activity there is still seen";
        }
        if (nodeTypes.contains(NodeType.PET_COLLAR)) {
            return "the pet's movements cannot be told apart from the person's";
        }
        return "it cannot be used until it reports again; it does not watch the person";
    }

    /** @return {@code instant} as platform clock time in {@code zone}, e.g. "2026-11-25 14:02" */
    static String clock(Instant instant, ZoneId zone) {
        return instant == null ? "the platform's start" : CLOCK.format(instant.atZone(zone));
    }
}
