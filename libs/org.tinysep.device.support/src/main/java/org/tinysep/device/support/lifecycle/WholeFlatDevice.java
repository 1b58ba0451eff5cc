package org.tinysep.device.support.lifecycle;

/**
 * A service of the whole flat, like Flat Occupancy, Inactivity Recognition or House Information: it has no room,
 * so it has no {@code room} parameter and keeps none in its backup.
 */
public abstract class WholeFlatDevice extends AbstractDevice {

    protected WholeFlatDevice(DriverContext context, String uid, String type, String name) {
        super(context, uid, type, name);
    }

    /** @return false: the whole flat is in no room */
    @Override
    protected final boolean placeable() {
        return false;
    }
}
