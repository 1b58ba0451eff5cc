package org.tinysep.houseinformation.internal;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** One console line per burst of placements, not one per device (issue 17 item 8). */
class PlacementSummaryTest {

    @Test
    void aBurstBecomesOneLineAndTheNextBurstStartsAgain() {
        PlacementSummary s = new PlacementSummary();
        assertTrue(s.add("Kitchen"), "the first placement schedules the line");
        assertFalse(s.add("Hall"));
        assertFalse(s.add("Kitchen"));
        assertEquals("Placed 3 devices in 2 rooms by their node address: Hall, Kitchen (tinysep:rooms lists them)",
                s.takeLine());
        assertTrue(s.add("Bathroom"));
        assertEquals("Placed 1 device in 1 room by their node address: Bathroom (tinysep:rooms lists them)",
                s.takeLine());
    }
}
