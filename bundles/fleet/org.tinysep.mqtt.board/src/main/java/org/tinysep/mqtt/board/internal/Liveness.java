package org.tinysep.mqtt.board.internal;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneId;
import org.tinysep.mqtt.board.internal.Flat.Snapshot;

/**
 * Tells whether a flat's platform is online, offline (its Last Will, or an orderly stop) or silent (connected but no
 * heartbeat for {@code missedHeartbeats} × its heartbeat period, or no daily summary for more than
 * {@code summaryHours}), and explains it in plain words ("Flat 17: platform silent since 14:02 — no heartbeat for
 * 3 min; its last words: …"). Silence is measured on the board's clock: a heartbeat counts from when it arrived,
 * or from its own time when that is earlier (an old retained heartbeat read after a restart of the board).
 */
final class Liveness {

    enum Status { OFFLINE, SILENT, UNKNOWN, ONLINE }

    record Rules(int missedHeartbeats, int summaryHours, int lowBatteryPercent, ZoneId zone) { }

    record Verdict(Status status, String explanation) { }

    private Liveness() {
    }

    static Verdict judge(Snapshot f, Rules r, Instant now) {
        String name = "Flat " + f.id();
        if ("offline".equals(f.status())) {
            return new Verdict(Status.OFFLINE, name + ": platform offline since " + BoardTime.time(f.statusAt(), now, r.zone())
                    + " — it stopped, or its link to the broker died and the broker published its Last Will"
                    + lastWords(f, r, now));
        }
        if (f.platform() != null) {
            Duration period = Duration.ofSeconds(f.platform().heartbeatSeconds());
            Duration quiet = Duration.between(f.heartbeatHeard(), now);
            if (quiet.compareTo(period.multipliedBy(r.missedHeartbeats())) > 0) {
                return new Verdict(Status.SILENT, name + ": platform silent since "
                        + BoardTime.time(f.heartbeatHeard(), now, r.zone()) + " — no heartbeat for " + BoardTime.duration(quiet)
                        + " (it sends one every " + BoardTime.duration(period) + ")" + lastWords(f, r, now));
            }
        }
        Instant summaryRef = f.summaryHeard() != null ? f.summaryHeard()
                : f.platform() != null && f.platform().startedAt() != null ? f.platform().startedAt() : f.firstHeard();
        Duration sinceSummary = Duration.between(summaryRef, now);
        if (f.status() != null && sinceSummary.compareTo(Duration.ofHours(r.summaryHours())) > 0) {
            String which = f.summaryHeard() == null ? "no daily summary since " + BoardTime.time(summaryRef, now, r.zone())
                    : "no daily summary for " + BoardTime.duration(sinceSummary) + " (the last one at "
                    + BoardTime.time(summaryRef, now, r.zone()) + ")";
            return new Verdict(Status.SILENT, name + ": platform silent — " + which + ", more than "
                    + r.summaryHours() + " h" + lastWords(f, r, now));
        }
        if ("online".equals(f.status())) {
            String beat = f.platform() == null ? "no heartbeat yet"
                    : "last heartbeat at " + BoardTime.time(f.heartbeatHeard(), now, r.zone()) + " (one every "
                    + BoardTime.duration(Duration.ofSeconds(f.platform().heartbeatSeconds())) + ")";
            return new Verdict(Status.ONLINE, name + ": online since " + BoardTime.time(f.statusAt(), now, r.zone()) + ", " + beat);
        }
        return new Verdict(Status.UNKNOWN, name + ": no status yet — the board has not seen its platform say online or"
                + " offline" + lastWords(f, r, now));
    }

    private static String lastWords(Snapshot f, Rules r, Instant now) {
        if (f.lastWordsAt() == null) {
            return "; it has said nothing else";
        }
        return "; its last words: " + f.lastWords() + " at " + BoardTime.time(f.lastWordsAt(), now, r.zone());
    }
}
