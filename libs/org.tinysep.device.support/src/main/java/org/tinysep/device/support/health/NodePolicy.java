package org.tinysep.device.support.health;

import java.util.ArrayList;
import java.util.List;

/**
 * A bus radio's health and capacity settings, from its configuration.
 *
 * @param silentAfterIntervals report intervals without a valid frame after which a node is OFFLINE (at least 1)
 * @param lowBatteryMillivolts a keep-alive battery voltage below this is reported as low (0 = never)
 * @param maxNodes             most nodes the bus radio creates; frames that would create more are rejected and
 *                             counted (at least 1)
 */
public record NodePolicy(int silentAfterIntervals, int lowBatteryMillivolts, int maxNodes) {

    /** 30 intervals (60 s for a movement node, 5 min for a light), 2200 mV (two AA cells near empty), 1000 nodes. */
    public static final NodePolicy DEFAULT = new NodePolicy(30, 2200, 1000);

    /**
     * @param problems receives a plain-words line for each value out of range (replaced by its default)
     * @return the policy with bad values replaced by the defaults
     */
    public static NodePolicy of(int silentAfterIntervals, int lowBatteryMillivolts, int maxNodes,
            List<String> problems) {
        List<String> p = problems == null ? new ArrayList<>() : problems;
        if (silentAfterIntervals < 1) {
            p.add("silentAfterIntervals " + silentAfterIntervals + " must be at least 1; using "
                    + DEFAULT.silentAfterIntervals);
            silentAfterIntervals = DEFAULT.silentAfterIntervals;
        }
        if (lowBatteryMillivolts < 0) {
            p.add("lowBatteryMillivolts " + lowBatteryMillivolts + " must not be negative; using "
                    + DEFAULT.lowBatteryMillivolts);
            lowBatteryMillivolts = DEFAULT.lowBatteryMillivolts;
        }
        if (maxNodes < 1) {
            p.add("maxNodes " + maxNodes + " must be at least 1; using " + DEFAULT.maxNodes);
            maxNodes = DEFAULT.maxNodes;
        }
        return new NodePolicy(silentAfterIntervals, lowBatteryMillivolts, maxNodes);
    }
}
