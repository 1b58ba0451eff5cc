package org.tinysep.inactivity.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.tinysep.api.alert.AlertKind;
import org.tinysep.api.alert.AlertRequest;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.service.InactivityAlert;
import org.tinysep.api.service.InactivityState;
import org.tinysep.api.service.MailManagerProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.api.service.PersonWatch;
import org.tinysep.inactivity.internal.learn.Amounts;
import org.tinysep.inactivity.internal.person.PersonAlertWords;
import org.tinysep.inactivity.internal.person.Wearers;

/**
 * Each wearer of a person node watched on their own: one {@link InactivityLogic} per node, fed
 * with the node's movement and the room activity {@link Wearers} attributes to its wearer. The limit is that of the
 * room where the person was last seen. An alert goes to the alert service (source {@code inactivity:<node uid>}),
 * else to a Mail Manager, and is cleared there when the person is active again. Every method returns the event-log
 * lines it caused. Thread-safe.
 */
final class PersonWatches {

    static final String SOURCE_PREFIX = "inactivity:";

    /** What a summary did: event-log lines, and the activity when the node moved. */
    record Moved(List<String> events, Optional<Activity> activity) {
    }

    private static final class Watch {
        final InactivityLogic logic;
        Activity basis;
        Instant handedOver;
        boolean toService;
        boolean told;

        Watch(InactivityLogic logic) {
            this.logic = logic;
        }
    }

    private final Wearers wearers;
    private final PersonAlertWords words;
    private final Duration defaultLimit;
    private final HelpCall.AlertDesk desk;
    private final Supplier<Optional<MailManagerProvider>> mailer;
    private final Map<String, Watch> watches = new LinkedHashMap<>();
    private final Set<String> unnamed = new HashSet<>();
    private Occupancy occupancy = Occupancy.UNKNOWN;
    /**
     * Whether any wearer is watched (written under this object's lock): without one (most homes) a room activity
     * is nobody's and is answered without taking the lock, so a wearer's alert being handed on (under the lock, to
     * the alert service or a Mail Manager) never holds up the radio's delivery thread (issue 29, item 1).
     */
    private volatile boolean anyone;

    PersonWatches(Wearers wearers, PersonAlertWords words, Duration defaultLimit, HelpCall.AlertDesk desk,
            Supplier<Optional<MailManagerProvider>> mailer) {
        this.wearers = wearers;
        this.words = words;
        this.defaultLimit = defaultLimit;
        this.desk = desk;
        this.mailer = mailer;
    }

    /** A movement summary of the node {@code nodeUid} worn by {@code person} (empty: nobody named yet). */
    synchronized Moved summary(String nodeUid, Optional<String> person, MovementSummary s, Instant now) {
        if (person.isEmpty()) {
            return new Moved(unnamed.add(nodeUid) ? List.of("person node " + nodeUid + " has no wearer's name (its "
                    + "parameter person is empty): its movement is nobody's activity until it has one") : List.of(),
                    Optional.empty());
        }
        unnamed.remove(nodeUid);
        String who = person.get();
        Watch w = watches.computeIfAbsent(nodeUid, uid -> {
            Watch n = new Watch(new InactivityLogic(defaultLimit, now));
            if (occupancy == Occupancy.OCCUPIED) {
                n.logic.occupancy(Occupancy.OCCUPIED, now);
            }
            return n;
        });
        anyone = true;
        List<String> events = new ArrayList<>();
        wearers.summary(nodeUid, who, s).ifPresent(n -> events.add(n.words()));
        if (!wearers.moving(s)) {
            return new Moved(events, Optional.empty());
        }
        Activity a = w.basis == null
                ? new Activity("", "unknown room", who + "'s pendant moved", s.end(), defaultLimit, "default limit "
                        + Amounts.duration(defaultLimit) + ": " + who + " has not been seen in a room yet")
                : new Activity(w.basis.roomUid(), w.basis.roomName(), who + "'s pendant moved", s.end(),
                        w.basis.limit(), w.basis.explanation());
        w.logic.rebase(now);
        w.logic.activity(a).ifPresent(state -> events.addAll(left(nodeUid, w, state, a.description() + " at "
                + words.time(a.at()))));
        return new Moved(events, Optional.of(a));
    }

