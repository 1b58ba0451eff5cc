package org.tinysep.sensorhealth.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Set;
import org.junit.jupiter.api.Test;
import org.tinysep.api.health.NodeHealth;
import org.tinysep.api.health.SensorHealth;
import org.tinysep.api.health.UnmonitoredRoom;
import org.tinysep.sensorhealth.internal.Notices.Kind;
import org.tinysep.sensorhealth.internal.Notices.Notice;

class NoticesTest {

    private static final Instant T0 = Instant.parse("2026-01-05T09:12:00Z");

    private static SensorHealth sensor(String uid, String room, boolean online, Instant lastHeard, boolean low,
            String... types) {
        NodeHealth h = new NodeHealth(uid, "1." + uid.length(), Set.of(types), online, lastHeard,
                online ? null : lastHeard, Duration.ofSeconds(2), low ? 2100 : 3000, low, 0, 0, 0);
        return new SensorHealth(h, "Movement sensor " + uid, room == null ? null : room + "-uid", room);
    }

    @Test
    void oneOfflineNoticeAfterTheDelayAndOneWhenBack() {
        Notices n = new Notices(Duration.ofMinutes(10));
        SensorHealth silent = sensor("a", "Bathroom", false, T0, false, "movement");
        assertEquals(List.of(), n.due(List.of(silent), T0.plusSeconds(60)));
        assertEquals(List.of(), n.due(List.of(silent), T0.plusSeconds(60 + 599)));
        List<Notice> due = n.due(List.of(silent), T0.plusSeconds(60 + 600));
        assertEquals(1, due.size());
        assertEquals(Kind.OFFLINE, due.get(0).kind());
        assertEquals(T0, due.get(0).since(), "since its last report, not since the platform noticed");
        assertEquals(List.of(), n.due(List.of(silent), T0.plusSeconds(3600)), "once per silence");
        SensorHealth back = sensor("a", "Bathroom", true, T0.plusSeconds(4000), false, "movement");
        assertEquals(Kind.BACK, n.due(List.of(back), T0.plusSeconds(4000)).get(0).kind());
    }

    @Test
    void aSensorBackBeforeTheDelaySendsNothing() {
        Notices n = new Notices(Duration.ofMinutes(10));
        n.due(List.of(sensor("a", "Bathroom", false, T0, false, "movement")), T0.plusSeconds(60));
        assertEquals(List.of(), n.due(List.of(sensor("a", "Bathroom", true, T0, false, "movement")),
                T0.plusSeconds(120)));
    }

    @Test
    void aLowBatteryOncePerLowPeriod() {
        Notices n = new Notices(Duration.ZERO);
        SensorHealth low = sensor("a", "Hall", true, T0, true, "door");
        assertEquals(Kind.LOW_BATTERY, n.due(List.of(low), T0).get(0).kind());
        assertEquals(List.of(), n.due(List.of(low), T0.plusSeconds(60)));
    }

    @Test
    void aRoomIsUnmonitoredWhenAllItsSensingNodesAreSilent() {
        List<SensorHealth> s = List.of(sensor("a", "Bathroom", false, T0, false, "movement"),
                sensor("bb", "Bathroom", false, T0.plusSeconds(30), false, "door"),
                sensor("ccc", "Kitchen", false, T0, false, "movement"),
                sensor("dddd", "Kitchen", true, T0, false, "movement"),
                sensor("eeeee", "Living", false, T0, false, "dimmable-light"));
        List<UnmonitoredRoom> u = Unmonitored.of(s);
        assertEquals(1, u.size(), "Kitchen still has a movement sensor, a light watches nobody: " + u);
        assertEquals("Bathroom", u.get(0).roomName());
        assertEquals(T0.plusSeconds(30), u.get(0).since(), "since the last of its sensors fell silent");
        assertEquals(List.of("a", "bb"), u.get(0).deviceUids());
    }

    @Test
    void theNoticeSaysWhereAndSinceWhenInPlainWords() {
        NoticeWords w = new NoticeWords(ZoneOffset.UTC);
        List<Notice> one = List.of(new Notice(Kind.OFFLINE, sensor("a", "Bathroom", false, T0, false, "movement"), T0));
        assertEquals("TinySEP notice: sensor offline in Bathroom since 09:12", w.subject(one));
        String body = w.body(one);
        assertTrue(body.startsWith("This is a notice about the sensors, not an alarm"), body);
        assertTrue(body.contains("Its last report came at 2026-01-05 09:12:00 Z"), body);
    }

    /** Issue 29 (idle CPU): silences waiting for their notice are looked at once the first is due, not every tick. */
    @Test
    void waitingSilencesAreLookedAtOnlyWhenTheFirstIsDue() {
        Notices n = new Notices(Duration.ofMinutes(10));
        List<Notice> out = new java.util.ArrayList<>();
        for (int i = 0; i < 50; i++) {
            n.update(sensor("s" + i, "Room" + i, false, T0, false, "movement"), T0, out);
        }
        int sent = 0;
        for (int s = 1; s < 600; s++) {
            sent += n.due(T0.plusSeconds(s)).size();
        }
        assertEquals(0, sent);
        assertEquals(0, n.looked(), "silences looked at in the 10 minutes before the first is due");
        assertEquals(50, n.due(T0.plusSeconds(600)).size(), "then all 50 notices, at their time");
        assertEquals(List.of(), n.due(T0.plusSeconds(601)));
    }
}
