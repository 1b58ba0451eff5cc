package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.Objects;
import java.util.function.Supplier;

/**
 * One observed activity, already placed in its room. Its description ("movement by Bathroom sensor") names the
 * device, which costs a look-up in the service registry: it is built when something first reads it (the event
 * log line of a state change, an alert, the backup every 10 s), not on the radio's receive thread for every
 * activity (21 % of that thread). Equal activities have equal fields (the description's text).
 */
final class Activity {

    private final String roomUid;
    private final String roomName;
    private final Instant at;
    private final Duration limit;
    private final String explanation;
    private Supplier<String> describe; // null once built
    private volatile String description;

    /**
     * @param roomUid     the room's UID, empty when the reporting device has no room
     * @param roomName    the room's name for people (e.g. "Bathroom", or "unknown room (device Hall sensor)")
     * @param description what happened, e.g. "movement by Bathroom sensor"
     * @param at          when it happened
     * @param limit       how long inactivity may last after it before help is called
     * @param explanation why that limit, in plain words (empty when not known, e.g. restored from an old backup)
     */
    Activity(String roomUid, String roomName, String description, Instant at, Duration limit, String explanation) {
        this(roomUid, roomName, at, limit, explanation, null, Objects.requireNonNull(description, "description"));
    }

    Activity(String roomUid, String roomName, String description, Instant at, Duration limit) {
        this(roomUid, roomName, description, at, limit, "");
    }

    /** As the canonical constructor, with the description built from {@code describe} when first read. */
    static Activity described(String roomUid, String roomName, Supplier<String> describe, Instant at,
            Duration limit, String explanation) {
        return new Activity(roomUid, roomName, at, limit, explanation, Objects.requireNonNull(describe, "describe"),
                null);
    }

    private Activity(String roomUid, String roomName, Instant at, Duration limit, String explanation,
            Supplier<String> describe, String description) {
        this.roomUid = Objects.requireNonNull(roomUid, "roomUid");
        this.roomName = Objects.requireNonNull(roomName, "roomName");
        this.at = Objects.requireNonNull(at, "at");
        this.explanation = explanation == null ? "" : explanation;
        if (limit == null || limit.isNegative() || limit.isZero()) {
            throw new IllegalArgumentException("limit must be positive, was " + limit);
        }
        this.limit = limit;
        this.describe = describe;
        this.description = description;
    }

    String roomUid() {
        return roomUid;
    }

    String roomName() {
        return roomName;
    }

    /** @return what happened, e.g. "movement by Bathroom sensor" (built at the first call) */
    String description() {
        String d = description;
        if (d == null) {
            synchronized (this) {
                d = description;
                if (d == null) {
                    d = Objects.requireNonNull(describe.get(), "description");
                    description = d;
                    describe = null;
                }
            }
        }
        return d;
    }

    Instant at() {
        return at;
    }

    Duration limit() {
        return limit;
    }

    String explanation() {
        return explanation;
    }

    /** @return this activity moved to {@code when} (the clock went back); the description stays lazy */
    Activity at(Instant when) {
        String d = description;
        return d != null ? new Activity(roomUid, roomName, when, limit, explanation, null, d)
                : new Activity(roomUid, roomName, when, limit, explanation, this::description, null);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Activity a && roomUid.equals(a.roomUid) && roomName.equals(a.roomName)
                && at.equals(a.at) && limit.equals(a.limit) && explanation.equals(a.explanation)
                && description().equals(a.description());
    }

    @Override
    public int hashCode() {
        return Objects.hash(roomUid, roomName, at, limit, explanation);
    }

    @Override
    public String toString() {
        return "Activity[roomUid=" + roomUid + ", roomName=" + roomName + ", description=" + description() + ", at="
                + at + ", limit=" + limit + ", explanation=" + explanation + "]";
    }
}
