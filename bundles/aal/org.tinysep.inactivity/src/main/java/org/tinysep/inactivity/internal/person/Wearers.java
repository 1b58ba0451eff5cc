package org.tinysep.inactivity.internal.person;

import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.TreeSet;
import java.util.function.Function;
import org.tinysep.api.sensor.person.MovementSummary;

/**
 * Whose activity is what (bundle README, "Activity per person"). Pure logic with explicit times.
 * <ul>
 * <li>A person node's movement (a summary whose magnitude spread is above the threshold) is its wearer's activity,
 * wherever they are.</li>
 * <li>A room sensor's activity counts for a wearer unless another worn node was moving at that moment (it moved
 * within {@link WearerSettings#movingWithin()}): then that other wearer explains it. With nobody else moving it may
 * be the wearer and counts for them, so in a one-person home the room sensors stay the fallback.</li>
 * <li>A worn node that has not moved for {@link WearerSettings#notWornAfter()} while room activity that counts for
 * its wearer happens seems not to be worn: a notice, and until it moves again every room activity counts for that
 * person (the room sensors alone watch them, as without a node). Its next movement: worn again, a notice.</li>
 * </ul>
 * Thread-safe.
 */
public final class Wearers {

    /** A notice for the event log about a node. */
    public record Notice(String nodeUid, String words) {
    }

    /** One wearer as seen now. {@code explainedBy}: who explained the room activity not counted for them. */
    public record View(String nodeUid, String person, boolean worn, Instant lastMovement, boolean everMoved,
            String roomUid, String roomName, int explained, Set<String> explainedBy) {
    }

    /**
     * For which nodes' wearers a room activity counts, at which of them it was surely not another wearer (so the
     * room is where they were last seen), and the notices it caused.
     */
    public record Attribution(Set<String> countsFor, Set<String> seenThere, List<Notice> notices) {
    }

    /**
     * What the system backup keeps of a wearer (README "System backup and restarts"): the node, the name, when it was
     * first heard and last moved (null: not since it was heard), whether it seemed worn, where last seen.
     */
    public record Saved(String nodeUid, String person, Instant heard, Instant lastMovement, boolean worn,
            String roomUid, String roomName) {

        public Saved {
            Objects.requireNonNull(nodeUid, "nodeUid");
            Objects.requireNonNull(person, "person");
            Objects.requireNonNull(heard, "heard");
            roomUid = roomUid == null ? "" : roomUid;
            roomName = roomName == null ? "" : roomName;
        }
    }

    private static final class Wearer {
        final String nodeUid;
        String person;
        final Instant heard;
        Instant lastMovement;
        boolean worn = true;
        String roomUid = "";
        String roomName = "";
        int explained;
        final Set<String> explainedBy = new TreeSet<>();

        Wearer(String nodeUid, String person, Instant heard) {
            this.nodeUid = nodeUid;
            this.person = person;
            this.heard = heard;
        }

        Instant stillSince() {
            return lastMovement != null ? lastMovement : heard;
        }
    }

    private final WearerSettings settings;
    private final Function<Instant, String> clock;
    private final Map<String, Wearer> nodes = new LinkedHashMap<>();

    /** @param clock a time of day for the notices, e.g. "10:12" */
    public Wearers(WearerSettings settings, Function<Instant, String> clock) {
        this.settings = Objects.requireNonNull(settings, "settings");
        this.clock = Objects.requireNonNull(clock, "clock");
    }

    public WearerSettings settings() {
        return settings;
    }

    /** @return whether {@code s} is movement by the settings' threshold */
    public boolean moving(MovementSummary s) {
        return s.magnitudeSdMg() > settings.movingAboveMg();
    }

    /**
     * A summary of the node worn by {@code person} arrived. @return the notice "worn again" when a node that seemed
     * not worn moves
     */
    public synchronized Optional<Notice> summary(String nodeUid, String person, MovementSummary s) {
        Wearer w = nodes.computeIfAbsent(nodeUid, uid -> new Wearer(uid, person, s.end()));
        w.person = person;
        if (!moving(s)) {
            return Optional.empty();
        }
        w.lastMovement = s.end();
        w.explained = 0;
        w.explainedBy.clear();
        if (w.worn) {
            return Optional.empty();
        }
        w.worn = true;
        return Optional.of(new Notice(nodeUid, person + "'s pendant is worn again: it moved at " + clock.apply(s.end())
                + "; its movement counts as " + person + "'s activity again"));
    }

