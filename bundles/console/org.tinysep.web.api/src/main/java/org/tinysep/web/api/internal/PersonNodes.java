package org.tinysep.web.api.internal;

import org.tinysep.device.support.lifecycle.Safely;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.function.Function;
import java.util.stream.Collectors;
import java.util.Map;
import java.util.Optional;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.NodeHealthSource;
import org.tinysep.api.sensor.person.MovementSummary;
import org.tinysep.api.sensor.person.PersonNodeProvider;
import org.tinysep.api.service.InactivityRecognitionProvider;
import org.tinysep.api.service.PersonWatch;

/**
 * The person nodes for the caregiver page ({@code personNodes} of {@code GET /api/caregiver}): per
 * node the wearer's name, when it last reported and its battery, whether it is worn, its last movement, where its
 * wearer was last seen and the wearer's own inactivity watch, each also in words. The battery and the last report
 * come from the node's bus device ({@link NodeHealthSource}); the Sun SPOT protocol carries no battery level, which
 * is said rather than left blank. Worn, movement, room and watch come from Inactivity Recognition's
 * {@link InactivityRecognitionProvider#persons()} ({@link PersonWatchWords}).
 */
final class PersonNodes {

    /**
     * What is known of one person node. {@code health} is null when no bus device reports the node's health;
     * {@code watch}: what Inactivity Recognition knows of its wearer.
     */
    record Node(String uid, String name, String person, String address, Instant lastSummary, NodeHealth health,
            PersonWatchWords.Source watch) {
    }

    private PersonNodes() {
    }

    /** @return every person node of the platform, ordered by wearer then node address */
    static List<Map<String, Object>> of(PlatformView platform, Instant now) {
        List<PlatformView.DeviceRef> devices = platform.devices();
        Optional<Map<String, PersonWatch>> watches = platform.withService(InactivityRecognitionProvider.class,
                r -> Safely.get(r::persons, List.<PersonWatch>of()).stream()
                        .collect(Collectors.toMap(PersonWatch::nodeUid, Function.identity(), (a, b) -> a)));
        List<Node> nodes = new ArrayList<>();
        for (PlatformView.DeviceRef d : devices) {
            if (d.device() instanceof PersonNodeProvider p) {
                NodeHealth health = devices.stream()
                        .filter(b -> b.device() instanceof NodeHealthSource && b.nodeAddress().equals(d.nodeAddress()))
                        .map(b -> Safely.get(((NodeHealthSource) b.device())::health, null))
                        .filter(h -> h != null).findFirst().orElse(null);
                nodes.add(new Node(d.uid(), Safely.get(() -> d.device().name(), d.uid()),
                        Safely.get(p::person, Optional.<String>empty()).orElse(""), d.nodeAddress(),
                        Safely.get(p::lastSummary, Optional.<MovementSummary>empty()).map(MovementSummary::end)
                                .orElse(null), health, new PersonWatchWords.Source(watches.isPresent(),
                                watches.map(w -> w.get(d.uid())).orElse(null))));
            }
        }
        nodes.sort((a, b) -> (a.person() + " " + a.address()).compareToIgnoreCase(b.person() + " " + b.address()));
        return nodes.stream().map(n -> json(n, now)).toList();
    }

    static Map<String, Object> json(Node n, Instant now) {
        Map<String, Object> m = new LinkedHashMap<>();
        String who = n.person().isBlank() ? "" : n.person();
        m.put("uid", n.uid());
        m.put("name", n.name());
        m.put("person", who);
        m.put("personWords", who.isEmpty() ? "nobody is named as its wearer (set the node's parameter 'person')"
                : "worn by " + who);
        m.put("node", n.address());
        Instant last = lastReport(n);
        m.put("lastReport", last);
        m.put("online", n.health() == null ? null : n.health().online());
        m.put("lastReportWords", lastReportWords(n, last, now));
        Integer mv = n.health() == null ? null : n.health().batteryMillivolts();
        m.put("batteryMillivolts", mv);
        m.put("batteryLow", n.health() != null && n.health().batteryLow());
        m.put("batteryWords", batteryWords(n.health()));
        Map<String, Object> watch = PersonWatchWords.json(who, n.watch(), now);
        m.putAll(watch);
        m.put("summary", (who.isEmpty() ? "Person node " + n.address() : who + "'s person node (" + n.address() + ")")
                + ": " + lastReportWords(n, last, now) + "; battery " + batteryWords(n.health()) + "; worn: "
                + watch.get("wornWords") + "; last movement " + watch.get("lastMovementWords") + "; "
                + watch.get("lastRoomWords") + "; " + watch.get("watchWords") + ".");
        return m;
    }

    /** @return the node's last valid frame (bus device), else the end of its last movement summary, else null */
    private static Instant lastReport(Node n) {
        Instant heard = n.health() == null ? null : n.health().lastHeard();
        if (heard == null) {
            return n.lastSummary();
        }
        return n.lastSummary() != null && n.lastSummary().isAfter(heard) ? n.lastSummary() : heard;
    }

    static String lastReportWords(Node n, Instant last, Instant now) {
        if (last == null) {
            return "no report since the platform started";
        }
        String words = "last report " + ago(Duration.between(last, now));
        if (n.health() != null && !n.health().online()) {
            words += ", silent now: the node is off, out of range or its battery is empty";
        }
        return words;
    }

    static String batteryWords(NodeHealth h) {
        if (h == null) {
            return "not known (no health of this node from its bus radio)";
        }
        if (h.batteryMillivolts() == null) {
            return "not reported (the node's protocol carries no battery level; a Sun SPOT lasts about a day: "
                    + "charge it every night)";
        }
        String volts = String.format(Locale.ROOT, "%.2f V", h.batteryMillivolts() / 1000.0);
        return h.batteryLow() ? volts + ", LOW: charge or replace it soon" : volts + ", fine";
    }

    static String ago(Duration d) {
        long s = Math.max(0, d.getSeconds());
        if (s < 120) {
            return s + " s ago";
        }
        if (s < 120 * 60) {
            return s / 60 + " min ago";
        }
        return s / 3600 + " h ago";
    }
}
