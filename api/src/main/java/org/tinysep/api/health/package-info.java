/**
 * Sensor health: what each node's bus device knows about its node (last heard, the report interval its
 * node type promises, silence, battery, link quality) and which rooms are currently unmonitored because all their
 * sensing nodes are silent. Bus devices register {@link NodeHealthSource}; the Sensor Health service
 * ({@code org.tinysep.sensorhealth}) combines them with House Information into {@link SensorHealthProvider}.
 */
@Export
@Version("1.1.0")
package org.tinysep.api.health;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
