package org.tinysep.inactivity.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceListener;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.device.support.testing.FakeProvider;

/**
 * A flush or an appliance turning OFF after the person was last seen in another room is the device finishing by
 * itself, not the person (Ordonez B, 30 November 2012: flush ON 01:40:19, bedroom 01:40:31, bed mat ON 01:40:53,
 * flush OFF 01:41:11 — the quiet night then ran from the flush with the bathroom's 20 min limit).
 */
class DeviceFinishedTest {

    private static final Instant T = Instant.parse("2012-11-30T01:40:19Z");

    private static final class Mat extends FakeProvider<PresenceListener> implements PresenceProvider {
        private final PresenceKind kind;
        private boolean on;

        Mat(String uid, PresenceKind kind) {
            super(uid);
            this.kind = kind;
        }

        void set(boolean now, int second) {
            on = now;
            List.copyOf(listeners).forEach(l -> l.presenceChanged(this, now, false, T.plusSeconds(second)));
        }

        @Override
        public PresenceKind kind() {
            return kind;
        }

        @Override
        public boolean present() {
            return on;
        }
    }

    private final List<Activity> seen = new ArrayList<>();
    private final Mat flush = new Mat("flush", PresenceKind.FLUSH);
    private final Mat kettle = new Mat("kettle", PresenceKind.APPLIANCE);
    private final Mat bed = new Mat("bed", PresenceKind.BED);
    private final Mat seat = new Mat("seat", PresenceKind.SEAT);

    DeviceFinishedTest() {
        Fakes.Directory d = new Fakes.Directory();
        d.rooms.put("flush", "bath");
        d.rooms.put("kettle", "kitchen");
        d.rooms.put("bed", "bedroom");
        d.rooms.put("seat", "living");
        ActivityFactory f = new ActivityFactory(d, LimitTable.parse(120, "", ""), seen::add);
        for (Mat m : List.of(flush, kettle, bed, seat)) {
            m.connect(f);
        }
    }

    private List<String> rooms() {
        return seen.stream().map(a -> a.roomUid() + (a.description().endsWith(" off") ? " off" : " on")).toList();
    }

    @Test
    void theFlushEndingAfterThePersonLayDownIsNoActivity() {
        flush.set(true, 0);
        bed.set(true, 34);
        flush.set(false, 52);
        assertEquals(List.of("bath on", "bedroom on"), rooms(), "the quiet period must start with the bed mat");
    }

    @Test
    void anApplianceEndingWhileThePersonSitsElsewhereIsNoActivity() {
        kettle.set(true, 0);
        seat.set(true, 60);
        kettle.set(false, 180);
        assertEquals(List.of("kitchen on", "living on"), rooms());
    }

    @Test
    void anOffInTheRoomTheyWereLastSeenInStaysActivity() {
        flush.set(true, 0);
        flush.set(false, 40);
        seat.set(false, 100);
        bed.set(true, 200);
        bed.set(false, 300);
        assertEquals(List.of("bath on", "bath off", "living off", "bedroom on", "bedroom off"), rooms(),
                "the flush in the bathroom they are in, and the mats' OFF (the person getting up), count");
    }

    @Test
    void anOffBeforeAnyActivityCounts() {
        kettle.set(false, 0);
        assertEquals(List.of("kitchen off"), rooms(), "nothing says the person is elsewhere");
    }
}
