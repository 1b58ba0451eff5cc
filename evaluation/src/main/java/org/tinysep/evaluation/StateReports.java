package org.tinysep.evaluation;

import java.time.LocalDateTime;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.tinysep.simulator.replay.Kind;
import org.tinysep.simulator.replay.SensorEvent;

/**
 * What a real node tells a platform that has just started: its current state. A recording holds changes only and the
 * harness replays at the simulator's {@code changes} rate, so without this a contact's or mat's first recorded change
 * inside a replayed stretch would be its first report to the restarted platform, which (rightly, in a live home) is
 * taken as its resting state and not as activity: a seat mat turning ON at 15:43 would not begin the sitting quiet
 * period, and the quiet time would run from an older activity in another room. Real nodes repeat their state every
 * 1–2 s (thesis 3.9), so a restarted platform has heard every contact's state before its next change; this rebuilds
 * that. Motion sensors are left out: a motion report is activity whatever came before it.
 */
final class StateReports {

    private StateReports() {
    }

    /**
     * @param recording the whole recording, in time order
     * @param stretch   a stretch of it to replay (not empty), in time order
     * @return the stretch, preceded (at its first event's time) by each contact's and mat's state just before it, for
     *         every such sensor that changed at least once before the stretch
     */
    static List<SensorEvent> prepend(List<SensorEvent> recording, List<SensorEvent> stretch) {
        LocalDateTime start = stretch.get(0).time();
        Map<String, SensorEvent> last = new LinkedHashMap<>();
        for (SensorEvent e : recording) {
            if (!e.time().isBefore(start)) {
                break;
            }
            if (e.kind() != Kind.MOTION) {
                last.put(e.sensor(), e);
            }
        }
        List<SensorEvent> out = new ArrayList<>();
        last.values().forEach(e -> out.add(new SensorEvent(start, e.sensor(), e.room(), e.kind(), e.on())));
        out.addAll(stretch);
        return out;
    }
}
