package org.tinysep.web.api.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.time.Duration;
import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.device.support.testing.MutableClock;
import org.tinysep.web.api.internal.Sessions.Session;

/** Issue 25, item 5: one user used to take all 16 stream slots, and the installer then got 503. */
class StreamSlotsTest {

    private final Sessions sessions = new Sessions(Duration.ofMinutes(10), new MutableClock(Instant.parse("2026-11-25T12:00:00Z")));

    @Test
    void oneLoginGetsFourAndTheCaregiversLeaveRoomForTheInstaller() {
        StreamSlots slots = new StreamSlots();
        Session first = sessions.open(Role.CAREGIVER);
        for (int i = 0; i < StreamSlots.PER_SESSION; i++) {
            slots.take(first);
        }
        ApiException perLogin = assertThrows(ApiException.class, () -> slots.take(first));
        assertEquals(503, perLogin.status());
        assertTrue(perLogin.getMessage().contains("this login already has 4"), perLogin.getMessage());
        take4(slots, sessions.open(Role.CAREGIVER)); // two more caregiver logins: 12 caregiver streams
        take4(slots, sessions.open(Role.CAREGIVER));
        ApiException caregivers = assertThrows(ApiException.class, () -> slots.take(sessions.open(Role.CAREGIVER)));
        assertTrue(caregivers.getMessage().contains("kept for the installer"), caregivers.getMessage());
        Session installer = sessions.open(Role.INSTALLER);
        slots.take(installer); // the installer always gets one
        assertEquals(13, slots.total());
        slots.release(installer);
        slots.release(first);
        slots.take(first); // a slot given back can be taken again
        assertEquals(12, slots.total());
    }

    @Test
    void atMostSixteenInAll() {
        StreamSlots slots = new StreamSlots();
        for (int i = 0; i < 4; i++) {
            take4(slots, sessions.open(Role.INSTALLER));
        }
        ApiException all = assertThrows(ApiException.class, () -> slots.take(sessions.open(Role.INSTALLER)));
        assertTrue(all.getMessage().contains("too many open live streams (16)"), all.getMessage());
    }

    private static void take4(StreamSlots slots, Session s) {
        for (int i = 0; i < 4; i++) {
            slots.take(s);
        }
    }
}
