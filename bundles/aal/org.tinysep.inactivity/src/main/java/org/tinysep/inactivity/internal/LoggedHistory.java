package org.tinysep.inactivity.internal;

import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import org.tinysep.inactivity.internal.learn.Sighting;

/**
 * The LEARNED detector's history from the event log: entries of devices that were not connected yet wait in
 * {@link HistoryFromLog}; once a device is an activity source here, its entries go to the learner (looked at most
 * once a minute, wall time).
 */
final class LoggedHistory {

    /** How often (wall time) the waiting entries are looked at. */
    static final long EVERY_NANOS = 60_000_000_000L;

    private final HistoryFromLog fromLog;
    private final ActivityFactory activities;
    /** The activity sources connected so far (devices whose logged entries count as history). */
    private final Set<String> sources = ConcurrentHashMap.newKeySet();
    private volatile long lastResolve = System.nanoTime() - EVERY_NANOS;

    /** @param fromLog the entries waiting for their devices, or null (no learning from the log) */
    LoggedHistory(HistoryFromLog fromLog, ActivityFactory activities) {
        this.fromLog = fromLog;
        this.activities = activities;
    }

    /** A device whose logged activity counts as history. */
    void source(String deviceUid) {
        sources.add(deviceUid);
    }

    /** Hands logged history of devices that are now sources to the learner (at most once a minute). */
    void resolve(DeviceSide side) {
        long wall = System.nanoTime();
        if (fromLog == null || wall - lastResolve < EVERY_NANOS || !fromLog.hasPending()) {
            return;
        }
        lastResolve = wall;
        int finished = fromLog.finishedByItself();
        int n = fromLog.resolve(raw -> {
            if (!sources.contains(raw.device())) {
                return Optional.empty();
            }
            ActivityFactory.Placed p = activities.placed(raw.device());
            return Optional.of(new Sighting(raw.at(), p.uid(), p.name(), p.type(), raw.inBed(), raw.seated()));
        });
        finished = fromLog.finishedByItself() - finished;
        if (n > 0 || finished > 0) {
            side.event("learning: " + n + " logged activities of connected sensors added to the history"
                    + (finished == 0 ? "" : "; " + finished + " flush or appliance OFF entries left out: each came "
                            + "after the person was seen in another room, so it was the device finishing by itself"));
        }
    }
}
