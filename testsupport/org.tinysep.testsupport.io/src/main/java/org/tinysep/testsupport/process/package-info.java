/**
 * <b>Test utilities, not for production code.</b> The real TinySEP distribution as a separate process, driven
 * through its interactive shell.
 */
@Export
@Version("1.1.0")
package org.tinysep.testsupport.process;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
