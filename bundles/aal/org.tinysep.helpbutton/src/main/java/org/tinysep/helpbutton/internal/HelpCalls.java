package org.tinysep.helpbutton.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.format.DateTimeFormatter;
import java.util.HashMap;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.tinysep.api.alert.Alert;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.sensor.person.ButtonAction;
import org.tinysep.api.sensor.person.ButtonEvent;
import org.tinysep.device.support.time.Due;

/**
 * The help button's rule, without OSGi: a switch held for at least {@code hold} is a help call, raised at once
 * through the alert service (on the release, or at the platform tick that finds the switch still held, whichever
 * comes first); a press within {@code cancel} of the call cancels it as pressed by mistake. Every step is told in
 * words to {@code events}. Times are the frames' arrivals and the platform's ticks. Thread-safe.
 */
final class HelpCalls {

    /** Where help calls go: the alert service, if one runs. */
    interface Desk {
        /** @return the alert raised, or empty if no alert service runs */
        Optional<Alert> raise(AlertRequest request);

        /** @return how many alerts were cleared, or empty if no alert service runs */
        Optional<Integer> clear(String source, String why);
    }

    /** One person node as the help button knows it. */
    record Node(String uid, String address, java.util.function.Supplier<Optional<String>> person) {
        String who() {
            return person.get().orElse("the wearer of person node " + address);
        }

        String source() {
            return "help:" + address;
        }
    }

    private static final class State {
        Instant pressedAt;
        int pressedButton;
        boolean raisedByThisPress;
        boolean cancelPress;
        Instant calledAt;
    }

    private final Desk desk;
    private final Consumer<String> events;
    private final Map<String, State> states = new HashMap<>();
    private final Map<String, Node> nodes = new HashMap<>();
    private volatile HelpSettings settings = HelpSettings.DEFAULTS;
    private volatile Consumer<Instant> due = at -> { };

    HelpCalls(Desk desk, Consumer<String> events) {
        this.desk = desk;
        this.events = events;
    }

    void settings(HelpSettings s) {
        settings = s;
    }

    /** Where a press says when it becomes a help call if still held: a tick is needed then (the ticker). */
    void whenDue(Consumer<Instant> due) {
        this.due = due;
    }

    /** A switch of {@code node} changed. */
    synchronized void button(Node node, ButtonEvent e) {
        HelpSettings s = settings;
        if (!s.isHelpSwitch(e.button())) {
            return;
        }
        nodes.put(node.uid(), node);
        State st = states.computeIfAbsent(node.uid(), k -> new State());
        if (e.action() == ButtonAction.PRESSED) {
            if (st.calledAt != null && !s.cancel().isZero() && !e.at().isAfter(st.calledAt.plus(s.cancel()))) {
                cancel(node, st, e.at());
                return;
            }
            st.calledAt = null;
            st.pressedAt = e.at();
            st.pressedButton = e.button();
            st.raisedByThisPress = false;
            st.cancelPress = false;
            due.accept(e.at().plus(s.hold())); // still held then: a help call
            return;
        }
        if (st.cancelPress) {
            st.cancelPress = false;
            return;
        }
        if (st.pressedAt == null || st.pressedButton != e.button()) {
            return; // a release whose press was lost or belongs to the other switch
        }
        Duration held = Duration.between(st.pressedAt, e.at());
        if (!st.raisedByThisPress) {
            if (held.compareTo(s.hold()) >= 0) {
                call(node, st, e.at(), held, "held for " + seconds(held));
            } else {
                events.accept(node.who() + " pressed switch " + e.button() + " for only " + seconds(held)
                        + ": not a help call (the switch must be held for at least " + seconds(s.hold()) + ")");
            }
        }
        st.pressedAt = null;
    }

    /**
     * A platform tick: a switch held long enough but not yet released is a help call now.
     *
     * @return when a switch pressed now becomes a help call if still held; null when none is held
     */
    synchronized Instant tick(Instant now) {
        HelpSettings s = settings;
        Instant next = null;
        for (Map.Entry<String, State> e : states.entrySet()) {
            State st = e.getValue();
            if (st.pressedAt == null || st.raisedByThisPress) {
                continue;
            }
            Duration held = Duration.between(st.pressedAt, now);
            if (held.compareTo(s.hold()) >= 0) {
                call(nodes.get(e.getKey()), st, now, held, "still held after " + seconds(held));
            } else {
                Instant at = st.pressedAt.plus(s.hold());
                next = Due.earliest(next, at);
            }
        }
        return next;
    }

    /** The node is gone: forget its state. */
    synchronized void forget(String uid) {
        states.remove(uid);
        nodes.remove(uid);
    }

    private void call(Node node, State st, Instant at, Duration held, String how) {
        HelpSettings s = settings;
        st.raisedByThisPress = true;
        st.calledAt = at;
        String time = time(at);
        String cancel = s.cancel().isZero() ? "" : " If it was pressed by mistake, a second press within "
                + seconds(s.cancel()) + " cancels the call and everyone told gets an all clear.";
        AlertRequest request = new AlertRequest(AlertKind.HELP, node.source(), "", "", at,
                "TinySEP: " + node.who() + " asks for help (help button, " + time + ")",
                node.who() + " held switch " + st.pressedButton + " of the person node " + node.address() + " ("
                        + how + ", at " + time + "): a call for help. Please call back or go there now."
                        + cancel);
        Optional<Alert> alert = desk.raise(request);
        if (alert.isEmpty()) {
            events.accept("help call from " + node.who() + " at " + time + " (switch " + st.pressedButton + " " + how
                    + ") could not be raised: no alert service is running (bundle org.tinysep.alerts), nobody was "
                    + "told");
            return;
        }
        events.accept("help call from " + node.who() + " at " + time + " (switch " + st.pressedButton + " " + how
                + "): raised as alert " + alert.get().id() + " through the alert service"
                + (s.cancel().isZero() ? "" : "; a second press by " + time(at.plus(s.cancel())) + " cancels it"));
    }

    private void cancel(Node node, State st, Instant at) {
        Instant calledAt = st.calledAt;
        st.calledAt = null;
        st.pressedAt = null;
        st.cancelPress = true;
        String why = "pressed by mistake: " + node.who() + " pressed the switch again at " + time(at) + ", "
                + seconds(Duration.between(calledAt, at)) + " after the help call";
        Optional<Integer> cleared = desk.clear(node.source(), why);
        events.accept("help call from " + node.who() + " of " + time(calledAt) + " cancelled, " + why
                + cleared.map(n -> n == 0 ? " (the alert was already closed)"
                        : "; everyone told gets an all clear").orElse(" (no alert service is running)"));
    }

    private String time(Instant at) {
        return DateTimeFormatter.ofPattern("HH:mm:ss").withZone(settings.zone()).format(at);
    }

    static String seconds(Duration d) {
        return String.format(java.util.Locale.ROOT, "%.1f s", d.toMillis() / 1000.0);
    }
}
