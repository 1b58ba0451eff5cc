package org.tinysep.evaluation;

import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.NavigableMap;
import java.util.TreeMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * What a run's event-log entries say, mapped back to recorded time: the inactivity alerts raised, Inactivity
 * Recognition's state (watching or not) and Flat Occupancy's decision over time. Read from the entries the bundles
 * write ({@code inactivity alert (...)}, {@code inactivity not watching (...)}, {@code flat unoccupied (...)},
 * {@code restored after a restart: flat occupied since ...}); any inactivity state other than "not watching" counts
 * as watching.
 *
 * @param alerts      recorded times of the alerts raised (entry {@code inactivity alert ...})
 * @param watching    recorded time → whether the platform watches from then on
 * @param occupancy   recorded time → Flat Occupancy's state from then on ({@code OCCUPIED}, {@code UNOCCUPIED}, ...)
 * @param detectorLog the first entry that names the detector in use, or empty
 */
record Timeline(List<LocalDateTime> alerts, NavigableMap<LocalDateTime, Boolean> watching,
        NavigableMap<LocalDateTime, String> occupancy, String detectorLog) {

    private static final Pattern INACTIVITY = Pattern.compile("^inactivity ([a-z][a-z ]*?) \\(");
    private static final Pattern FLAT = Pattern.compile("^(?:restored after a restart: )?flat ([a-z]+)\\b");

    /** @param shiftDays days between recorded and virtual time */
    static Timeline of(List<LogEntry> entries, long shiftDays, LocalDateTime notBefore) {
        List<LocalDateTime> alerts = new ArrayList<>();
        NavigableMap<LocalDateTime, Boolean> watching = new TreeMap<>();
        NavigableMap<LocalDateTime, String> occupancy = new TreeMap<>();
        watching.put(notBefore, false); // until Inactivity Recognition says otherwise
        occupancy.put(notBefore, "UNKNOWN");
        String detector = "";
        boolean started = false;
        for (LogEntry e : entries) {
            LocalDateTime t = LocalDateTime.ofInstant(e.time(), ZoneOffset.UTC).minusDays(shiftDays);
            if (t.isBefore(notBefore)) {
                if (started) {
                    continue; // the platform stopping after the replay (its clock back on the wall clock)
                }
                t = notBefore; // a restart entry stamped before the first TICK: the initial state
            } else {
                started = true;
            }
            Matcher m = INACTIVITY.matcher(e.message());
            if (m.find()) {
                String state = m.group(1);
                watching.put(t, !state.equals("not watching"));
                if (state.equals("alert")) {
                    alerts.add(t);
                }
            }
            Matcher f = FLAT.matcher(e.message());
            if (f.find()) {
                occupancy.put(t, f.group(1).toUpperCase());
            }
            if (detector.isEmpty() && e.message().toLowerCase().contains("detector")) {
                detector = e.message();
            }
        }
        return new Timeline(alerts, watching, occupancy, detector);
    }
}
