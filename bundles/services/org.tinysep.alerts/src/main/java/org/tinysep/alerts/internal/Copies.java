package org.tinysep.alerts.internal;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.alert.AlertState;
import org.tinysep.api.alert.Notification;

/** New values of the immutable {@link Alert}: raised, closed, with one more message, with updated messages. */
final class Copies {

    private Copies() {
    }

    static Alert raised(String id, AlertRequest r) {
        return new Alert(id, r.kind(), r.source(), r.roomUid(), r.roomName(), r.raisedAt(), r.subject(), r.text(),
                AlertState.OPEN, 0, null, "", List.of());
    }

    /** @return {@code a} acknowledged or cleared; an earlier close (time, who or why) is kept */
    static Alert closed(Alert a, AlertState state, Instant at, String byOrWhy) {
        return new Alert(a.id(), a.kind(), a.source(), a.roomUid(), a.roomName(), a.raisedAt(), a.subject(),
                a.text(), state, a.contactsReached(), a.closedAt() == null ? at : a.closedAt(),
                a.closedBy().isEmpty() ? byOrWhy : a.closedBy(), a.notifications());
    }

    static Alert plus(Alert a, Notification n, int contactsReached) {
        List<Notification> all = new ArrayList<>(a.notifications());
        all.add(n);
        return notifications(a, all, contactsReached);
    }

    static Alert notifications(Alert a, List<Notification> all, int contactsReached) {
        return new Alert(a.id(), a.kind(), a.source(), a.roomUid(), a.roomName(), a.raisedAt(), a.subject(),
                a.text(), a.state(), contactsReached, a.closedAt(), a.closedBy(), all);
    }
}
