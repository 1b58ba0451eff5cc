/**
 * <b>Test utilities, not for production code.</b> {@link org.tinysep.testsupport.mail.SmtpSink}: an in-process SMTP
 * server on 127.0.0.1 that keeps what it receives, for the integration tests (inside Pax Exam's probe) and the
 * launcher's process tests.
 * <p>
 * Exported, so that the probe bundle can load it inside the framework; no deployed bundle imports it.
 */
@Export
@Version("1.0.0")
package org.tinysep.testsupport.mail;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
