/**
 * A serial port link that opens a port by path, reads it on its own thread, writes without blocking the caller
 * and reopens by itself while the port is missing or lost (jSerialComm). Shared by the serial bus radios (AmICA,
 * Sun SPOT).
 * <p>
 * Bundles do not import this package at run time: bnd copies it into each of them
 * ({@code -conditionalpackage: ...,org.tinysep.serial.support}); they import {@code com.fazecast.jSerialComm}.
 */
@Version("1.0.0")
package org.tinysep.serial.support;

import org.osgi.annotation.versioning.Version;
