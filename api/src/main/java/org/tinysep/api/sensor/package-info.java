/**
 * Hardware-abstraction interfaces of sensors: movement, door, window, pet movement, temperature, light brightness.
 * 1.1: door and window listeners are told whether a report is the contact's first after its device started
 * ({@code first}: it establishes the state, it is not a change).
 */
@Export
@Version("1.1.0")
package org.tinysep.api.sensor;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
