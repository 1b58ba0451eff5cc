package org.tinysep.drivers.internal;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

/**
 * Brings the framework in line with a drivers list: installs and starts enabled entries that are not running, stops
 * disabled ones, uninstalls the bundles of entries that disappeared (only bundles this list manages), and leaves
 * running bundles untouched — no refresh of anything but an uninstalled bundle. Not thread-safe: the caller holds
 * one lock.
 */
final class Reconciler {

    /** The outcome: the entries with their new status and FULL_NAME, and one line per change made. */
    record Result(List<DriverEntry> entries, List<String> changes) {
    }

    private final Bundles bundles;
    private final Locations locations;
    private final int startLevel;
    /** entry key → bundle id, for every bundle this list manages. */
    private final Map<String, Long> managed = new LinkedHashMap<>();
    /** ids this list is uninstalling itself (so the bundle listener does not mistake them for shell uninstalls). */
    private final Set<Long> uninstalling = new HashSet<>();

    Reconciler(Bundles bundles, Locations locations, int startLevel) {
        this.bundles = bundles;
        this.locations = locations;
        this.startLevel = startLevel;
    }

    /** Applies {@code wanted}; every managed bundle whose key is not in it is uninstalled. */
    Result apply(List<DriverEntry> wanted) {
        List<String> changes = new ArrayList<>();
        Set<String> keep = new HashSet<>();
        wanted.forEach(e -> keep.add(e.key()));
        for (Map.Entry<String, Long> m : List.copyOf(managed.entrySet())) {
            if (!keep.contains(m.getKey())) {
                changes.add(uninstall(m.getKey(), m.getValue()));
            }
        }
        // install everything first, then start: a bundle started before its library is installed would not resolve
        List<DriverEntry> installed = new ArrayList<>();
        for (DriverEntry e : wanted) {
            installed.add(install(e, changes));
        }
        List<DriverEntry> result = new ArrayList<>();
        for (DriverEntry e : installed) {
            result.add(start(e, changes));
        }
        return new Result(result, changes);
    }

    /** Stops a disabled entry, installs a missing enabled one; the entry's status is final unless it is empty. */
    private DriverEntry install(DriverEntry e, List<String> changes) {
        long id = idOf(e);
        if (!e.enabled()) {
            if (id >= 0 && bundles.isRunning(id)) {
                try {
                    bundles.stop(id);
                    changes.add("stopped " + e.key() + " (disabled)");
                } catch (Exception ex) {
                    changes.add("cannot stop " + e.key() + ": " + ex.getMessage());
                }
            }
            return e.withStatus(Status.DISABLED);
        }
        if (id >= 0) {
            return e.withStatus("");
        }
        Optional<String> refused = locations.refusal(e.location());
        if (refused.isPresent()) {
            changes.add("cannot install " + e.key() + ": " + refused.get());
            return e.withStatus(Status.failed(refused.get()));
        }
        Optional<Path> file = locations.file(e.location());
        if (file.isPresent() && !Files.isRegularFile(file.get())) {
            changes.add("missing " + e.key() + ": no file " + file.get());
            return e.withStatus(Status.missing(file.get().toString()));
        }
        try {
            id = bundles.install(locations.url(e.location()), startLevel);
        } catch (Exception ex) {
            changes.add("cannot install " + e.key() + ": " + ex.getMessage());
            return e.withStatus(Status.failed(ex.getMessage()));
        }
        DriverEntry named = e.withSymbolicName(bundles.symbolicName(id)).withStatus("");
        managed.put(named.key(), id);
        changes.add("installed " + named.key());
        return named;
    }

    /** Starts an installed enabled entry that is not running; running bundles are left untouched. */
    private DriverEntry start(DriverEntry e, List<String> changes) {
        Long id = managed.get(e.key());
        if (!e.status().isEmpty() || id == null) {
            return e;
        }
        if (!bundles.isRunning(id)) {
            try {
                bundles.start(id);
                changes.add("started " + e.key());
            } catch (Exception ex) {
                changes.add("cannot start " + e.key() + ": " + ex.getMessage());
                return e.withStatus(Status.failed(ex.getMessage()));
            }
        }
        return e.withStatus(bundles.status(id));
    }

    /** @return the managed (or adopted: already installed, same name or location) bundle of {@code e}, else -1 */
    private long idOf(DriverEntry e) {
        Long id = managed.get(e.key());
        if (id != null && !bundles.symbolicName(id).isEmpty()) {
            return id;
        }
        managed.remove(e.key());
        long found = bundles.find(e.symbolicName(), locations.url(e.location()));
        if (found >= 0) {
            managed.put(e.key(), found);
        }
        return found;
    }

    private String uninstall(String key, long id) {
        managed.remove(key);
        uninstalling.add(id);
        try {
            bundles.uninstall(id);
            return "uninstalled " + key + " (entry removed)";
        } catch (Exception ex) {
            uninstalling.remove(id);
            return "cannot uninstall " + key + ": " + ex.getMessage();
        }
    }

    /** @return the live status of {@code e} */
    String status(DriverEntry e) {
        if (!e.enabled()) {
            return Status.DISABLED;
        }
        Long id = managed.get(e.key());
        String s = id == null ? "" : bundles.status(id);
        return s.isEmpty() ? (e.status().startsWith("MISSING") || e.status().startsWith("FAILED") ? e.status()
                : Status.PENDING) : s;
    }

    /** Records a bundle installed by someone else (the shell) as managed under {@code key}. */
    void adopt(String key, long id) {
        managed.put(key, id);
    }

    /** @return whether the list manages bundle {@code id} */
    boolean manages(long id) {
        return managed.containsValue(id);
    }

    /**
     * Forgets bundle {@code id} after it was uninstalled.
     *
     * @return the key of the entry it belonged to, when someone else uninstalled it; empty when this list did
     */
    Optional<String> uninstalled(long id) {
        if (uninstalling.remove(id)) {
            return Optional.empty();
        }
        for (Map.Entry<String, Long> m : List.copyOf(managed.entrySet())) {
            if (m.getValue() == id) {
                managed.remove(m.getKey());
                return Optional.of(m.getKey());
            }
        }
        return Optional.empty();
    }
}