    /** A room sensor's activity: counted for the wearers it may be. */
    List<String> room(Activity a, Instant now) {
        if (!anyone) {
            return List.of(); // nobody's watch to feed: no lock, nothing built per activity
        }
        synchronized (this) {
            return roomLocked(a, now);
        }
    }

    private List<String> roomLocked(Activity a, Instant now) {
        Wearers.Attribution who = wearers.room(a.at(), a.roomUid(), a.roomName());
        if (who.notices().isEmpty() && who.countsFor().isEmpty()) {
            return List.of(); // nobody's watch to feed (no wearer): nothing built per activity
        }
        List<String> events = new ArrayList<>();
        who.notices().forEach(n -> events.add(n.words()));
        for (String uid : who.countsFor()) {
            Watch w = watches.get(uid);
            if (w == null) {
                continue;
            }
            if (who.seenThere().contains(uid)) {
                w.basis = a;
            }
            w.logic.rebase(now);
            w.logic.activity(a).ifPresent(state -> events.addAll(left(uid, w, state, a.description() + " in "
                    + a.roomName() + " at " + words.time(a.at()))));
        }
        return events;
    }

    synchronized List<String> occupancy(Occupancy o, Instant at) {
        occupancy = o;
        List<String> events = new ArrayList<>();
        watches.forEach((uid, w) -> w.logic.occupancy(o, at).ifPresent(state -> {
            String why = "the flat became " + o.name().toLowerCase(Locale.ROOT) + " at " + words.time(at);
            if (state == InactivityState.WATCHING) { // no alert to clear; one handed on before a restart stays so
                events.add("inactivity watching for " + wearers.view(uid).map(Wearers.View::person).orElse(uid)
                        + " (" + why + ")");
            } else {
                events.addAll(left(uid, w, state, why));
            }
        }));
        return events;
    }

    /** Time passed: raises each wearer's alert when due, and hands on one not handed on yet. */
    synchronized List<String> tick(Instant now) {
        List<String> events = new ArrayList<>();
        watches.forEach((uid, w) -> {
            w.logic.rebase(now);
            Optional<InactivityState> change = w.logic.tick(now);
            Optional<InactivityAlert> alert = w.logic.alert();
            Optional<Wearers.View> v = wearers.view(uid);
            if (alert.isEmpty() || v.isEmpty()) {
                return;
            }
            if (change.isPresent()) {
                events.add("inactivity alert for " + v.get().person() + " (limit reached): "
                        + words.subject(v.get().person(), alert.get()) + words.why(v.get(), alert.get()));
            }
            if (!alert.get().raisedAt().equals(w.handedOver)) {
                handOver(uid, w, v.get(), alert.get()).ifPresent(events::add);
            }
        });
        return events;
    }

    private Optional<String> handOver(String uid, Watch w, Wearers.View v, InactivityAlert a) {
        String subject = words.subject(v.person(), a);
        String body = words.body(v, a);
        boolean raised = desk.use(s -> s.raise(new AlertRequest(AlertKind.INACTIVITY, SOURCE_PREFIX + uid,
                a.roomUid(), a.roomName(), a.raisedAt(), subject, body))).isPresent();
        Optional<MailManagerProvider> m = raised ? Optional.empty() : mailer.get();
        if (!raised && m.isEmpty()) {
            boolean first = !w.told;
            w.told = true;
            return first ? Optional.of("alert for " + v.person() + " not handed on yet: neither the alert service "
                    + "nor a Mail Manager is running; it goes out as soon as one is: " + subject) : Optional.empty();
        }
        m.ifPresent(mail -> mail.send(subject, body));
        w.handedOver = a.raisedAt();
        w.toService = raised;
        w.told = false;
        return Optional.of("alert for " + v.person() + (raised ? " handed to the alert service (it tells the "
                + "contacts, repeats and escalates until someone acknowledges): " : " handed to the Mail Manager "
                + "(it queues, sends and logs the delivery): ") + subject);
    }

