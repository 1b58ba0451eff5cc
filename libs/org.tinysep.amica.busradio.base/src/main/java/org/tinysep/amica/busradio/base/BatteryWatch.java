package org.tinysep.amica.busradio.base;

/**
 * An AmICA node's battery from its keep-alives: reported once when it falls below the low level, and once more
 * when it is back 100 mV above it (new batteries), so a voltage wobbling at the level does not repeat the report.
 * A reading of 0 mV means the node does not measure (e.g. USB powered). Thread-safe.
 */
final class BatteryWatch {

    /** What a reading changed. */
    enum Change { NONE, LOW, RECOVERED }

    static final int HYSTERESIS_MILLIVOLTS = 100;

    private boolean low;

    synchronized Change update(int millivolts, int lowMillivolts) {
        if (millivolts <= 0 || lowMillivolts <= 0) {
            return Change.NONE;
        }
        if (!low && millivolts < lowMillivolts) {
            low = true;
            return Change.LOW;
        }
        if (low && millivolts >= lowMillivolts + HYSTERESIS_MILLIVOLTS) {
            low = false;
            return Change.RECOVERED;
        }
        return Change.NONE;
    }

    synchronized boolean low() {
        return low;
    }

    /** @return e.g. "3000 mV", "2150 mV LOW (below 2200 mV)", "not measured" */
    String describe(int millivolts, int lowMillivolts) {
        if (millivolts <= 0) {
            return "not measured";
        }
        return millivolts + " mV" + (low() ? " LOW (below " + lowMillivolts + " mV)" : "");
    }
}