    /** No worn node heard: a room activity counts for nobody's own watch and says nothing. */
    static final Attribution NOBODY = new Attribution(Set.of(), Set.of(), List.of());

    /**
     * A room sensor saw activity in {@code roomName} at {@code at}. Without any worn node (most homes) the answer
     * is {@link #NOBODY}, built once: a room activity allocates nothing here (issue 29, item 1: the sets and the
     * stream built per activity for no wearer were 12 % of the radio's delivery thread).
     */
    public synchronized Attribution room(Instant at, String roomUid, String roomName) {
        if (nodes.isEmpty()) {
            return NOBODY;
        }
        Set<String> movers = new TreeSet<>();
        nodes.values().stream().filter(w -> w.worn && w.lastMovement != null
                && !w.lastMovement.isBefore(at.minus(settings.movingWithin()))).forEach(w -> movers.add(w.nodeUid));
        Set<String> counts = new TreeSet<>();
        Set<String> seen = new TreeSet<>();
        List<Notice> notices = new ArrayList<>();
        for (Wearer w : nodes.values()) {
            Set<String> others = new TreeSet<>(movers);
            others.remove(w.nodeUid);
            if (others.isEmpty()) {
                seen.add(w.nodeUid);
                w.roomUid = roomUid;
                w.roomName = roomName;
                w.explained = 0;
                w.explainedBy.clear();
            }
            if (!w.worn) {
                counts.add(w.nodeUid); // not worn: the room sensors alone watch this person
            } else if (others.isEmpty()) {
                counts.add(w.nodeUid);
                if (!w.stillSince().isAfter(at.minus(settings.notWornAfter()))) {
                    w.worn = false;
                    notices.add(new Notice(w.nodeUid, w.person + "'s pendant seems not to be worn: it has not moved "
                            + "since " + clock.apply(w.stillSince()) + " while the sensors saw someone in the "
                            + roomName + "; until it moves again, " + w.person + " is watched by the room sensors"));
                }
            } else {
                w.explained++;
                others.forEach(o -> w.explainedBy.add(nodes.get(o).person));
            }
        }
        return new Attribution(counts, seen, notices);
    }

    /** @return each wearer as the backup keeps it, in the order their nodes were first heard */
    public synchronized List<Saved> saved() {
        return nodes.values().stream().map(w -> new Saved(w.nodeUid, w.person, w.heard, w.lastMovement, w.worn,
                w.roomUid, w.roomName)).toList();
    }

    /**
     * After a restart: takes a saved wearer back (before its node is heard again); times later than {@code now} (a
     * backup from virtual time) are taken as {@code now}. Who explained room activity meanwhile is not kept.
     */
    public synchronized void restore(Saved s, Instant now) {
        Wearer w = new Wearer(s.nodeUid(), s.person(), s.heard().isAfter(now) ? now : s.heard());
        w.lastMovement = s.lastMovement() == null || !s.lastMovement().isAfter(now) ? s.lastMovement() : now;
        w.worn = s.worn();
        w.roomUid = s.roomUid();
        w.roomName = s.roomName();
        nodes.put(s.nodeUid(), w);
    }

    /** The node went away. */
    public synchronized void remove(String nodeUid) {
        nodes.remove(nodeUid);
    }

    /** @return the wearers in the order their nodes were first heard */
    public synchronized List<View> view() {
        return nodes.values().stream().map(w -> new View(w.nodeUid, w.person, w.worn, w.stillSince(),
                w.lastMovement != null, w.roomUid, w.roomName, w.explained, Set.copyOf(w.explainedBy))).toList();
    }

    /** @return the wearer of that node, if heard */
    public synchronized Optional<View> view(String nodeUid) {
        return view().stream().filter(v -> v.nodeUid().equals(nodeUid)).findFirst();
    }
}
