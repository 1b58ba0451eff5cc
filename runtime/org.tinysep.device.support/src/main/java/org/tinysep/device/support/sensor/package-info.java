/**
 * Sensor abstraction devices as small declarations (issue 16): {@link SensorDevice} owns status, change detection,
 * the first-report rule, the {@code state}/{@code since} parameters and the listeners; {@link AmicaSensorDevice}
 * and {@link SunSpotSensorDevice} add the node family's payload handling. Compiled into each sensor bundle like
 * the rest of device support ({@code -conditionalpackage}).
 */
@Version("1.0.0")
package org.tinysep.device.support.sensor;

import org.osgi.annotation.versioning.Version;
