/**
 * <b>Test utilities, not for production code.</b> {@link org.tinysep.testsupport.mail.SmtpSink}: the one in-process SMTP
 * server on 127.0.0.1 that keeps what it receives (refusing, full mailboxes, login and TLS on demand), for the Mail
 * Manager's tests, the integration tests (inside Pax Exam's probe), the launcher's process tests and the evaluation.
 * <p>
 * Exported, so that the probe bundle can load it inside the framework; no deployed bundle imports it.
 */
@Export
@Version("1.1.0")
package org.tinysep.testsupport.mail;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
