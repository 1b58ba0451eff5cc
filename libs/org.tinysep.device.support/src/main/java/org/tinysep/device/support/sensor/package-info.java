/**
 * Sensor abstraction devices as small declarations: {@link SensorDevice} owns status, decoding and
 * filtering through its {@link Source} (one per node family), change detection, the first-report rule, the
 * {@code state}/{@code since} parameters and the listeners; {@link ContactSensorDevice}, {@link MotionSensorDevice}
 * and {@link MovementSensorDevice} add the rules of their kind once for both node families; {@link SensorDriver}
 * is the driver. A sensor declares its listener call to the constructor ({@link SensorDevice.ListenerCall}, e.g.
 * {@code DoorListener::doorChanged}) or overrides {@code tell}; 2.0: {@link ContactSensorDevice} takes the call
 * only; 3.0: the device support types in its signatures moved to the job packages ({@code DriverContext},
 * {@code AbstractDevice}, {@code NodeTypeDriver} to {@code org.tinysep.device.support.lifecycle}). Compiled into
 * each sensor bundle like the rest of device support ({@code -conditionalpackage: org.tinysep.device.support.*}).
 */
@Version("3.0.0")
package org.tinysep.device.support.sensor;

import org.osgi.annotation.versioning.Version;
