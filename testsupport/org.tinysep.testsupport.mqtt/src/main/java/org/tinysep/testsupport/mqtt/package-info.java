/**
 * Test support for MQTT: a real Mosquitto broker ({@link org.tinysep.testsupport.mqtt.Mosquitto}) and a recording
 * test client ({@link org.tinysep.testsupport.mqtt.MqttTestClient}). Exported so Pax Exam probes can import it;
 * the embedded Paho client stays private.
 */
@Export
@Version("1.2.0")
package org.tinysep.testsupport.mqtt;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
