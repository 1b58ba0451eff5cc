package org.tinysep.api.alert;

import java.time.Instant;
import java.util.Objects;

/**
 * What a detector hands to {@link AlertService#raise}.
 *
 * @param kind     what it is about
 * @param source   who raises it, e.g. {@code inactivity}: an open alert of the same source and {@code raisedAt}
 *                 is the same alert (raising it again changes nothing), and {@link AlertService#clear} ends the
 *                 source's open alerts
 * @param roomUid  the room concerned, or empty
 * @param roomName its name, or empty
 * @param raisedAt when the condition was detected
 * @param subject  one line for people (the mail subject)
 * @param text     the explanation in plain words (the mail body)
 */
public record AlertRequest(AlertKind kind, String source, String roomUid, String roomName, Instant raisedAt,
        String subject, String text) {

    public AlertRequest {
        Objects.requireNonNull(kind, "kind");
        Objects.requireNonNull(source, "source");
        Objects.requireNonNull(raisedAt, "raisedAt");
        Objects.requireNonNull(subject, "subject");
        roomUid = roomUid == null ? "" : roomUid;
        roomName = roomName == null ? "" : roomName;
        text = text == null ? "" : text;
    }
}
