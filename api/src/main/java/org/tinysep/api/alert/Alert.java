package org.tinysep.api.alert;

import java.time.Instant;
import java.util.List;
import java.util.Objects;

/**
 * An alert and its history. Immutable: every change yields a new value.
 *
 * @param id            short, stable id for people and commands ({@code tinysep:ack 3}); never reused
 * @param kind          what it is about
 * @param source        who raised it and for what, e.g. {@code inactivity}; {@link AlertService#clear} matches it
 * @param roomUid       the room concerned, or empty
 * @param roomName      its name for people, or empty
 * @param raisedAt      when the condition was detected (platform time)
 * @param subject       one line for people, e.g. "TinySEP: no activity in Bathroom since 14:02"
 * @param text          the full explanation, in plain words
 * @param state         where it stands
 * @param contactsReached how many contacts of the escalation list have been told (1 after the first message)
 * @param closedAt      when it was acknowledged or cleared, or null while open
 * @param closedBy      who acknowledged it, or why it cleared; empty while open
 * @param notifications every message sent about it, oldest first
 */
public record Alert(String id, AlertKind kind, String source, String roomUid, String roomName, Instant raisedAt,
        String subject, String text, AlertState state, int contactsReached, Instant closedAt, String closedBy,
        List<Notification> notifications) {

    public Alert {
        Objects.requireNonNull(id, "id");
        Objects.requireNonNull(kind, "kind");
        source = source == null ? "" : source;
        roomUid = roomUid == null ? "" : roomUid;
        roomName = roomName == null ? "" : roomName;
        Objects.requireNonNull(raisedAt, "raisedAt");
        subject = subject == null ? "" : subject;
        text = text == null ? "" : text;
        Objects.requireNonNull(state, "state");
        closedBy = closedBy == null ? "" : closedBy;
        notifications = notifications == null ? List.of() : List.copyOf(notifications);
    }

    /** @return whether nobody has acknowledged it and its cause has not ended */
    public boolean isOpen() {
        return state == AlertState.OPEN;
    }
}
