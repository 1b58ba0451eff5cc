package org.tinysep.amica.actuator.base.testing;

import org.tinysep.device.support.testing.FakeAmicaBus;

/**
 * For unit tests of AmICA actuator devices: a hand-written bus device of one node that records every payload sent
 * to it ({@code sent}), or fails on demand ({@code failure}); device support's testing double under the name the
 * actuator tests know. Never referenced by main code, so bnd never copies it into a bundle.
 */
public final class FakeBus extends FakeAmicaBus {

    public FakeBus(String nodeId, String... types) {
        super(nodeId, types);
    }
}
