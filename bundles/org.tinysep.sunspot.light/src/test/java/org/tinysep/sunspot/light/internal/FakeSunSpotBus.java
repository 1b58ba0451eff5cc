package org.tinysep.sunspot.light.internal;

/** The shared Sun SPOT bus device double (device support's testing package). */
final class FakeSunSpotBus extends org.tinysep.device.support.testing.FakeSunSpotBus {
}
