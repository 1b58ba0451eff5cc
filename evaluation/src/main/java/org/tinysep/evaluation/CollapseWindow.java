package org.tinysep.evaluation;

import java.time.Duration;
import java.time.LocalDateTime;
import java.util.List;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * A collapse's replay: from {@code warmupHours} before it (earlier if needed, so that at least the last three
 * events before it are replayed) to the collapse; every event of the 12 h after it is deleted, and the replay
 * plays on, quiet, until 12 h and a minute after it.
 */
record CollapseWindow(LocalDateTime collapse, LocalDateTime from, List<SensorEvent> events) {

    LocalDateTime quietSince() {
        return events.get(events.size() - 1).time();
    }

    LocalDateTime end() {
        return collapse.plus(CollapseResult.WINDOW).plusMinutes(1);
    }

    /** @return the window of a collapse at {@code c} in {@code home} */
    static CollapseWindow of(Home home, LocalDateTime c, int warmupHours) {
        List<SensorEvent> before = home.events().stream().filter(e -> e.time().isBefore(c)).toList();
        LocalDateTime third = before.get(Math.max(0, before.size() - 3)).time();
        LocalDateTime warm = c.minusHours(warmupHours);
        LocalDateTime tenBefore = third.minusMinutes(10);
        LocalDateTime from = warm.isBefore(tenBefore) ? warm : tenBefore;
        return new CollapseWindow(c, from, before.stream().filter(e -> !e.time().isBefore(from)).toList());
    }

    /**
     * @return days between two windows of one run: whole weeks, more than any window's span plus a day (7 without
     *         windows: {@code --collapses 0}, the test half only)
     */
    static long step(List<CollapseWindow> windows) {
        if (windows.isEmpty()) {
            return 7;
        }
        LocalDateTime first = windows.stream().map(CollapseWindow::from).min(LocalDateTime::compareTo).orElseThrow();
        LocalDateTime last = windows.stream().map(CollapseWindow::end).max(LocalDateTime::compareTo).orElseThrow();
        long days = Duration.between(first, last).toDays() + 2;
        return (days + 6) / 7 * 7;
    }
}
