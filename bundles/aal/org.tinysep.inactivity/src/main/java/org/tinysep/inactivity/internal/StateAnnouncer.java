package org.tinysep.inactivity.internal;

import java.time.Instant;
import java.util.List;
import java.util.Locale;
import java.util.Optional;
import java.util.function.Supplier;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityState;

/**
 * What a change of the flat's inactivity state leads to: an event log entry that says why, the listeners told, the
 * state saved, and an alert handed on once (to the alert service or a Mail Manager), unless the wearers of person
 * nodes are watched on their own (README "Activity per person"), which is then said once per alert.
 */
final class StateAnnouncer {

    private final InactivityLogic logic;
    private final HelpCall help;
    private final AlertMail words;
    private final Supplier<PersonWatches> persons;
    private final DeviceSide side;
    /** The flat's alert not handed on because wearers have their own watches (said once per alert). */
    private volatile Instant flatAlertLeftToPersons;

    StateAnnouncer(InactivityLogic logic, HelpCall help, AlertMail words, Supplier<PersonWatches> persons,
            DeviceSide side) {
        this.logic = logic;
        this.help = help;
        this.words = words;
        this.persons = persons;
        this.side = side;
    }

    /** @return the current alert of the flat, if raised */
    Optional<InactivityAlert> alert() {
        synchronized (logic) {
            return logic.alert();
        }
    }

    /** A change, if any, at {@code at}; {@code reason} is built only on a change. */
    void announce(Optional<InactivityState> change, Instant at, Supplier<String> reason) {
        change.ifPresent(s -> {
            String detail = s == InactivityState.ALERT ? alert().map(a -> help.subject(a) + words.why(a)).orElse("")
                    : "";
            side.event("inactivity " + lower(s) + " (" + reason.get() + ")" + (detail.isEmpty() ? "" : ": " + detail));
            side.fire(s, at);
            side.save(); // whether (since when) the flat is watched survives a crash
            if (s == InactivityState.ALERT) {
                handOn();
            } else {
                side.online();
            }
        });
    }

    /** Hands the current alert on once, as soon as the alert service or a Mail Manager is there. */
    void handOn() {
        Optional<InactivityAlert> a = alert();
        if (a.isEmpty()) {
            return;
        }
        List<String> wearers = persons.get().watched();
        if (!wearers.isEmpty()) { // each wearer's own watch calls for help for them (README "Activity per person")
            if (!a.get().raisedAt().equals(flatAlertLeftToPersons)) {
                flatAlertLeftToPersons = a.get().raisedAt();
                side.event("the flat's inactivity alert is not handed on: " + String.join(", ", wearers) + " wear"
                        + (wearers.size() == 1 ? "s a person node and is" : " person nodes and are") + " watched "
                        + "on their own, and that watch calls for help (it counts the room sensors when nobody "
                        + "else's node moves)");
            }
            return;
        }
        HelpCall.Outcome outcome = help.call(a.get());
        switch (outcome) {
            case HANDED_OVER, HANDED_TO_ALERT_SERVICE, RAISED_AGAIN -> {
                side.event(help.outcomeWords(a.get(), outcome == HelpCall.Outcome.RAISED_AGAIN));
                side.online();
                side.save(); // not handed over twice after a restart
            }
            case NO_MAIL_MANAGER -> side.error("alert raised but no Mail Manager to send it");
            case ALREADY_HANDED_OVER -> { }
        }
    }

    static String lower(Enum<?> e) {
        return e.name().toLowerCase(Locale.ROOT).replace('_', ' ');
    }
}
