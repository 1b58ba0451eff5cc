package org.tinysep.mqtt.internal;

import org.tinysep.device.support.lifecycle.Safely;
import static org.tinysep.json.JsonWriter.object;
import static org.tinysep.json.JsonWriter.writePlain;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertService;
import org.tinysep.api.alert.AlertState;

/**
 * Turns alert changes into alert messages (retained, QoS 1, through the outbox on disk, each with the next per-flat
 * {@code seq}): one message per change of {@link AlertState} (changes of notifications alone are not published);
 * when an alert is CLEARED the CLEARED message is followed at once by a zero-length retained message on the same
 * topic, so the broker keeps nothing of a cleared alert. Used on the bridge's thread.
 */
final class Alerts {

    private final Topics topics;
    private final AlertSpool spool;
    private final Outbox outbox;

    Alerts(Topics topics, Outbox outbox) {
        this.topics = topics;
        this.outbox = outbox;
        this.spool = outbox.spool();
    }

    /** @return whether a message was queued */
    boolean changed(Alert a) throws IOException {
        Message last = spool.latest(a.id());
        if (last != null && last.payload().length == 0) {
            return false; // cleared and emptied already; ids are never reused
        }
        if (last == null && a.state() == AlertState.CLEARED) {
            return false; // never published: nothing to take back
        }
        if (last != null && a.state().name().equals(stateOf(last))) {
            return false; // a notification or delivery outcome changed, not the state
        }
        long seq = spool.nextSeq();
        outbox.alert(new Message(topics.alert(a.id()), writePlain(payload(a, seq)).getBytes(
                java.nio.charset.StandardCharsets.UTF_8), true, seq, a.id()));
        if (a.state() == AlertState.CLEARED) {
            outbox.alert(new Message(topics.alert(a.id()), new byte[0], true, spool.nextSeq(), a.id()));
        }
        return true;
    }

    /** After a start or a new alert service: publishes what changed while the bridge was not running. */
    void sync(AlertService service) throws IOException {
        for (Alert a : Safely.get(() -> service.recent(200), List.<Alert>of())) {
            changed(a);
        }
    }

    Map<String, Object> payload(Alert a, long seq) {
        boolean acked = a.state() == AlertState.ACKNOWLEDGED;
        boolean cleared = a.state() == AlertState.CLEARED;
        return object("id", a.id(), "flat", topics.flatId(), "kind", a.kind().name(), "state", a.state().name(),
                "raisedAt", a.raisedAt(), "room", a.roomName(), "title", a.subject(), "text", a.text(),
                "acknowledgedBy", acked ? a.closedBy() : null, "acknowledgedAt", acked ? a.closedAt() : null,
                "clearedAt", cleared ? a.closedAt() : null, "clearedWhy", cleared ? a.closedBy() : null,
                "explanation", explanation(a), "seq", seq);
    }

    private static String explanation(Alert a) {
        return switch (a.state()) {
            case OPEN -> "open, nobody has acknowledged it yet: " + a.subject();
            case ACKNOWLEDGED -> a.closedBy() + " acknowledged it at " + a.closedAt() + ": " + a.subject();
            case CLEARED -> "over: " + a.closedBy();
        };
    }

    /** The retained ON/OFF of one alert kind (Home Assistant's problem sensor). */
    Message kindState(AlertKind kind, List<Alert> open) {
        long n = open.stream().filter(a -> a.kind() == kind).count();
        return Message.state(topics.alertKind(kind.name()), writePlain(object("kind", kind.name(),
                "state", n > 0 ? "ON" : "OFF", "open", n, "explanation", n == 0 ? "no open " + kind.words()
                        + " alert" : n + " open " + kind.words() + " alert(s), not yet acknowledged")));
    }

    private static String stateOf(Message m) {
        try {
            Object s = Commands.object(m.text()).get("state");
            return s == null ? "" : s.toString();
        } catch (IllegalArgumentException e) {
            return "";
        }
    }
}
