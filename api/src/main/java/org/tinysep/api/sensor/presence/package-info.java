/**
 * Presence and use sensors: pressure mats on a bed or a seat, a toilet flush, an appliance in use.
 * Unlike a window, such a sensor is about the person: turning ON is activity in its room, and a bed or seat mat
 * that is ON says that someone is here right now.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.sensor.presence;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
