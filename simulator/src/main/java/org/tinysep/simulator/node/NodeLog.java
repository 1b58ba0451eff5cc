package org.tinysep.simulator.node;

import java.util.logging.Logger;

/** The simulator's node log (java.util.logging). */
final class NodeLog {

    static final Logger LOG = Logger.getLogger("org.tinysep.simulator.node");

    private NodeLog() {
    }
}
