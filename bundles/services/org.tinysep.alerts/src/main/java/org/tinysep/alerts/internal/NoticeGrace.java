package org.tinysep.alerts.internal;

import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.tinysep.api.log.EventEntry;

/**
 * The grace of sensor notices: a "Monitoring reduced" signal about one sensor that went away (device
 * support's words: {@code … its sensor "Bathroom movement" …}) is held for {@code grace}; when the same watcher says
 * {@code monitoring restored: the sensor "Bathroom movement" …} within it, the notice is dropped, so a platform
 * start or a driver update, where sensors go and come within seconds, mails nothing. Other signals pass at once.
 * Held signals live in memory only: a restart within the grace forgets them (the watcher's {@code roomsNotSeen}
 * still names the room). Not thread-safe: one poller uses it.
 */
final class NoticeGrace {

    private static final Pattern LOST = Pattern.compile("its sensor \"([^\"]*)\"");
    private static final String BACK_START = "monitoring restored: the sensor \"";
    private static final Pattern BACK = Pattern.compile("^" + BACK_START + "([^\"]*)\"");

    private record Held(EventEntry signal, Instant due) {
    }

    private final Duration grace;
    /** Held signals by watcher and sensor, oldest first. */
    private final Map<String, Held> held = new LinkedHashMap<>();
    private int dropped;

    NoticeGrace(Duration grace) {
        this.grace = grace;
    }

    /**
     * @param signals the new signals to mail (the feed's choice)
     * @param entries every new entry of the log, oldest first (where a sensor's return is seen)
     * @param now     the time of this look
     * @return the signals to mail now: those not held, and the held ones whose grace has passed
     */
    List<EventEntry> pass(List<EventEntry> signals, List<EventEntry> entries, Instant now) {
        List<EventEntry> out = new ArrayList<>();
        for (EventEntry s : signals) {
            String key = sensorKey(s, LOST.matcher(s.message()), false);
            if (key == null || grace.isZero()) {
                out.add(s);
            } else {
                held.put(key, new Held(s, now.plus(grace)));
            }
        }
        for (EventEntry e : entries) {
            if (held.isEmpty()) {
                break; // nothing waits for a sensor to come back: no matcher per entry
            }
            String key = e.message().startsWith(BACK_START) ? sensorKey(e, BACK.matcher(e.message()), true) : null;
            Held h = key == null ? null : held.get(key);
            if (h != null && e.sequence() > h.signal().sequence()) {
                held.remove(key);
                dropped++;
            }
        }
        for (Iterator<Held> i = held.values().iterator(); i.hasNext();) {
            Held h = i.next();
            if (!now.isBefore(h.due())) {
                out.add(h.signal());
                i.remove();
            }
        }
        out.sort((a, b) -> Long.compare(a.sequence(), b.sequence()));
        return out;
    }

    /** @return the signals held now */
    int held() {
        return held.size();
    }

    /** @return how many held signals were dropped because their sensor came back within the grace */
    int dropped() {
        return dropped;
    }

    private static String sensorKey(EventEntry e, Matcher m, boolean back) {
        if (!(back ? m.lookingAt() : e.message().startsWith(NoticeFeed.REDUCED) && m.find())) {
            return null;
        }
        return e.origin() + "\n" + m.group(1);
    }
}
