/**
 * <b>Test utilities, not for production code.</b> Phones for the tests of alerts by phone:
 * {@link org.tinysep.testsupport.phone.GammuSmsd} runs the real gammu-smsd on its {@code dummy} modem (a folder)
 * with a files spool, and lets a simulated phone reply; {@link org.tinysep.testsupport.phone.PushSink} is an HTTPS
 * server on 127.0.0.1 (certificate made by keytool) that keeps what ntfy-style clients publish.
 */
@Export
@Version("1.0.0")
package org.tinysep.testsupport.phone;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
