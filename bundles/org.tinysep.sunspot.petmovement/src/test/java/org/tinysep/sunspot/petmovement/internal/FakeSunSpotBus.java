package org.tinysep.sunspot.petmovement.internal;

/** The shared Sun SPOT bus device double (device support's testing package), a node with a pet collar. */
final class FakeSunSpotBus extends org.tinysep.device.support.testing.FakeSunSpotBus {

    FakeSunSpotBus() {
        super("pet-collar", "movement");
    }
}
