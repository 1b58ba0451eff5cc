/**
 * The device manager's event and packet logs: {@link Reporter} (writes to them when present, never throws) and
 * {@link RecordingLogs} (unbounded in-memory logs for tests and tools that run devices without a framework).
 * <p>
 * Not exported: bnd copies the packages an application uses into its bundle
 * ({@code -conditionalpackage: org.tinysep.device.support.*}), so an application still depends only on the exported
 * API packages and can be updated on its own.
 */
@Version("1.0.0")
package org.tinysep.device.support.logs;

import org.osgi.annotation.versioning.Version;
