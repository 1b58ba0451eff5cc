package org.tinysep.alerts.internal;

import java.io.IOException;
import java.time.LocalDate;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.function.Consumer;
import org.tinysep.api.alert.Alert;

/**
 * The alerts in memory, mirrored in an {@link AlertStore} after every change. Keeps every open alert and the
 * newest {@value #CLOSED_KEPT} closed ones. Not thread-safe: the {@link AlertManager} holds its lock.
 */
final class AlertBook {

    static final int CLOSED_KEPT = 200;

    private final AlertStore store;
    private final Consumer<String> problems;
    private final Map<String, Alert> byId = new LinkedHashMap<>();
    private long lastId;
    private LocalDate lastSummary;

    AlertBook(AlertStore store, Consumer<String> problems) {
        this.store = store;
        this.problems = problems;
    }

    /** Loads the file; an unreadable file is reported and moved aside by the caller's choice (kept as is). */
    void load() {
        try {
            AlertStore.Content c = store.load(problems);
            c.alerts().forEach(a -> byId.put(a.id(), a));
            lastId = c.lastId();
            lastSummary = c.lastSummary();
        } catch (IOException | RuntimeException e) {
            problems.accept("the saved alerts in " + store.file() + " could not be read (" + e
                    + "); starting without them, the file is left as it is");
        }
    }

    /** @return the sentence for the event log after loading open alerts, if any */
    Optional<String> restored() {
        List<Alert> open = open();
        return open.isEmpty() ? Optional.empty() : Optional.of("restored after a restart: " + open.size()
                + " open alert(s), still repeated and escalated until acknowledged: " + String.join("; ",
                open.stream().map(a -> "alert " + a.id() + " \"" + a.subject() + "\"").toList()));
    }

    String nextId() {
        return Long.toString(++lastId);
    }

    void put(Alert a) {
        byId.remove(a.id());
        byId.put(a.id(), a);
        prune();
        save();
    }

    Optional<Alert> get(String id) {
        return Optional.ofNullable(byId.get(id == null ? "" : id.strip()));
    }

    List<Alert> all() {
        return new ArrayList<>(byId.values());
    }

    List<Alert> open() {
        return byId.values().stream().filter(Alert::isOpen).sorted((a, b) -> Long.compare(Long.parseLong(a.id()),
                Long.parseLong(b.id()))).toList();
    }

    LocalDate lastSummary() {
        return lastSummary;
    }

    void lastSummary(LocalDate day) {
        lastSummary = day;
        save();
    }

    private void prune() {
        List<Alert> closed = byId.values().stream().filter(a -> !a.isOpen()).toList();
        for (int i = 0; i < closed.size() - CLOSED_KEPT; i++) {
            byId.remove(closed.get(i).id());
        }
    }

    private void save() {
        try {
            store.save(new AlertStore.Content(all(), lastId, lastSummary));
        } catch (IOException e) {
            problems.accept("cannot save the alerts to " + store.file() + " (kept in memory only): " + e);
        }
    }
}
