package org.tinysep.sunspot.movement.internal;

/** The shared Sun SPOT bus device double (device support's testing package). */
final class FakeSunSpotBus extends org.tinysep.device.support.testing.FakeSunSpotBus {
}
