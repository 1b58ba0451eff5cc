package org.tinysep.amica.window.internal;

import org.tinysep.device.support.testing.FakeAmicaBus;

/** A hand-written AmICA bus device: one node, records every payload sent to it (device support's testing double). */
final class FakeBus extends FakeAmicaBus {

    FakeBus(String nodeId, String... types) {
        super(nodeId, types);
    }
}
