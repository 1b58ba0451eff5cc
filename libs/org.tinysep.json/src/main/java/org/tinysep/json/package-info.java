/**
 * JSON for TinySEP's wire formats, written once: {@link org.tinysep.json.JsonReader} (strict, bounded, errors that
 * name the character), {@link org.tinysep.json.JsonWriter} and {@link org.tinysep.json.JsonSignature} (1.1.0: the
 * signed JSON messages of the MQTT bridge and the board; 1.2.0: {@code readKey}, the key files of both).
 * <p>
 * Bundles do not import this package at run time: bnd copies the classes into each bundle that uses them
 * ({@code -conditionalpackage: org.tinysep.json}), like the device support library.
 */
@Version("1.2.0")
package org.tinysep.json;

import org.osgi.annotation.versioning.Version;
