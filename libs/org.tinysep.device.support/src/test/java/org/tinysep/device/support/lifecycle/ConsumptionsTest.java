package org.tinysep.device.support.lifecycle;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import org.junit.jupiter.api.Test;
import org.tinysep.api.device.ConnectionInfo;
import org.tinysep.api.device.Connection;

class ConsumptionsTest {

    /** A connection that only knows whether it is open; also used by DeviceBasicsTest. */
    static final class Handle implements Connection {
        boolean open = true;

        @Override
        public void close() {
            open = false;
        }

        @Override
        public boolean isOpen() {
            return open;
        }
    }

    @Test
    void vitalUntilTheLastVitalConnectionGoes() {
        Consumptions c = new Consumptions();
        Handle movement = new Handle();
        Handle door = new Handle();
        Handle time = new Handle();
        c.add("MovementProvider", "m1", true, movement);
        c.add("DoorProvider", "d1", true, door);
        c.add("TimeControllerProvider", "t1", false, time);

        assertTrue(c.remove("MovementProvider", "m1"));
        assertFalse(movement.isOpen());
        assertTrue(c.hasVital(), "the door is still vital");
        assertTrue(c.remove("DoorProvider", "d1"));
        assertFalse(c.hasVital(), "an optional connection alone is not vital");
        assertEquals(List.of(new ConnectionInfo("TimeControllerProvider", "t1", false)), c.infos());
        assertFalse(c.remove("DoorProvider", "d1"));
    }

    @Test
    void reconnectingUnderTheSameKeyClosesTheOldHandle() {
        Consumptions c = new Consumptions();
        Handle first = new Handle();
        Handle second = new Handle();
        c.add("DoorProvider", "d1", true, first);
        c.add("DoorProvider", "d1", true, second);
        assertFalse(first.isOpen());
        assertTrue(second.isOpen());
        c.closeAll();
        assertFalse(second.isOpen());
        assertEquals(List.of(), c.infos());
    }
}
