/**
 * <b>Test utilities, not for production code.</b> The repository's own files for tests: one helper resolves every
 * data path a test reads and refuses any that lies outside the clone (a clone tests green on its own).
 */
@Export
@Version("1.0.0")
package org.tinysep.testsupport.repo;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
