/**
 * <b>Test utilities, not for production code.</b> Real serial ports for tests without hardware:
 * {@link org.tinysep.testsupport.serial.SocatPair} starts a socat pseudo-terminal pair (what a USB serial adapter
 * and the device behind it look like to a serial link) and {@link org.tinysep.testsupport.serial.PtyPeer} plays the
 * device at the far end. Used by the tests of serial support and of the serial bus radios and by the integration
 * tests; they need {@code socat} ({@code scripts/install-deps.sh}).
 * <p>
 * Exported, so that Pax Exam's probe bundle can load it inside the framework (the integration tests provision this
 * bundle); no deployed bundle imports it.
 */
@Export
@Version("1.0.0")
package org.tinysep.testsupport.serial;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
