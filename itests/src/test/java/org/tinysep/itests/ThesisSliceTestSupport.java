package org.tinysep.itests;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;

/**
 * Base of the thesis scenario tests that run exactly the drivers of thesis Fig 3.3 ({@link #FIRST_SLICE}), so no
 * other device may join the graph, and compare the device graph with the figure's: written once here so the
 * scenarios agree on what Fig 3.3 is.
 */
abstract class ThesisSliceTestSupport extends TinySepTestSupport {

    /** The graph of thesis Fig 3.3 with the movement node (1.17) only. */
    static final Set<String> MOVEMENT_ONLY = Set.of(
            "BusRadioAmicaUdp@1.17",
            "AmicaMovement@1.17",
            "AmicaMovement@1.17 <- BusRadioAmicaProvider of BusRadioAmicaUdp@1.17",
            "FlatOccupancy",
            "FlatOccupancy <- MovementProvider of AmicaMovement@1.17");

    /** The door half of Fig 3.3 (its bus device, AmicaDoor, Flat Occupancy's door connection). */
    static final Set<String> DOOR_PART = Set.of(
            "BusRadioAmicaUdp@1.20",
            "AmicaDoor@1.20",
            "AmicaDoor@1.20 <- BusRadioAmicaProvider of BusRadioAmicaUdp@1.20",
            "FlatOccupancy <- DoorProvider of AmicaDoor@1.20");

    /** The whole graph of thesis Fig 3.3: movement node 1.17 and door node 1.20 feeding Flat Occupancy. */
    static final Set<String> FIG_33 = union(MOVEMENT_ONLY, DOOR_PART);

    private static Set<String> union(Set<String> a, Set<String> b) {
        Set<String> u = new TreeSet<>(a);
        u.addAll(b);
        return u;
    }

    /** Exactly the drivers the thesis loads for this scenario (Fig 3.3): no other device may join the graph. */
    @Override
    protected List<String> applications() {
        return FIRST_SLICE;
    }
}
