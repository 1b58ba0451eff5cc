/**
 * The device the AmICA percent actuators share (thesis 3.9.1: dimmable light, heater and speaker nodes report a
 * percentage every 10 s and take the same payload as a command): {@link PercentActuatorDevice}. Each actuator
 * bundle only names its payload, node type, quantity and listener callback.
 * <p>
 * Actuator bundles do not import this package at run time: bnd copies the classes into each of them
 * ({@code -conditionalpackage: org.tinysep.device.support.*,org.tinysep.amica.actuator.base}). 4.0.0: the device
 * support types in its signatures ({@code DriverContext}) moved to {@code org.tinysep.device.support.lifecycle}.
 */
@Version("4.0.0")
package org.tinysep.amica.actuator.base;

import org.osgi.annotation.versioning.Version;
