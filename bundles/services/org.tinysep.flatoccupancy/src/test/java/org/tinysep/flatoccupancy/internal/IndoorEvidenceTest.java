package org.tinysep.flatoccupancy.internal;

import static org.tinysep.flatoccupancy.internal.Fixtures.door;
import static org.tinysep.flatoccupancy.internal.Fixtures.flat;
import static org.tinysep.flatoccupancy.internal.Fixtures.presence;
import static org.tinysep.flatoccupancy.internal.Fixtures.window;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Instant;
import org.junit.jupiter.api.Test;
import org.tinysep.api.sensor.DoorKind;
import org.tinysep.api.sensor.DoorProvider;
import org.tinysep.api.sensor.OpenState;
import org.tinysep.api.sensor.WindowProvider;
import org.tinysep.api.sensor.presence.PresenceKind;
import org.tinysep.api.sensor.presence.PresenceProvider;
import org.tinysep.api.service.Occupancy;
import org.tinysep.device.support.logs.RecordingLogs;

/**
 * Presence from all evidence (issue 11): a home without a single motion sensor — front door, an inner door, a
 * fridge contact, a seat mat, a flush — is seen as occupied whenever any of them shows someone inside.
 */
class IndoorEvidenceTest {

    private static final Instant T0 = Instant.parse("2026-11-22T07:00:00Z");

    private final RecordingLogs logs = new RecordingLogs(() -> T0);
    private final FlatOccupancyDevice flat = flat(logs, T0);
    private final DoorProvider front = door("front", DoorKind.OUTER);

    /** Someone came home (door opened) and the door closed behind them at T0 + 5 s. */
    private void arrived() {
        flat.doorChanged(front, OpenState.CLOSED, true, T0.minusSeconds(60)); // first report: resting state
        flat.doorChanged(front, OpenState.OPEN, T0);
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(5));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());
    }

    @Test
    void aWindowOrContactChangeCancelsTheLeaveCheck() {
        WindowProvider fridge = window("fridge");
        arrived();
        flat.windowChanged(fridge, OpenState.OPEN, false, T0.plusSeconds(120));
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy(), "the fridge opened after the door closed");
    }

    @Test
    void aWindowsFirstReportIsNoActivity() {
        WindowProvider fridge = window("fridge");
        arrived();
        flat.windowChanged(fridge, OpenState.CLOSED, true, T0.plusSeconds(120)); // its first report
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.UNOCCUPIED, flat.occupancy());
    }

    @Test
    void anInnerDoorChangeCancelsTheLeaveCheck() {
        DoorProvider bath = door("bathroom door", DoorKind.INNER);
        flat.doorChanged(bath, OpenState.CLOSED, true, T0.minusSeconds(100)); // its first report
        arrived();
        flat.doorChanged(bath, OpenState.OPEN, false, T0.plusSeconds(300));
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());
    }

    /**
     * Issue 16: the door device says which report is its first, so a change is a change even when this device
     * (re)started after the door did and never heard the door's first report (it used to be taken for one).
     */
    @Test
    void anInnerDoorsChangeCountsEvenIfThisDeviceMissedItsFirstReport() {
        DoorProvider bath = door("bathroom door", DoorKind.INNER);
        arrived();
        flat.doorChanged(bath, OpenState.OPEN, false, T0.plusSeconds(300));
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy(), "the bathroom door opened after the front door closed");
    }

    @Test
    void aSeatMatThatIsOnKeepsTheFlatOccupiedWhenAVisitorLeaves() {
        PresenceProvider seat = presence("seat", PresenceKind.SEAT);
        flat.doorChanged(front, OpenState.CLOSED, true, T0.minusSeconds(3600));
        flat.presenceChanged(seat, true, false, T0.minusSeconds(1800)); // the resident sits down
        flat.doorChanged(front, OpenState.OPEN, T0); // the visitor leaves
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(5));
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy(), "the seat mat says someone is here");
        flat.presenceChanged(seat, false, false, T0.plusSeconds(2000)); // gets up: activity, still occupied
        assertEquals(Occupancy.OCCUPIED, flat.occupancy());
        flat.doorChanged(front, OpenState.OPEN, T0.plusSeconds(2100));
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(2105));
        flat.tick(T0.plusSeconds(2105 + 600));
        assertEquals(Occupancy.UNOCCUPIED, flat.occupancy(), "left with the mat OFF: empty");
    }

    @Test
    void aFlushIsActivityButDoesNotHoldTheFlat() {
        PresenceProvider flush = presence("flush", PresenceKind.FLUSH);
        arrived();
        flat.presenceChanged(flush, true, false, T0.plusSeconds(200));
        flat.presenceChanged(flush, false, false, T0.plusSeconds(210));
        flat.tick(T0.plusSeconds(5 + 600));
        assertEquals(Occupancy.OCCUPIED, flat.occupancy(), "the flush cancelled the leave check");
        flat.doorChanged(front, OpenState.OPEN, T0.plusSeconds(1000));
        flat.presenceChanged(flush, true, false, T0.plusSeconds(1001)); // ON when the door closes
        flat.doorChanged(front, OpenState.CLOSED, T0.plusSeconds(1005));
        flat.tick(T0.plusSeconds(1005 + 600));
        assertEquals(Occupancy.UNOCCUPIED, flat.occupancy(), "a flush that is ON holds nobody");
    }
}
