package org.tinysep.simulator.node;

/** Report periods in seconds (thesis 3.9.1 and 3.9.2) and the AmICA keep-alive period (a TinySEP choice). */
public final class Rates {

    public static final int MOTION = 2;
    public static final int PET_COLLAR = 2;
    public static final int REED_SWITCH = 1;
    public static final int ACTUATOR_STATUS = 10;
    public static final int SUNSPOT_STATUS = 10;
    public static final int KEEP_ALIVE = 60;

    private Rates() {
    }

    /** @return true if a report of period {@code period} is due {@code elapsed} seconds after start-up */
    public static boolean due(long elapsed, int period) {
        return elapsed % period == 0;
    }
}
