/** <b>Test utilities, not for production code.</b> Waiting on a condition with a bound, never a bare sleep. */
@Export
@Version("1.0.0")
package org.tinysep.testsupport.wait;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
