package org.tinysep.sunspot.busradio.internal;

import org.tinysep.device.support.lifecycle.DriverContext;

/**
 * What every link of the bus radio feeds, built once by {@link SunSpotLinks#start}: the one decoder path, the node
 * table (a lost link marks the nodes last heard on it OFFLINE) and the driver's context (events, thread names).
 */
record Feed(PacketHandler handler, SunSpotNodes nodes, DriverContext context) {
}
