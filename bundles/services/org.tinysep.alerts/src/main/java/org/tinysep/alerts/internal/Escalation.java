package org.tinysep.alerts.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.List;
import java.util.Optional;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.Notification;
import org.tinysep.api.alert.NotificationStep;

/**
 * The schedule of an open alert, from its history alone (so it continues after a restart): the first message
 * when nothing was sent yet; contact n+1 once the alert has gone unacknowledged for n × {@code escalateMinutes}
 * since its first message; otherwise a repeat to the contacts told so far {@code repeatMinutes} after the last
 * message. An escalation is a message too: the repeat period starts again after it.
 */
final class Escalation {

    /** The next message due: why, to whom, and how many contacts are told after it. */
    record Step(NotificationStep step, List<String> to, int reached) {
    }

    private Escalation() {
    }

    static Optional<Step> due(Alert a, AlertSettings s, Instant now) {
        if (!a.isOpen()) {
            return Optional.empty();
        }
        List<Notification> sent = a.notifications();
        if (sent.isEmpty()) {
            return Optional.of(new Step(NotificationStep.FIRST, s.reached(1), 1));
        }
        Instant first = sent.get(0).at();
        int reached = Math.max(1, a.contactsReached());
        if (s.escalateMinutes() > 0 && reached < s.contacts().size()
                && !now.isBefore(first.plus(Duration.ofMinutes((long) s.escalateMinutes() * reached)))) {
            return Optional.of(new Step(NotificationStep.ESCALATION, List.of(s.contacts().get(reached)),
                    reached + 1));
        }
        Instant last = sent.get(sent.size() - 1).at();
        if (s.repeatMinutes() > 0 && !now.isBefore(last.plus(Duration.ofMinutes(s.repeatMinutes())))) {
            return Optional.of(new Step(NotificationStep.REPEAT, s.reached(reached), reached));
        }
        return Optional.empty();
    }
}
