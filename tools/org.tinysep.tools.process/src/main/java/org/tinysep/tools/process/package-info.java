/**
 * The built TinySEP distribution ({@code tinysep.jar}) run as its own process, written once for the evaluation, the
 * benchmarks, the launcher's process tests and the integration tests: {@link PlatformLaunch} prepares and starts it,
 * {@link PlatformProcess} waits for its banner, talks to its shell and stops it; {@link ChildProcesses} ends every
 * child that is still running when the starting JVM exits. Not for production code: never deployed.
 */
@Export
@Version("1.0.0")
package org.tinysep.tools.process;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