    /** The wearer's watch left {@code ALERT} (or changed otherwise): says so, and clears a handed-on alert. */
    private List<String> left(String uid, Watch w, InactivityState state, String why) {
        String person = wearers.view(uid).map(Wearers.View::person).orElse(uid);
        List<String> events = new ArrayList<>();
        events.add("inactivity " + state.name().toLowerCase(Locale.ROOT).replace('_', ' ') + " for " + person + " ("
                + why + ")");
        if (w.handedOver != null && w.toService) {
            desk.use(s -> s.clear(SOURCE_PREFIX + uid, person + " is active again (" + why + ")"));
        }
        w.handedOver = null;
        return events;
    }

    /** The node went away: its wearer is no longer watched (an alert already handed on stays open). */
    synchronized void remove(String nodeUid) {
        watches.remove(nodeUid);
        anyone = !watches.isEmpty();
        wearers.remove(nodeUid);
        unnamed.remove(nodeUid);
    }

    /** @return each wearer's watch for the device's backup state ({@link PersonBackup}) */
    synchronized Map<String, String> state() {
        return PersonBackup.write(wearers.saved().stream().filter(w -> watches.containsKey(w.nodeUid())).map(w -> {
            Watch x = watches.get(w.nodeUid());
            return new PersonBackup.SavedWatch(w, x.basis, x.logic.lastActivity().orElse(null),
                    x.logic.watchingFrom().orElse(null), x.handedOver, x.toService);
        }).toList());
    }

    /**
     * After a restart, before the nodes are heard: each saved wearer's watch comes back (last movement, where last
     * seen, worn, last activity, since when watched, the alert handed on), so the quiet time keeps counting from
     * before the restart. @return the event-log lines (one per wearer)
     */
    synchronized List<String> restore(Map<String, String> state, Instant now, List<String> problems) {
        List<String> events = new ArrayList<>();
        for (PersonBackup.SavedWatch s : PersonBackup.read(state, problems)) {
            String uid = s.wearer().nodeUid();
            wearers.restore(s.wearer(), now);
            Watch w = new Watch(new InactivityLogic(defaultLimit, now));
            Activity last = s.last() == null ? null : s.last().description().endsWith(" (before restart)") ? s.last()
                    : new Activity(s.last().roomUid(), s.last().roomName(), s.last().description()
                            + " (before restart)", s.last().at(), s.last().limit(), s.last().explanation());
            w.logic.resume(last, s.watchingFrom());
            w.logic.rebase(now);
            w.basis = s.seen();
            w.handedOver = s.handedOver();
            w.toService = s.toService();
            watches.put(uid, w);
            anyone = true;
            unnamed.remove(uid);
            Wearers.View v = wearers.view(uid).orElseThrow();
            events.add("restored after a restart: " + v.person() + "'s watch: " + (s.last() == null ? "no activity "
                    + "counted yet" : "last active at " + words.time(s.last().at()) + " (" + s.last().description()
                    + ")") + (v.roomName().isEmpty() ? ", not seen in a room yet" : ", last seen in " + v.roomName())
                    + ", pendant " + (v.worn() ? "worn" : "seems not to be worn") + ", still since "
                    + words.time(v.lastMovement()) + (s.handedOver() == null ? "" : ", the alert due at "
                    + words.time(s.handedOver()) + " was already handed on") + "; the quiet time keeps counting");
        }
        return events;
    }

    /** @return the names of the wearers watched now (empty: no named person node) */
    synchronized List<String> watched() {
        return wearers.view().stream().filter(v -> watches.containsKey(v.nodeUid())).map(Wearers.View::person)
                .toList();
    }

    synchronized List<PersonWatch> persons() {
        return wearers.view().stream().filter(v -> watches.containsKey(v.nodeUid()))
                .map(v -> new PersonWatch(v.person(), v.nodeUid(), v.worn(), v.lastMovement(),
                        v.roomName().isEmpty() ? Optional.empty() : Optional.of(v.roomName()),
                        watches.get(v.nodeUid()).logic.state()))
                .toList();
    }

    /** @return for the device parameter, e.g. "Anna: worn, still since 10:12, last seen in Kitchen, watching" */
    synchronized String describe() {
        return persons().stream().map(p -> p.person() + ": " + (p.worn() ? "worn" : "seems not worn")
                + ", last moved " + p.lastMovement() + p.lastRoom().map(r -> ", last seen in " + r).orElse("")
                + ", " + p.state().name().toLowerCase(Locale.ROOT).replace('_', ' '))
                .collect(Collectors.joining("; "));
    }
}
